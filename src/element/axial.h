/* Internal: kinematics shared by two-node axial members (cable, spring): the current
 * chord, the nodal forces of an axial force and its tangent. */
#ifndef CTN_ELEMENT_AXIAL_H
#define CTN_ELEMENT_AXIAL_H

#include "element/element.h"

/* Unit chord e and length l of the current configuration X + u (3 per node, 2 nodes);
 * 1 if the element has collapsed (l not positive and finite), else 0. */
int ctn_axial_chord(const double *X, const double *u, double e[3], double *l);
/* f1 = -N e, f2 = N e. */
void ctn_axial_forces(const double e[3], double N, double *f);
/* Packed upper triangle of K = [[k, -k], [-k, k]], k = dN/dl e e^T + N/l (I - e e^T). */
void ctn_axial_tangent(const double e[3], double l, double N, double dNdl, double *K);

#endif
