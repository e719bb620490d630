/* Ids to indices: a direct table for dense ids, linear probing for the others. */
#include "model/idmap.h"

#include <limits.h>
#include <stdint.h>
#include <string.h>

static size_t slot_of(int id, size_t cap)
{
    uint32_t k = (uint32_t)id * 2654435761u;   /* Knuth multiplicative hash */
    return (size_t)k & (cap - 1);
}

void ctn_idmap_free(ctn_idmap *h)
{
    ctn_free(h->dense);
    ctn_free(h->keys);
    ctn_free(h->vals);
    memset(h, 0, sizeof *h);
}

int ctn_idmap_get(const ctn_idmap *h, int id)
{
    if (id > 0 && (size_t)id <= h->ndense && h->dense[id - 1]) return h->dense[id - 1] - 1;
    if (!h->cap) return -1;
    for (size_t s = slot_of(id, h->cap);; s = (s + 1) & (h->cap - 1)) {
        if (h->keys[s] == id) return h->vals[s];
        if (h->keys[s] == 0) return -1;
    }
}

static void hash_put(ctn_idmap *h, int id, int val)
{
    size_t s = slot_of(id, h->cap);
    while (h->keys[s]) s = (s + 1) & (h->cap - 1);
    h->keys[s] = id;
    h->vals[s] = val;
    h->n++;
}

/* The hash doubled until it holds need ids at most half full. */
static int hash_grow(ctn_ctx *ctx, ctn_idmap *h, size_t need)
{
    size_t cap = h->cap ? 2 * h->cap : 64;
    while (cap < 2 * need) cap *= 2;
    ctn_idmap g = { NULL, 0, ctn_calloc(ctx, cap, sizeof(int)), ctn_malloc(ctx, cap, sizeof(int)), cap, 0, 0 };
    if (!g.keys || !g.vals) {
        ctn_idmap_free(&g);
        return CTN_ERR_NOMEM;
    }
    for (size_t s = 0; s < h->cap; s++)
        if (h->keys[s]) hash_put(&g, h->keys[s], h->vals[s]);
    ctn_free(h->keys);
    ctn_free(h->vals);
    h->keys = g.keys;
    h->vals = g.vals;
    h->cap = cap;
    return CTN_OK;
}

/* Cover ids 1 .. id with the direct table (doubling). */
static int dense_cover(ctn_ctx *ctx, ctn_idmap *h, size_t id)
{
    if (id <= h->ndense) return CTN_OK;
    size_t n = h->ndense ? 2 * h->ndense : 64;
    while (n < id) n *= 2;
    int *d = ctn_realloc(ctx, h->dense, n, sizeof(int));
    if (!d) return CTN_ERR_NOMEM;
    memset(d + h->ndense, 0, (n - h->ndense) * sizeof(int));
    h->dense = d;
    h->ndense = n;
    return CTN_OK;
}

/* Into the direct table when id is within twice the count (plus slack), else into the
 * hash. */
int ctn_idmap_put(ctn_ctx *ctx, ctn_idmap *h, int id, int val)
{
    if (id <= 0 || val < 0 || val == INT_MAX) return ctn_error(ctx, CTN_ERR_INVALID, "id map: bad entry");
    int rc;
    if ((size_t)id <= 2 * h->count + CTN_IDMAP_SLACK) {
        if ((rc = dense_cover(ctx, h, (size_t)id))) return rc;
        h->dense[id - 1] = val + 1;
    } else {
        if ((rc = ctn_idmap_reserve(ctx, h, 1))) return rc;
        hash_put(h, id, val);
    }
    h->count++;
    return CTN_OK;
}

/* Room in both parts: the direct table up to where the next `extra` ids may land in it,
 * the hash for `extra` more. */
int ctn_idmap_reserve(ctn_ctx *ctx, ctn_idmap *h, size_t extra)
{
    int rc = dense_cover(ctx, h, 2 * (h->count + extra) + CTN_IDMAP_SLACK);
    if (rc || 2 * (h->n + extra) <= h->cap) return rc;
    return hash_grow(ctx, h, h->n + extra);
}
