/* The triangular solves of a CHOLMOD supernodal LL' factor on two threads (psolve.h).
 *
 * CHOLMOD's supernodal factor: supernode s holds columns Super[s] .. Super[s+1]-1 (nc
 * of them) and the nr row indices Ls[Lpi[s] ..], the first nc of them the diagonal
 * block's; its values are the nr x nc column-major block at Lx + Lpx[s]: L11 (nc x nc,
 * lower) over L21 ((nr - nc) x nc). Supernodes are numbered children before parents,
 * the parent of s being the supernode of its first row below the diagonal block.
 *
 * With Y = P B (rows permuted):
 *   forward  L Y = Y:  Y1 = L11 \ Y1; Y[rows of L21] -= L21 Y1, for s increasing;
 *   backward L'X = Y:  Y1 -= L21' Y[rows of L21]; Y1 = L11' \ Y1, for s decreasing;
 * and X = P' Y. A supernode's forward update goes only to its ancestors and its
 * backward sweep reads only theirs, so two disjoint sets of whole subtrees can be
 * solved on two threads: only rows of their common ancestors (the top) are written by
 * both, forward, and those updates go to each thread's own buffer, summed after. */
#include "core/threads.h"
#include "linalg/backends/cholmod/psolve.h"
#include "linalg/backends/cholmod/psolve_k4.h"
#include "linalg/backends/cholmod/chol.h"
#include "linalg/lapack.h"
#include "linalg/linsolve.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#define PS_TOP 2                 /* the set of the sequential top */
#define PS_SPLITS 512            /* most subtrees split open while balancing */
#define PS_BALANCE 0.02          /* stop splitting when the two sets differ by less */
#define PS_CANDIDATES 4096       /* or when there are this many subtrees to place */

struct ctn_psolve {
    ctn_ctx *ctx;
    int n;                       /* order */
    long *set[3];                /* supernodes of each set (0, 1, top), increasing */
    long count[3];
    double work[3];              /* entries of the factor in each set */
    long *toprow;                /* n: row's index in the top buffers, -1 if not a top row */
    long *first;                 /* nsuper: a set's supernode: the first row of the top
                                    above it (its subtree's root's last row + 1) */
    long ntop;                   /* rows of the top supernodes */
    long maxoff;                 /* most off-diagonal rows of a supernode */
    size_t kcap;                 /* columns the workspace holds */
    double *Y;                   /* n x kcap: the permuted solution, by rows (Y[r k + c]) */
    double *E[2];                /* maxoff x kcap: a supernode's update, per thread, by rows */
    double *T[2];                /* ntop x kcap: updates to top rows, per thread, by rows */
    ctn_ps4_kernels k4;          /* a supernode's sweeps for 4 columns */
};

/* ---- the plan ---- */

typedef struct tree {
    long ns;
    long *parent, *head, *next;  /* ns each: parent (-1: a root), children lists */
    double *w, *sub;             /* ns: entries of the supernode, of its subtree */
    long *cand;                  /* ns: roots of the subtrees being placed */
    signed char *owner;          /* ns: 0, 1, PS_TOP, or -1 (below a candidate) */
} tree;

typedef struct wcand {
    double w;
    long s;
} wcand;

static int by_weight(const void *a, const void *b)
{
    const wcand *x = a, *y = b;
    return x->w < y->w ? 1 : x->w > y->w ? -1 : (x->s > y->s) - (x->s < y->s);
}

/* Parents, children and subtree weights of L's supernodes. */
static int tree_build(ctn_ctx *ctx, const cholmod_factor *L, tree *t)
{
    const SuiteSparse_long *Super = L->super, *Lpi = L->pi, *Ls = L->s;
    long ns = (long)L->nsuper, n = (long)L->n;
    long *col = ctn_malloc(ctx, (size_t)n, sizeof *col);
    t->ns = ns;
    t->parent = ctn_malloc(ctx, (size_t)ns, sizeof(long));
    t->head = ctn_malloc(ctx, (size_t)ns, sizeof(long));
    t->next = ctn_malloc(ctx, (size_t)ns, sizeof(long));
    t->cand = ctn_malloc(ctx, (size_t)ns, sizeof(long));
    t->w = ctn_malloc(ctx, (size_t)ns, sizeof(double));
    t->sub = ctn_malloc(ctx, (size_t)ns, sizeof(double));
    t->owner = ctn_malloc(ctx, (size_t)ns, 1);
    if (!col || !t->parent || !t->head || !t->next || !t->cand || !t->w || !t->sub || !t->owner) {
        ctn_free(col);
        return CTN_ERR_NOMEM;
    }
    for (long s = 0; s < ns; s++)
        for (SuiteSparse_long j = Super[s]; j < Super[s + 1]; j++) col[j] = s;
    for (long s = 0; s < ns; s++) t->head[s] = -1;
    for (long s = ns - 1; s >= 0; s--) {                /* children in increasing order */
        long nc = (long)(Super[s + 1] - Super[s]), nr = (long)(Lpi[s + 1] - Lpi[s]);
        t->parent[s] = nr > nc ? col[Ls[Lpi[s] + nc]] : -1;
        t->w[s] = (double)nr * (double)nc;
        if (t->parent[s] >= 0) {
            t->next[s] = t->head[t->parent[s]];
            t->head[t->parent[s]] = s;
        }
    }
    for (long s = 0; s < ns; s++) t->sub[s] = t->w[s];
    for (long s = 0; s < ns; s++)
        if (t->parent[s] >= 0) t->sub[t->parent[s]] += t->sub[s];
    ctn_free(col);
    return CTN_OK;
}

static void tree_free(tree *t)
{
    ctn_free(t->parent);
    ctn_free(t->head);
    ctn_free(t->next);
    ctn_free(t->cand);
    ctn_free(t->w);
    ctn_free(t->sub);
    ctn_free(t->owner);
}

/* Place the candidates in two sets, heaviest first into the lighter (owner[] of each
 * candidate); work[] of the sets. */
static void place(tree *t, long nc, wcand *tmp, double work[2])
{
    for (long i = 0; i < nc; i++) tmp[i] = (wcand){ t->sub[t->cand[i]], t->cand[i] };
    qsort(tmp, (size_t)nc, sizeof *tmp, by_weight);
    work[0] = work[1] = 0;
    for (long i = 0; i < nc; i++) {
        int b = work[1] < work[0];
        work[b] += tmp[i].w;
        t->owner[tmp[i].s] = (signed char)b;
    }
}

/* Split the heaviest subtree open `splits` times (its root to the top, its children
 * candidates), or until the sets balance or the heaviest is a leaf; the owners of the
 * candidates and top, the work of the three sets; returns the splits made. The
 * estimated time after i splits, top + the larger set, in cost[i] (splits + 1). */
static int grow(tree *t, int splits, wcand *tmp, double work[3], double *cost)
{
    long nc = 0;
    for (long s = 0; s < t->ns; s++) {
        t->owner[s] = -1;
        if (t->parent[s] < 0) t->cand[nc++] = s;
    }
    work[PS_TOP] = 0;
    int i = 0;
    for (;; i++) {
        place(t, nc, tmp, work);
        double hi = work[0] > work[1] ? work[0] : work[1], lo = work[0] + work[1] - hi;
        cost[i] = work[PS_TOP] + hi;
        if (i >= splits || hi - lo <= PS_BALANCE * hi || nc == 0 || nc > PS_CANDIDATES) break;
        long h = 0;
        for (long c = 1; c < nc; c++)
            if (t->sub[t->cand[c]] > t->sub[t->cand[h]]) h = c;
        long s = t->cand[h];
        if (t->head[s] < 0) break;                     /* a leaf: nothing to split */
        t->cand[h] = t->cand[--nc];
        t->owner[s] = PS_TOP;
        work[PS_TOP] += t->w[s];
        for (long c = t->head[s]; c >= 0; c = t->next[c]) t->cand[nc++] = c;
    }
    return i;
}

/* The best number of splits (least estimated time), then the owners it gives. */
static void choose(tree *t, wcand *tmp, double work[3])
{
    double cost[PS_SPLITS + 1];
    int made = grow(t, PS_SPLITS, tmp, work, cost), keep = 0;
    for (int i = 1; i <= made; i++)
        if (cost[i] < cost[keep]) keep = i;
    grow(t, keep, tmp, work, cost);
    for (long s = t->ns - 1; s >= 0; s--)               /* parents first: subtrees inherit */
        if (t->owner[s] < 0) t->owner[s] = t->owner[t->parent[s]];
}

/* The sets' supernode lists, the top rows' buffer indices, the largest update. */
static int lists(ctn_psolve *p, const cholmod_factor *L, const tree *t)
{
    const SuiteSparse_long *Super = L->super, *Lpi = L->pi;
    for (int b = 0; b < 3; b++) p->count[b] = 0;
    for (long s = 0; s < t->ns; s++) p->count[t->owner[s]]++;
    for (int b = 0; b < 3; b++)
        if (!(p->set[b] = ctn_malloc(p->ctx, (size_t)p->count[b] + 1, sizeof(long)))) return CTN_ERR_NOMEM;
    if (!(p->toprow = ctn_malloc(p->ctx, (size_t)p->n, sizeof(long)))) return CTN_ERR_NOMEM;
    if (!(p->first = ctn_malloc(p->ctx, (size_t)t->ns, sizeof(long)))) return CTN_ERR_NOMEM;
    for (long s = t->ns - 1; s >= 0; s--) {            /* parents first */
        long up = t->parent[s];
        if (t->owner[s] == PS_TOP) p->first[s] = LONG_MAX;
        else if (up < 0 || t->owner[up] == PS_TOP) p->first[s] = (long)Super[s + 1];
        else p->first[s] = p->first[up];
    }
    long c[3] = { 0, 0, 0 };
    for (long s = 0; s < t->ns; s++) p->set[t->owner[s]][c[t->owner[s]]++] = s;
    for (int r = 0; r < p->n; r++) p->toprow[r] = -1;
    p->ntop = p->maxoff = 0;
    for (long s = 0; s < t->ns; s++) {
        long nc = (long)(Super[s + 1] - Super[s]), off = (long)(Lpi[s + 1] - Lpi[s]) - nc;
        if (off > p->maxoff) p->maxoff = off;
        if (t->owner[s] != PS_TOP) continue;
        for (SuiteSparse_long j = Super[s]; j < Super[s + 1]; j++) p->toprow[j] = p->ntop++;
    }
    return CTN_OK;
}

int ctn_psolve_create(ctn_ctx *ctx, const cholmod_factor *L, ctn_psolve **out)
{
    *out = NULL;
    if (!L->is_super || !L->is_ll || L->xtype != CHOLMOD_REAL || L->nsuper < 3 || L->n > (size_t)1 << 30)
        return CTN_OK;
    tree t = { 0 };
    wcand *tmp = NULL;
    ctn_psolve *p = ctn_calloc(ctx, 1, sizeof *p);
    int rc = p ? tree_build(ctx, L, &t) : CTN_ERR_NOMEM;
    if (!rc && !(tmp = ctn_malloc(ctx, L->nsuper, sizeof *tmp))) rc = CTN_ERR_NOMEM;
    if (!rc) {
        p->ctx = ctx;
        p->n = (int)L->n;
        ctn_ps4_choose(&p->k4);
        choose(&t, tmp, p->work);
        rc = lists(p, L, &t);
    }
    ctn_free(tmp);
    tree_free(&t);
    double all = p ? p->work[0] + p->work[1] + p->work[PS_TOP] : 0;
    if (!rc && p->work[0] + p->work[1] >= 0.5 * all && p->count[0] && p->count[1]) *out = p;
    else ctn_psolve_destroy(&p);
    return rc;
}

void ctn_psolve_destroy(ctn_psolve **pp)
{
    ctn_psolve *p = pp ? *pp : NULL;
    if (!p) return;
    for (int b = 0; b < 3; b++) ctn_free(p->set[b]);
    ctn_free(p->toprow);
    ctn_free(p->first);
    ctn_free(p->Y);
    for (int t = 0; t < 2; t++) {
        ctn_free(p->E[t]);
        ctn_free(p->T[t]);
    }
    ctn_free(p);
    *pp = NULL;
}

void ctn_psolve_shares(const ctn_psolve *p, double share[3])
{
    double all = p->work[0] + p->work[1] + p->work[PS_TOP];
    for (int b = 0; b < 3; b++) share[b] = p->work[b] / all;
}

/* ---- the solve ---- */

static int workspace(ctn_psolve *p, size_t k)
{
    if (k <= p->kcap) return CTN_OK;
    ctn_free(p->Y);
    p->Y = NULL;
    for (int t = 0; t < 2; t++) {
        ctn_free(p->E[t]);
        ctn_free(p->T[t]);
        p->E[t] = p->T[t] = NULL;
    }
    p->kcap = 0;
    p->Y = ctn_malloc(p->ctx, (size_t)p->n * k, sizeof(double));
    for (int t = 0; t < 2 && p->Y; t++) {
        p->E[t] = ctn_malloc(p->ctx, (size_t)(p->maxoff > 0 ? p->maxoff : 1) * k, sizeof(double));
        p->T[t] = ctn_malloc(p->ctx, (size_t)(p->ntop > 0 ? p->ntop : 1) * k, sizeof(double));
        if (!p->E[t] || !p->T[t]) return CTN_ERR_NOMEM;
    }
    if (!p->Y) return CTN_ERR_NOMEM;
    p->kcap = k;
    return CTN_OK;
}

typedef struct job {
    ctn_psolve *p;
    const cholmod_factor *L;
    const double *B;             /* the right-hand sides (forward) */
    double *X;                   /* the solution (backward) */
    int k;
    int set;                     /* 0, 1 or PS_TOP */
    double *E, *T;               /* this thread's update and top buffers (T: NULL for the top) */
} job;

/* Forward on supernode s, Y held by rows (Z = Y1' is k x nc, leading dimension k):
 * Y1 = L11 \ Y1, then its update L21 Y1 subtracted from the rows below: into T for the
 * top's rows (from row `top` on) when T is given, summed after the join. */
static void forward(const job *j, long s)
{
    const cholmod_factor *L = j->L;
    const SuiteSparse_long *Super = L->super, *Lpi = L->pi, *Lpx = L->px, *Ls = L->s;
    const double *Lx = L->x, one = 1, zero = 0;
    const int k = j->k, k1 = (int)Super[s];
    const int nc = (int)(Super[s + 1] - k1), nr = (int)(Lpi[s + 1] - Lpi[s]), m = nr - nc;
    const double *L11 = Lx + Lpx[s];
    double *Y = j->p->Y, *Z = Y + (size_t)k1 * (size_t)k;
    if (k == 4) j->p->k4.forward(L11, nr, nc, Z, j->E);                               /* both, by hand */
    else if (k == 1) dtrsv_("L", "N", "N", &nc, L11, &nr, Z, &k, 1, 1, 1);             /* Y1 = L11 \ Y1 */
    else dtrsm_("R", "L", "T", "N", &k, &nc, &one, L11, &nr, Z, &k, 1, 1, 1, 1);   /* Y1' = Y1' L11'^-1 */
    if (m <= 0) return;
    if (k == 1) dgemv_("N", &m, &nc, &one, L11 + nc, &nr, Z, &k, &zero, j->E, &k, 1);    /* E = L21 Y1 */
    else if (k != 4) dgemm_("N", "T", &k, &m, &nc, &one, Z, &k, L11 + nc, &nr, &zero, j->E, &k, 1, 1);   /* E' = Y1' L21' */
    const SuiteSparse_long *rows = Ls + Lpi[s] + nc;
    const long *top = j->p->toprow, first = j->T ? j->p->first[s] : LONG_MAX;
    const double *e = j->E;
    for (int i = 0; i < m; i++, e += k) {
        long r = (long)rows[i];
        double *y = r < first ? Y + (size_t)r * (size_t)k : j->T + (size_t)top[r] * (size_t)k;
        if (r < first) for (int c = 0; c < k; c++) y[c] -= e[c];
        else for (int c = 0; c < k; c++) y[c] += e[c];
    }
}

/* Backward on supernode s: Y1 -= L21' Y[rows below], then Y1 = L11' \ Y1. */
static void backward(const job *j, long s)
{
    const cholmod_factor *L = j->L;
    const SuiteSparse_long *Super = L->super, *Lpi = L->pi, *Lpx = L->px, *Ls = L->s;
    const double *Lx = L->x, one = 1, minus = -1;
    const int k = j->k, k1 = (int)Super[s];
    const int nc = (int)(Super[s + 1] - k1), nr = (int)(Lpi[s + 1] - Lpi[s]), m = nr - nc;
    const double *L11 = Lx + Lpx[s];
    double *Y = j->p->Y, *Z = Y + (size_t)k1 * (size_t)k;
    if (m > 0) {
        const SuiteSparse_long *rows = Ls + Lpi[s] + nc;
        double *e = j->E;
        for (int i = 0; i < m; i++, e += k) {
            const double *y = Y + (size_t)rows[i] * (size_t)k;
            for (int c = 0; c < k; c++) e[c] = y[c];
        }
    }
    if (k == 4) {
        j->p->k4.backward(L11, nr, nc, Z, j->E);                                      /* both, by hand */
        return;
    }
    if (m > 0 && k == 1) dgemv_("T", &m, &nc, &minus, L11 + nc, &nr, j->E, &k, &one, Z, &k, 1);   /* Y1 -= L21' E */
    else if (m > 0) dgemm_("N", "N", &k, &nc, &m, &minus, j->E, &k, L11 + nc, &nr, &one, Z, &k, 1, 1);   /* Y1' -= E' L21 */
    if (k == 1) dtrsv_("L", "T", "N", &nc, L11, &nr, Z, &k, 1, 1, 1);                   /* Y1 = L11' \ Y1 */
    else dtrsm_("R", "L", "N", "N", &k, &nc, &one, L11, &nr, Z, &k, 1, 1, 1, 1);   /* Y1' = Y1' L11^-1 */
}

/* Rows of supernode s between B or X (original order, by columns) and Y (permuted, by
 * rows). */
static void permute(const job *j, long s, int in)
{
    const SuiteSparse_long *Super = j->L->super, *Perm = j->L->Perm;
    const size_t n = (size_t)j->p->n, k = (size_t)j->k;
    for (SuiteSparse_long r = Super[s]; r < Super[s + 1]; r++) {
        double *y = j->p->Y + (size_t)r * k;
        size_t q = Perm ? (size_t)Perm[r] : (size_t)r;
        if (in) for (size_t c = 0; c < k; c++) y[c] = j->B[q + n * c];
        else for (size_t c = 0; c < k; c++) j->X[q + n * c] = y[c];
    }
}

/* A subtree set's forward sweep: its rows permuted in, its top updates into T. */
static void set_forward(void *arg)
{
    const job *j = arg;
    const ctn_psolve *p = j->p;
    ctn_threads_saved saved;
    ctn_threads_push(1, &saved);
    memset(j->T, 0, (size_t)p->ntop * (size_t)j->k * sizeof(double));
    for (long i = 0; i < p->count[j->set]; i++) permute(j, p->set[j->set][i], 1);
    for (long i = 0; i < p->count[j->set]; i++) forward(j, p->set[j->set][i]);
    ctn_threads_pop(&saved);
}

/* A subtree set's backward sweep, its rows permuted out into X. */
static void set_backward(void *arg)
{
    const job *j = arg;
    const ctn_psolve *p = j->p;
    ctn_threads_saved saved;
    ctn_threads_push(1, &saved);
    for (long i = p->count[j->set] - 1; i >= 0; i--) backward(j, p->set[j->set][i]);
    for (long i = 0; i < p->count[j->set]; i++) permute(j, p->set[j->set][i], 0);
    ctn_threads_pop(&saved);
}

/* fn on both sets: the second on the context's helper when asked for (and the thread
 * policy lets it: the helper may be busy beside a modal analysis). */
static void both(ctn_thr_fn fn, job jobs[2], int threads)
{
    const ctn_psolve *p = jobs[0].p;
    if (threads >= 2) ctn_thr_both(p->ctx, 0, CTN_THR_PSOLVE, (double)p->n, fn, &jobs[0], &jobs[1]);
    else {
        fn(&jobs[0]);
        fn(&jobs[1]);
    }
}

/* The top's rows in: P B less both sets' updates. */
static void top_in(const job *j, long s)
{
    const ctn_psolve *p = j->p;
    permute(j, s, 1);
    const SuiteSparse_long *Super = j->L->super;
    const size_t k = (size_t)j->k;
    for (SuiteSparse_long r = Super[s]; r < Super[s + 1]; r++) {
        double *y = p->Y + (size_t)r * k;
        const double *t0 = p->T[0] + (size_t)p->toprow[r] * k, *t1 = p->T[1] + (size_t)p->toprow[r] * k;
        for (size_t c = 0; c < k; c++) y[c] -= t0[c] + t1[c];
    }
}

int ctn_psolve_solve(ctn_psolve *p, const cholmod_factor *L, const double *B, double *X, size_t k, int threads)
{
    if (k == 0) return CTN_OK;
    if (k > INT_MAX / 2) return ctn_error(p->ctx, CTN_ERR_INVALID, "a parallel solve of %zu columns", k);
    int rc = workspace(p, k);
    if (rc) return rc;
    job jobs[2], top;
    for (int t = 0; t < 2; t++) jobs[t] = (job){ p, L, B, X, (int)k, t, p->E[t], p->T[t] };
    top = (job){ p, L, B, X, (int)k, PS_TOP, p->E[0], NULL };
    ctn_threads_saved saved;
    both(set_forward, jobs, threads);
    ctn_threads_push(1, &saved);
    const long *ts = p->set[PS_TOP];
    for (long i = 0; i < p->count[PS_TOP]; i++) top_in(&top, ts[i]);
    for (long i = 0; i < p->count[PS_TOP]; i++) forward(&top, ts[i]);
    for (long i = p->count[PS_TOP] - 1; i >= 0; i--) backward(&top, ts[i]);
    for (long i = 0; i < p->count[PS_TOP]; i++) permute(&top, ts[i], 0);
    ctn_threads_pop(&saved);
    both(set_backward, jobs, threads);
    return CTN_OK;
}

int ctn_chol_psolve_plan(chol *c)
{
    if (c->ps_planned || (c->plain & CTN_LA_PLAIN_SOLVE)
        || !ctn_thr_allows(c->ctx, c->threads, CTN_THR_PSOLVE, (double)c->L->n)) return CTN_OK;
    c->ps_planned = 1;
    return ctn_psolve_create(c->ctx, c->L, &c->ps);
}
