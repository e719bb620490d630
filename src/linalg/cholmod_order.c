/* The fill-reducing ordering of the CHOLMOD backends and their symbolic analysis.
 *
 * AUTO: the natural ordering if it makes no fill (a chain: nothing can beat it); else
 * AMD and METIS (nested dissection), both on the node graph (cholmod_quotient.c), and
 * natural unless its envelope rules it out, are analysed (ordering, elimination tree,
 * column counts: cheap next to a factorization) and the one with the fewest flops is
 * kept, natural on ties within 10 % (it keeps memory access local). METIS's ordering is
 * not postordered here: the final analysis postorders the one kept. An ordering whose
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

/* Workspace of the analyses: 7 arrays of n, and the quotient graph AMD and METIS
 * order (cholmod_quotient.c). */
typedef struct order_work {
    SuiteSparse_long *perm, *best, *parent, *post, *count, *first, *level, *sperm;
    ctn_chol_quot q;
} order_work;

/* AMD or METIS on the quotient graph (built on first use), expanded into w->perm; on
 * the pattern itself when no two columns merge or the quotient could not be built. */
static int fill_reducing(chol *c, ctn_ordering o, order_work *w)
{
    if (!w->q.first) (void)ctn_chol_quotient(c, &w->q);
    cholmod_sparse *G = w->q.G ? w->q.G : c->A;
    SuiteSparse_long *p = w->q.G ? w->sperm : w->perm;
    int ok = o == CTN_ORDER_AMD ? cholmod_l_amd(G, NULL, 0, p, &c->cm) : cholmod_l_metis(G, NULL, 0, 0, p, &c->cm);
    if (ok && w->q.G) ctn_chol_quotient_expand(&w->q, w->sperm, w->perm);
    return ok;
}

/* Analyse one ordering: its permutation in w->perm, flops and lnz; 0 if it failed. */
static int try_order(chol *c, ctn_ordering o, order_work *w, double *fl, double *lnz)
{
    int ok = 1;
    if (o == CTN_ORDER_NATURAL)
        for (size_t j = 0; j < c->A->ncol; j++) w->perm[j] = (SuiteSparse_long)j;
    else ok = fill_reducing(c, o, w);
    ok = ok && cholmod_l_analyze_ordering(c->A, cholmod_method(o), w->perm, NULL, 0, w->parent, w->post,
                                        w->count, w->first, w->level, &c->cm);
    *fl = ok ? c->cm.fl : 0;
    *lnz = ok ? c->cm.lnz : 0;
    return ok && c->cm.status == CHOLMOD_OK;
}

/* The envelope of the upper pattern (rows sorted): the positions between each column's
 * first row and its diagonal. The natural ordering's factor lies inside it. */
static double envelope(const cholmod_sparse *A)
{
    const SuiteSparse_long *Ap = A->p, *Ai = A->i;
    double e = 0;
    for (size_t j = 0; j < A->ncol; j++) e += Ap[j + 1] > Ap[j] ? (double)((SuiteSparse_long)j - Ai[Ap[j]] + 1) : 1;
    return e;
}

/* The best ordering by flops into w->best (and *kept); the status of the last failure
 * in *status when all failed. For AUTO: a full envelope means the natural ordering makes
 * no fill (a chain), and nothing can beat it; otherwise AMD and METIS are analysed, and
 * natural too unless its envelope is more than NATURAL_ENVELOPE times the better one's
 * factor (a mesh numbered row by row: its factor fills the envelope, and analysing it
 * costs as much as the others together at 3 million DOFs). Natural is kept on ties
 * within 10 % (it keeps memory access local). */
#define NATURAL_ENVELOPE 4.0
static int pick(chol *c, ctn_ordering ord, order_work *w, ctn_ordering *kept, int *status)
{
    static const ctn_ordering all[CANDIDATES] = { CTN_ORDER_AMD, CTN_ORDER_METIS, CTN_ORDER_NATURAL };
    size_t n = c->A->ncol;
    double env = envelope(c->A), anz = (double)((SuiteSparse_long *)c->A->p)[n];
    double best = -1, best_lnz = 0, fl, lnz;
    for (int i = 0; i < CANDIDATES; i++) {
        ctn_ordering o = all[i];
        if (ord != CTN_ORDER_AUTO && o != ord) continue;
        if (ord == CTN_ORDER_AUTO && o != CTN_ORDER_NATURAL && env <= anz) continue;
        if (ord == CTN_ORDER_AUTO && o == CTN_ORDER_NATURAL && best > 0 && env > NATURAL_ENVELOPE * best_lnz) continue;
        if (!try_order(c, o, w, &fl, &lnz)) {
            *status = c->cm.status;
            continue;
        }
        if (best < 0 || (o == CTN_ORDER_NATURAL ? fl <= 1.1 * best : fl < best)) {
            best = fl;
            best_lnz = lnz;
            *kept = o;
            memcpy(w->best, w->perm, n * sizeof *w->perm);
        }
    }
    return best >= 0;
}

int ctn_chol_analyze(chol *c, ctn_ordering ord)
{
    size_t n = c->A->ncol;
    order_work w;
    SuiteSparse_long **arrays[] = { &w.perm, &w.best, &w.parent, &w.post, &w.count, &w.first, &w.level, &w.sperm };
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
    ctn_chol_quotient_free(c, &w.q);
    return rc;
}
