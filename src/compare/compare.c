/* The comparison object: creation, access, names of the forms. */
#include "compare/cmp.h"
#include "model/model.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static const char *const keys[CTN_FORM_COUNT] = { "fea", "catenary", "elastic_catenary", "parabola",
                                                  "elastic_parabola", "funicular", "elastic_funicular" };
static const char *const names[CTN_FORM_COUNT] = { "FEA", "catenary", "elastic catenary", "parabola",
                                                   "elastic parabola", "funicular", "elastic funicular" };

const char *ctn_form_key(ctn_form f) { return f >= 0 && f < CTN_FORM_COUNT ? keys[f] : ""; }
const char *ctn_form_name(ctn_form f) { return f >= 0 && f < CTN_FORM_COUNT ? names[f] : ""; }

double ctn_compare_rel(double a, double b) { return b != 0 ? (a - b) / b : 0; }

int ctn_cmp_error(ctn_ctx *ctx, const char *file, int code, const char *fmt, ...)
{
    char msg[CTN_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (!file || !*file) return ctn_error(ctx, code, "%s", msg);
    return ctn_error(ctx, code, "%s: %s", file, msg);
}

static void units(ctn_span *s, const ctn_model *m)
{
    snprintf(s->force_unit, sizeof s->force_unit, "%s", ctn_model_force_unit(m));
    snprintf(s->length_unit, sizeof s->length_unit, "%s", ctn_model_length_unit(m));
    s->mpa = ctn_model_mpa_factor(m);
}

int ctn_compare_create(ctn_ctx *ctx, const ctn_model *m, ctn_compare **out)
{
    if (!out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_compare_create: out is NULL");
    *out = NULL;
    if (!m) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_compare_create: no model");
    ctn_compare *c = ctn_calloc(ctx, 1, sizeof *c);
    if (!c) return CTN_ERR_NOMEM;
    c->ctx = ctx;
    snprintf(c->file, sizeof c->file, "%s", ctn_model_file(m));
    units(&c->span, m);
    for (size_t h = 0; h < m->hloads.n; h++) c->follow |= !m->hloads.v[h].reference;
    int rc = ctn_model_validate(m);                 /* file:line messages for bad models */
    if (!rc) rc = ctn_model_targets_found(ctx, m);  /* a target's length is found first */
    if (!rc) rc = ctn_cmp_find_span(c, m);
    if (!rc && c->span.n == 1 && ctn_element_family(m->elements.v[c->elem[0]].type) == &ctn_catenary2_ops) {
        c->catenary = 1;                            /* one catenary element */
        ctn_catenary2_ops.setup(m, c->elem[0], &c->catp);
    }
    if (!rc) rc = ctn_cmp_span_loads(c, m);
    if (!rc) rc = ctn_cmp_solve_forms(c);
    if (rc) ctn_compare_destroy(&c);
    *out = c;
    return rc;
}

void ctn_compare_destroy(ctn_compare **c)
{
    if (!c || !*c) return;
    ctn_compare *p = *c;
    ctn_free(p->node);
    ctn_free(p->elem);
    ctn_free(p->l0);
    ctn_free(p->EA);
    ctn_free(p->Xref);
    ctn_free(p->kink);
    ctn_free(p->P);
    ctn_free(p->Pref);
    ctn_free(p->poly[0]);
    ctn_free(p->poly[1]);
    ctn_free(p->fea);
    ctn_free(p);
    *c = NULL;
}

const ctn_span *ctn_compare_span(const ctn_compare *c) { return c ? &c->span : NULL; }

int ctn_compare_has(const ctn_compare *c, ctn_form f)
{
    return c && f >= 0 && f < CTN_FORM_COUNT && (c->has >> f & 1u);
}

int ctn_compare_get(const ctn_compare *c, ctn_form f, ctn_compare_values *out)
{
    if (!out) return CTN_ERR_INVALID;
    memset(out, 0, sizeof *out);
    if (!ctn_compare_has(c, f)) return CTN_ERR_DOMAIN;
    *out = c->v[f];
    return CTN_OK;
}
