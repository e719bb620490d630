/* The block Lanczos solver's second thread. Its dense work over the basis (products
 * V^T B W, updates W -= V H, triangular solves, Ritz vectors) is memory-bound: one thread
 * reads memory at about 13 GB/s on the machine of bench/RESULTS.md, two at about 24. So
 * the rows of the tall matrices are split between two threads, each calling the
 * single-threaded BLAS on its half (the small products of the halves summed after);
 * independent products with A or B go one column each. The solves (one thread, the
 * factor's triangular sweeps) have no use for the second CPU: while they run, a helper
 * thread writes the basis's fresh pages (their first touch costs 4-8 s per GB there),
 * column by column ahead of the Lanczos process, which claims a column itself when it
 * gets there first. docs/solver.md, "Threads". */
#include "core/threads.h"
#include "linalg/eigen/blanczos.h"
#include "linalg/lapack.h"
#include "linalg/linsolve.h"

#include <pthread.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>

int ctn_blz_threads(const ctn_ctx *ctx, int asked, int n)
{
    if (asked == 1 || asked == 2) return asked;
    return ctn_thr_allows(ctx, asked, CTN_THR_LANCZOS, n) ? 2 : 1;
}

/* ---- two halves ---- */

typedef struct half half;
typedef void (*half_fn)(const half *h);
struct half {
    ctn_blz *z;
    half_fn fn;
    int r0, r1;                 /* rows (row-split jobs) or columns (column jobs) */
    int part;                   /* 0: the calling thread, 1: the helper */
    const void *args;
};

static void run_half(void *arg)
{
    const half *h = arg;
    ctn_threads_saved saved;
    ctn_threads_push(1, &saved);                 /* this thread's BLAS on one thread */
    h->fn(h);
    ctn_threads_pop(&saved);
}

/* fn over [0, count) in two halves when there are two threads, the second on the
 * context's helper (when one may take it: else one after the other, the same
 * arithmetic); 1 if it went in two halves. */
static int split(ctn_blz *z, half_fn fn, int count, const void *args)
{
    half h[2] = { { z, fn, 0, count, 0, args }, { z, fn, count, count, 1, args } };
    if (z->threads < 2 || count < 2) {
        fn(&h[0]);
        return 0;
    }
    h[0].r1 = h[1].r0 = count / 2;
    ctn_thr_both(z->ctx, z->asked, CTN_THR_LANCZOS, z->n, run_half, &h[0], &h[1]);
    return 1;
}

/* ---- row-split BLAS ---- */

typedef struct gemm_args {
    char ta;                    /* 'T': C = A^T B summed over rows; 'N': C = alpha A B + beta C */
    int k, w, ldb, ldc;
    double alpha, beta;
    const double *A, *B;        /* A n x k, B n x w ('T') or k x w ('N') */
    double *C;
} gemm_args;

static void gemm_half(const half *h)
{
    const gemm_args *g = h->args;
    const int n = h->z->n, m = h->r1 - h->r0;
    const size_t r0 = (size_t)h->r0;
    const double one = 1, zero = 0;
    if (m <= 0 || g->k <= 0 || g->w <= 0) return;
    if (g->ta == 'T') {                          /* the helper's half into the scratch */
        double *C = h->part ? h->z->Cpart : g->C;
        int ldc = h->part ? g->k : g->ldc;
        dgemm_("T", "N", &g->k, &g->w, &m, &one, g->A + r0, &n, g->B + r0, &n, &zero, C, &ldc, 1, 1);
    } else {
        dgemm_("N", "N", &m, &g->w, &g->k, &g->alpha, g->A + r0, &n, g->B, &g->ldb, &g->beta, g->C + r0, &n, 1, 1);
    }
}

void ctn_blz_gemm_t(ctn_blz *z, int k, int w, const double *A, const double *B, double *C, int ldc)
{
    gemm_args g = { 'T', k, w, 0, ldc, 1, 0, A, B, C };
    if (k <= 0 || w <= 0) return;
    if (!split(z, gemm_half, z->n, &g)) return;
    for (int c = 0; c < w; c++)
        for (int r = 0; r < k; r++) C[r + (size_t)ldc * (size_t)c] += z->Cpart[r + (size_t)k * (size_t)c];
}

void ctn_blz_gemm_n(ctn_blz *z, int k, int w, double alpha, const double *A, const double *B, int ldb, double beta,
                    double *C)
{
    gemm_args g = { 'N', k, w, ldb, 0, alpha, beta, A, B, C };
    split(z, gemm_half, z->n, &g);
}

typedef struct trsm_args {
    int w, ldu;
    const double *U;
    double *X;
} trsm_args;

/* By hand, rows in chunks that stay in cache while each column takes the earlier ones out:
 * the BLAS's dtrsm packs a tall matrix of a few columns first, which cost more than the
 * solve (Cholesky QR of a block of 4 columns: 21 ms against 6 ms). */
#define BLZ_TRSM_ROWS 512
static void trsm_half(const half *h)
{
    const trsm_args *t = h->args;
    const size_t n = (size_t)h->z->n, ldu = (size_t)t->ldu;
    const int w = t->w;
    for (int i0 = h->r0; i0 < h->r1; i0 += BLZ_TRSM_ROWS) {
        const int i1 = h->r1 - i0 < BLZ_TRSM_ROWS ? h->r1 : i0 + BLZ_TRSM_ROWS;
        for (int c = 0; c < w; c++) {
            double *xc = t->X + n * (size_t)c;
            for (int k = 0; k < c; k++) {
                const double u = t->U[(size_t)k + ldu * (size_t)c], *xk = t->X + n * (size_t)k;
                for (int i = i0; i < i1; i++) xc[i] -= u * xk[i];
            }
            const double d = t->U[(size_t)c + ldu * (size_t)c];
            for (int i = i0; i < i1; i++) xc[i] /= d;
        }
    }
}

void ctn_blz_trsm(ctn_blz *z, int w, const double *U, int ldu, double *X)
{
    trsm_args t = { w, ldu, U, X };
    split(z, trsm_half, z->n, &t);
}

typedef struct rotate_args {
    int ne, k, ldy;
    const double *Y;
} rotate_args;

static void rotate_half(const half *h)
{
    const rotate_args *a = h->args;
    const int n = h->z->n;
    const double one = 1, zero = 0;
    double *tmp = h->z->Rot + (size_t)h->part * CTN_BLZ_ROWS * (size_t)h->z->mcap;
    for (int r0 = h->r0; r0 < h->r1; r0 += CTN_BLZ_ROWS) {
        int m = h->r1 - r0 < CTN_BLZ_ROWS ? h->r1 - r0 : CTN_BLZ_ROWS;
        double *v = h->z->V + r0;
        dgemm_("N", "N", &m, &a->k, &a->ne, &one, v, &n, a->Y, &a->ldy, &zero, tmp, &m, 1, 1);
        for (int c = 0; c < a->k; c++)
            memcpy(v + (size_t)n * (size_t)c, tmp + (size_t)m * (size_t)c, (size_t)m * sizeof(double));
    }
}

void ctn_blz_rotate(ctn_blz *z, int ne, int k, const double *Y, int ldy)
{
    rotate_args a = { ne, k, ldy, Y };
    if (k > 0 && ne > 0) split(z, rotate_half, z->n, &a);
}

typedef struct copy_args {
    double *dst;
    const double *src;
} copy_args;

static void copy_half(const half *h)
{
    const copy_args *a = h->args;
    memcpy(a->dst + h->r0, a->src + h->r0, (size_t)(h->r1 - h->r0) * sizeof(double));
}

void ctn_blz_copy(ctn_blz *z, double *dst, const double *src, size_t count)
{
    copy_args a = { dst, src };
    if (count > INT32_MAX) {                     /* halves of an int count */
        memcpy(dst, src, count * sizeof(double));
        return;
    }
    split(z, copy_half, (int)count, &a);
}

/* ---- columns ---- */

typedef struct cols_args {
    void (*op)(void *ud, const double *x, double *y);
    const double *X;
    double *Y;
} cols_args;

/* The columns by pairs where the operator has a two-column form (one pass over its
 * matrix for both), the odd one alone. */
static void cols_half(const half *h)
{
    const cols_args *a = h->args;
    const ctn_eigen_ops *ops = h->z->ops;
    const size_t n = (size_t)h->z->n;
    void (*op2)(void *, const double *, const double *, double *, double *) =
        a->op == ops->bmul ? ops->bmul2 : a->op == ops->amul ? ops->amul2 : NULL;
    int c = h->r0;
    for (; op2 && c + 1 < h->r1; c += 2)
        op2(ops->ud, a->X + n * (size_t)c, a->X + n * (size_t)(c + 1), a->Y + n * (size_t)c, a->Y + n * (size_t)(c + 1));
    for (; c < h->r1; c++) a->op(ops->ud, a->X + n * (size_t)c, a->Y + n * (size_t)c);
}

void ctn_blz_apply(ctn_blz *z, void (*op)(void *ud, const double *x, double *y), const double *X, double *Y, int k)
{
    cols_args a = { op, X, Y };
    split(z, cols_half, k, &a);
}

typedef struct abs_args {
    const double *X, *lambda;
    double *Y;
} abs_args;

static void abs_half(const half *h)
{
    const abs_args *a = h->args;
    const size_t n = (size_t)h->z->n;
    for (int c = h->r0; c < h->r1; c++) {
        double *y = a->Y + n * (size_t)c;
        memset(y, 0, n * sizeof(double));
        h->z->ops->absmul(h->z->ops->ud, a->X + n * (size_t)c, a->lambda[c], y);
    }
}

void ctn_blz_apply_abs(ctn_blz *z, const double *X, const double *lambda, double *Y, int k)
{
    abs_args a = { X, lambda, Y };
    split(z, abs_half, k, &a);
}

/* ---- populating the basis ---- */

/* The pages wholly inside x[0:count] (a page shared with the array beside it is touched
 * by whoever writes that): a write each. MADV_POPULATE_WRITE would map them without a
 * write, but it was measured not to pay on the virtual machine of bench/RESULTS.md: it
 * returned at once and the first write of each page still cost the whole first touch
 * (the host backs a page when the guest first writes it). */
static void populate(const ctn_blz *z, double *x, size_t count)
{
    const uintptr_t page = (uintptr_t)z->page;
    uintptr_t a = ((uintptr_t)x + page - 1) / page * page, b = (uintptr_t)(x + count) / page * page;
    for (uintptr_t p = a; p < b; p += page) *(volatile char *)p = 0;
}

/* Unit u: below mcap column u of V, then the columns of X (the Ritz vectors, first
 * written by the final Rayleigh-Ritz), then those of W and B W from b (the scratch of the
 * Rayleigh-Ritz and the residuals). */
static void populate_unit(const ctn_blz *z, int u)
{
    const size_t n = (size_t)z->n;
    if (u < z->mcap) {
        populate(z, z->V + n * (size_t)u, n);
        return;
    }
    u -= z->mcap;
    if (u < z->nx) {
        populate(z, z->X + n * (size_t)u, n);
        return;
    }
    u -= z->nx - z->b;
    populate(z, z->W + n * (size_t)u, n);
    populate(z, z->MW + n * (size_t)u, n);
}

static void populate_run(void *arg)
{
    ctn_blz *z = arg;
    pthread_mutex_lock(&z->pf_lock);
    while (!z->pf_stop && z->pf_next < z->pf_units) {
        int u = z->pf_next++;
        z->pf_busy = u;
        pthread_mutex_unlock(&z->pf_lock);
        populate_unit(z, u);
        pthread_mutex_lock(&z->pf_lock);
        z->pf_busy = -1;
        pthread_cond_broadcast(&z->pf_done);
    }
    pthread_mutex_unlock(&z->pf_lock);
}

void ctn_blz_populate_start(ctn_blz *z)
{
    z->pf_on = 0;
    if (z->threads < 2) return;
    long page = sysconf(_SC_PAGESIZE);
    z->page = page > 0 ? page : 4096;
    z->pf_units = z->mcap + z->nx + z->ws - z->b;
    z->pf_next = 0;
    z->pf_busy = -1;
    z->pf_stop = 0;
    if (pthread_mutex_init(&z->pf_lock, NULL)) return;
    if (pthread_cond_init(&z->pf_done, NULL)) {
        pthread_mutex_destroy(&z->pf_lock);
        return;
    }
    z->pf_ticket = ctn_thr_start(z->ctx, z->asked, CTN_THR_LANCZOS, z->n, populate_run, z);
    if (!z->pf_ticket) {
        pthread_cond_destroy(&z->pf_done);
        pthread_mutex_destroy(&z->pf_lock);
        return;
    }
    z->pf_on = 1;
}

void ctn_blz_populate_wait(ctn_blz *z, int upto)
{
    if (!z->pf_on) return;
    pthread_mutex_lock(&z->pf_lock);
    if (upto > z->pf_units) upto = z->pf_units;
    while (z->pf_next < upto) {                   /* there first: populate them here */
        int u = z->pf_next++;
        pthread_mutex_unlock(&z->pf_lock);
        populate_unit(z, u);
        pthread_mutex_lock(&z->pf_lock);
    }
    while (z->pf_busy >= 0 && z->pf_busy < upto) pthread_cond_wait(&z->pf_done, &z->pf_lock);
    pthread_mutex_unlock(&z->pf_lock);
}

void ctn_blz_populate_stop(ctn_blz *z)
{
    if (!z->pf_on) return;
    pthread_mutex_lock(&z->pf_lock);
    z->pf_stop = 1;
    pthread_mutex_unlock(&z->pf_lock);
    ctn_thr_wait(z->ctx, z->pf_ticket);
    pthread_cond_destroy(&z->pf_done);
    pthread_mutex_destroy(&z->pf_lock);
    z->pf_on = 0;
}
