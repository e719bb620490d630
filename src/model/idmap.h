/* Internal: open-addressing hash map from positive int ids to indices. */
#ifndef CTN_MODEL_IDMAP_H
#define CTN_MODEL_IDMAP_H

#include "core/ctx.h"

typedef struct ctn_idmap {
    int *keys;       /* 0 = empty slot */
    int *vals;
    size_t cap, n;   /* cap is a power of two */
} ctn_idmap;

void ctn_idmap_free(ctn_idmap *h);
/* Index stored for id, or -1. */
int ctn_idmap_get(const ctn_idmap *h, int id);
/* Make room for `extra` more ids, so that as many puts cannot fail. */
int ctn_idmap_reserve(ctn_ctx *ctx, ctn_idmap *h, size_t extra);
/* Insert (id > 0 must be absent); 0 or CTN_ERR_NOMEM. */
int ctn_idmap_put(ctn_ctx *ctx, ctn_idmap *h, int id, int val);

#endif
