/* Post-processing of a solution: mid-span sag of generated cables. */
#include "model/model.h"
#include "solve/solution.h"

#include <math.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Current position of node index i. */
static void current(const ctn_model *m, const ctn_solution *s, int i, double x[3])
{
    for (int k = 0; k < 3; k++) x[k] = m->nodes.v[i].X[k] + ctn_solution_displacements(s)[3 * (size_t)i + (size_t)k];
}

/* Unit vectors: g (along gravity, or 0) and h (the direction along which "mid-span"
 * is measured: the chord's horizontal projection, or the chord). */
static void axes(const ctn_model *m, const double A[3], const double B[3], double g[3], double h[3])
{
    double gn = sqrt(dot3(m->gravity, m->gravity)), c[3] = { B[0] - A[0], B[1] - A[1], B[2] - A[2] };
    for (int k = 0; k < 3; k++) g[k] = gn > 0 ? m->gravity[k] / gn : 0;
    double cg = dot3(c, g);
    for (int k = 0; k < 3; k++) h[k] = c[k] - cg * g[k];
    double hn = sqrt(dot3(h, h)), cn = sqrt(dot3(c, c));
    if (!(hn > 1e-12 * cn)) {
        for (int k = 0; k < 3; k++) h[k] = c[k];
        hn = cn;
    }
    for (int k = 0; k < 3; k++) h[k] /= hn;
}

int ctn_solution_cable_sag(const ctn_model *m, const ctn_solution *s, size_t i, double *sag)
{
    if (!m || !s || !sag || i >= m->cables.n) return CTN_ERR_INVALID;
    const ctn_cable *c = &m->cables.v[i];
    double A[3], B[3], g[3], h[3], M[3];
    current(m, s, c->node[0], A);
    current(m, s, c->node[1], B);
    axes(m, A, B, g, h);
    for (int k = 0; k < 3; k++) M[k] = 0.5 * (A[k] + B[k]);
    double tm = dot3(M, h);
    *sag = 0;
    for (size_t e = c->first; e < c->first + c->count; e++) {
        double P[3], Q[3];
        current(m, s, ctn_elem_nodes(m, e)[0], P);
        current(m, s, ctn_elem_nodes(m, e)[1], Q);
        double tp = dot3(P, h) - tm, tq = dot3(Q, h) - tm;
        if ((tp <= 0 && tq >= 0) || (tp >= 0 && tq <= 0)) {
            double t = tq != tp ? -tp / (tq - tp) : 0.5;
            double X[3];
            for (int k = 0; k < 3; k++) X[k] = P[k] + t * (Q[k] - P[k]) - M[k];
            *sag = dot3(g, g) > 0 ? dot3(X, g) : sqrt(dot3(X, X));
            return CTN_OK;
        }
    }
    return CTN_ERR_DOMAIN;     /* the cable never crosses mid-span (folded back) */
}
