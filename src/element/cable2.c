/* Two-node cable element, total Lagrangian (shared/THEORY.md).
 *   a = x2 - x1, l = |a|, e = a / l, lambda = l / l0
 *   Green-Lagrange: eps = (lambda^2 - 1)/2, N = EA eps lambda, dN/dl = EA (3 lambda^2 - 1)/(2 l0)
 *   engineering:    eps = lambda - 1,       N = EA eps,        dN/dl = EA / l0
 *   strain energy U = EA l0 eps^2 / 2 (dU/dl = N for both measures)
 *   f2 = N e = -f1;  K = [[k, -k], [-k, k]],  k = dN/dl e e^T + N/l (I - e e^T)         */
#include "element/element.h"

#include <math.h>

const ctn_element_ops ctn_cable2_ops = { "cable2", 2, ctn_cable2_eval };

/* Axial force and its derivative with respect to the current length. */
static void axial_law(const ctn_cable_props *p, double l, ctn_elem_state *st, double *dNdl)
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
    if (p->tension_only && st->N <= 0) {
        st->N = 0;
        st->energy = 0;
        *dNdl = 0;
        st->slack = 1;
    }
}

int ctn_cable2_eval(const void *props, const double *X, const double *u, double *f,
                    double *K, ctn_elem_state *out)
{
    const ctn_cable_props *p = props;
    double a[3];
    for (int i = 0; i < 3; i++) a[i] = (X[3 + i] - X[i]) + (u[3 + i] - u[i]);
    double l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(l > 0) || !isfinite(l)) return CTN_ERR_DOMAIN;
    double e[3] = { a[0] / l, a[1] / l, a[2] / l };
    ctn_elem_state st;
    double dNdl;
    st.l = l;
    axial_law(p, l, &st, &dNdl);
    for (int i = 0; i < 3; i++) {
        f[i] = -st.N * e[i];                                  /* f1 = -N e */
        f[3 + i] = st.N * e[i];                               /* f2 =  N e */
    }
    if (K) {                                                  /* packed upper triangle */
        double s = st.N / l, k[3][3];
        for (int i = 0; i < 3; i++)
            for (int j = i; j < 3; j++) k[i][j] = k[j][i] = (dNdl - s) * e[i] * e[j] + (i == j ? s : 0.0);
        int t = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = i; j < 3; j++) K[t++] = k[i][j];      /* node 1 - node 1 */
            for (int j = 0; j < 3; j++) K[t++] = -k[i][j];     /* node 1 - node 2 */
        }
        for (int i = 0; i < 3; i++)
            for (int j = i; j < 3; j++) K[t++] = k[i][j];      /* node 2 - node 2 */
    }
    if (out) *out = st;
    return CTN_OK;
}
