/* The block Lanczos solver (linalg/eigen/blanczos*.c) on one and on two threads:
 * - a pencil whose eigenvalues are known independently: a membrane of springs and
 *   masses, separable (A = A1 (x) B2 + B1 (x) A2, B = B1 (x) B2 with tridiagonal A1, A2
 *   and diagonal B1, B2), so that its eigenvalues are the sums of two rows', which
 *   LAPACK's dstev gives; the nev lowest of the block solver within 1e-10 of them,
 *   residuals |A x - lambda B x| / |A x| <= 1e-10, B-orthonormal eigenvectors (1e-12);
 * - two threads (forced, whatever the order: the row-split products, the helper that
 *   populates the basis, the products with A and B on two threads) against one: the
 *   same counts, eigenvalues equal to 1e-13 relative and the same eigenvectors (to
 *   1e-9, up to sign), on a basis that holds every DOF (no restart) and on one that
 *   restarts;
 * - every allocation may fail on the two-thread path: CTN_ERR_NOMEM, no leak (ASan). */
#include "linalg/eigen/eigen.h"
#include "linalg/linsolve.h"
#include "check.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The context's helpers allowed, at any order (the two-thread runs are forced). */
static void two_threads(ctn_ctx *ctx)
{
    if (!ctx) return;
    ctn_ctx_set_threads(ctx, 2);
    ctx->thr_any_size = 1;
}

void dpbtrf_(const char *uplo, const int *n, const int *kd, double *ab, const int *ldab, int *info, size_t lu);
void dpbtrs_(const char *uplo, const int *n, const int *kd, const int *nrhs, const double *ab, const int *ldab,
             double *b, const int *ldb, int *info, size_t lu);
void dstev_(const char *jobz, const int *n, double *d, double *e, double *z, const int *ldz, double *work, int *info,
            size_t lj);

/* A 1-D pencil: springs k[0..n] in a row (fixed at both ends), masses m[0..n-1]. */
typedef struct row {
    int n;
    double *k, *m;
} row;

/* The 2-D pencil of two rows: A = A1 (x) B2 + B1 (x) A2, B = B1 (x) B2 (DOF i + n1 j),
 * whose eigenvalues are the sums mu_i + nu_j of the rows' (a membrane of springs and
 * masses, separable); A's banded Cholesky factor (LAPACK's upper storage, kd = n1). */
typedef struct pencil {
    row r[2];
    int n;
    double *band;
} pencil;

static double row_diag(const row *r, int i) { return r->k[i] + r->k[i + 1]; }

/* The five-point stencil of A (absolute = 0: y = A x) or of the rounding bound
 * (absolute = 1: y += (|A| + |lambda| B) |x|). */
static void stencil(const pencil *p, const double *x, double lambda, int absolute, double *y)
{
    const row *a = &p->r[0], *b = &p->r[1];
    const int n1 = a->n, n2 = b->n;
    const double sign = absolute ? 1.0 : -1.0;
#define V(q) (absolute ? fabs(x[q]) : x[q])
    for (int j = 0; j < n2; j++)
        for (int i = 0; i < n1; i++) {
            size_t q = (size_t)i + (size_t)n1 * (size_t)j;
            double s = (row_diag(a, i) * b->m[j] + a->m[i] * row_diag(b, j) + fabs(lambda) * a->m[i] * b->m[j]) * V(q);
            if (i > 0) s += sign * a->k[i] * b->m[j] * V(q - 1);
            if (i + 1 < n1) s += sign * a->k[i + 1] * b->m[j] * V(q + 1);
            if (j > 0) s += sign * a->m[i] * b->k[j] * V(q - (size_t)n1);
            if (j + 1 < n2) s += sign * a->m[i] * b->k[j + 1] * V(q + (size_t)n1);
            y[q] = absolute ? y[q] + s : s;
        }
#undef V
}

static void amul(void *ud, const double *x, double *y) { stencil(ud, x, 0.0, 0, y); }

static void bmul(void *ud, const double *x, double *y)
{
    const pencil *p = ud;
    const int n1 = p->r[0].n;
    for (int q = 0; q < p->n; q++) y[q] = p->r[0].m[q % n1] * p->r[1].m[q / n1] * x[q];
}

static void absmul(void *ud, const double *x, double lambda, double *y) { stencil(ud, x, lambda, 1, y); }

static int solve_block(void *ud, const double *X, double *Y, int k)
{
    const pencil *p = ud;
    const int kd = p->r[0].n, ld = kd + 1;
    int info = 0;
    memcpy(Y, X, (size_t)p->n * (size_t)k * sizeof(double));
    dpbtrs_("U", &p->n, &kd, &k, p->band, &ld, Y, &p->n, &info, 1);
    return info ? CTN_ERR_LINALG : CTN_OK;
}

static int solve(void *ud, const double *b, double *y) { return solve_block(ud, b, y, 1); }

/* Springs 1 + 0.5 sin(s i), masses 1 + 0.3 cos(t i). */
static int row_make(row *r, int n, double s, double t)
{
    r->n = n;
    r->k = malloc((size_t)(n + 1) * sizeof(double));
    r->m = malloc((size_t)n * sizeof(double));
    if (!r->k || !r->m) return 1;
    for (int i = 0; i <= n; i++) r->k[i] = 1 + 0.5 * sin(s * i);
    for (int i = 0; i < n; i++) r->m[i] = 1 + 0.3 * cos(t * i);
    return 0;
}

/* The row's eigenvalues, ascending, into w: dstev on B^-1/2 A B^-1/2 (tridiagonal). */
static int row_eigenvalues(const row *r, double *w)
{
    int n = r->n, info = 0;
    double *e = malloc((size_t)n * sizeof(double));
    if (!e) return 1;
    for (int i = 0; i < n; i++) {
        w[i] = row_diag(r, i) / r->m[i];
        if (i + 1 < n) e[i] = -r->k[i + 1] / sqrt(r->m[i] * r->m[i + 1]);
    }
    dstev_("N", &n, w, e, NULL, &n, NULL, &info, 1);
    free(e);
    return info;
}

static int pencil_make(pencil *p, int n1, int n2)
{
    memset(p, 0, sizeof *p);
    if (row_make(&p->r[0], n1, 0.37, 0.11) || row_make(&p->r[1], n2, 0.23, 0.29)) return 1;
    const row *a = &p->r[0], *b = &p->r[1];
    const int kd = n1, ld = kd + 1;
    int info = 0;
    p->n = n1 * n2;
    p->band = calloc((size_t)ld * (size_t)p->n, sizeof(double));
    if (!p->band) return 1;
    for (int q = 0; q < p->n; q++) {                     /* column q: rows q - kd .. q */
        int i = q % n1, j = q / n1;
        double *col = p->band + (size_t)ld * (size_t)q + kd;
        col[0] = row_diag(a, i) * b->m[j] + a->m[i] * row_diag(b, j);
        if (i > 0) col[-1] = -a->k[i] * b->m[j];
        if (j > 0) col[-kd] = -a->m[i] * b->k[j];
    }
    ctn_threads_saved saved;
    ctn_threads_push(1, &saved);               /* the BLAS on one thread, as the solver's */
    dpbtrf_("U", &p->n, &kd, p->band, &ld, &info, 1);
    ctn_threads_pop(&saved);
    return info != 0;
}

static void pencil_free(pencil *p)
{
    for (int k = 0; k < 2; k++) {
        free(p->r[k].k);
        free(p->r[k].m);
    }
    free(p->band);
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The nev lowest eigenvalues: sums of the rows' (the nev lowest of each suffice). */
static int exact_eigenvalues(const pencil *p, int nev, double *w)
{
    int n1 = p->r[0].n, n2 = p->r[1].n, m = 0;
    double *mu = malloc((size_t)n1 * sizeof(double)), *nu = malloc((size_t)n2 * sizeof(double));
    double *all = malloc((size_t)nev * (size_t)nev * sizeof(double));
    int rc = !mu || !nu || !all || nev > n1 || nev > n2 || row_eigenvalues(&p->r[0], mu) || row_eigenvalues(&p->r[1], nu);
    for (int i = 0; !rc && i < nev; i++)
        for (int j = 0; j < nev; j++) all[m++] = mu[i] + nu[j];
    if (!rc) qsort(all, (size_t)m, sizeof(double), cmp);
    if (!rc) memcpy(w, all, (size_t)nev * sizeof(double));
    free(mu);
    free(nu);
    free(all);
    return rc;
}

static ctn_eigen_ops pencil_ops(pencil *p, int threads)
{
    return (ctn_eigen_ops){ .ud = p, .solve = solve, .bmul = bmul, .solve_block = solve_block, .amul = amul,
                            .absmul = absmul, .threads = threads };
}

/* Residuals, B-orthonormality and the eigenvalues against dstev's. */
static void check_pairs(const pencil *p, int nev, const double *lambda, const double *V, const double *exact)
{
    const size_t n = (size_t)p->n;
    double *ax = malloc(n * sizeof(double)), *bx = malloc(n * sizeof(double));
    if (!ax || !bx) {
        CHECK(0);
        free(ax);
        free(bx);
        return;
    }
    for (int c = 0; c < nev; c++) {
        const double *x = V + n * (size_t)c;
        CHECK_CLOSE(lambda[c], exact[c], 1e-10, 0);
        amul((void *)p, x, ax);
        bmul((void *)p, x, bx);
        double r = 0, s = 0;
        for (size_t i = 0; i < n; i++) {
            r += (ax[i] - lambda[c] * bx[i]) * (ax[i] - lambda[c] * bx[i]);
            s += ax[i] * ax[i];
        }
        CHECK_MSG(sqrt(r / s) <= 1e-10, "pair %d: residual %.1e", c, sqrt(r / s));
        for (int d = 0; d <= c; d++) {
            const double *y = V + n * (size_t)d;
            double g = 0;
            for (size_t i = 0; i < n; i++) g += y[i] * bx[i];
            CHECK_CLOSE(g, c == d ? 1.0 : 0.0, 0, 1e-12);
        }
    }
    free(ax);
    free(bx);
}

/* One thread against two on the same pencil. */
static void one_and_two(int n1, int n2, int nev, int restarts)
{
    pencil p;
    double exact[64], lam[2][64], *V[2] = { NULL, NULL };
    ctn_eigen_info info[2];
    ctn_ctx *ctx = NULL;
    CHECK(nev <= 64 && !pencil_make(&p, n1, n2) && !exact_eigenvalues(&p, nev, exact) && !ctn_ctx_create(&ctx));
    two_threads(ctx);
    const int n = p.n;
    for (int t = 0; t < 2; t++) {
        ctn_eigen_ops ops = pencil_ops(&p, t + 1);
        CHECK(ctn_eigen_block(ctx, n, nev, 0.0, &ops, lam[t], &V[t], &info[t]) == CTN_OK);
        if (V[t]) check_pairs(&p, nev, lam[t], V[t], exact);
    }
    CHECK(info[0].ops == info[1].ops && info[0].block_solves == info[1].block_solves &&
          info[0].restarts == info[1].restarts);
    CHECK_MSG(restarts ? info[0].restarts > 0 : info[0].restarts == 0, "%d restarts", info[0].restarts);
    for (int c = 0; V[0] && V[1] && c < nev; c++) {
        CHECK_CLOSE(lam[1][c], lam[0][c], 1e-13, 0);
        double dot = 0, sign, worst = 0;
        for (int i = 0; i < n; i++) dot += V[0][(size_t)n * c + i] * V[1][(size_t)n * c + i];
        sign = dot < 0 ? -1 : 1;
        for (int i = 0; i < n; i++)
            worst = fmax(worst, fabs(V[0][(size_t)n * c + i] - sign * V[1][(size_t)n * c + i]));
        CHECK_MSG(worst <= 1e-9, "mode %d: the two threads' eigenvectors differ by %.1e", c, worst);
    }
    ctn_free(V[0]);
    ctn_free(V[1]);
    ctn_ctx_destroy(&ctx);
    pencil_free(&p);
}

/* Every allocation on the two-thread path may fail. */
static void alloc_failures(void)
{
    pencil p;
    double lam[8];
    CHECK(!pencil_make(&p, 40, 43));
    ctn_eigen_ops ops = pencil_ops(&p, 2);
    int failures = 0;
    for (long k = 1; k < 1000; k++) {
        ctn_ctx *ctx = NULL;
        double *V = NULL;
        ctn_eigen_info info;
        ctn_ctx_create(&ctx);
        two_threads(ctx);
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_eigen_block(ctx, p.n, 8, 0.0, &ops, lam, &V, &info);
        CHECK(rc == CTN_OK || rc == CTN_ERR_NOMEM);
        CHECK(rc == CTN_OK || V == NULL);
        failures += rc == CTN_ERR_NOMEM;
        ctn_free(V);
        ctn_ctx_destroy(&ctx);
        if (rc == CTN_OK) break;
    }
    CHECK(failures > 10);
    pencil_free(&p);
}

int main(void)
{
    one_and_two(8, 9, 8, 0);
    one_and_two(97, 103, 20, 1);
    alloc_failures();
    CHECK_DONE();
}
