/* CHOLMOD backends: symbolic analysis once, numeric refactorization per call.
 *   "cholmod":     LL' (supernodal), or for a simplicial factor CHOLMOD's own LDL'
 *                  whose pivots are checked: the first d <= 0 is where LL' would have
 *                  failed, and is reported as such (LL' by final_ll would convert the
 *                  factor after every factorization and make the solves slower:
 *                  measured by bench/bench_floor, +15 % CPU per iteration);
 *   "cholmod-ldl": simplicial LDL' (no pivoting), for indefinite matrices; the signs of
 *                  D give the inertia.
 * The matrix is held as a pattern; the caller's values are lent to CHOLMOD for each
 * factorization, its right-hand side and solution arrays for each solve (no copy).
 * CHOLMOD's long-integer interface throughout (chol.h). */
#include "core/threads.h"
#include "linalg/backends/cholmod/chol.h"
#include "linalg/backends/cholmod/psolve.h"

#include <math.h>
#include <string.h>
#include <unistd.h>

static void chol_destroy(void *impl)
{
    chol *c = impl;
    if (!c) return;
    cholmod_l_free_factor(&c->L, &c->cm);
    cholmod_l_free_sparse(&c->A, &c->cm);
    cholmod_l_free_dense(&c->B, &c->cm);
    cholmod_l_free_dense(&c->Y, &c->cm);
    cholmod_l_free_dense(&c->E, &c->cm);
    cholmod_l_free_dense(&c->Yk, &c->cm);
    cholmod_l_free_dense(&c->Ek, &c->cm);
    ctn_psolve_destroy(&c->ps);
    cholmod_l_finish(&c->cm);
    ctn_free(c);
}

/* A factor that cannot fit in the machine's memory is refused before CHOLMOD tries (and
 * the system starts to swap or kills the process): out of memory, with what it needs. */
static int check_memory(chol *c)
{
    double need = 8.0 * (c->L->is_super ? (double)c->L->xsize : c->lnz);
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    double have = pages > 0 && page > 0 ? (double)pages * (double)page : 0;
    if (!(have > 0) || need < have) return CTN_OK;
    return ctn_error(c->ctx, CTN_ERR_NOMEM, "the factorization needs %.1f GB for its factor (%.0f non-zeros, "
                     "ordering %s), more than this machine's %.1f GB of memory", 1e-9 * need, c->lnz,
                     ctn_la_ordering_name(c->ordering), 1e-9 * have);
}

static int chol_create(ctn_ctx *ctx, const ctn_pattern *p, const ctn_la_options *o, int indefinite, void **out)
{
    *out = NULL;
    chol *c = ctn_calloc(ctx, 1, sizeof(chol));
    if (!c) return CTN_ERR_NOMEM;
    c->ctx = ctx;
    cholmod_l_start(&c->cm);
    c->indefinite = indefinite;
    c->threads = o->threads;
    c->plain = o->plain;
    c->cm.final_ll = 0;
    if (indefinite) c->cm.supernodal = CHOLMOD_SIMPLICIAL;
    c->cm.quick_return_if_not_posdef = 1;
    c->cm.print = 0;
    c->cm.error_handler = NULL;
    size_t n = p->n, nnz = (size_t)p->colptr[n];
    int rc = CTN_OK;
    c->A = cholmod_l_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_PATTERN, &c->cm);
    c->B = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &c->cm);
    if (!c->A || !c->B) { rc = ctn_chol_error(c, "allocation"); goto fail; }
    SuiteSparse_long *Ap = c->A->p, *Ai = c->A->i;
    for (size_t j = 0; j <= n; j++) Ap[j] = p->colptr[j];
    for (size_t k = 0; k < nnz; k++) Ai[k] = p->rowind[k];
    if ((rc = ctn_chol_analyze(c, o->ordering)) || (rc = check_memory(c))) goto fail;
    *out = c;
    return CTN_OK;
fail:
    chol_destroy(c);
    return rc;
}

static int ll_create(ctn_ctx *ctx, const ctn_pattern *p, const ctn_la_options *o, void **out)
{
    return chol_create(ctx, p, o, 0, out);
}

static int ldl_create(ctn_ctx *ctx, const ctn_pattern *p, const ctn_la_options *o, void **out)
{
    return chol_create(ctx, p, o, 1, out);
}

/* The first pivot d <= 0 of a simplicial LDL' factor (its column's first entry), -1 if
 * none or the factor is LL'. */
static long first_nonpositive(const cholmod_factor *L)
{
    return L->is_super || L->is_ll ? -1 : ctn_chol_first_nonpositive(L, 0, L->n);
}

static int chol_factor(void *impl, const double *Kx, double shift, ctn_factor_info *info)
{
    chol *c = impl;
    double beta[2] = { shift, 0 };
    info->ok = 0;
    info->fail_col = -1;
    if (c->L->is_super && c->L->xtype == CHOLMOD_PATTERN) {
        /* the factor's values, allocated here as the factorization would, so that
         * they are advised for huge pages and first touched on two threads
         * (cholmod_touch.c) */
        if (!cholmod_l_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, c->L, &c->cm))
            return ctn_chol_error(c, "factorization");
        ctn_mem_huge(c->L->x, c->L->xsize * sizeof(double));
        ctn_chol_touch(c);
    }
    c->A->xtype = CHOLMOD_REAL;                  /* lend the caller's values */
    c->A->x = (void *)Kx;
    int ok = cholmod_l_factorize_p(c->A, beta, NULL, 0, c->L, &c->cm);
    c->A->x = NULL;
    c->A->xtype = CHOLMOD_PATTERN;
    if (!ok || c->cm.status < CHOLMOD_OK) return ctn_chol_error(c, "factorization");
    long k = c->cm.status == CHOLMOD_NOT_POSDEF ? (long)c->L->minor : c->indefinite ? -1 : first_nonpositive(c->L);
    if (k >= 0) {
        const SuiteSparse_long *perm = c->L->Perm;
        info->fail_col = perm ? perm[k] : k;
        return CTN_OK;
    }
    info->ok = 1;
    return CTN_OK;
}

/* The caller's array x of n x k values as a CHOLMOD dense matrix of B's shape. Given as
 * X, solve2 writes the solution there instead of into a matrix of its own that would
 * then be copied (it keeps an X of the right shape, as this one always is, and would
 * free one of another shape). solve2 reads B into its workspace (permuted) and solves
 * there before it writes X, so x may be b. */
static cholmod_dense lent(const cholmod_dense *B, size_t k, const double *x)
{
    cholmod_dense h = *B;
    h.ncol = k;
    h.nzmax = B->nrow * k;
    h.x = (void *)x;
    return h;
}

/* x = K \ b: on two threads for a large supernodal factor (1.2-1.6x faster than
 * CHOLMOD's solve on this machine; bench/RESULTS.md), else by cholmod_l_solve2. */
static int chol_solve(void *impl, const double *b, double *x)
{
    chol *c = impl;
    size_t n = c->A->nrow;
    int rc = c->L->is_super ? ctn_chol_psolve_plan(c) : CTN_OK;
    if (rc) return rc;
    if (c->ps) return ctn_psolve_solve(c->ps, c->L, b, x, 1, 2);   /* x may be b */
    cholmod_dense bh = lent(c->B, 1, b), xh = lent(c->B, 1, x), *X = &xh;
    /* cholmod_l_solve2 reallocates its workspace Y whenever Y's shape is not the one it
     * wants (4 x n for a simplicial factor), although the space it kept suffices; give
     * it that shape back, so the loop allocates nothing. Only when the space is there. */
    if (c->Y && !c->L->is_super && c->Y->nzmax >= 4 * n) {
        c->Y->nrow = 4;
        c->Y->ncol = n;
        c->Y->d = 4;
    }
    int ok = cholmod_l_solve2(CHOLMOD_A, c->L, &bh, NULL, &X, NULL, &c->Y, &c->E, &c->cm);
    return ok ? CTN_OK : ctn_chol_error(c, "solve");
}

/* X = K \ B for k columns at once, B and X lent to solve2; the block workspace is kept
 * apart from the single solves' (solve2 reallocates a workspace of another shape) and is
 * reused while k stays the same. */
static int chol_solve_block(void *impl, const double *B, double *X, size_t k)
{
    chol *c = impl;
    int rc = ctn_chol_psolve_plan(c);
    if (rc) return rc;
    if (c->ps) return ctn_psolve_solve(c->ps, c->L, B, X, k, 2);
    cholmod_dense bh = lent(c->B, k, B), xh = lent(c->B, k, X), *Xp = &xh;
    int ok = cholmod_l_solve2(CHOLMOD_A, c->L, &bh, NULL, &Xp, NULL, &c->Yk, &c->Ek, &c->cm);
    return ok ? CTN_OK : ctn_chol_error(c, "block solve");
}

/* Signs of D (the diagonal of a simplicial LDL' factor: each column's first entry). */
static int ldl_inertia(void *impl, double tol, long *negative, long *zero, long *first)
{
    chol *c = impl;
    const SuiteSparse_long *p = c->L->p, *perm = c->L->Perm;
    const double *x = c->L->x;
    *negative = *zero = 0;
    *first = -1;
    if (c->L->is_super || c->L->is_ll || c->L->minor < c->L->n) return ctn_error(c->ctx, CTN_ERR_LINALG, "no LDL' factorization to read the inertia from");
    for (size_t j = 0; j < c->L->n; j++) {
        double d = x[p[j]];
        *negative += d < -tol;
        *zero += fabs(d) <= tol;
        if (*first < 0 && d <= tol) *first = perm ? perm[j] : (long)j;
    }
    return CTN_OK;
}

static int chol_feedable(const void *impl) { return ctn_chol_feedable(impl); }

static int chol_factor_feed(void *impl, const double *Kx, double shift, ctn_feed *feed, ctn_factor_info *info)
{
    return ctn_chol_factor_feed(impl, Kx, shift, feed, info);
}

static ctn_la_ordering chol_ordering(const void *impl) { return ((const chol *)impl)->ordering; }

static void chol_set_threads(void *impl, int asked)
{
    chol *c = impl;
    c->threads = asked;
    if (c->ps && !ctn_thr_allows(c->ctx, asked, CTN_THR_PSOLVE, (double)c->L->n)) ctn_psolve_destroy(&c->ps);
    if (!c->ps) c->ps_planned = 0;           /* planned again at the next solve */
}

static int chol_solve_threads(const void *impl)
{
    const chol *c = impl;
    return c->ps ? 2 : 1;
}

static size_t chol_factor_nnz(const void *impl) { return (size_t)((const chol *)impl)->lnz; }

static double chol_flops(const void *impl) { return ((const chol *)impl)->fl; }

const ctn_linsolve_ops ctn_cholmod_ll_ops = {
    .name = "cholmod", .indefinite = 0, .create = ll_create, .destroy = chol_destroy,
    .factor = chol_factor, .solve = chol_solve, .inertia = NULL, .ordering = chol_ordering,
    .factor_nnz = chol_factor_nnz, .flops = chol_flops, .solve_block = chol_solve_block,
    .set_threads = chol_set_threads, .feedable = chol_feedable, .factor_feed = chol_factor_feed,
    .solve_threads = chol_solve_threads,
};

const ctn_linsolve_ops ctn_cholmod_ldl_ops = {
    .name = "cholmod-ldl", .indefinite = 1, .create = ldl_create, .destroy = chol_destroy,
    .factor = chol_factor, .solve = chol_solve, .inertia = ldl_inertia, .ordering = chol_ordering,
    .factor_nnz = chol_factor_nnz, .flops = chol_flops, .solve_block = chol_solve_block,
    .set_threads = chol_set_threads, .feedable = chol_feedable, .factor_feed = chol_factor_feed,
    .solve_threads = chol_solve_threads,
};
