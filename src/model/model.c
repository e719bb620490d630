/* Model: creation, destruction, origin tracking and growable arrays. */
#include "model/model.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

int ctn_array_reserve(ctn_ctx *ctx, void **v, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap) return CTN_OK;
    size_t cap2 = *cap ? *cap : 16;
    while (cap2 < need) cap2 *= 2;
    void *p = ctn_realloc(ctx, *v, cap2, size);
    if (!p) return CTN_ERR_NOMEM;
    *v = p;
    *cap = cap2;
    return CTN_OK;
}

int ctn_model_create(ctn_ctx *ctx, ctn_model **out)
{
    if (!out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_model_create: out is NULL");
    *out = ctn_calloc(ctx, 1, sizeof(ctn_model));
    if (!*out) return CTN_ERR_NOMEM;
    (*out)->ctx = ctx;
    return CTN_OK;
}

void ctn_model_destroy(ctn_model **m)
{
    if (!m || !*m) return;
    ctn_model *p = *m;
    ctn_free(p->nodes.v);
    ctn_free(p->materials.v);
    ctn_free(p->sections.v);
    ctn_free(p->elements.v);
    ctn_free(p->conn.v);
    ctn_free(p->ploads.v);
    ctn_free(p->mloads.v);
    ctn_free(p->pdisps.v);
    ctn_free(p->steps.v);
    ctn_free(p->hloads.v);
    ctn_free(p->cables.v);
    ctn_free(p->groups.v);
    ctn_free(p->tloads.v);
    ctn_free(p->lloads.v);
    ctn_free(p->cases.v);
    ctn_free(p->combos.v);
    ctn_free(p->terms.v);
    ctn_model_free_sets(p);
    ctn_free(p->etargets.v);
    ctn_free(p->densities.v);
    ctn_free(p->records.v);
    for (size_t i = 0; i < p->fns.n; i++) {
        ctn_free(p->fns.v[i].t);
        ctn_free(p->fns.v[i].v);
    }
    ctn_free(p->fns.v);
    ctn_free(p->dloads.v);
    ctn_free(p->removals.v);
    ctn_free(p->chart.v);
    ctn_idmap_free(&p->node_ids);
    ctn_idmap_free(&p->element_ids);
    ctn_free(p);
    *m = NULL;
}

int ctn_model_set_origin(ctn_model *m, const char *file, int line)
{
    if (!m) return CTN_ERR_INVALID;
    snprintf(m->file, sizeof m->file, "%s", file ? file : "");
    m->line = line;
    return CTN_OK;
}

int ctn_model_error(const ctn_model *m, int code, const char *fmt, ...)
{
    char msg[CTN_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (m->line > 0) return ctn_error_at(m->ctx, code, m->file, m->line, "%s", msg);
    return ctn_error(m->ctx, code, "%s", msg);
}

int ctn_model_find_section(const ctn_model *m, const char *name)
{
    for (size_t i = 0; i < m->sections.n; i++)
        if (!strcmp(m->sections.v[i].name, name)) return (int)i;
    return -1;
}

int ctn_model_find_material(const ctn_model *m, const char *name)
{
    for (size_t i = 0; i < m->materials.n; i++)
        if (!strcmp(m->materials.v[i].name, name)) return (int)i;
    return -1;
}

void ctn_spec_copy(void *dst, size_t dst_size, const void *src)
{
    size_t n = *(const size_t *)src;        /* the caller's sizeof */
    memcpy(dst, src, n < dst_size ? n : dst_size);
    *(size_t *)dst = dst_size;
}
