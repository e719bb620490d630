/* A refactorization that starts before its matrix is complete (feed.h): CHOLMOD's
 * simplicial factorization computes L (and D) one row at a time, row k from column k of
 * the matrix's upper triangle and the rows above it, and cholmod_l_rowfac computes any
 * range of rows whose predecessors are done. In the natural ordering the rows are the
 * pattern's columns, so the factorization follows the assembly a block of rows behind,
 * and checks each block's pivots while they are still in cache. The same operations in
 * the same order as cholmod_l_factorize_p: the same factor, to the bit. Told to stop
 * (the factorization is no longer wanted), it returns between two blocks, the factor
 * then half new: the next factorization starts it again. */
#include "linalg/backends/cholmod/chol.h"

#define FEED_ROWS 8192          /* rows factorized per call */

int ctn_chol_feedable(const chol *c)
{
    const cholmod_factor *L = c->L;
    return !L->is_super && !L->is_ll && L->xtype == CHOLMOD_REAL && L->ordering == CHOLMOD_NATURAL &&
           L->is_monotonic && c->A->stype > 0;
}

/* The first pivot d <= 0 among rows j0 .. j1 - 1 of an LDL' factor, -1 if none. */
long ctn_chol_first_nonpositive(const cholmod_factor *L, size_t j0, size_t j1)
{
    const SuiteSparse_long *p = L->p;
    const double *x = L->x;
    for (size_t j = j0; j < j1; j++)
        if (!(x[p[j]] > 0)) return (long)j;
    return -1;
}

int ctn_chol_factor_feed(chol *c, const double *Kx, double shift, ctn_feed *feed, ctn_factor_info *info)
{
    cholmod_factor *L = c->L;
    SuiteSparse_long *Lnz = L->nz;
    const size_t n = L->n;
    double beta[2] = { shift, 0 };
    long bad = -1;
    int ok = 1, go = 1;
    info->ok = 0;
    info->fail_col = -1;
    c->A->xtype = CHOLMOD_REAL;                  /* lend the caller's values */
    c->A->x = (void *)Kx;
    L->minor = n;                                /* a refactorization: every row to do */
    for (size_t k0 = 0; k0 < n;) {
        size_t k1 = k0 + FEED_ROWS < n ? k0 + FEED_ROWS : n;
        if (!(go = ctn_feed_wait(feed, k1))) break;      /* no longer wanted */
        for (size_t k = k0; k < k1; k++) Lnz[k] = 1;     /* column k empty until row k */
        if (!(ok = cholmod_l_rowfac(c->A, NULL, beta, k0, k1, L, &c->cm))) break;
        if (L->minor < n || (!c->indefinite && (bad = ctn_chol_first_nonpositive(L, k0, k1)) >= 0)) break;
        k0 = k1;
    }
    if (go && ok && bad < 0 && L->minor == n && !c->cm.final_asis)   /* as cholmod_l_factorize_p ends */
        ok = cholmod_l_change_factor(L->xtype, L->is_ll, 0, c->cm.final_pack, c->cm.final_monotonic, L, &c->cm);
    c->A->x = NULL;
    c->A->xtype = CHOLMOD_PATTERN;
    if (!go) return CTN_OK;                      /* abandoned: not ok, no pivot */
    if (!ok || c->cm.status < CHOLMOD_OK) return ctn_chol_error(c, "factorization");
    long k = L->minor < n ? (long)L->minor : bad;
    if (k >= 0) {
        info->fail_col = k;                      /* natural ordering: no permutation */
        return CTN_OK;
    }
    info->ok = 1;
    return CTN_OK;
}
