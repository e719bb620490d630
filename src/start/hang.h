/* The hanging place of a dangling chain (an anchor, then n members to a tip): the exact
 * equilibrium of the chain under its nodal loads, the tip held in some directions. */
#ifndef CTN_START_HANG_H
#define CTN_START_HANG_H

#include <stddef.h>

typedef struct ctn_hang {
    size_t n;           /* members, anchor to tip */
    const double *l0;   /* n unstressed lengths */
    const double *k;    /* n axial stiffnesses E A / l0 (0: stretched by strain0) */
    double strain0;     /* the stretch of a member without a stiffness */
    const double *f;    /* 3 n loads on the free nodes 1..n (node n: the tip) */
    double a[3];        /* the anchor */
    unsigned held;      /* the tip's held directions (bits 0..2; not all three) */
    double target[3];   /* the tip's coordinates in those directions */
} ctn_hang;

/* Place the chain: x (3 n) the nodes 1..n. 1 if placed; 0 if the held tip cannot be
 * reached or a member carries no force. */
int ctn_hang_place(const ctn_hang *h, double *x);

#endif
