/* The hanging place of a dangling chain, the tip held in some directions (a rope's end
 * on a slide or a plane).
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
 * no minimizer: no placement. With the tip free there is no unknown: one walk. */
#include "start/hang.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define HANG_ITERATIONS 100
#define HANG_TOL 1e-12      /* |tip - t| relative to the chain's length */

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

/* Solve the m x m system A z = b (m <= 2) of the held directions; 0 if singular. */
static int solve_small(int m, const double A[4], const double b[2], double z[2])
{
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

int ctn_hang_place(const ctn_hang *h, double *x)
{
    int dirs[3], m = 0;
    double L = h->length;
    for (int k = 0; k < 3; k++)
        if (h->held & (1u << k)) dirs[m++] = k;
    if (m == 3 || h->n == 0 || !(L > 0)) return 0;
    double r[3] = { 0, 0, 0 }, tip[3], H[9], phi;
    if (!walk(h, r, tip, &phi, H, NULL)) return 0;
    for (int it = 0; m > 0; it++) {
        double g[2], A[4], z[2], psi = phi;
        for (int i = 0; i < m; i++) {
            g[i] = h->a[dirs[i]] + tip[dirs[i]] - h->target[dirs[i]];   /* psi's gradient */
            psi -= r[dirs[i]] * (h->target[dirs[i]] - h->a[dirs[i]]);
            for (int j = 0; j < m; j++) A[i * m + j] = H[3 * dirs[i] + dirs[j]];
        }
        double gn = m == 1 ? fabs(g[0]) : hypot(g[0], g[1]);
        if (gn <= HANG_TOL * L) break;
        if (it == HANG_ITERATIONS || !solve_small(m, A, g, z)) return 0;
        double t = 1, slope = -(g[0] * z[0] + (m == 2 ? g[1] * z[1] : 0)), r1[3];
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
