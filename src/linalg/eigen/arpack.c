/* Shift-invert Lanczos by ARPACK (dsaupd/dseupd, mode 3, bmat "G", which "LM"): the
 * eigenvalues theta = 1 / (lambda - sigma) of the operator (A - sigma B)^-1 B of
 * largest magnitude are those lambda nearest sigma; dseupd maps them back. */
#include "linalg/eigen/eigen.h"
#include "linalg/linsolve.h"

#include <arpack/arpack.h>
#include <pthread.h>
#include <string.h>

/* ARPACK keeps its reverse-communication state (and its timing and debug common
 * blocks) in Fortran SAVE variables: one analysis at a time in the process, whatever the
 * contexts. Two concurrent modal analyses take turns here (the second waits for the
 * first's whole iteration); the block Lanczos solver (blanczos.c) has no such state.
 * This lock is the library's one process-wide object, guarding a library that has one. */
static pthread_mutex_t arpack_lock = PTHREAD_MUTEX_INITIALIZER;

#define CTN_ARPACK_MAXITER 500  /* implicit restarts */

typedef struct arpack_work {
    int n, nev, ncv, lworkl;
    double *resid, *v, *workd, *workl, *d;
    int *select;
} arpack_work;

static void work_free(arpack_work *w)
{
    double *p[] = { w->resid, w->v, w->workd, w->workl, w->d };
    for (size_t i = 0; i < sizeof p / sizeof *p; i++) ctn_free(p[i]);
    ctn_free(w->select);
}

static int work_alloc(ctn_ctx *ctx, arpack_work *w)
{
    w->lworkl = w->ncv * (w->ncv + 8);
    w->resid = ctn_malloc(ctx, (size_t)w->n, sizeof(double));
    w->v = ctn_malloc(ctx, (size_t)w->n * (size_t)w->ncv, sizeof(double));
    w->workd = ctn_malloc(ctx, 3 * (size_t)w->n, sizeof(double));
    w->workl = ctn_malloc(ctx, (size_t)w->lworkl, sizeof(double));
    w->d = ctn_malloc(ctx, (size_t)w->ncv, sizeof(double));
    w->select = ctn_calloc(ctx, (size_t)w->ncv, sizeof(int));
    return w->resid && w->v && w->workd && w->workl && w->d && w->select ? CTN_OK : CTN_ERR_NOMEM;
}

/* A start vector of fixed pseudo-random entries (a local LCG: runs repeat exactly, and
 * ARPACK's own generator keeps state between calls). */
static void start_vector(double *r, int n)
{
    unsigned long long x = 0x2545F4914F6CDD1DULL;
    for (int i = 0; i < n; i++) {
        x = x * 6364136223846793005ULL + 1442695040888963407ULL;
        r[i] = (double)(x >> 11) / 9007199254740992.0 - 0.5;    /* [-0.5, 0.5) */
    }
}

/* The reverse-communication loop of dsaupd. */
static int iterate(ctn_ctx *ctx, arpack_work *w, const ctn_eigen_ops *ops, int *iparam, int *ipntr,
                   ctn_eigen_info *info)
{
    int ido = 0, status = 1;                        /* status 1: resid is the start */
    for (;;) {
        dsaupd_c(&ido, "G", w->n, "LM", w->nev, 0.0, w->resid, w->ncv, w->v, w->n, iparam, ipntr,
                 w->workd, w->workl, w->lworkl, &status);
        double *x = w->workd + ipntr[0] - 1, *y = w->workd + ipntr[1] - 1;
        int rc = CTN_OK;
        if (ido == -1) {                            /* y = OP x */
            ops->bmul(ops->ud, x, ops->work);
            rc = ops->solve(ops->ud, ops->work, y);
            info->ops++;
        } else if (ido == 1) {                      /* y = OP x, B x given */
            rc = ops->solve(ops->ud, w->workd + ipntr[2] - 1, y);
            info->ops++;
        } else if (ido == 2) {
            ops->bmul(ops->ud, x, y);               /* y = B x */
        } else {
            break;
        }
        if (rc) return rc;
    }
    info->restarts = iparam[2];
    info->nconv = iparam[4];
    if (status == 1 || (status == 0 && iparam[4] < w->nev))
        return ctn_error(ctx, CTN_ERR_NOCONV, "eigen-solver: %d of %d modes converged in %d Lanczos restarts",
                         iparam[4], w->nev, iparam[2]);
    if (status == 3)
        return ctn_error(ctx, CTN_ERR_NOCONV, "eigen-solver: no shifts could be applied (ARPACK info 3)");
    if (status != 0) return ctn_error(ctx, CTN_ERR_LINALG, "eigen-solver: ARPACK dsaupd failed (info %d)", status);
    return CTN_OK;
}

/* Selection sort of the pairs (d[k], column k of v) by ascending d: at most nev - 1
 * swaps of columns. */
static void sort_pairs(double *d, double *v, int n, int nev)
{
    for (int k = 0; k + 1 < nev; k++) {
        int m = k;
        for (int j = k + 1; j < nev; j++)
            if (d[j] < d[m]) m = j;
        if (m == k) continue;
        double t = d[k], *a = v + (size_t)k * (size_t)n, *b = v + (size_t)m * (size_t)n;
        d[k] = d[m];
        d[m] = t;
        for (int i = 0; i < n; i++) {
            double x = a[i];
            a[i] = b[i];
            b[i] = x;
        }
    }
}

int ctn_eigen_shift_invert(ctn_ctx *ctx, int n, int nev, double sigma, const ctn_eigen_ops *ops,
                           double *lambda, double **vecs, ctn_eigen_info *info)
{
    arpack_work w;
    memset(&w, 0, sizeof w);
    memset(info, 0, sizeof *info);
    *vecs = NULL;
    if (nev < 1 || nev >= n) return ctn_error(ctx, CTN_ERR_INVALID, "eigen-solver: %d modes of %d unknowns", nev, n);
    w.n = n;
    w.nev = nev;
    w.ncv = 2 * nev + 1 > 20 ? 2 * nev + 1 : 20;
    if (w.ncv > n) w.ncv = n;
    int iparam[11] = { 0 }, ipntr[11] = { 0 }, rc = work_alloc(ctx, &w);
    iparam[0] = 1;                                  /* exact shifts */
    iparam[2] = CTN_ARPACK_MAXITER;
    iparam[6] = 3;                                  /* mode 3: shift-invert */
    ctn_threads_saved saved;                        /* ARPACK's BLAS calls are vector-sized: */
    ctn_threads_push(1, &saved);                    /* threads would only spin in them */
    if (!rc) {
        pthread_mutex_lock(&arpack_lock);
        start_vector(w.resid, n);
        rc = iterate(ctx, &w, ops, iparam, ipntr, info);
        if (!rc) {
            int status = 0;
            dseupd_c(1, "A", w.select, w.d, w.v, n, sigma, "G", n, "LM", nev, 0.0, w.resid, w.ncv, w.v, n,
                     iparam, ipntr, w.workd, w.workl, w.lworkl, &status);
            if (status) rc = ctn_error(ctx, CTN_ERR_LINALG, "eigen-solver: ARPACK dseupd failed (info %d)", status);
        }
        pthread_mutex_unlock(&arpack_lock);
    }
    ctn_threads_pop(&saved);
    if (!rc) {
        sort_pairs(w.d, w.v, n, nev);
        memcpy(lambda, w.d, (size_t)nev * sizeof(double));
        *vecs = w.v;
        w.v = NULL;
    }
    work_free(&w);
    return rc;
}
