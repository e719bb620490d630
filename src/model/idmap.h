/* Internal: map from positive int ids to indices. Ids numbered densely from 1 (the
 * usual case: a mesh generator's 1 .. N) live in a direct table, dense[id - 1]; an id
 * far beyond the count of ids stored (more than twice it, plus CTN_IDMAP_SLACK) goes to
 * an open-addressing hash, so memory stays linear in the count whatever the ids are. A
 * get looks in both. */
#ifndef CTN_MODEL_IDMAP_H
#define CTN_MODEL_IDMAP_H

#include "core/ctx.h"

#define CTN_IDMAP_SLACK 1024

typedef struct ctn_idmap {
    int *dense;      /* dense[id - 1] = index + 1 of the ids 1 .. ndense; 0 = absent */
    size_t ndense;
    int *keys;       /* the hash: 0 = empty slot */
    int *vals;
    size_t cap, n;   /* cap is a power of two; n ids in the hash */
    size_t count;    /* ids stored in all */
} ctn_idmap;

void ctn_idmap_free(ctn_idmap *h);
/* Index stored for id, or -1. */
int ctn_idmap_get(const ctn_idmap *h, int id);
/* Make room for `extra` more ids, so that as many puts cannot fail. */
int ctn_idmap_reserve(ctn_ctx *ctx, ctn_idmap *h, size_t extra);
/* Insert (id > 0 must be absent); 0 or CTN_ERR_NOMEM. */
int ctn_idmap_put(ctn_ctx *ctx, ctn_idmap *h, int id, int val);

#endif
