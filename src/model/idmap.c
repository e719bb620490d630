/* Open-addressing (linear probing) hash map of ids. */
#include "model/idmap.h"

#include <stdint.h>

static size_t slot_of(int id, size_t cap)
{
    uint32_t k = (uint32_t)id * 2654435761u;   /* Knuth multiplicative hash */
    return (size_t)k & (cap - 1);
}

void ctn_idmap_free(ctn_idmap *h)
{
    ctn_free(h->keys);
    ctn_free(h->vals);
    h->keys = h->vals = NULL;
    h->cap = h->n = 0;
}

int ctn_idmap_get(const ctn_idmap *h, int id)
{
    if (!h->cap) return -1;
    for (size_t s = slot_of(id, h->cap);; s = (s + 1) & (h->cap - 1)) {
        if (h->keys[s] == id) return h->vals[s];
        if (h->keys[s] == 0) return -1;
    }
}

static void put_unchecked(ctn_idmap *h, int id, int val)
{
    size_t s = slot_of(id, h->cap);
    while (h->keys[s]) s = (s + 1) & (h->cap - 1);
    h->keys[s] = id;
    h->vals[s] = val;
    h->n++;
}

static int grow(ctn_ctx *ctx, ctn_idmap *h, size_t need)
{
    size_t cap = h->cap ? 2 * h->cap : 64;
    while (cap < 2 * need) cap *= 2;
    ctn_idmap g = { ctn_calloc(ctx, cap, sizeof(int)), ctn_malloc(ctx, cap, sizeof(int)), cap, 0 };
    if (!g.keys || !g.vals) {
        ctn_idmap_free(&g);
        return CTN_ERR_NOMEM;
    }
    for (size_t s = 0; s < h->cap; s++)
        if (h->keys[s]) put_unchecked(&g, h->keys[s], h->vals[s]);
    ctn_idmap_free(h);
    *h = g;
    return CTN_OK;
}

int ctn_idmap_put(ctn_ctx *ctx, ctn_idmap *h, int id, int val)
{
    int rc = ctn_idmap_reserve(ctx, h, 1);
    if (rc) return rc;
    put_unchecked(h, id, val);
    return CTN_OK;
}

int ctn_idmap_reserve(ctn_ctx *ctx, ctn_idmap *h, size_t extra)
{
    if (2 * (h->n + extra) <= h->cap) return CTN_OK;
    return grow(ctx, h, h->n + extra);
}
