/* Sparsity pattern of the tangent (upper triangle, compressed columns) from the node
 * adjacency graph, and the element-to-slot scatter map. Equations are numbered in node
 * order, so the rows of a column come out sorted by walking sorted node neighbours. */
#include "assemble/asm.h"

#include <stdlib.h>

static int cmp_int(const void *x, const void *y)
{
    int p = *(const int *)x, q = *(const int *)y;
    return (p > q) - (p < q);
}

/* Node adjacency (self included), each list sorted and unique: CSR ptr/adj. */
static int adjacency(ctn_ctx *ctx, const ctn_asm *a, int **ptr_out, int **adj_out)
{
    const ctn_model *m = a->m;
    int *ptr = ctn_calloc(ctx, a->nn + 1, sizeof(int));
    int *adj = ctn_malloc(ctx, a->nn + 2 * a->ne, sizeof(int));
    int *fill = ctn_malloc(ctx, a->nn, sizeof(int));
    if (!ptr || !adj || !fill) goto fail;
    for (size_t e = 0; e < a->ne; e++) {
        ptr[m->elements.v[e].node[0] + 1]++;
        ptr[m->elements.v[e].node[1] + 1]++;
    }
    for (size_t i = 0; i < a->nn; i++) ptr[i + 1] += ptr[i] + 1;   /* +1: self */
    for (size_t i = 0; i < a->nn; i++) {
        adj[ptr[i]] = (int)i;
        fill[i] = ptr[i] + 1;
    }
    for (size_t e = 0; e < a->ne; e++) {
        int p = m->elements.v[e].node[0], q = m->elements.v[e].node[1];
        adj[fill[p]++] = q;
        adj[fill[q]++] = p;
    }
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

/* Walk column structure: count (rowind == NULL) or fill. Returns the entry count. */
static size_t walk_columns(const ctn_asm *a, const int *ptr, const int *adj, int *rowind)
{
    size_t nz = 0;
    for (size_t q = 0; q < a->nn; q++)
        for (int k = 0; k < 3; k++) {
            int c = a->eq[3 * q + k];
            if (c < 0) continue;
            for (int t = ptr[q]; t < ptr[q + 1] && adj[t] <= (int)q; t++) {
                for (int j = 0; j < 3; j++) {
                    int r = a->eq[3 * adj[t] + j];
                    if (r < 0 || r > c) continue;
                    if (rowind) rowind[nz] = r;
                    nz++;
                }
            }
            if (rowind) a->colptr[c + 1] = (int)nz;
        }
    return nz;
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

int ctn_asm_scatter_map(ctn_ctx *ctx, ctn_asm *a)
{
    unsigned char *seen = ctn_calloc(ctx, a->nnz ? a->nnz : 1, 1);
    a->slot = ctn_malloc(ctx, a->ne, CTN_ESLOTS * sizeof(int));
    if (!a->slot || !seen) {
        ctn_free(seen);
        return CTN_ERR_NOMEM;
    }
    for (size_t e = 0; e < a->ne; e++) {
        const int *nd = a->m->elements.v[e].node;
        int g[CTN_EDOF], *s = a->slot + e * CTN_ESLOTS;
        for (int k = 0; k < CTN_EDOF; k++) g[k] = a->eq[3 * nd[k / 3] + k % 3];
        for (int i = 0; i < CTN_EDOF; i++)
            for (int j = i; j < CTN_EDOF; j++) {
                int r = g[i] < g[j] ? g[i] : g[j], c = g[i] < g[j] ? g[j] : g[i];
                int k = r < 0 ? -1 : find_slot(a, r, c);
                if (k >= 0 && !seen[k]) {                 /* first to reach it: assign */
                    seen[k] = 1;
                    k = -(k + 2);
                }
                s[ctn_asm_local_slot(i, j)] = k;
            }
    }
    ctn_free(seen);
    return CTN_OK;
}
