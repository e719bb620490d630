/* The hanging place of a dangling chain, the tip held in some directions (a rope's end
 * on a slide or a plane), or in all three (a chain between two anchors: the tip is the
 * second anchor, its reaction the three unknowns).
 *
 * Walking from the tip to the anchor, member j carries the force F_j = r + S_j, the
 * loads S_j of the nodes from j to the tip plus the tip's reaction r (in its held
 * directions only), and lies along F_j: node j - 1 plus v_j = l_j F_j / |F_j| is node j,
 * with l_j = l0_j + |F_j| / k_j (the member's elastic stretch, engineering strain). The
 * tip is then at a + sum_j v_j(r). Since v_j is the gradient in F of the convex
 * phi_j(F) = l0_j |F| + |F|^2 / (2 k_j), the reaction that brings the tip to its held
 * coordinates t minimizes the convex psi(r) = sum_j phi_j(r + S_j) - r . (t - a) over
 * the held directions: Newton's method with a backtracking line search on psi, whose
 * Hessian sum_j l0_j (I - u_j u_j^T) / |F_j| + I / k_j is positive semi-definite. A
 * member is whatever gives its chord as such a gradient (element.h's `hang` op: a bar,
 * or an elastic catenary whose own weight bends it between its nodes). The
 * tip out of reach (held on a plane farther from the anchor than the chain is long) has
 * no minimizer: no placement. With the tip free there is no unknown: one walk. Newton
 * stops at |tip - t| <= HANG_TOL of the length, or where it no longer lowers it within
 * HANG_STALL (a long chain's sum of chords at its round-off). */
#include "start/hang.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define HANG_ITERATIONS 100
#define HANG_TOL 1e-12      /* |tip - t| relative to the chain's length */
#define HANG_STALL 1e-9     /* the same where Newton no longer lowers it (its round-off) */

/* One walk from the tip at reaction r: the tip's offset from the anchor (tip), psi's
 * energy part (*phi), its Hessian (H, 3x3); 0 if a member gives no chord. x (or NULL):
 * the members' vectors v_j, member j at 3 j. */
static int walk(const ctn_hang *h, const double r[3], double tip[3], double *phi, double H[9], double *x)
{
    double S[3] = { r[0], r[1], r[2] };
    memset(tip, 0, 3 * sizeof(double));
    memset(H, 0, 9 * sizeof(double));
    *phi = 0;
    for (size_t j = h->n; j-- > 0;) {
        double v[3], Hj[9];
        for (int k = 0; k < 3; k++) S[k] += h->f[3 * j + (size_t)k];
        double p = h->member(h->ud, j, S, v, Hj);
        if (!isfinite(p)) return 0;
        *phi += p;
        for (int k = 0; k < 3; k++) {
            tip[k] += v[k];
            if (x) x[3 * j + (size_t)k] = v[k];
        }
        for (int k = 0; k < 9; k++) H[k] += Hj[k];
    }
    return 1;
}

/* Solve the m x m system A z = b (m <= 3) of the held directions; 0 if singular. One or
 * two directions directly; three (a chain between anchors) by elimination with partial
 * pivoting. */
static int solve_three(const double A[9], const double b[3], double z[3])
{
    double M[3][4], big = 0;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) big = fmax(big, fabs(M[i][j] = A[3 * i + j]));
        M[i][3] = b[i];
    }
    for (int c = 0; c < 3; c++) {
        int p = c;
        for (int i = c + 1; i < 3; i++)
            if (fabs(M[i][c]) > fabs(M[p][c])) p = i;
        if (!(fabs(M[p][c]) > 1e-14 * big)) return 0;
        for (int j = 0; j < 4; j++) {
            double t = M[c][j];
            M[c][j] = M[p][j];
            M[p][j] = t;
        }
        for (int i = c + 1; i < 3; i++) {
            double f = M[i][c] / M[c][c];
            for (int j = c; j < 4; j++) M[i][j] -= f * M[c][j];
        }
    }
    for (int i = 3; i-- > 0;) {
        double t = M[i][3];
        for (int j = i + 1; j < 3; j++) t -= M[i][j] * z[j];
        z[i] = t / M[i][i];
    }
    return 1;
}

static int solve_small(int m, const double A[9], const double b[3], double z[3])
{
    if (m == 3) return solve_three(A, b, z);
    if (m == 1) {
        if (!(A[0] > 0)) return 0;
        z[0] = b[0] / A[0];
        return 1;
    }
    double det = A[0] * A[3] - A[1] * A[2];
    if (!(det > 1e-14 * (A[0] * A[3] + fabs(A[1] * A[2])))) return 0;
    z[0] = (A[3] * b[0] - A[1] * b[1]) / det;
    z[1] = (A[0] * b[1] - A[2] * b[0]) / det;
    return 1;
}

/* A tip held in every direction (a chain between two anchors): the first reaction is
 * that of a parabola of moderate sag, H = |W| along the chord and half the loads W
 * against them, so that every member starts with a force (at r = 0 the member at the
 * tip has none). 0 if the chain carries no load (no funicular to find). */
static int first_reaction(const ctn_hang *h, double r[3])
{
    double W[3] = { 0, 0, 0 }, c[3], cn = 0, wn = 0;
    for (size_t j = 0; j < h->n; j++)
        for (int k = 0; k < 3; k++) W[k] += h->f[3 * j + (size_t)k];
    for (int k = 0; k < 3; k++) {
        c[k] = h->target[k] - h->a[k];
        cn += c[k] * c[k];
        wn += W[k] * W[k];
    }
    cn = sqrt(cn);
    wn = sqrt(wn);
    if (!(wn > 0 && cn > 0)) return 0;
    for (int k = 0; k < 3; k++) r[k] = wn * c[k] / cn - 0.5 * W[k];
    return 1;
}

int ctn_hang_place(const ctn_hang *h, double *x)
{
    int dirs[3], m = 0;
    double L = h->length;
    for (int k = 0; k < 3; k++)
        if (h->held & (1u << k)) dirs[m++] = k;
    if (h->n == 0 || !(L > 0)) return 0;
    double r[3] = { 0, 0, 0 }, tip[3], H[9], phi;
    if (m == 3 && !first_reaction(h, r)) return 0;
    if (!walk(h, r, tip, &phi, H, NULL)) return 0;
    double last = INFINITY;
    for (int it = 0; m > 0; it++) {
        double g[3], A[9], z[3], psi = phi;
        for (int i = 0; i < m; i++) {
            g[i] = h->a[dirs[i]] + tip[dirs[i]] - h->target[dirs[i]];   /* psi's gradient */
            psi -= r[dirs[i]] * (h->target[dirs[i]] - h->a[dirs[i]]);
            for (int j = 0; j < m; j++) A[i * m + j] = H[3 * dirs[i] + dirs[j]];
        }
        double gn = m == 1 ? fabs(g[0]) : m == 2 ? hypot(g[0], g[1]) : sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        double slope = 0, t = 1, r1[3];
        if (gn <= HANG_TOL * L || (gn >= last && gn <= HANG_STALL * L)) break;
        last = gn;
        if (it == HANG_ITERATIONS || !solve_small(m, A, g, z)) return 0;
        slope = -(g[0] * z[0] + (m >= 2 ? g[1] * z[1] : 0) + (m == 3 ? g[2] * z[2] : 0));
        for (int ls = 0;; ls++, t *= 0.5) {            /* Armijo on psi */
            if (ls == 60) return 0;
            memcpy(r1, r, sizeof r1);
            for (int i = 0; i < m; i++) r1[dirs[i]] -= t * z[i];
            if (!walk(h, r1, tip, &phi, H, NULL)) continue;   /* a member without force: shorter */
            double psi1 = phi;
            for (int i = 0; i < m; i++) psi1 -= r1[dirs[i]] * (h->target[dirs[i]] - h->a[dirs[i]]);
            if (psi1 <= psi + 1e-4 * t * slope || fabs(psi1 - psi) <= 4 * DBL_EPSILON * fabs(psi)) break;
        }
        memcpy(r, r1, sizeof r);
    }
    if (!walk(h, r, tip, &phi, H, x)) return 0;
    for (size_t j = 0; j < h->n; j++)                  /* the members' vectors to the nodes */
        for (int k = 0; k < 3; k++) x[3 * j + (size_t)k] += j ? x[3 * (j - 1) + (size_t)k] : h->a[k];
    return 1;
}
