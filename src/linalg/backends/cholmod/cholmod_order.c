/* The fill-reducing ordering of the CHOLMOD backends and their symbolic analysis.
 *
 * AUTO: the natural ordering if it makes no fill (a chain: nothing can beat it); else
 * AMD and METIS (nested dissection), both on the node graph (cholmod_quotient.c), and
 * natural unless its envelope rules it out, are analysed (ordering, elimination tree,
 * column counts: cheap next to a factorization) and the one with the fewest flops is
 * kept, natural on ties within 10 % (it keeps memory access local). METIS's ordering is
 * not postordered here: the final analysis postorders the one kept. An ordering whose
 * analysis fails (METIS out of memory, say) is skipped; only when every one fails is it
 * an error, with CHOLMOD's status in words. The symbolic analysis is then done once,
 * for the ordering kept: from the node graph (cholmod_symbolic.c) when nodes were
 * merged, else by cholmod_l_analyze_p. */
#include "core/threads.h"
#include "linalg/backends/cholmod/chol.h"

#include <stdio.h>
#include <string.h>

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
                         "alone needs %.2f GB (%.0f non-zeros), beyond the model and its matrix", what, s,
                         8e-9 * c->lnz * 1.2, c->lnz);
    return ctn_error(c->ctx, s == CHOLMOD_OUT_OF_MEMORY ? CTN_ERR_NOMEM : CTN_ERR_LINALG,
                     "CHOLMOD %s failed: %s (status %d)", what, ctn_chol_status(s), s);
}

static int cholmod_method(ctn_la_ordering o)
{
    return o == CTN_LA_ORDER_AMD ? CHOLMOD_AMD : o == CTN_LA_ORDER_METIS ? CHOLMOD_METIS : CHOLMOD_NATURAL;
}

/* One ordering's analysis on the graph H the orderings see (the quotient graph, or the
 * pattern itself when no columns merge): its permutation of H's vertices (and the
 * analysis' other outputs, which CHOLMOD requires), its flops and factor size, on the
 * caller's CHOLMOD common or on a thread's own. */
enum { PERM, PARENT, POST, COUNT, FIRST, LEVEL, ARRAYS };
typedef struct cand {
    chol *c;
    const ctn_chol_quot *q;
    cholmod_sparse *H;
    ctn_la_ordering o;
    cholmod_common own, *cm;
    SuiteSparse_long *a[ARRAYS];
    double fl, lnz;
    int ok, status, counted;
} cand;

static int cand_alloc(cand *k, chol *c, const ctn_chol_quot *q)
{
    k->c = c;
    k->q = q;
    k->H = q->G ? q->G : c->A;
    k->cm = &c->cm;
    size_t m = k->H->ncol;
    for (int i = 0; i < ARRAYS; i++)
        if (!(k->a[i] = ctn_malloc(c->ctx, m ? m : 1, sizeof(SuiteSparse_long)))) return CTN_ERR_NOMEM;
    return CTN_OK;
}

static void cand_free(cand *k)
{
    for (int i = 0; i < ARRAYS; i++) ctn_free(k->a[i]);
}

/* The factor's size and flops from the column counts of H's factor: vertex v (a
 * supervariable of w DOFs) whose column has c vertices is w DOF columns of w_avg (c - 1)
 * + w, ..., w_avg (c - 1) + 1 entries (w_avg: the mean weight stands for the weights of
 * the other vertices). Exact when every node has the same number of free DOFs, as the
 * block structure of the factor is the factor of the block structure; the final
 * analysis counts the kept ordering exactly in any case. */
static void estimate(cand *k)
{
    const ctn_chol_quot *q = k->q;
    size_t m = k->H->ncol;
    double wbar = (double)k->c->A->ncol / (double)(m ? m : 1), fl = 0, lnz = 0;
    for (size_t j = 0; j < m; j++) {
        SuiteSparse_long v = k->a[PERM][j];
        long w = q->G ? (long)(q->first[v + 1] - q->first[v]) : 1;
        double off = wbar * (double)(k->a[COUNT][j] - 1);
        lnz += (double)w * off + 0.5 * (double)w * (double)(w + 1);
        for (long t = 1; t <= w; t++) fl += (off + (double)t) * (off + (double)t);
    }
    k->fl = fl;
    k->lnz = lnz;
}

/* Count the factor of H in k's ordering (its elimination tree, column counts, flops). */
static void cand_count(cand *k)
{
    SuiteSparse_long **a = k->a;
    k->ok = cholmod_l_analyze_ordering(k->H, cholmod_method(k->o), a[PERM], NULL, 0, a[PARENT], a[POST], a[COUNT],
                                       a[FIRST], a[LEVEL], k->cm) && k->cm->status == CHOLMOD_OK;
    k->status = k->cm->status;
    k->counted = k->ok;
    if (k->ok) estimate(k);
}

/* Order H by o (natural: the identity) and, if analyse, count its factor. */
static void cand_run(cand *k, ctn_la_ordering o, int analyse)
{
    SuiteSparse_long **a = k->a;
    size_t m = k->H->ncol;
    int ok = 1;
    k->o = o;
    k->counted = 0;
    if (o == CTN_LA_ORDER_NATURAL)
        for (size_t j = 0; j < m; j++) a[PERM][j] = (SuiteSparse_long)j;
    else if (o == CTN_LA_ORDER_AMD) ok = cholmod_l_amd(k->H, NULL, 0, a[PERM], k->cm);
    else ok = cholmod_l_metis(k->H, NULL, 0, 0, a[PERM], k->cm);
    k->status = k->cm->status;
    k->ok = ok && k->status == CHOLMOD_OK;
    if (k->ok && analyse) cand_count(k);
}

/* A candidate on a second thread, with a CHOLMOD common of its own (the library is
 * reentrant across commons; the pattern and the quotient graph are only read). */
static void cand_thread(void *arg)
{
    cand *k = arg;
    cholmod_l_start(&k->own);
    k->own.print = 0;
    k->own.error_handler = NULL;
    k->cm = &k->own;
    cand_run(k, k->o, 1);
    cholmod_l_finish(&k->own);
    k->cm = &k->c->cm;
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

/* The better of two analysed candidates (natural kept on ties within 10 %, it keeps
 * memory access local; else the earlier on ties), -1 if neither succeeded. */
static int better(const cand *k, int i, int j)
{
    if (i < 0 || !k[i].ok) return j >= 0 && k[j].ok ? j : -1;
    if (j < 0 || !k[j].ok) return i;
    if (k[j].o == CTN_LA_ORDER_NATURAL) return k[j].fl <= 1.1 * k[i].fl ? j : i;
    if (k[i].o == CTN_LA_ORDER_NATURAL) return k[j].fl < k[i].fl / 1.1 ? j : i;
    return k[j].fl < k[i].fl ? j : i;
}

/* The best ordering by flops: the index of its candidate (k[0] or k[1]), -1 if every
 * ordering failed (*status: the last failure's). An ordering asked for is taken without
 * counting. AUTO: a full envelope means the natural ordering makes no fill (a chain), and
 * nothing can beat it; otherwise METIS and AMD are counted on the quotient graph, AMD on
 * a second thread for large patterns (the two are independent; on a busy machine the
 * thread only shares the CPU), and natural too unless its envelope is more than
 * NATURAL_ENVELOPE times the better one's factor (a mesh numbered row by row: its
 * factor fills the envelope, and counting it costs as much as the others together). */
#define NATURAL_ENVELOPE 4.0
static int pick(chol *c, ctn_la_ordering ord, cand *k, int *status)
{
    size_t n = c->A->ncol;
    double env = envelope(c->A), anz = (double)((SuiteSparse_long *)c->A->p)[n];
    int best;
    if (ord != CTN_LA_ORDER_AUTO || env <= anz) {
        cand_run(&k[0], ord == CTN_LA_ORDER_AUTO ? CTN_LA_ORDER_NATURAL : ord, 0);
        best = k[0].ok ? 0 : -1;
    } else {
        k[1].o = CTN_LA_ORDER_AMD;
        int ticket = ctn_thr_start(c->ctx, c->threads, CTN_THR_ORDER, (double)n, cand_thread, &k[1]);
        cand_run(&k[0], CTN_LA_ORDER_METIS, 1);
        if (ticket) ctn_thr_wait(c->ctx, ticket);
        else cand_run(&k[1], CTN_LA_ORDER_AMD, 1);
        best = better(k, 1, 0);                               /* AMD on ties */
        if (best < 0 || env <= NATURAL_ENVELOPE * k[best].lnz) {
            int spare = best == 0 ? 1 : 0;
            cand_run(&k[spare], CTN_LA_ORDER_NATURAL, 1);
            best = better(k, best, spare);
        }
    }
    if (best < 0) *status = k[0].ok ? k[1].status : k[0].status;
    return best;
}

/* CTN_LA_PLAIN_ORDER: cholmod_l_analyze's own choice on the DOF pattern (its default
 * nmethods: AMD, and METIS too when AMD's factor is dense enough). */
static int plain_analyze(chol *c)
{
    c->L = cholmod_l_analyze(c->A, &c->cm);
    if (!c->L) return ctn_chol_error(c, "analysis");
    int m = c->cm.method[c->cm.selected].ordering;
    c->ordering = m == CHOLMOD_NATURAL ? CTN_LA_ORDER_NATURAL : m == CHOLMOD_AMD ? CTN_LA_ORDER_AMD : CTN_LA_ORDER_METIS;
    c->fl = c->cm.fl;
    c->lnz = c->cm.lnz;
    return CTN_OK;
}

/* The analysis of ordering b (of the graph its candidate ordered) by
 * cholmod_l_analyze_p on the DOF pattern: b's permutation expanded to the DOFs when it
 * orders the node graph (CTN_LA_PLAIN_SYMBOLIC), postordered unless natural. */
static int analyze_p(chol *c, const ctn_chol_quot *q, const cand *b)
{
    SuiteSparse_long *perm = b->o == CTN_LA_ORDER_NATURAL ? NULL : b->a[PERM], *full = NULL;
    if (perm && q->G) {
        if (!(full = ctn_malloc(c->ctx, c->A->ncol ? c->A->ncol : 1, sizeof *full))) return CTN_ERR_NOMEM;
        ctn_chol_quotient_expand(q, perm, full);
        perm = full;
    }
    c->cm.nmethods = 1;
    c->cm.method[0].ordering = perm ? CHOLMOD_GIVEN : CHOLMOD_NATURAL;
    c->cm.postorder = perm != NULL;
    c->L = cholmod_l_analyze_p(c->A, perm, NULL, 0, &c->cm);
    ctn_free(full);
    return c->L ? CTN_OK : ctn_chol_error(c, "analysis");
}

int ctn_chol_analyze(chol *c, ctn_la_ordering ord)
{
    if (ord == CTN_LA_ORDER_AUTO && (c->plain & CTN_LA_PLAIN_ORDER)) return plain_analyze(c);
    cand k[2];
    ctn_chol_quot q;
    memset(k, 0, sizeof k);
    memset(&q, 0, sizeof q);
    int rc = CTN_OK, status = CHOLMOD_OK;
    if (ord != CTN_LA_ORDER_NATURAL) rc = ctn_chol_quotient(c, &q);
    for (int i = 0; !rc && i < 2; i++) rc = cand_alloc(&k[i], c, &q);
    int best = rc ? -1 : pick(c, ord, k, &status);
    if (!rc && best < 0) {
        c->cm.status = status;
        rc = ctn_chol_error(c, ord == CTN_LA_ORDER_AUTO ? "analysis (every ordering)" : "analysis");
    }
    if (!rc) {
        cand *b = &k[best];
        c->ordering = b->o;
        c->lnz = b->lnz;                   /* counted: what a failure below says it needs */
        if (q.G && b->o != CTN_LA_ORDER_NATURAL && !(c->plain & CTN_LA_PLAIN_SYMBOLIC)) {  /* from the node graph */
            if (!b->counted) cand_count(b);           /* an ordering asked for */
            if (b->ok) rc = ctn_chol_symbolic(c, &q, b->a[PERM], b->a[PARENT], b->a[COUNT]);
            else {
                c->cm.status = b->status;
                rc = ctn_chol_error(c, "analysis");
            }
        } else
            rc = analyze_p(c, &q, b);
        c->fl = c->cm.fl;
        c->lnz = c->cm.lnz;
    }
    for (int i = 0; i < 2; i++) cand_free(&k[i]);
    ctn_chol_quotient_free(c, &q);
    return rc;
}
