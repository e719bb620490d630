/* Shared by benchmarks on a model file: the model read, its assembler, and the tangent at
 * the reference state (d = 0) in a malloc'ed array of the pattern's values. Status; on
 * failure the caller frees what was made (the pointers stay NULL otherwise). */
#ifndef CTN_BENCH_TANGENT_H
#define CTN_BENCH_TANGENT_H

#include "assemble/asm.h"

#include <stdlib.h>

static inline int bench_tangent(ctn_ctx *ctx, const char *path, ctn_model **m, ctn_asm **a, double **Kx)
{
    int rc = ctn_read_file(ctx, path, m, NULL);
    if (!rc) rc = ctn_asm_create(ctx, *m, a);
    if (rc) return rc;
    double *d = calloc((*a)->map.nstate, sizeof *d), *f = calloc((*a)->map.nstate, sizeof *f);
    *Kx = calloc((*a)->nnz, sizeof **Kx);
    rc = d && f && *Kx ? 0 : CTN_ERR_NOMEM;
    if (!rc && ctn_asm_eval(*a, d, 0, f, *Kx, NULL, NULL))
        rc = ctn_error(ctx, CTN_ERR_MODEL, "%s: an element has zero length in the reference state", path);
    free(d);
    free(f);
    return rc;
}

#endif
