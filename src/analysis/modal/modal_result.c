/* The modes a modal analysis stores in a solution, and their accessors. */
#include "problem/solution.h"

ctn_modes *ctn_modes_create(ctn_ctx *ctx, size_t count, size_t nn)
{
    ctn_modes *m = ctn_calloc(ctx, 1, sizeof *m);
    if (!m) return NULL;
    m->mode = ctn_calloc(ctx, count, sizeof *m->mode);
    m->shapes = ctn_calloc(ctx, 3 * nn * count, sizeof(double));
    if (!m->mode || !m->shapes) {
        ctn_modes_destroy(&m);
        return NULL;
    }
    m->sum.count = (int)count;
    for (size_t k = 0; k < count; k++) m->mode[k].shape = m->shapes + 3 * nn * k;
    return m;
}

void ctn_modes_destroy(ctn_modes **m)
{
    if (!m || !*m) return;
    ctn_free((*m)->mode);
    ctn_free((*m)->shapes);
    ctn_free((*m)->rshapes);
    ctn_free(*m);
    *m = NULL;
}

size_t ctn_solution_mode_count(const ctn_solution *s)
{
    return s && s->modes ? (size_t)s->modes->sum.count : 0;
}

int ctn_solution_mode(const ctn_solution *s, size_t k, ctn_mode *out)
{
    if (!out || k >= ctn_solution_mode_count(s)) return CTN_ERR_INVALID;
    *out = s->modes->mode[k];
    return CTN_OK;
}

int ctn_solution_modal_summary(const ctn_solution *s, ctn_modal_summary *out)
{
    if (!s || !out || !s->modes) return CTN_ERR_INVALID;
    *out = s->modes->sum;
    return CTN_OK;
}

const char *ctn_mode_kind_name(ctn_mode_kind k)
{
    switch (k) {
    case CTN_MODE_VIBRATION: return "vibration";
    case CTN_MODE_ZERO: return "zero";
    case CTN_MODE_UNSTABLE: return "unstable";
    default: return "unknown";
    }
}
