/* Sparsity pattern of the tangent (upper triangle, compressed columns) from the node
 * adjacency graph (the nodes of an element are all adjacent), and the element-to-slot
 * scatter map. Equations are numbered node by node, so the rows of a column come out
 * sorted by walking sorted node neighbours. */
#include "assemble/asm.h"

#include <stdlib.h>

static int cmp_int(const void *x, const void *y)
{
    int p = *(const int *)x, q = *(const int *)y;
    return (p > q) - (p < q);
}

/* Neighbour entries an element adds: each node sees the others. */
static size_t pair_count(const ctn_asm *a)
{
    size_t n = 0;
    for (size_t k = 0; k < a->nblocks; k++)
        n += a->blocks[k].count * (size_t)a->blocks[k].nnodes * (size_t)(a->blocks[k].nnodes - 1);
    return n;
}

/* For every element, node p sees node q (count: adj == NULL, then fill). */
static void each_pair(const ctn_asm *a, int *ptr, int *fill, int *adj)
{
    for (size_t k = 0; k < a->nblocks; k++) {
        const ctn_asm_block *b = &a->blocks[k];
        const int *conn = ctn_elem_nodes(a->m, b->e0);
        if (b->nnodes == 2) {                           /* the common shape */
            for (size_t i = 0; i < 2 * b->count; i += 2) {
                int p = conn[i], q = conn[i + 1];
                if (adj) {
                    adj[fill[p]++] = q;
                    adj[fill[q]++] = p;
                } else {
                    ptr[p + 1]++;
                    ptr[q + 1]++;
                }
            }
            continue;
        }
        for (size_t i = 0; i < b->count; i++, conn += b->nnodes)
            for (int s = 0; s < b->nnodes; s++)
                for (int t = 0; t < b->nnodes; t++) {
                    if (s == t) continue;
                    if (adj) adj[fill[conn[s]]++] = conn[t];
                    else ptr[conn[s] + 1]++;
                }
    }
}

/* Node adjacency (self included), each list sorted and unique: CSR ptr/adj. */
static int adjacency(ctn_ctx *ctx, const ctn_asm *a, int **ptr_out, int **adj_out)
{
    size_t pairs = pair_count(a);
    if (a->nn + pairs > 0x7fffffff) return ctn_error(ctx, CTN_ERR_MODEL, "model too large: %zu node adjacencies", pairs);
    int *ptr = ctn_calloc(ctx, a->nn + 1, sizeof(int));
    int *adj = ctn_malloc(ctx, a->nn + pairs, sizeof(int));
    int *fill = ctn_malloc(ctx, a->nn ? a->nn : 1, sizeof(int));
    if (!ptr || !adj || !fill) goto fail;
    each_pair(a, ptr, NULL, NULL);
    for (size_t i = 0; i < a->nn; i++) ptr[i + 1] += ptr[i] + 1;   /* +1: self */
    for (size_t i = 0; i < a->nn; i++) {
        adj[ptr[i]] = (int)i;
        fill[i] = ptr[i] + 1;
    }
    each_pair(a, NULL, fill, adj);
    int w = 0, start = 0;                                /* sort, unique, compact */
    for (size_t i = 0; i < a->nn; i++) {
        int end = ptr[i + 1], last = -1;
        qsort(adj + start, (size_t)(end - start), sizeof(int), cmp_int);
        ptr[i] = w;
        for (int k = start; k < end; k++)
            if (adj[k] != last) last = adj[w++] = adj[k];
        start = end;
    }
    ptr[a->nn] = w;
    ctn_free(fill);
    *ptr_out = ptr;
    *adj_out = adj;
    return CTN_OK;
fail:
    ctn_free(ptr); ctn_free(adj); ctn_free(fill);
    return CTN_ERR_NOMEM;
}

/* Walk column structure: count (rowind == NULL) or fill. Returns the entry count.
 * u = the DOFs of every node when uniform (a constant the compiler unrolls), else 0. */
static inline size_t walk(const ctn_asm *a, const int *ptr, const int *adj, int *rowind, int u)
{
    const ctn_dofmap *map = &a->map;
    size_t nz = 0;
    for (size_t q = 0; q < a->nn; q++) {
        int nq = u ? u : ctn_dofmap_count(map, q);
        for (int k = 0; k < nq; k++) {
            int c = map->eq[(u ? (size_t)u * q : ctn_dofmap_node(map, q)) + (size_t)k];
            if (c < 0) continue;
            for (int t = ptr[q]; t < ptr[q + 1] && adj[t] <= (int)q; t++) {
                size_t p = (size_t)adj[t], s = u ? (size_t)u * p : ctn_dofmap_node(map, p);
                int np = u ? u : ctn_dofmap_count(map, p);
                for (int j = 0; j < np; j++) {
                    int r = map->eq[s + (size_t)j];
                    if (r < 0 || r > c) continue;
                    if (rowind) rowind[nz] = r;
                    nz++;
                }
            }
            if (rowind) a->colptr[c + 1] = (int)nz;
        }
    }
    return nz;
}

static size_t walk_columns(const ctn_asm *a, const int *ptr, const int *adj, int *rowind)
{
    return a->map.uniform == 3 ? walk(a, ptr, adj, rowind, 3) : walk(a, ptr, adj, rowind, 0);
}

int ctn_asm_pattern(ctn_ctx *ctx, ctn_asm *a)
{
    int *ptr = NULL, *adj = NULL, rc = adjacency(ctx, a, &ptr, &adj);
    if (rc) return rc;
    size_t nz = walk_columns(a, ptr, adj, NULL);
    if (nz > 0x7fffffff) {
        rc = ctn_error(ctx, CTN_ERR_MODEL, "model too large: %zu non-zeros in the tangent", nz);
        goto done;
    }
    a->colptr = ctn_calloc(ctx, a->ndof + 1, sizeof(int));
    a->rowind = ctn_malloc(ctx, nz ? nz : 1, sizeof(int));
    if (!a->colptr || !a->rowind) { rc = CTN_ERR_NOMEM; goto done; }
    a->nnz = walk_columns(a, ptr, adj, a->rowind);
    rc = ctn_asm_gather_build(ctx, a, &ptr, &adj);
done:
    ctn_free(ptr);
    ctn_free(adj);
    return rc;
}

/* Position of row r in column c, -1 if absent (binary search, rows sorted). */
static int find_slot(const ctn_asm *a, int r, int c)
{
    int lo = a->colptr[c], hi = a->colptr[c + 1] - 1;
    while (lo <= hi) {
        int mid = lo + (hi - lo) / 2;
        if (a->rowind[mid] == r) return mid;
        if (a->rowind[mid] < r) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

/* Equation numbers of an element's DOFs (-1: fixed). */
static void element_eqs(const ctn_asm *a, const ctn_asm_block *b, const int *nd, int *g)
{
    int ndn = b->ops->ndof_node;
    for (int k = 0; k < b->nedof; k++)
        g[k] = a->map.eq[ctn_dofmap_node(&a->map, (size_t)nd[k / ndn]) + (size_t)(k % ndn)];
}

static void block_slots(const ctn_asm *a, const ctn_asm_block *b, unsigned char *seen, int *g)
{
    const int *conn = ctn_elem_nodes(a->m, b->e0);
    int n = b->nedof;
    for (size_t e = 0; e < b->count; e++, conn += b->nnodes) {
        int *s = a->slot + b->slot0 + e * (size_t)b->nslots;
        element_eqs(a, b, conn, g);
        for (int i = 0; i < n; i++)
            for (int j = i; j < n; j++) {
                int r = g[i] < g[j] ? g[i] : g[j], c = g[i] < g[j] ? g[j] : g[i];
                int k = r < 0 ? -1 : find_slot(a, r, c);
                if (k >= 0 && !seen[k] && !a->gather) {   /* first to reach it: assign */
                    seen[k] = 1;
                    k = -(k + 2);
                }
                s[ctn_packed_index(n, i, j)] = k;
            }
    }
}

int ctn_asm_scatter_map(ctn_ctx *ctx, ctn_asm *a)
{
    size_t nslots = 0;
    for (size_t k = 0; k < a->nblocks; k++) nslots += a->blocks[k].count * (size_t)a->blocks[k].nslots;
    unsigned char *seen = ctn_calloc(ctx, a->nnz ? a->nnz : 1, 1);
    int *g = ctn_malloc(ctx, (size_t)a->maxdof + 1, sizeof(int));
    a->slot = ctn_malloc(ctx, nslots ? nslots : 1, sizeof(int));
    if (a->slot && seen && g)
        for (size_t k = 0; k < a->nblocks; k++) block_slots(a, &a->blocks[k], seen, g);
    int rc = a->slot && seen && g ? CTN_OK : CTN_ERR_NOMEM;
    ctn_free(seen);
    ctn_free(g);
    return rc;
}
