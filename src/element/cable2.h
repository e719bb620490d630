/* Internal: the cable's kernel (cable2.c, docs/theory.md), inline: the family's eval and
 * eval_axial, and the node-by-node assembly (assemble/gather.c), which calls it directly
 * for the cable's elements instead of through the ops table (measured: 10 % of the
 * assembly). The same code in both places, so the same bits.
 *   a = x2 - x1, l = |a|, e = a / l, lambda = l / l0
 *   Green-Lagrange: eps = (lambda^2 - 1)/2, N = EA eps lambda, dN/dl = EA (3 lambda^2 - 1)/(2 l0)
 *   engineering:    eps = lambda - 1,       N = EA eps,        dN/dl = EA / l0
 *   strain energy U = EA l0 eps^2 / 2 (dU/dl = N for both measures)
 *   f2 = N e = -f1;  K = [[k, -k], [-k, k]],  k = dN/dl e e^T + N/l (I - e e^T)         */
#ifndef CTN_ELEMENT_CABLE2_H
#define CTN_ELEMENT_CABLE2_H

#include "element/axial.h"

/* Properties of a two-node cable (truss) element (cable2.c). */
typedef struct ctn_cable_props {
    double EA;          /* axial rigidity [force] */
    double l0;          /* unstressed length [length] */
    double A;           /* area [length^2], for the stress */
    int strain;         /* ctn_strain */
    int tension_only;   /* 1: N = max(N, 0) */
    double l0_ref;      /* unstressed length at the reference temperature */
    double alpha;       /* thermal expansion [1/K] */
    double mass;        /* m' l0: the element's mass [force s^2/length]; NAN when the
                           model cannot tell it (no units, a weight and no mass=) */
} ctn_cable_props;

/* Axial force and its derivative with respect to the current length. */
static inline void ctn_cable_law(const ctn_cable_props *p, unsigned mode, double l, ctn_elem_state *st,
                                 double *dNdl)
{
    double lam = l / p->l0;
    if (p->strain == CTN_STRAIN_ENGINEERING) {
        st->strain = lam - 1.0;                               /* eps = lambda - 1 */
        st->N = p->EA * st->strain;
        *dNdl = p->EA / p->l0;
    } else {
        st->strain = 0.5 * (lam - 1.0) * (lam + 1.0);         /* (lambda^2 - 1)/2 */
        st->N = p->EA * st->strain * lam;                     /* A S lambda */
        *dNdl = p->EA * (3.0 * lam * lam - 1.0) / (2.0 * p->l0);
    }
    st->energy = 0.5 * p->EA * p->l0 * st->strain * st->strain;   /* U = EA l0 eps^2 / 2 */
    st->slack = 0;
    /* Slack below zero force; at exactly zero (an unstressed start) the member keeps its
     * tension-side stiffness, so a straight start is not a matrix of zeros. */
    if ((p->tension_only || (mode & CTN_EVAL_CUT_COMPRESSION)) && st->N < 0) {
        st->N = 0;
        st->energy = 0;
        *dNdl = 0;
        st->slack = 1;
    }
    st->stress = mode & CTN_EVAL_STRESS ? st->N / p->A : 0.0;
}

static inline int ctn_cable_axial(const void *props, unsigned mode, const double *X, const double *u,
                                  double *f, double *kk, ctn_elem_state *out)
{
    const ctn_cable_props *p = props;
    double e[3], dNdl;
    if (ctn_axial_chord(X, u, e, &out->l)) return 1;
    ctn_cable_law(p, mode, out->l, out, &dNdl);
    ctn_axial_forces(e, out->N, f);
    if (kk) ctn_axial_k(e, out->l, out->N, dNdl, kk);
    return 0;
}

#endif
