/* Funicular polygon: the closure equation for the force F = F_0 in the first segment.
 * Segment i carries F_i = F - Q_i, Q_i = P_1 + ... + P_i, tension N_i = |F_i|, direction
 * e_i = F_i / N_i and stretched length l_i = L0_i (1 + N_i / EA_i). With the convex
 * complementary energy  Phi(F) = sum L0_i (N_i + N_i^2 / (2 EA_i)) - F . (l, h):
 *   g = grad Phi = sum l_i e_i - (l, h)                    (closure residual)
 *   J = sum (l_i / N_i) (I - e_i e_i^T) + (L0_i / EA_i) e_i e_i^T      (Hessian, SPD) */
#include "analytic/an.h"

#include <math.h>

/* Load of joint k (1..n-1) into P[0..1]; zero without loads. */
static void joint_load(const ctn_funicular_in *in, size_t k, double *P)
{
    P[0] = in->P ? in->P[2 * (k - 1)] : 0.0;
    P[1] = in->P ? in->P[2 * (k - 1) + 1] : 0.0;
}

/* Add segment i with force Fi to the sums. */
static void add_segment(const ctn_funicular_in *in, size_t i, const double *Fi,
                        ctn_an_funicular_eq *eq)
{
    double N = hypot(Fi[0], Fi[1]), EA = in->EA ? in->EA[i] : INFINITY, L0 = in->L0[i];
    double ex = Fi[0] / N, ey = Fi[1] / N, len = L0 * (1.0 + N / EA);
    double a = len / N, b = L0 / EA - a;                       /* a I + b e e^T */
    eq->g[0] += len * ex;
    eq->g[1] += len * ey;
    eq->J[0] += a + b * ex * ex;
    eq->J[1] += b * ex * ey;
    eq->J[2] += a + b * ey * ey;
    eq->phi += L0 * (N + 0.5 * N * N / EA);
    eq->len += len;
    if (N == 0.0) eq->slack = 1;
}

void ctn_an_funicular_eval(const ctn_funicular_in *in, const double *F, ctn_an_funicular_eq *eq)
{
    double Fi[2] = {F[0], F[1]}, P[2];
    *eq = (ctn_an_funicular_eq){{0, 0}, {0, 0, 0}, 0, 0, 0, 0};
    for (size_t i = 0; i < in->n; i++) {
        if (i > 0) {
            joint_load(in, i, P);
            Fi[0] -= P[0];
            Fi[1] -= P[1];
        }
        add_segment(in, i, Fi, eq);
    }
    eq->g[0] -= in->l;
    eq->g[1] -= in->h;
    eq->phi_abs = eq->phi + fabs(F[0] * in->l + F[1] * in->h);
    eq->phi -= F[0] * in->l + F[1] * in->h;
}

void ctn_an_funicular_shape(const ctn_funicular_in *in, const double *F, double *xy, double *N)
{
    double Fi[2] = {F[0], F[1]}, P[2];
    xy[0] = xy[1] = 0.0;
    for (size_t i = 0; i < in->n; i++) {
        if (i > 0) {
            joint_load(in, i, P);
            Fi[0] -= P[0];
            Fi[1] -= P[1];
        }
        double Ni = hypot(Fi[0], Fi[1]), EA = in->EA ? in->EA[i] : INFINITY;
        double len = in->L0[i] * (1.0 + Ni / EA);
        N[i] = Ni;
        xy[2 * i + 2] = xy[2 * i] + len * Fi[0] / Ni;
        xy[2 * i + 3] = xy[2 * i + 1] + len * Fi[1] / Ni;
    }
}

double ctn_an_funicular_slackest(const ctn_funicular_in *in, const double *F, size_t *imin)
{
    double Fi[2] = {F[0], F[1]}, P[2], Nmin = INFINITY, Nmax = 0.0;
    *imin = 0;
    for (size_t i = 0; i < in->n; i++) {
        if (i > 0) {
            joint_load(in, i, P);
            Fi[0] -= P[0];
            Fi[1] -= P[1];
        }
        double N = hypot(Fi[0], Fi[1]);
        if (N < Nmin) { Nmin = N; *imin = i; }
        Nmax = fmax(Nmax, N);
    }
    return Nmax > 0.0 ? Nmin / Nmax : 0.0;
}

/* Q_i = P_1 + ... + P_i. */
static void cumulative_load(const ctn_funicular_in *in, size_t i, double *Q)
{
    double P[2];
    Q[0] = Q[1] = 0.0;
    for (size_t k = 1; k <= i; k++) {
        joint_load(in, k, P);
        Q[0] += P[0];
        Q[1] += P[1];
    }
}

void ctn_an_funicular_gap(const ctn_funicular_in *in, size_t i, double *Q, double *gap,
                          double *allow)
{
    double Fj[2], P[2];
    cumulative_load(in, i, Q);                                 /* F = Q_i: F_i = 0 */
    Fj[0] = Q[0];
    Fj[1] = Q[1];
    gap[0] = -in->l;
    gap[1] = -in->h;
    *allow = 0.0;
    for (size_t j = 0; j < in->n; j++) {
        if (j > 0) {
            joint_load(in, j, P);
            Fj[0] -= P[0];
            Fj[1] -= P[1];
        }
        double N = hypot(Fj[0], Fj[1]), EA = in->EA ? in->EA[j] : INFINITY;
        if (j == i || N <= 1e-12 * hypot(Q[0], Q[1])) {       /* slack: any direction */
            *allow += in->L0[j];
            continue;
        }
        gap[0] += in->L0[j] * (1.0 + N / EA) * Fj[0] / N;
        gap[1] += in->L0[j] * (1.0 + N / EA) * Fj[1] / N;
    }
}
