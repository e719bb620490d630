/* The buckling factors an analysis stores in a solution, and their accessors. */
#include "problem/solution.h"

ctn_buckles *ctn_buckles_create(ctn_ctx *ctx, size_t count, size_t nn)
{
    ctn_buckles *b = ctn_calloc(ctx, 1, sizeof *b);
    if (!b) return NULL;
    b->mode = ctn_calloc(ctx, count ? count : 1, sizeof *b->mode);
    b->shapes = ctn_calloc(ctx, nn && count ? 3 * nn * count : 1, sizeof(double));
    if (!b->mode || !b->shapes) {
        ctn_buckles_destroy(&b);
        return NULL;
    }
    b->sum.count = (int)count;
    for (size_t k = 0; k < count; k++) b->mode[k].shape = b->shapes + 3 * nn * k;
    return b;
}

void ctn_buckles_destroy(ctn_buckles **b)
{
    if (!b || !*b) return;
    ctn_free((*b)->mode);
    ctn_free((*b)->shapes);
    ctn_free(*b);
    *b = NULL;
}

size_t ctn_solution_buckling_count(const ctn_solution *s)
{
    return s && s->buckling ? (size_t)s->buckling->sum.count : 0;
}

int ctn_solution_buckling(const ctn_solution *s, size_t k, ctn_buckling_mode *out)
{
    if (!out || k >= ctn_solution_buckling_count(s)) return CTN_ERR_INVALID;
    *out = s->buckling->mode[k];
    return CTN_OK;
}

int ctn_solution_buckling_summary(const ctn_solution *s, ctn_buckling_summary *out)
{
    if (!s || !out || !s->buckling) return CTN_ERR_INVALID;
    *out = s->buckling->sum;
    return CTN_OK;
}
