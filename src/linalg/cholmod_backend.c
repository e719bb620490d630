/* CHOLMOD backend: symbolic analysis once, numeric LL' refactorization per call. LL'
 * (final_ll) rather than LDL' so that a non-positive pivot is reported, not factored. */
#include "linalg/chol.h"

#include <cholmod.h>
#include <string.h>

struct ctn_chol {
    ctn_ctx *ctx;
    cholmod_common cm;
    cholmod_sparse *A;
    cholmod_factor *L;
    cholmod_dense *B, *X, *Y, *E;       /* right-hand side and solve2 workspace */
    ctn_ordering ordering;
    double lnz;                         /* non-zeros of L from the analysis */
    int indefinite;                     /* simplicial LDL' instead of LL' */
};

static int backend_error(ctn_chol *c, const char *what)
{
    return ctn_error(c->ctx, c->cm.status == CHOLMOD_OUT_OF_MEMORY ? CTN_ERR_NOMEM : CTN_ERR_LINALG,
                     "CHOLMOD %s failed (status %d)", what, c->cm.status);
}

/* Symbolic analysis with one given ordering; flops in *fl. */
static cholmod_factor *analyze(ctn_chol *c, int cholmod_ordering, double *fl, double *lnz)
{
    c->cm.nmethods = 1;
    c->cm.method[0].ordering = cholmod_ordering;
    c->cm.postorder = cholmod_ordering != CHOLMOD_NATURAL;
    cholmod_factor *L = cholmod_analyze(c->A, &c->cm);
    *fl = L ? c->cm.fl : 0;
    *lnz = L ? c->cm.lnz : 0;
    return L;
}

static int choose_ordering(ctn_chol *c, ctn_ordering ord)
{
    double fl_nat = 0, fl_amd = 0, lnz_nat = 0, lnz_amd = 0;
    cholmod_factor *nat = NULL, *amd = NULL;
    if (ord != CTN_ORDER_AMD && !(nat = analyze(c, CHOLMOD_NATURAL, &fl_nat, &lnz_nat)))
        return backend_error(c, "analysis");
    int no_fill = nat && lnz_nat <= (double)((const int *)c->A->p)[c->A->ncol];
    if (ord == CTN_ORDER_AUTO && no_fill) ord = CTN_ORDER_NATURAL;   /* nothing can beat it */
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

int ctn_chol_create(ctn_ctx *ctx, size_t n, const int *colptr, const int *rowind,
                    ctn_ordering ord, ctn_chol **out)
{
    return ctn_chol_create_ex(ctx, n, colptr, rowind, ord, 0, out);
}

int ctn_chol_create_ex(ctn_ctx *ctx, size_t n, const int *colptr, const int *rowind,
                       ctn_ordering ord, int indefinite, ctn_chol **out)
{
    *out = NULL;
    ctn_chol *c = ctn_calloc(ctx, 1, sizeof(ctn_chol));
    if (!c) return CTN_ERR_NOMEM;
    c->ctx = ctx;
    cholmod_start(&c->cm);
    c->indefinite = indefinite != 0;
    c->cm.final_ll = !c->indefinite;
    if (c->indefinite) c->cm.supernodal = CHOLMOD_SIMPLICIAL;
    c->cm.quick_return_if_not_posdef = 1;
    c->cm.print = 0;
    c->cm.error_handler = NULL;
    size_t nnz = (size_t)colptr[n];
    int rc = CTN_OK;
    c->A = cholmod_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL, &c->cm);
    c->B = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &c->cm);
    if (!c->A || !c->B) { rc = backend_error(c, "allocation"); goto fail; }
    memcpy(c->A->p, colptr, (n + 1) * sizeof(int));
    memcpy(c->A->i, rowind, nnz * sizeof(int));
    memset(c->A->x, 0, nnz * sizeof(double));
    if ((rc = choose_ordering(c, ord))) goto fail;
    *out = c;
    return CTN_OK;
fail:
    ctn_chol_destroy(&c);
    return rc;
}

void ctn_chol_destroy(ctn_chol **c)
{
    if (!c || !*c) return;
    ctn_chol *p = *c;
    cholmod_free_factor(&p->L, &p->cm);
    cholmod_free_sparse(&p->A, &p->cm);
    cholmod_free_dense(&p->B, &p->cm);
    cholmod_free_dense(&p->X, &p->cm);
    cholmod_free_dense(&p->Y, &p->cm);
    cholmod_free_dense(&p->E, &p->cm);
    cholmod_finish(&p->cm);
    ctn_free(p);
    *c = NULL;
}

double *ctn_chol_values(ctn_chol *c) { return c->A->x; }

int ctn_chol_factorize(ctn_chol *c, long *fail_col)
{
    return ctn_chol_factorize_shifted(c, 0.0, fail_col);
}


int ctn_chol_factorize_shifted(ctn_chol *c, double shift, long *fail_col)
{
    double beta[2] = { shift, 0 };
    *fail_col = -1;
    if (!cholmod_factorize_p(c->A, beta, NULL, 0, c->L, &c->cm) || c->cm.status < CHOLMOD_OK)
        return backend_error(c, "factorization");
    if (c->cm.status == CHOLMOD_NOT_POSDEF) {
        size_t k = c->L->minor;
        const int *perm = c->L->Perm;
        *fail_col = perm ? perm[k] : (long)k;
        return ctn_error(c->ctx, CTN_ERR_LINALG, "tangent stiffness not positive definite");
    }
    return CTN_OK;
}

int ctn_chol_solve(ctn_chol *c, const double *b, double *x)
{
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

ctn_ordering ctn_chol_ordering(const ctn_chol *c) { return c->ordering; }

size_t ctn_chol_factor_nnz(const ctn_chol *c) { return (size_t)c->lnz; }
