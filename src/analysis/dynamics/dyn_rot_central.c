/* The explicit central differences with finite rotations (beams): each node's body-frame
 * angular velocity W by the velocity form of the translations, on Euler's equations
 * J A = R^T m - W x J W (m the spatial moment of the residual and the damping):
 *   W(n+1/2) = W_n + h/2 A_n,   R1 = R0 exp(h W(n+1/2))  (the spin R0 h W(n+1/2)),
 *   W1 = W(n+1/2) + h/2 J^-1 (R1^T m1 - W1 x J W1),   A1 = (W1 - W(n+1/2)) 2 / h,
 * W1 by fixed-point iteration (a contraction of about h |W| cond(J): a few sweeps at a
 * stable step). Second order in h, exact for a rotation at a constant rate about a
 * principal axis. A node with some rotations fixed keeps its free ones (J restricted to
 * them). The stable step takes each node's least rotary inertia, lambda_min(J), as the
 * mass of its rotations: R J R^T >= lambda_min I, so Gershgorin's bound on M^-1 K over
 * that diagonal bounds omega_max^2. docs/theory.md "Dynamics". */
#include "analysis/dynamics/dyn_rot.h"

#include <string.h>

/* The least eigenvalue of the symmetric J (3 x 3), by the trigonometric formula. */
static double least_eigenvalue(const double J[9])
{
    double p1 = J[1] * J[1] + J[2] * J[2] + J[5] * J[5], q = (J[0] + J[4] + J[8]) / 3;
    if (p1 == 0) return fmin(J[0], fmin(J[4], J[8]));
    double p2 = (J[0] - q) * (J[0] - q) + (J[4] - q) * (J[4] - q) + (J[8] - q) * (J[8] - q) + 2 * p1;
    double p = sqrt(p2 / 6), B[9];
    for (int i = 0; i < 9; i++) B[i] = (J[i] - (i % 4 == 0 ? q : 0)) / p;
    double det = B[0] * (B[4] * B[8] - B[5] * B[7]) - B[1] * (B[3] * B[8] - B[5] * B[6]) + B[2] * (B[3] * B[7] - B[4] * B[6]);
    double r = fmax(-1.0, fmin(1.0, det / 2)), phi = acos(r) / 3;
    return q + 2 * p * cos(phi + 2.0943951023931954923);  /* + 2 pi / 3: the least */
}

void ctn_dyn_rot_stable_diag(ctn_dyn *dy)
{
    const struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; r && k < r->n; k++) {
        double l = least_eigenvalue(r->J + 9 * k);
        for (int c = 0; c < 3; c++) {
            int q = r->eq[3 * k + (size_t)c];
            if (q >= 0) dy->diag[q] = l;
        }
    }
}

/* x = J^-1 b on the node's free rotations (0 on the fixed ones), by Cramer's rule on J
 * with the fixed rows and columns made the identity's. */
static void solve_free(const struct ctn_dyn_rot *r, size_t k, const double b[3], double x[3])
{
    double A[9], c[3];
    memcpy(A, r->J + 9 * k, sizeof A);
    for (int i = 0; i < 3; i++) {
        c[i] = b[i];
        if (r->eq[3 * k + (size_t)i] >= 0) continue;
        for (int j = 0; j < 3; j++) A[3 * i + j] = A[3 * j + i] = (double)(i == j);
        c[i] = 0;
    }
    double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) + A[2] * (A[3] * A[7] - A[4] * A[6]);
    for (int i = 0; i < 3; i++) {
        double M[9];
        memcpy(M, A, sizeof M);
        for (int j = 0; j < 3; j++) M[3 * j + i] = c[j];
        x[i] = (M[0] * (M[4] * M[8] - M[5] * M[7]) - M[1] * (M[3] * M[8] - M[5] * M[6]) + M[2] * (M[3] * M[7] - M[4] * M[6])) / det;
    }
}

void ctn_dyn_rot_central_turn(ctn_dyn *dy, double h, double *w)
{
    struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; r && k < r->n; k++) {
        double q[4], R[9], th[3], ts[3], *Wh = r->W1 + 3 * k;
        for (int c = 0; c < 3; c++) {
            Wh[c] = r->W0[3 * k + (size_t)c] + 0.5 * h * r->A0[3 * k + (size_t)c];   /* W(n+1/2) */
            th[c] = h * Wh[c];
        }
        dr_quat(dy->d0 + r->st[k], q);
        dr_rmat(q, R);
        dr_mv(R, th, ts);                                /* R0 exp(th) = exp(R0 th) R0 */
        for (int c = 0; c < 3; c++) {
            int e = r->eq[3 * k + (size_t)c];
            if (e >= 0) w[e] = ts[c];
        }
    }
}

/* Sweeps of the fixed point W1 = Wh + h/2 J^-1 (R1^T m - W1 x J W1) before a step fails. */
#define CTN_DYN_ROT_SWEEPS 50

int ctn_dyn_rot_central_rates(ctn_dyn *dy, double h, const double *f)
{
    struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; r && k < r->n; k++) {
        double q[4], R[9], m[3], mb[3], Wh[3], *W = r->W1 + 3 * k, *A = r->A1 + 3 * k;
        int done = 0;
        for (int c = 0; c < 3; c++) {
            int e = r->eq[3 * k + (size_t)c];
            m[c] = e >= 0 ? f[e] : 0.0;
            Wh[c] = W[c];
        }
        dr_quat(dy->d1 + r->st[k], q);
        dr_rmat(q, R);
        dr_mtv(R, m, mb);                                /* the body-frame moment */
        for (int it = 0; it < CTN_DYN_ROT_SWEEPS && !done; it++) {
            double JW[3], b[3], x[3], change = 0, size = 0;
            dr_mv(r->J + 9 * k, W, JW);
            for (int c = 0; c < 3; c++) b[c] = mb[c] - (W[(c + 1) % 3] * JW[(c + 2) % 3] - W[(c + 2) % 3] * JW[(c + 1) % 3]);
            solve_free(r, k, b, x);
            for (int c = 0; c < 3; c++) {
                double wn = Wh[c] + 0.5 * h * x[c];
                change += (wn - W[c]) * (wn - W[c]);
                size += wn * wn;
                W[c] = wn;
                A[c] = x[c];
            }
            done = change <= 1e-28 * size || size == 0;
        }
        if (!done) return 0;
        for (int c = 0; c < 3; c++) {
            int e = r->eq[3 * k + (size_t)c];
            if (e < 0) continue;
            dy->v1[e] = W[c];
            dy->a1[e] = A[c];
        }
    }
    return 1;
}
