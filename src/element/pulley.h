/* Internal: the properties of the pulley family (pulley.c). */
#ifndef CTN_ELEMENT_PULLEY_H
#define CTN_ELEMENT_PULLEY_H

#include "element/cable2.h"

/* Properties of a cable running over frictionless pulleys (pulley.c): the cable law of
 * the whole length over its nnodes - 1 straight segments, tension-only. */
typedef struct ctn_pulley_props {
    ctn_cable_props cable;  /* EA, l0 (the whole unstressed length), A, strain law */
    int nnodes;             /* nodes: the two ends and the pulleys between them */
    int pad;
    double l0_ref;          /* l0 at the reference temperature */
    double alpha;           /* thermal expansion coefficient [1/K] */
} ctn_pulley_props;

#endif
