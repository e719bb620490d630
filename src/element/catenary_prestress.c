/* The unstressed length of a catenary element that carries a given prestress in its
 * reference geometry: the largest end tension N0 (s0 = N0 / A, eps0 = N0 / EA). Its
 * weight is w L |g|, so the tension is a function of L alone: decreasing from the taut
 * bar (L -> 0) to a least value, then rising again as a long chain hangs; the taut
 * branch is taken, bracketed by steps in L and bisected to the resolution of L. */
#include "element/catenary.h"

#include <float.h>
#include <math.h>

typedef struct pre {
    ctn_catenary_props p;
    double X[6];
    double w;                /* weight per unstressed length times |g| */
} pre;

/* The largest end tension at unstressed length L; NAN if it cannot be solved. */
static double tension(pre *q, double L)
{
    double u[6] = { 0 }, f[6];
    ctn_elem_state st;
    q->p.l0 = L;
    q->p.W = q->w * L;
    return ctn_catenary2_ops.eval(&q->p, 0, q->X, u, f, NULL, &st) ? NAN : st.N;
}

/* Bisect N(L) = N0 on [lo, hi] with N(lo) >= N0 >= N(hi). */
static double bisect(pre *q, double lo, double hi, double N0)
{
    for (int it = 0; it < 200 && hi - lo > 4 * DBL_EPSILON * hi; it++) {
        double mid = 0.5 * (lo + hi), N = tension(q, mid);
        if (!(N == N)) return NAN;
        if (N >= N0) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* L with N(L) = N0 on the taut branch; 0 if the least tension is above N0. */
static double length_for(pre *q, double C, double N0)
{
    double L = C, N = tension(q, L);
    if (!(N == N)) return 0;
    if (N < N0) {                                     /* shorter: tighter */
        double hi = L;
        for (int k = 0; k < 2200 && N < N0; k++) {
            hi = L;
            L *= 0.5;
            N = tension(q, L);
            if (!(N == N)) return 0;
        }
        return N < N0 ? 0 : bisect(q, L, hi, N0);
    }
    for (double d = 1e-9; d < 1e6; d *= 2) {          /* longer: slacker, up to the least N */
        double Ln = C * (1 + d), Nn = tension(q, Ln);
        if (!(Nn == Nn) || Nn > N) return 0;
        if (Nn <= N0) return bisect(q, L, Ln, N0);
        L = Ln;
        N = Nn;
    }
    return 0;
}

int ctn_catenary_prestress_l0(const ctn_model *m, const ctn_element *e, int kind, double v, double l, double *l0)
{
    const ctn_section *sp = &m->sections.v[e->section];
    double EA = m->materials.v[sp->material].E * sp->A, g = hypot(hypot(m->gravity[0], m->gravity[1]), m->gravity[2]);
    double N0 = kind == CTN_PRESTRESS_FORCE ? v : kind == CTN_PRESTRESS_STRESS ? v * sp->A : v * EA;
    if (!isfinite(N0) || N0 <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "catenary %d: the prestress must be a positive finite tension "
                               "(a catenary is never compressed; got N0 = %g)", e->id, N0);
    pre q = { .w = sp->w * g };
    q.p.EA = EA;
    q.p.A = sp->A;
    for (int i = 0; i < 3; i++) q.p.up[i] = q.w > 0 ? -m->gravity[i] / g : 0;
    for (int a = 0; a < 2; a++)
        for (int i = 0; i < 3; i++) q.X[3 * a + i] = m->nodes.v[m->conn.v[e->conn + (size_t)a]].X[i];
    *l0 = q.w > 0 ? length_for(&q, l, N0) : l / (1 + N0 / EA);
    if (!(*l0 > 0) || !isfinite(*l0))
        return ctn_model_error(m, CTN_ERR_MODEL, "catenary %d: no unstressed length gives a largest tension of %g in "
                               "its reference chord (its weight alone needs more)", e->id, N0);
    return CTN_OK;
}
