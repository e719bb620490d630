/* Restarted GMRES with right preconditioning (Saad, Iterative Methods for Sparse Linear
 * Systems, Alg. 9.5), modified Gram-Schmidt and Givens rotations. For a non-symmetric
 * operator that a symmetric factorization nearly inverts (the tangent of a load that
 * follows the geometry, preconditioned by the Cholesky factor of its symmetric part),
 * a handful of iterations reach round-off. */
#include "linalg/gmres.h"

#include <math.h>
#include <string.h>

static double local_dot(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) s += a[i] * b[i];
    return s;
}

static double gdot(const ctn_gmres *g, const double *a, const double *b)
{
    return g->dot ? g->dot(g->data, a, b) : local_dot(a, b, g->n);
}

/* x += M^-1 (V y), V's first k columns; z: scratch. */
static int update(const ctn_gmres *g, double *x, const double *y, int k, double *z, double *t)
{
    size_t n = g->n;
    memset(t, 0, n * sizeof(double));
    for (int j = 0; j < k; j++)
        for (size_t i = 0; i < n; i++) t[i] += y[j] * g->V[(size_t)j * n + i];
    int rc = g->precond(g->data, t, z);
    if (!rc)
        for (size_t i = 0; i < n; i++) x[i] += z[i];
    return rc;
}

/* y = R^-1 s for the leading k x k upper triangle of H (column-major, ld m + 1). */
static void back_solve(const ctn_gmres *g, int k, const double *s, double *y)
{
    int ld = g->m + 1;
    for (int i = k - 1; i >= 0; i--) {
        double v = s[i];
        for (int j = i + 1; j < k; j++) v -= g->H[j * ld + i] * y[j];
        y[i] = v / g->H[i * ld + i];
    }
}

/* One cycle of at most m iterations from x; *rnorm gets the residual estimate. */
static int cycle(ctn_gmres *g, const double *b, double *x, double target, double *rnorm, int *iters)
{
    size_t n = g->n;
    int m = g->m, ld = m + 1, k = 0, rc;
    double *w = g->V + (size_t)(m + 1) * n, *z = w + n, *t = z + n;
    double *cs = g->H + (size_t)ld * m, *sn = cs + m, *s = sn + m, *y = s + m + 1;
    if ((rc = g->apply(g->data, x, w))) return rc;               /* r0 = b - A x */
    for (size_t i = 0; i < n; i++) w[i] = b[i] - w[i];
    double beta = sqrt(gdot(g, w, w));
    *rnorm = beta;
    if (beta <= target || !(beta > 0)) return CTN_OK;
    for (size_t i = 0; i < n; i++) g->V[i] = w[i] / beta;
    memset(s, 0, (size_t)(m + 1) * sizeof(double));
    s[0] = beta;
    while (k < m) {
        double *v = g->V + (size_t)k * n, *vn = v + n;
        if ((rc = g->precond(g->data, v, z)) || (rc = g->apply(g->data, z, w))) return rc;
        for (int i = 0; i <= k; i++) {                          /* modified Gram-Schmidt */
            double h = gdot(g, w, g->V + (size_t)i * n);
            g->H[k * ld + i] = h;
            for (size_t r = 0; r < n; r++) w[r] -= h * g->V[(size_t)i * n + r];
        }
        double hn = sqrt(gdot(g, w, w));
        g->H[k * ld + k + 1] = hn;
        for (int i = 0; i < k; i++) {                           /* old rotations */
            double a = g->H[k * ld + i], c = g->H[k * ld + i + 1];
            g->H[k * ld + i] = cs[i] * a + sn[i] * c;
            g->H[k * ld + i + 1] = -sn[i] * a + cs[i] * c;
        }
        double a = g->H[k * ld + k], r = hypot(a, hn);          /* the new one */
        cs[k] = r > 0 ? a / r : 1;
        sn[k] = r > 0 ? hn / r : 0;
        g->H[k * ld + k] = r;
        g->H[k * ld + k + 1] = 0;
        s[k + 1] = -sn[k] * s[k];
        s[k] = cs[k] * s[k];
        k++;
        (*iters)++;
        *rnorm = fabs(s[k]);
        if (*rnorm <= target || !(hn > 0)) break;
        for (size_t i = 0; i < n; i++) vn[i] = w[i] / hn;
    }
    back_solve(g, k, s, y);
    return update(g, x, y, k, z, t);
}

int ctn_gmres_solve(ctn_gmres *g, const double *b, double *x, double rtol, int maxcycles,
                    double *rel, int *iters)
{
    double bn = sqrt(gdot(g, b, b)), rnorm = 0;
    int rc = g->precond(g->data, b, x);                        /* x0 = M^-1 b */
    *iters = 0;
    for (int c = 0; !rc && c < maxcycles; c++) {
        if ((rc = cycle(g, b, x, rtol * bn, &rnorm, iters))) break;
        if (rnorm <= rtol * bn) break;
    }
    *rel = bn > 0 ? rnorm / bn : 0;
    return rc;
}

size_t ctn_gmres_work_size(size_t n, int m)
{
    size_t ld = (size_t)m + 1;
    return (ld + 3) * n + ld * (size_t)m + 3 * (size_t)m + 2 + ld;
}

void ctn_gmres_init(ctn_gmres *g, size_t n, int m, double *work)
{
    g->n = n;
    g->m = m;
    g->dot = NULL;
    g->V = work;                                   /* (m + 1) n, then w, z, t */
    g->H = work + ((size_t)m + 4) * n;             /* (m + 1) m, then cs, sn, s, y */
}
