/* The symbolic analysis of the full pattern from an ordering of its quotient graph.
 *
 * cholmod_l_analyze_p permutes the full pattern twice over (A(p,p) and its transpose, once
 * for the column counts and again, postordered, for the supernodes): four scattered
 * transposes of a pattern of tens of millions of entries, and as much fresh memory, most
 * of the analysis' time on a large net after the ordering itself. Here only the node
 * graph G is permuted (9 times smaller for 3-DOF nodes). The pattern of A is exactly G
 * blown up, each supervariable to its block of DOFs (its columns are indistinguishable,
 * cholmod_quotient.c), and so is everything the analysis derives from it:
 * - the order: sperm postordered by the node tree (weighted by the column counts, as
 *   CHOLMOD does), each supervariable's DOFs kept together;
 * - the elimination tree: within a supervariable each column's parent is the next, the
 *   last one's is the first column of the node's parent;
 * - the column counts: column a of a node of w DOFs has w - a rows in its own block and
 *   the DOFs of the later nodes in the node column's pattern: w (count - 1) of them when
 *   every node has w DOFs, else summed over the node factor's supernodal pattern (exact
 *   supernodes only: no relaxed amalgamation there);
 * - the supernodes, by cholmod_l_super_symbolic2 on a pattern that lists for each column
 *   the first DOF of each earlier neighbour only: the DOFs of a node lie in one
 *   supernode, and that routine only follows each row's supernode up the tree (it reads
 *   rows before the supernode's first column, once each, and nothing else).
 * The factor is the one cholmod_l_analyze_p gives for the expanded, postordered
 * permutation: tests/test_symbolic.c checks it array by array. */
#include "linalg/backends/cholmod/chol.h"

#include <string.h>

/* The node order: Q[k] the supervariable at position k (sperm postordered, weighted by
 * the column counts as CHOLMOD does), par[k] its parent in the node tree (-1: a root),
 * count[k] its column count in the node factor, off[k] its first column. */
typedef struct order {
    size_t m;
    SuiteSparse_long *Q, *par, *off, *count;
} order;

static int order_make(chol *c, const ctn_chol_quot *q, const SuiteSparse_long *sperm, const SuiteSparse_long *sparent,
                      const SuiteSparse_long *scount, order *o)
{
    size_t m = q->ns;
    o->m = m;
    o->Q = ctn_malloc(c->ctx, m ? m : 1, sizeof *o->Q);
    o->par = ctn_malloc(c->ctx, m ? m : 1, sizeof *o->par);
    o->off = ctn_malloc(c->ctx, m + 1, sizeof *o->off);
    o->count = ctn_malloc(c->ctx, m ? m : 1, sizeof *o->count);
    SuiteSparse_long *post = ctn_malloc(c->ctx, m ? m : 1, sizeof *post);
    SuiteSparse_long *inv = ctn_malloc(c->ctx, m ? m : 1, sizeof *inv);
    int rc = !o->Q || !o->par || !o->off || !o->count || !post || !inv ? CTN_ERR_NOMEM : CTN_OK;
    if (!rc && cholmod_l_postorder((SuiteSparse_long *)sparent, m, (SuiteSparse_long *)scount, post, &c->cm) !=
                   (SuiteSparse_long)m) {
        if (c->cm.status == CHOLMOD_OK) c->cm.status = CHOLMOD_INVALID;
        rc = ctn_chol_error(c, "analysis (postordering the node tree)");
    }
    if (!rc) {
        for (size_t k = 0; k < m; k++) inv[post[k]] = (SuiteSparse_long)k;
        for (size_t k = 0; k < m; k++) {
            SuiteSparse_long p = sparent[post[k]];
            o->Q[k] = sperm[post[k]];
            o->count[k] = scount[post[k]];
            o->par[k] = p < 0 ? -1 : inv[p];
        }
    }
    ctn_free(post);
    ctn_free(inv);
    if (rc) return rc;
    o->off[0] = 0;
    for (size_t k = 0; k < m; k++) o->off[k + 1] = o->off[k] + q->first[o->Q[k] + 1] - q->first[o->Q[k]];
    return CTN_OK;
}

static void order_free(order *o)
{
    ctn_free(o->Q);
    ctn_free(o->par);
    ctn_free(o->off);
    ctn_free(o->count);
}

/* The node pattern triu(G(Q,Q)), rows sorted (two transposes of the small graph). */
static cholmod_sparse *node_pattern(const ctn_chol_quot *q, const order *o, cholmod_common *cm)
{
    cholmod_sparse *Fn = cholmod_l_ptranspose(q->G, 0, o->Q, NULL, 0, cm);
    cholmod_sparse *Sn = Fn ? cholmod_l_ptranspose(Fn, 0, NULL, NULL, 0, cm) : NULL;
    cholmod_l_free_sparse(&Fn, cm);
    return Sn;
}

/* Column a of a node of w DOFs whose later pattern holds `below` DOFs: w - a + below. */
static void count_node(const order *o, SuiteSparse_long k, SuiteSparse_long below, SuiteSparse_long *cc, double *lnz,
                       double *fl)
{
    SuiteSparse_long w = o->off[k + 1] - o->off[k];
    for (SuiteSparse_long a = 0; a < w; a++) {
        SuiteSparse_long c = w - a + below;
        cc[o->off[k] + a] = c;
        *lnz += (double)c;
        *fl += (double)c * (double)c;
    }
}

/* The column counts of the blown-up factor, and its non-zeros and flops into cm as
 * cholmod_l_rowcolcounts gives them. When every node has w DOFs, from the node counts:
 * w (count - 1) below. Otherwise from the node factor's exact supernodes (Ln), whose
 * rows after a column are that column's pattern. */
static void counts(const order *o, const cholmod_factor *Ln, SuiteSparse_long *cc, cholmod_common *cm)
{
    const SuiteSparse_long *off = o->off;
    double lnz = 0, fl = 0;
    if (!Ln)
        for (size_t k = 0; k < o->m; k++)
            count_node(o, (SuiteSparse_long)k, (off[k + 1] - off[k]) * (o->count[k] - 1), cc, &lnz, &fl);
    else {
        const SuiteSparse_long *super = Ln->super, *pi = Ln->pi, *ls = Ln->s;
        for (size_t s = 0; s < Ln->nsuper; s++) {
            SuiteSparse_long k1 = super[s], k2 = super[s + 1], below = 0;
            for (SuiteSparse_long p = pi[s] + (k2 - k1); p < pi[s + 1]; p++) below += off[ls[p] + 1] - off[ls[p]];
            for (SuiteSparse_long k = k2 - 1; k >= k1; k--) {
                count_node(o, k, below, cc, &lnz, &fl);
                below += off[k + 1] - off[k];
            }
        }
    }
    cm->lnz = lnz;
    cm->fl = fl;
}

/* Whether every node has the same number of DOFs. */
static int uniform(const order *o)
{
    for (size_t k = 1; k < o->m; k++)
        if (o->off[k + 1] - o->off[k] != o->off[1] - o->off[0]) return 0;
    return 1;
}

/* The node factor's supernodal pattern with no relaxed amalgamation (supernodes merge
 * only where no zero is added): each column's pattern is its supernode's rows from it on. */
static cholmod_factor *node_factor(const order *o, cholmod_sparse *Sn, cholmod_common *cm)
{
    cholmod_factor *Ln = cholmod_l_allocate_factor(o->m, cm);
    if (!Ln) return NULL;
    memcpy(Ln->ColCount, o->count, o->m * sizeof *o->count);
    double zrelax[3];
    size_t nrelax[3];
    memcpy(zrelax, cm->zrelax, sizeof zrelax);
    memcpy(nrelax, cm->nrelax, sizeof nrelax);
    for (int i = 0; i < 3; i++) cm->zrelax[i] = 0, cm->nrelax[i] = 0;
    int ok = cholmod_l_super_symbolic2(1, Sn, NULL, o->par, Ln, cm);
    memcpy(cm->zrelax, zrelax, sizeof zrelax);
    memcpy(cm->nrelax, nrelax, sizeof nrelax);
    if (!ok) cholmod_l_free_factor(&Ln, cm);
    return Ln;
}

/* The elimination tree of the blown-up pattern. */
static void tree(const order *o, SuiteSparse_long *parent)
{
    const SuiteSparse_long *off = o->off;
    for (size_t k = 0; k < o->m; k++) {
        for (SuiteSparse_long j = off[k]; j + 1 < off[k + 1]; j++) parent[j] = j + 1;
        if (off[k + 1] > off[k]) parent[off[k + 1] - 1] = o->par[k] < 0 ? -1 : off[o->par[k]];
    }
}

/* The supernodal analysis of the blown-up pattern, given through the rows CHOLMOD reads:
 * for column j of node k, the first DOF of each earlier neighbour of k, a list all of k's
 * columns share (an unpacked pattern: column j's nz[j] rows from p[j]). */
static int supernodes(chol *c, const order *o, const cholmod_sparse *Sn, const SuiteSparse_long *parent,
                      cholmod_factor *L)
{
    const SuiteSparse_long *Np = Sn->p, *Ni = Sn->i, *off = o->off;
    size_t m = o->m, n = (size_t)off[m];
    SuiteSparse_long *rows = ctn_malloc(c->ctx, Np[m] ? (size_t)Np[m] : 1, sizeof *rows);
    SuiteSparse_long *Ap = ctn_malloc(c->ctx, n + 1, sizeof *Ap), *Anz = ctn_malloc(c->ctx, n ? n : 1, sizeof *Anz);
    int rc = rows && Ap && Anz ? CTN_OK : CTN_ERR_NOMEM;
    if (!rc) {
        SuiteSparse_long t = 0;
        for (size_t k = 0; k < m; k++) {
            SuiteSparse_long t0 = t;
            for (SuiteSparse_long p = Np[k]; p < Np[k + 1]; p++)
                if (Ni[p] < (SuiteSparse_long)k) rows[t++] = off[Ni[p]];
            for (SuiteSparse_long j = off[k]; j < off[k + 1]; j++) Ap[j] = t0, Anz[j] = t - t0;
        }
        Ap[n] = t;
        cholmod_sparse S = { .nrow = n, .ncol = n, .nzmax = (size_t)(t ? t : 1), .p = Ap, .i = rows, .nz = Anz,
                             .stype = 1, .itype = CHOLMOD_LONG, .xtype = CHOLMOD_PATTERN, .dtype = CHOLMOD_DOUBLE,
                             .sorted = 1, .packed = 0 };
        if (!cholmod_l_super_symbolic2(1, &S, NULL, (SuiteSparse_long *)parent, L, &c->cm))
            rc = ctn_chol_error(c, "analysis (supernodes)");
    }
    ctn_free(rows);
    ctn_free(Ap);
    ctn_free(Anz);
    return rc;
}

int ctn_chol_symbolic(chol *c, const ctn_chol_quot *q, const SuiteSparse_long *sperm,
                      const SuiteSparse_long *sparent, const SuiteSparse_long *scount)
{
    cholmod_common *cm = &c->cm;
    size_t n = c->A->ncol;
    order o;
    memset(&o, 0, sizeof o);
    cholmod_sparse *Sn = NULL;
    cholmod_factor *Ln = NULL, *L = NULL;
    SuiteSparse_long *parent = NULL;
    int rc = order_make(c, q, sperm, sparent, scount, &o);
    if (!rc && !(parent = ctn_malloc(c->ctx, n ? n : 1, sizeof *parent))) rc = CTN_ERR_NOMEM;
    if (!rc && !(Sn = node_pattern(q, &o, cm))) rc = ctn_chol_error(c, "analysis (permuting the node graph)");
    if (!rc && !uniform(&o) && !(Ln = node_factor(&o, Sn, cm))) rc = ctn_chol_error(c, "analysis (the node factor)");
    if (!rc && !(L = cholmod_l_allocate_factor(n, cm))) rc = ctn_chol_error(c, "analysis");
    if (!rc) {
        ctn_chol_quotient_expand(q, o.Q, L->Perm);
        L->ordering = CHOLMOD_GIVEN;
        counts(&o, Ln, L->ColCount, cm);
        tree(&o, parent);
    }
    cholmod_l_free_factor(&Ln, cm);
    int super = cm->supernodal > CHOLMOD_AUTO ||
                (cm->supernodal == CHOLMOD_AUTO && cm->lnz > 0 && cm->fl / cm->lnz >= cm->supernodal_switch);
    if (!rc && super) rc = supernodes(c, &o, Sn, parent, L);
    cholmod_l_free_sparse(&Sn, cm);
    ctn_free(parent);
    order_free(&o);
    if (rc) cholmod_l_free_factor(&L, cm);
    c->L = L;
    return rc;
}
