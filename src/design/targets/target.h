/* Internal: what a target measures (target_q.c), for the root find that sets the
 * unstressed lengths (target.c). A target sits on a record `ctn_cable`: a generated
 * cable (a chain of elements from node[0] to node[1]) or a catenary element set by a
 * target (the record of a one-element cable, model->etargets). */
#ifndef CTN_SOLVE_TARGET_H
#define CTN_SOLVE_TARGET_H

#include "problem/problem.h"

/* The target quantity of record c (its c->target: H, sag or tension) at the state u3 (3
 * displacements per model node), with the element properties of problem p:
 *   H        the horizontal part (normal to gravity) of the record's force on node[0];
 *   tension  the larger of the record's forces on its two end nodes (the end element's
 *            pull plus the half of its weight that the node carries: the anchor load);
 *   sag      the largest distance along gravity below the chord, at the same
 *            horizontal position: over the interior nodes of a chain, over the exact
 *            curve of a catenary element;
 * NAN when it cannot be measured (a sag across a vertical chord). */
double ctn_target_quantity(const ctn_problem *p, const ctn_cable *c, const double *u3);
/* The largest strain of the elements of record c at u3. */
double ctn_target_strain(const ctn_problem *p, const ctn_cable *c, const double *u3);

#endif
