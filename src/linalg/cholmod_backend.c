/* CHOLMOD backends: symbolic analysis once, numeric refactorization per call.
 *   "cholmod":     LL' (final_ll) rather than LDL', so that a non-positive pivot is
 *                  reported, not factored;
 *   "cholmod-ldl": simplicial LDL' (no pivoting), for indefinite matrices; the signs of
 *                  D give the inertia.
 * The matrix is held as a pattern; the caller's values are lent to CHOLMOD for each
 * factorization (no copy). */
#include "linalg/linsolve.h"

#include <cholmod.h>
#include <math.h>
#include <string.h>

typedef struct chol {
    ctn_ctx *ctx;
    cholmod_common cm;
    cholmod_sparse *A;                  /* pattern only between factorizations */
    cholmod_factor *L;
    cholmod_dense *B, *X, *Y, *E;       /* right-hand side and solve2 workspace */
    ctn_ordering ordering;
    double lnz;                         /* non-zeros of L from the analysis */
    int indefinite;                     /* simplicial LDL' instead of LL' */
} chol;

static int backend_error(chol *c, const char *what)
{
    return ctn_error(c->ctx, c->cm.status == CHOLMOD_OUT_OF_MEMORY ? CTN_ERR_NOMEM : CTN_ERR_LINALG,
                     "CHOLMOD %s failed (status %d)", what, c->cm.status);
}

/* Symbolic analysis with one given ordering; flops in *fl. */
static cholmod_factor *analyze(chol *c, int cholmod_ordering, double *fl, double *lnz)
{
    c->cm.nmethods = 1;
    c->cm.method[0].ordering = cholmod_ordering;
    c->cm.postorder = cholmod_ordering != CHOLMOD_NATURAL;
    cholmod_factor *L = cholmod_analyze(c->A, &c->cm);
    *fl = L ? c->cm.fl : 0;
    *lnz = L ? c->cm.lnz : 0;
    return L;
}

/* AUTO: natural if it has no fill (nothing can beat it), else the fewer flops of natural
 * and AMD (natural on ties within 10 %: it keeps memory access local). */
static int choose_ordering(chol *c, ctn_ordering ord)
{
    double fl_nat = 0, fl_amd = 0, lnz_nat = 0, lnz_amd = 0;
    cholmod_factor *nat = NULL, *amd = NULL;
    if (ord != CTN_ORDER_AMD && !(nat = analyze(c, CHOLMOD_NATURAL, &fl_nat, &lnz_nat)))
        return backend_error(c, "analysis");
    int no_fill = nat && lnz_nat <= (double)((const int *)c->A->p)[c->A->ncol];
    if (ord == CTN_ORDER_AUTO && no_fill) ord = CTN_ORDER_NATURAL;
    if (ord != CTN_ORDER_NATURAL && !(amd = analyze(c, CHOLMOD_AMD, &fl_amd, &lnz_amd))) {
        cholmod_free_factor(&nat, &c->cm);
        return backend_error(c, "analysis");
    }
    int use_nat = nat && (!amd || fl_nat <= 1.1 * fl_amd);
    c->L = use_nat ? nat : amd;
    c->ordering = use_nat ? CTN_ORDER_NATURAL : CTN_ORDER_AMD;
    c->lnz = use_nat ? lnz_nat : lnz_amd;
    cholmod_free_factor(use_nat ? &amd : &nat, &c->cm);
    return CTN_OK;
}

static void chol_destroy(void *impl)
{
    chol *c = impl;
    if (!c) return;
    cholmod_free_factor(&c->L, &c->cm);
    cholmod_free_sparse(&c->A, &c->cm);
    cholmod_free_dense(&c->B, &c->cm);
    cholmod_free_dense(&c->X, &c->cm);
    cholmod_free_dense(&c->Y, &c->cm);
    cholmod_free_dense(&c->E, &c->cm);
    cholmod_finish(&c->cm);
    ctn_free(c);
}

static int chol_create(ctn_ctx *ctx, const ctn_pattern *p, ctn_ordering ord, int indefinite, void **out)
{
    *out = NULL;
    chol *c = ctn_calloc(ctx, 1, sizeof(chol));
    if (!c) return CTN_ERR_NOMEM;
    c->ctx = ctx;
    cholmod_start(&c->cm);
    c->indefinite = indefinite;
    c->cm.final_ll = !indefinite;
    if (indefinite) c->cm.supernodal = CHOLMOD_SIMPLICIAL;
    c->cm.quick_return_if_not_posdef = 1;
    c->cm.print = 0;
    c->cm.error_handler = NULL;
    size_t n = p->n, nnz = (size_t)p->colptr[n];
    int rc = CTN_OK;
    c->A = cholmod_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_PATTERN, &c->cm);
    c->B = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &c->cm);
    if (!c->A || !c->B) { rc = backend_error(c, "allocation"); goto fail; }
    memcpy(c->A->p, p->colptr, (n + 1) * sizeof(int));
    memcpy(c->A->i, p->rowind, nnz * sizeof(int));
    if ((rc = choose_ordering(c, ord))) goto fail;
    *out = c;
    return CTN_OK;
fail:
    chol_destroy(c);
    return rc;
}

static int ll_create(ctn_ctx *ctx, const ctn_pattern *p, ctn_ordering ord, void **out)
{
    return chol_create(ctx, p, ord, 0, out);
}

static int ldl_create(ctn_ctx *ctx, const ctn_pattern *p, ctn_ordering ord, void **out)
{
    return chol_create(ctx, p, ord, 1, out);
}

static int chol_factor(void *impl, const double *Kx, double shift, ctn_factor_info *info)
{
    chol *c = impl;
    double beta[2] = { shift, 0 };
    info->ok = 0;
    info->fail_col = -1;
    c->A->xtype = CHOLMOD_REAL;                  /* lend the caller's values */
    c->A->x = (void *)Kx;
    int ok = cholmod_factorize_p(c->A, beta, NULL, 0, c->L, &c->cm);
    c->A->x = NULL;
    c->A->xtype = CHOLMOD_PATTERN;
    if (!ok || c->cm.status < CHOLMOD_OK) return backend_error(c, "factorization");
    if (c->cm.status == CHOLMOD_NOT_POSDEF) {
        size_t k = c->L->minor;
        const int *perm = c->L->Perm;
        info->fail_col = perm ? perm[k] : (long)k;
        return CTN_OK;
    }
    info->ok = 1;
    return CTN_OK;
}

static int chol_solve(void *impl, const double *b, double *x)
{
    chol *c = impl;
    size_t n = c->A->nrow;
    void *own = c->B->x;
    c->B->x = (void *)b;                         /* solve2 only reads B: no copy */
    /* cholmod_solve2 reallocates its workspace Y whenever Y's shape is not the one it
     * wants (4 x n for a simplicial factor), although the space it kept suffices; give
     * it that shape back, so the loop allocates nothing. Only when the space is there. */
    if (c->Y && !c->L->is_super && c->Y->nzmax >= 4 * n) {
        c->Y->nrow = 4;
        c->Y->ncol = n;
        c->Y->d = 4;
    }
    int ok = cholmod_solve2(CHOLMOD_A, c->L, c->B, NULL, &c->X, NULL, &c->Y, &c->E, &c->cm);
    c->B->x = own;
    if (!ok) return backend_error(c, "solve");
    memcpy(x, c->X->x, n * sizeof(double));
    return CTN_OK;
}

/* Signs of D (the diagonal of a simplicial LDL' factor: each column's first entry). */
static int ldl_inertia(void *impl, double tol, long *negative, long *zero, long *first)
{
    chol *c = impl;
    const int *p = c->L->p, *perm = c->L->Perm;
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

static ctn_ordering chol_ordering(const void *impl) { return ((const chol *)impl)->ordering; }

static size_t chol_factor_nnz(const void *impl) { return (size_t)((const chol *)impl)->lnz; }

const ctn_linsolve_ops ctn_cholmod_ll_ops = {
    "cholmod", 0, ll_create, chol_destroy, chol_factor, chol_solve, NULL, chol_ordering, chol_factor_nnz,
};

const ctn_linsolve_ops ctn_cholmod_ldl_ops = {
    "cholmod-ldl", 1, ldl_create, chol_destroy, chol_factor, chol_solve, ldl_inertia, chol_ordering,
    chol_factor_nnz,
};
