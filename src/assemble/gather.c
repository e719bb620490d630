/* The node-by-node assembly of axial members (asm.h, ctn_asm_gather): instead of adding
 * every element's 6 x 6 into the tangent through a scatter map, each node writes its
 * columns of the tangent and its internal force once, in the pattern's order. An axial
 * member's tangent is [[k, -k], [-k, k]], so node q's diagonal block is the sum of its
 * elements' k and its block with a lower neighbour p is minus the sum over the elements
 * joining them: the values the scatter gives, summed in the same (model) order, so the
 * same bits. Nodes are taken in chunks: first the elements whose lower node is in the
 * chunk are evaluated, in one run of a list kept in that order, into a small per-thread
 * table, so that the evaluations of consecutive elements overlap; then each node of the
 * chunk sums and writes. A plain node (its three directions free, and its lower
 * neighbours', one element to each of them: a chain's, most of a net's) writes its
 * columns straight from its elements' k; the others sum each neighbour's block first.
 * No zeroing, no read-modify-write, no scatter map. Nodes are independent, so two
 * threads take half the nodes each (an element across the halves is evaluated by both;
 * its energy counted by its lower node's). */
#include "assemble/asm.h"
#include "core/threads.h"
#include "element/cable2.h"

#include <stdint.h>
#include <stdlib.h>   /* realloc: ctn_free is free (core/ctx.c) */
#include <string.h>

#define KEEP 4096                     /* elements kept per thread (448 KB: within L2) */
#define CHUNK 64                      /* nodes evaluated, then walked */
#define PLAIN 8                       /* free[q] bit: a plain node, its lower neighbours'
                                         count in bits 4 .. 7 */
#define PLAIN_DEG 8                   /* elements of a plain node at most */
#define FEED_CHUNKS 16                /* chunks between two publications of the columns
                                         done (ctn_asm_eval_feed) */

/* k's upper triangle (ctn_axial_k) at (i, j) of the symmetric 3 x 3. */
static const int sym3[3][3] = { { 0, 1, 2 }, { 1, 3, 4 }, { 2, 4, 5 } };

void ctn_asm_gather_free(ctn_asm_gather **g)
{
    if (!g || !*g) return;
    ctn_free((*g)->inc_ptr);
    ctn_free((*g)->inc);
    ctn_free((*g)->order);
    ctn_free((*g)->adj_ptr);
    ctn_free((*g)->adj);
    ctn_free((*g)->work);
    ctn_free((*g)->keep);
    ctn_free((*g)->X);
    ctn_free((*g)->free);
    ctn_free((*g)->ev_ptr);
    ctn_free((*g)->ev);
    ctn_free(*g);
    *g = NULL;
}

/* Count (inc == NULL: into inc_ptr[q + 1]) or list every axial element at its two ends,
 * in model order (fill: each node's next free place). 1 if an element joins a node to
 * itself (the path does not take it: the generic loop's collapse check does). */
static int each_end(const ctn_asm *a, int *inc_ptr, int *fill, ctn_asm_inc *inc)
{
    for (size_t k = 0; k < a->nblocks; k++) {
        const ctn_asm_block *b = &a->blocks[k];
        if (!ctn_asm_block_axial(b)) continue;
        const int *conn = ctn_elem_nodes(a->m, b->e0);
        for (size_t i = 0; i < b->count; i++) {
            int n1 = conn[2 * i], n2 = conn[2 * i + 1], e = (int)(b->e0 + i);
            if (n1 == n2) return 1;
            if (!inc) {
                inc_ptr[n1 + 1]++;
                inc_ptr[n2 + 1]++;
                continue;
            }
            inc[fill[n1]++] = (ctn_asm_inc){ e, 2 * n2, (int)k };
            inc[fill[n2]++] = (ctn_asm_inc){ e, 2 * n1 + 1, (int)k };
        }
    }
    return 0;
}

/* order: each node's elements by (other node, element), as positions in its own list. */
static void sort_by_neighbour(ctn_asm_gather *g, size_t nn)
{
    for (size_t q = 0; q < nn; q++) {
        int t0 = g->inc_ptr[q], n = g->inc_ptr[q + 1] - t0;
        int *o = g->order + t0;
        for (int t = 0; t < n; t++) {                  /* insertion: lists are short */
            int v = t, s = t;
            for (; s > 0 && g->inc[t0 + o[s - 1]].nb >> 1 > g->inc[t0 + v].nb >> 1; s--) o[s] = o[s - 1];
            o[s] = v;
        }
    }
}

/* ev: each node's elements whose other node is higher, in model order. */
static void lower_lists(ctn_asm_gather *g, size_t nn)
{
    int v = 0;
    for (size_t q = 0; q < nn; q++) {
        g->ev_ptr[q] = v;
        for (int t = g->inc_ptr[q]; t < g->inc_ptr[q + 1]; t++) {
            const ctn_asm_inc *in = &g->inc[t];
            int o = in->nb >> 1, first = !(in->nb & 1);
            if (o > (int)q) g->ev[v++] = (ctn_asm_ev){ in->e, in->blk, first ? (int)q : o, first ? o : (int)q };
        }
    }
    g->ev_ptr[nn] = v;
}

static int build_lists(ctn_ctx *ctx, const ctn_asm *a, ctn_asm_gather *g, size_t ends)
{
    int *fill = ctn_malloc(ctx, a->nn, sizeof(int));
    g->inc = ctn_malloc(ctx, ends, sizeof(ctn_asm_inc));
    g->order = ctn_malloc(ctx, ends, sizeof(int));
    g->ev_ptr = ctn_malloc(ctx, a->nn + 1, sizeof(int));
    g->ev = ctn_malloc(ctx, ends / 2, sizeof(ctn_asm_ev));
    if (!fill || !g->inc || !g->order || !g->ev_ptr || !g->ev) {
        ctn_free(fill);
        return CTN_ERR_NOMEM;
    }
    for (size_t q = 0; q < a->nn; q++) {
        g->inc_ptr[q + 1] += g->inc_ptr[q];
        fill[q] = g->inc_ptr[q];
        int deg = g->inc_ptr[q + 1] - g->inc_ptr[q];
        if (deg > g->maxdeg) g->maxdeg = deg;
    }
    each_end(a, NULL, fill, g->inc);
    ctn_free(fill);
    sort_by_neighbour(g, a->nn);
    lower_lists(g, a->nn);
    return CTN_OK;
}

/* Node q is plain when it and its lower neighbours (ptr/adj) have their three directions
 * free, it has at most PLAIN_DEG elements and one element joins it to each lower
 * neighbour: then its list in neighbour order (order) starts with exactly those. Their
 * count, or -1 if q is not plain. */
static int plain(const ctn_asm_gather *g, size_t q, const int *ptr, const int *adj)
{
    int t0 = g->inc_ptr[q], n = g->inc_ptr[q + 1] - t0, nl = 0;
    if ((g->free[q] & 7) != 7 || n > PLAIN_DEG) return -1;
    for (int s = ptr[q]; adj[s] < (int)q; s++, nl++)
        if ((g->free[adj[s]] & 7) != 7 || nl >= n || g->inc[t0 + g->order[t0 + nl]].nb >> 1 != adj[s]) return -1;
    return nl == n || g->inc[t0 + g->order[t0 + nl]].nb >> 1 > (int)q ? nl : -1;
}

/* Doubles of one thread's scratch: maxdeg blocks of 6, on cache lines of its own (the
 * threads write theirs for every element). */
static size_t work_stride(const ctn_asm_gather *g)
{
    return ((size_t)(g->maxdeg + g->maxadj) * 6 + 7) / 8 * 8 + 8;
}


int ctn_asm_gather_build(ctn_ctx *ctx, ctn_asm *a, int **ptr, int **adj)
{
    size_t ends = 0;
    int mixed = 0;
    if ((a->flags & CTN_ASM_GENERIC) || a->map.uniform != 3 || !a->nn) return CTN_OK;
    for (size_t k = 0; k < a->nblocks; k++) {
        if (ctn_asm_block_axial(&a->blocks[k])) ends += 2 * a->blocks[k].count;
        else mixed = 1;
    }
    if (!ends) return CTN_OK;
    ctn_asm_gather *g = ctn_calloc(ctx, 1, sizeof(ctn_asm_gather));
    if (!g) return CTN_ERR_NOMEM;
    g->mixed = mixed;
    g->inc_ptr = ctn_calloc(ctx, a->nn + 1, sizeof(int));
    int rc = g->inc_ptr ? CTN_OK : CTN_ERR_NOMEM;
    if (!rc && each_end(a, g->inc_ptr, NULL, NULL)) {      /* a self-joined element */
        ctn_asm_gather_free(&g);
        return CTN_OK;
    }
    if (!rc) rc = build_lists(ctx, a, g, ends);
    g->ctx = ctx;
    g->threads = ctn_thr_allows(ctx, ctn_asm_threads(a), CTN_THR_ASSEMBLY, (double)a->nn) ? 2 : 1;
    for (size_t q = 0; q < a->nn; q++)                 /* most neighbours of a node */
        if ((*ptr)[q + 1] - (*ptr)[q] > g->maxadj) g->maxadj = (*ptr)[q + 1] - (*ptr)[q];
    g->work = rc ? NULL : ctn_malloc(ctx, (size_t)g->threads * work_stride(g), sizeof(double));
    g->keep = rc ? NULL : ctn_malloc(ctx, (size_t)g->threads * KEEP, sizeof(ctn_asm_kept));
    g->X = rc ? NULL : ctn_malloc(ctx, a->nn * 3, sizeof(double));
    if (!rc && (!g->work || !g->keep || !g->X)) rc = CTN_ERR_NOMEM;
    g->free = rc ? NULL : ctn_malloc(ctx, a->nn, 1);
    if (!rc && !g->free) rc = CTN_ERR_NOMEM;
    for (size_t q = 0; !rc && q < a->nn; q++) {
        memcpy(g->X + 3 * q, a->m->nodes.v[q].X, sizeof(double[3]));
        g->free[q] = 0;
        for (int j = 0; j < 3; j++) g->free[q] |= (unsigned char)((a->map.eq[3 * q + (size_t)j] >= 0) << j);
    }
    for (size_t q = 0; !rc && q < a->nn; q++) {
        int nl = plain(g, q, *ptr, *adj);
        if (nl >= 0) g->free[q] |= (unsigned char)(PLAIN | nl << 4);
    }
    if (rc) {
        ctn_asm_gather_free(&g);
        return rc;
    }
    g->adj_ptr = *ptr;                                 /* taken over */
    g->adj = *adj;
    *ptr = *adj = NULL;
    g->q1 = a->nn;
    a->gather = g;
    return CTN_OK;
}

/* The entries [ptr[q0], ptr[q1]) of list *v (elements of size bytes) moved to its front,
 * ptr[q0 .. q1] rebased on them, and the list shrunk to them. */
static void keep_range(void **v, size_t size, int *ptr, size_t q0, size_t q1)
{
    size_t t0 = (size_t)ptr[q0], n = (size_t)ptr[q1] - t0;
    memmove(*v, (char *)*v + t0 * size, n * size);
    for (size_t q = q0; q <= q1; q++) ptr[q] -= (int)t0;
    void *w = realloc(*v, n ? n * size : 1);          /* ctn_free is free */
    if (w) *v = w;
}

int ctn_asm_gather_keep(ctn_asm *a, size_t q0, size_t q1)
{
    ctn_asm_gather *g = a->gather;
    if (!g || q0 > q1 || q1 > a->nn) return CTN_ERR_INVALID;
    void *inc = g->inc, *ev = g->ev, *adj = g->adj;
    int *order = g->order, t0 = g->inc_ptr[q0];        /* order is relative: kept as is */
    memmove(order, order + t0, (size_t)(g->inc_ptr[q1] - t0) * sizeof(int));
    keep_range(&inc, sizeof(ctn_asm_inc), g->inc_ptr, q0, q1);
    keep_range(&ev, sizeof(ctn_asm_ev), g->ev_ptr, q0, q1);
    keep_range(&adj, sizeof(int), g->adj_ptr, q0, q1);
    int *o = realloc(order, (size_t)(g->inc_ptr[q1] > 0 ? g->inc_ptr[q1] : 1) * sizeof(int));
    g->order = o ? o : order;
    g->inc = inc;
    g->ev = ev;
    g->adj = adj;
    g->q0 = q0;
    g->q1 = q1;
    return CTN_OK;
}

/* One thread's share: nodes q0 .. q1 - 1, their columns from Kx[k0]. */
typedef struct part {
    const ctn_asm *a;
    const double *d;
    unsigned mode;
    double *f, *Kx;
    size_t q0, q1, k0;
    double *w;                 /* maxdeg * 6 */
    double *S;                 /* maxadj * 6 */
    ctn_asm_kept *keep;        /* KEEP */
    double U;                  /* energy of the elements whose first node is here */
    size_t bad;                /* first collapsed element, SIZE_MAX if none */
    ctn_feed *feed;            /* NULL, or where the columns done are published */
} part;

/* Evaluate element e of block blk, joining nodes n1 and n2, into kept (its forces, and its
 * k when the tangent is asked for; all zero if it collapsed, and 1 returned). */
static inline __attribute__((always_inline)) int eval_elem(const part *pt, int e, int blk, size_t n1, size_t n2,
                                                           ctn_asm_kept *kept, double *energy)
{
    const ctn_asm *a = pt->a;
    const ctn_asm_block *b = &a->blocks[blk];
    double X[6], u[6];
    ctn_elem_state st;
    memcpy(X, a->gather->X + 3 * n1, sizeof(double[3]));
    memcpy(X + 3, a->gather->X + 3 * n2, sizeof(double[3]));
    memcpy(u, pt->d + 3 * n1, sizeof(double[3]));
    memcpy(u + 3, pt->d + 3 * n2, sizeof(double[3]));
    const void *props = a->props + b->props0 + ((size_t)e - b->e0) * b->ops->props_size;
    double *k = pt->Kx ? kept->k : NULL;
    kept->e = e;
    /* the cable's kernel inline (the bits of its eval_axial: cable2.h) */
    if (!(b->ops == &ctn_cable2_ops ? ctn_cable_axial(props, pt->mode, X, u, kept->f, k, &st)
                                    : b->ops->eval_axial(props, pt->mode, X, u, kept->f, k, &st))) {
        *energy = st.energy;
        return 0;
    }
    memset(kept->f, 0, sizeof kept->f);
    memset(kept->k, 0, sizeof kept->k);
    *energy = 0;
    return 1;
}

/* Evaluate the elements whose lower node is one of qa .. qb - 1 (one run of ev) into this
 * thread's table (slot e mod KEEP), their energy into U. Apart from the walk over the
 * nodes, so that the evaluations (chains of divisions and a square root) of consecutive
 * elements overlap. */
static void eval_chunk(const part *pt, size_t qa, size_t qb, double *U, size_t *bad)
{
    const ctn_asm_gather *g = pt->a->gather;
    for (int t = g->ev_ptr[qa]; t < g->ev_ptr[qb]; t++) {
        const ctn_asm_ev *v = &g->ev[t];
        double energy;
        if (eval_elem(pt, v->e, v->blk, (size_t)v->n1, (size_t)v->n2, pt->keep + (size_t)v->e % KEEP, &energy) &&
            (size_t)v->e < *bad)
            *bad = (size_t)v->e;
        *U += energy;
    }
}

/* eval_elem out of line, for the few elements evaluated at their higher node. */
static __attribute__((noinline)) int eval_again(const part *pt, int e, int blk, size_t n1, size_t n2,
                                                ctn_asm_kept *kept, double *energy)
{
    return eval_elem(pt, e, blk, n1, n2, kept, energy);
}

/* The evaluation of node q's element in from the table; evaluated into again if it is not
 * there (pushed out, or its lower node is another thread's: its energy is counted there). */
static const ctn_asm_kept *kept_of(const part *pt, const ctn_asm_inc *in, size_t q, ctn_asm_kept *again, size_t *bad)
{
    const ctn_asm_kept *kept = pt->keep + (size_t)in->e % KEEP;
    if (kept->e == in->e) return kept;
    size_t o = (size_t)(in->nb >> 1);
    double energy;
    if (eval_again(pt, in->e, in->blk, in->nb & 1 ? o : q, in->nb & 1 ? q : o, again, &energy) &&
        (size_t)in->e < *bad)
        *bad = (size_t)in->e;
    return again;
}

/* Node q's elements, in model order, from the table: their k into w (list order), the
 * force on q into f, the sum of their k into D. */
static void node_elements(const part *pt, size_t q, double D[6], size_t *bad)
{
    const ctn_asm_gather *g = pt->a->gather;
    double fq[3] = { 0, 0, 0 };
    for (int t = g->inc_ptr[q]; t < g->inc_ptr[q + 1]; t++) {
        const ctn_asm_inc *in = &g->inc[t];
        ctn_asm_kept again;
        const ctn_asm_kept *kept = kept_of(pt, in, q, &again, bad);
        const double *fe = kept->f + 3 * (in->nb & 1);
        for (int j = 0; j < 3; j++) fq[j] += fe[j];
        if (!pt->Kx) continue;
        memcpy(pt->w + 6 * (t - g->inc_ptr[q]), kept->k, sizeof kept->k);
        for (int j = 0; j < 6; j++) D[j] += kept->k[j];
    }
    memcpy(pt->f + 3 * q, fq, sizeof fq);
}

/* A plain node's force, and its columns from Kx[k] straight from its elements' k: those
 * to its nl lower neighbours first in its list by neighbour (order), one a neighbour.
 * Returns the next position. */
static size_t plain_node(const part *pt, size_t q, size_t k, size_t *bad)
{
    const ctn_asm_gather *g = pt->a->gather;
    int t0 = g->inc_ptr[q], n = g->inc_ptr[q + 1] - t0, nl = g->free[q] >> 4;
    const ctn_asm_kept *kp[PLAIN_DEG];
    ctn_asm_kept again[PLAIN_DEG];
    double D[6] = { 0, 0, 0, 0, 0, 0 }, fq[3] = { 0, 0, 0 };
    for (int t = 0; t < n; t++) {
        const ctn_asm_inc *in = &g->inc[t0 + t];
        kp[t] = kept_of(pt, in, q, &again[t], bad);
        const double *fe = kp[t]->f + 3 * (in->nb & 1);
        for (int j = 0; j < 3; j++) fq[j] += fe[j];
        if (pt->Kx)
            for (int j = 0; j < 6; j++) D[j] += kp[t]->k[j];
    }
    memcpy(pt->f + 3 * q, fq, sizeof fq);
    if (!pt->Kx) return k;
    const int *order = g->order + t0;
    double *c0 = pt->Kx + k, *c1 = c0 + 3 * nl + 1, *c2 = c1 + 3 * nl + 2;   /* its 3 columns */
    for (int l = 0; l < nl; l++, c0 += 3, c1 += 3, c2 += 3) {
        const double *kl = kp[order[l]]->k;
        double m[6];
        for (int i = 0; i < 6; i++) m[i] = -kl[i];
        c0[0] = m[0], c0[1] = m[1], c0[2] = m[2];                 /* k's (xx, xy, xz, yy, yz, zz) */
        c1[0] = m[1], c1[1] = m[3], c1[2] = m[4];
        c2[0] = m[2], c2[1] = m[4], c2[2] = m[5];
    }
    c0[0] = D[0];
    c1[0] = D[1], c1[1] = D[3];
    c2[0] = D[2], c2[1] = D[4], c2[2] = D[5];
    return k + 9 * (size_t)nl + 6;
}

/* The blocks of node q's lower neighbours, in the pattern's order: the sum of the k
 * joining each to q (in model order) into S, 6 a neighbour; returns their count. */
static int lower_blocks(const part *pt, size_t q, double *S)
{
    const ctn_asm_gather *g = pt->a->gather;
    const int *order = g->order + g->inc_ptr[q];
    const ctn_asm_inc *inc = g->inc + g->inc_ptr[q];
    int n = g->inc_ptr[q + 1] - g->inc_ptr[q], r = 0, nl = 0;
    for (int s = g->adj_ptr[q]; g->adj[s] < (int)q; s++, nl++) {
        int p = g->adj[s];
        double *Sp = S + 6 * nl;
        for (int i = 0; i < 6; i++) Sp[i] = 0;
        while (r < n && inc[order[r]].nb >> 1 < p) r++;
        for (; r < n && inc[order[r]].nb >> 1 == p; r++)
            for (int i = 0; i < 6; i++) Sp[i] += pt->w[6 * order[r] + i];
    }
    return nl;
}

/* Column j of node q (a free direction) from Kx[k]: minus the blocks S of its nl lower
 * neighbours, then its diagonal block's rows i <= j. Inline with j constant, so that the
 * symmetric indexing folds. Returns the next position. */
static inline __attribute__((always_inline)) size_t column(const part *pt, size_t q, int j, const double *S,
                                                           int nl, const double D[6], size_t k)
{
    const ctn_asm_gather *g = pt->a->gather;
    const int *nb = g->adj + g->adj_ptr[q];
    double *Kx = pt->Kx;
    for (int l = 0; l < nl; l++) {
        unsigned fp = g->free[nb[l]] & 7u;
        const double *Sp = S + 6 * l;
        if (fp == 7) {                                  /* the common case: all free */
            for (int i = 0; i < 3; i++) Kx[k + (size_t)i] = -Sp[sym3[i][j]];
            k += 3;
            continue;
        }
        for (int i = 0; i < 3; i++)
            if (fp >> i & 1) Kx[k++] = -Sp[sym3[i][j]];
    }
    for (int i = 0; i <= j; i++)
        if (g->free[q] >> i & 1) Kx[k++] = D[sym3[i][j]];
    return k;
}

/* Node q's columns of the tangent from Kx[k], its free directions in order. */
static size_t node_columns(const part *pt, size_t q, const double D[6], size_t k)
{
    unsigned fq = pt->a->gather->free[q];
    int nl = lower_blocks(pt, q, pt->S);
    if (fq & 1) k = column(pt, q, 0, pt->S, nl, D, k);
    if (fq & 2) k = column(pt, q, 1, pt->S, nl, D, k);
    if (fq & 4) k = column(pt, q, 2, pt->S, nl, D, k);
    return k;
}

/* The columns of the nodes before q: the first equation of node q or a later one. */
static size_t columns_before(const ctn_asm *a, size_t q)
{
    for (; q < a->nn; q++)
        for (int j = 0; j < 3; j++) {
            int c = a->map.eq[3 * q + (size_t)j];
            if (c >= 0) return (size_t)c;
        }
    return a->ndof;
}

static void run_part(void *arg)
{
    part *pt = arg;
    size_t k = pt->k0, bad = SIZE_MAX;
    double U = 0;
    for (size_t i = 0; i < KEEP; i++) pt->keep[i].e = -1;   /* nothing kept yet */
    for (size_t qa = pt->q0; qa < pt->q1; qa += CHUNK) {
        if (pt->feed && qa > pt->q0 && (qa - pt->q0) % (CHUNK * FEED_CHUNKS) == 0)
            ctn_feed_publish(pt->feed, columns_before(pt->a, qa));
        size_t qb = qa + CHUNK < pt->q1 ? qa + CHUNK : pt->q1;
        eval_chunk(pt, qa, qb, &U, &bad);
        for (size_t q = qa; q < qb; q++) {
            if (pt->a->gather->free[q] & PLAIN) {
                k = plain_node(pt, q, k, &bad);
                continue;
            }
            double D[6] = { 0, 0, 0, 0, 0, 0 };
            node_elements(pt, q, D, &bad);
            if (pt->Kx) k = node_columns(pt, q, D, k);
        }
    }
    pt->U = U;                                          /* once: the parts share a line */
    pt->bad = bad;
}

/* Position in Kx of the first column of node q or a later one. */
static size_t first_value(const ctn_asm *a, size_t q)
{
    for (; q < a->nn; q++)
        for (int j = 0; j < 3; j++) {
            int c = a->map.eq[3 * q + (size_t)j];
            if (c >= 0) return (size_t)a->colptr[c];
        }
    return a->nnz;
}

int ctn_asm_gather_eval(const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx,
                        double *U, size_t *bad)
{
    const ctn_asm_gather *g = a->gather;
    part pt[2];
    int np = g->threads;
    for (int i = 0; i < np; i++) {
        size_t q0 = a->nn * (size_t)i / (size_t)np;
        pt[i] = (part){ a, d, mode, f, Kx, q0, a->nn * (size_t)(i + 1) / (size_t)np, Kx ? first_value(a, q0) : 0,
                        g->work + (size_t)i * work_stride(g), g->work + (size_t)i * work_stride(g) + (size_t)g->maxdeg * 6,
                        g->keep + (size_t)i * KEEP, 0.0, SIZE_MAX, NULL };
    }
    if (np == 2) ctn_thr_both(g->ctx, ctn_asm_threads(a), CTN_THR_ASSEMBLY, (double)a->nn, run_part, &pt[0], &pt[1]);
    else run_part(&pt[0]);
    *U = pt[0].U + (np == 2 ? pt[1].U : 0.0);
    *bad = np == 2 && pt[1].bad < pt[0].bad ? pt[1].bad : pt[0].bad;
    return *bad != SIZE_MAX;
}

int ctn_asm_eval_feed(const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx, double *U,
                        size_t *bad, ctn_feed *feed)
{
    const ctn_asm_gather *g = a->gather;
    part pt = { a, d, mode, f, Kx, 0, a->nn, Kx ? first_value(a, 0) : 0, g->work, g->work + (size_t)g->maxdeg * 6,
                g->keep, 0.0, SIZE_MAX, feed };
    run_part(&pt);
    ctn_feed_publish(feed, a->ndof);
    if (U) *U = pt.U;
    if (bad && pt.bad != SIZE_MAX) *bad = pt.bad;
    return pt.bad != SIZE_MAX;
}

int ctn_asm_gather_eval_nodes(const ctn_asm *a, const double *d, unsigned mode, size_t q0, size_t q1, double *f,
                              double *Kx, double *U, size_t *bad)
{
    const ctn_asm_gather *g = a->gather;
    part pt = { a, d, mode, f, Kx, q0, q1, 0, g->work, g->work + (size_t)g->maxdeg * 6, g->keep, 0.0, SIZE_MAX, NULL };
    run_part(&pt);
    *U = pt.U;
    *bad = pt.bad;
    return pt.bad != SIZE_MAX;
}
