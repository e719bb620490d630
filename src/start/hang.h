/* The hanging place of a dangling chain (an anchor, then n members to a tip): the exact
 * equilibrium of the chain under its nodal loads, the tip held in some directions (all
 * three: a chain between two anchors). */
#ifndef CTN_START_HANG_H
#define CTN_START_HANG_H

#include <stddef.h>

/* Member j's chord v from the force S at its middle, phi and H (element.h's `hang` op). */
typedef double (*ctn_hang_member_fn)(const void *ud, size_t j, const double S[3], double v[3], double H[9]);

typedef struct ctn_hang {
    size_t n;           /* members, anchor to tip */
    ctn_hang_member_fn member;
    const void *ud;
    double length;      /* the chain's unstressed length (the tolerances' scale) */
    const double *f;    /* 3 n loads on the free nodes 1..n (node n: the tip) */
    double a[3];        /* the anchor */
    unsigned held;      /* the tip's held directions (bits 0..2; all three: a chain between
                           two anchors, the tip the second) */
    double target[3];   /* the tip's coordinates in those directions */
} ctn_hang;

/* Place the chain: x (3 n) the nodes 1..n. 1 if placed; 0 if the held tip cannot be
 * reached or a member carries no force. */
int ctn_hang_place(const ctn_hang *h, double *x);

#endif
