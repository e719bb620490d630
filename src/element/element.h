/* Internal: element kernels. Pure functions (no allocation, no I/O) behind one small
 * ops table, so the assembly loop is written once for every element type. */
#ifndef CTN_ELEMENT_ELEMENT_H
#define CTN_ELEMENT_ELEMENT_H

#include "catena/model.h"

/* Properties of a two-node cable (truss) element. */
typedef struct ctn_cable_props {
    double EA;          /* axial rigidity [force] */
    double l0;          /* unstressed length [length] */
    ctn_strain strain;  /* strain measure */
    int tension_only;   /* 1: N = max(N, 0) */
} ctn_cable_props;

/* What an evaluation reports besides forces and stiffness. */
typedef struct ctn_elem_state {
    double l;           /* current length */
    double strain;      /* strain of the element's measure */
    double N;           /* axial tension (true force) */
    double energy;      /* strain energy EA l0 eps^2 / 2 (0 when slack); dU/dl = N */
    int slack;          /* tension-only element with no force */
} ctn_elem_state;

/* eval(props, X, u, f, K, st): X = reference coordinates of the nodes (3 per node),
 * u = their displacements (the current chord is formed as (X2 - X1) + (u2 - u1), which
 * keeps round-off at the scale of the element, not of the coordinates);
 * f = internal nodal forces (3 per node); K = the upper triangle of the symmetric
 * tangent stiffness packed row by row ((3 nnodes)(3 nnodes + 1)/2 values: K00, K01, ...,
 * K05, K11, ..., K55 for two nodes), or NULL to skip it; st = element state (may be
 * NULL).
 * Returns 0, or CTN_ERR_DOMAIN if the element has collapsed to zero length. */
typedef int (*ctn_elem_eval_fn)(const void *props, const double *X, const double *u,
                                double *f, double *K, ctn_elem_state *st);

typedef struct ctn_element_ops {
    const char *name;
    int nnodes;
    ctn_elem_eval_fn eval;
} ctn_element_ops;

#define CTN_EPACKED 21   /* packed upper triangle of a 6 x 6 element matrix */

/* Index of (i, j), i <= j < 6, in the packed upper triangle. */
static inline int ctn_packed_index(int i, int j)
{
    return i * 6 - i * (i - 1) / 2 + (j - i);
}

/* The two-node total-Lagrangian cable element of shared/THEORY.md. */
extern const ctn_element_ops ctn_cable2_ops;
int ctn_cable2_eval(const void *props, const double *X, const double *u, double *f,
                    double *K, ctn_elem_state *st);

#endif
