/* The fill-reducing ordering of the CHOLMOD backends and their symbolic analysis.
 *
 * AUTO: the natural ordering if it makes no fill (a chain: nothing can beat it); else
 * each of natural, AMD and METIS (nested dissection) is analysed (ordering, elimination
 * tree, column counts: cheap next to a factorization) and the one with the fewest flops
 * is kept, natural on ties within 10 % (it keeps memory access local). An ordering whose
 * analysis fails (METIS out of memory, say) is skipped; only when every one fails is it
 * an error, with CHOLMOD's status in words. The supernodal analysis is then done once,
 * for the ordering kept, with its permutation. */
#include "linalg/chol.h"

#include <stdio.h>
#include <string.h>

#define CANDIDATES 3

const char *ctn_chol_status(int status)
{
    switch (status) {
    case CHOLMOD_OK: return "no error";
    case CHOLMOD_NOT_INSTALLED: return "a method this CHOLMOD was built without (e.g. METIS)";
    case CHOLMOD_OUT_OF_MEMORY: return "out of memory";
    case CHOLMOD_TOO_LARGE: return "the factor is too large to be indexed (integer overflow)";
    case CHOLMOD_INVALID: return "invalid input";
    case CHOLMOD_GPU_PROBLEM: return "GPU failure";
    case CHOLMOD_NOT_POSDEF: return "the matrix is not positive definite";
    case CHOLMOD_DSMALL: return "a pivot of the factor is tiny";
    default: return "unknown status";
    }
}

int ctn_chol_error(chol *c, const char *what)
{
    int s = c->cm.status;
    if (s == CHOLMOD_OUT_OF_MEMORY && c->lnz > 0)
        return ctn_error(c->ctx, CTN_ERR_NOMEM, "CHOLMOD %s failed: out of memory (status %d): the factor "
                         "needs %.2f GB (%.0f non-zeros)", what, s, 8e-9 * c->lnz * 1.2, c->lnz);
    return ctn_error(c->ctx, s == CHOLMOD_OUT_OF_MEMORY ? CTN_ERR_NOMEM : CTN_ERR_LINALG,
                     "CHOLMOD %s failed: %s (status %d)", what, ctn_chol_status(s), s);
}

static int cholmod_method(ctn_ordering o)
{
    return o == CTN_ORDER_AMD ? CHOLMOD_AMD : o == CTN_ORDER_METIS ? CHOLMOD_METIS : CHOLMOD_NATURAL;
}

/* Workspace of the analyses: 6 arrays of n. */
typedef struct order_work {
    SuiteSparse_long *perm, *best, *parent, *post, *count, *first, *level;
} order_work;

/* Analyse one ordering: its permutation in w->perm, flops and lnz; 0 if it failed. */
static int try_order(chol *c, ctn_ordering o, order_work *w, double *fl, double *lnz)
{
    int ok = 1;
    if (o == CTN_ORDER_NATURAL)
        for (size_t j = 0; j < c->A->ncol; j++) w->perm[j] = (SuiteSparse_long)j;
    else if (o == CTN_ORDER_AMD) ok = cholmod_l_amd(c->A, NULL, 0, w->perm, &c->cm);
    else ok = cholmod_l_metis(c->A, NULL, 0, 1, w->perm, &c->cm);
    ok = ok && cholmod_l_analyze_ordering(c->A, cholmod_method(o), w->perm, NULL, 0, w->parent, w->post,
                                        w->count, w->first, w->level, &c->cm);
    *fl = ok ? c->cm.fl : 0;
    *lnz = ok ? c->cm.lnz : 0;
    return ok && c->cm.status == CHOLMOD_OK;
}

/* The best ordering by flops into w->best (and *kept); the status of the last failure
 * in *status when all failed. */
static int pick(chol *c, ctn_ordering ord, order_work *w, ctn_ordering *kept, int *status)
{
    static const ctn_ordering all[CANDIDATES] = { CTN_ORDER_NATURAL, CTN_ORDER_AMD, CTN_ORDER_METIS };
    size_t n = c->A->ncol;
    double best = -1, fl, lnz;
    for (int i = 0; i < CANDIDATES; i++) {
        ctn_ordering o = all[i];
        if (ord != CTN_ORDER_AUTO && o != ord) continue;
        if (!try_order(c, o, w, &fl, &lnz)) {
            *status = c->cm.status;
            continue;
        }
        int no_fill = o == CTN_ORDER_NATURAL && lnz <= (double)((SuiteSparse_long *)c->A->p)[n];
        if (best < 0 || fl < (*kept == CTN_ORDER_NATURAL ? best / 1.1 : best)) {
            best = fl;
            *kept = o;
            memcpy(w->best, w->perm, n * sizeof *w->perm);
        }
        if (ord == CTN_ORDER_AUTO && no_fill) break;      /* no ordering can beat it */
    }
    return best >= 0;
}

int ctn_chol_analyze(chol *c, ctn_ordering ord)
{
    size_t n = c->A->ncol;
    order_work w;
    SuiteSparse_long **arrays[] = { &w.perm, &w.best, &w.parent, &w.post, &w.count, &w.first, &w.level };
    memset(&w, 0, sizeof w);
    int rc = CTN_OK, status = CHOLMOD_OK;
    for (size_t i = 0; !rc && i < sizeof arrays / sizeof *arrays; i++)
        if (!(*arrays[i] = ctn_malloc(c->ctx, n ? n : 1, sizeof(SuiteSparse_long)))) rc = CTN_ERR_NOMEM;
    ctn_ordering kept = CTN_ORDER_NATURAL;
    if (!rc && !pick(c, ord, &w, &kept, &status)) {
        c->cm.status = status;
        rc = ctn_chol_error(c, ord == CTN_ORDER_AUTO ? "analysis (every ordering)" : "analysis");
    }
    if (!rc) {
        c->cm.nmethods = 1;
        c->cm.method[0].ordering = kept == CTN_ORDER_NATURAL ? CHOLMOD_NATURAL : CHOLMOD_GIVEN;
        c->cm.postorder = kept != CTN_ORDER_NATURAL;
        c->L = cholmod_l_analyze_p(c->A, kept == CTN_ORDER_NATURAL ? NULL : w.best, NULL, 0, &c->cm);
        if (!c->L) rc = ctn_chol_error(c, "analysis");
        c->ordering = kept;
        c->fl = c->cm.fl;
        c->lnz = c->cm.lnz;
    }
    for (size_t i = 0; i < sizeof arrays / sizeof *arrays; i++) ctn_free(*arrays[i]);
    return rc;
}
