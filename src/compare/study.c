/* The length study: the span re-solved for many unstressed lengths. */
#include "compare/study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void ctn_study_options_default(ctn_study_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->sweep = 64;
}

static int by_length(const void *a, const void *b)
{
    double x = ((const ctn_study_row *)a)->L0, y = ((const ctn_study_row *)b)->L0;
    return (x > y) - (x < y);
}

/* The lengths: marked ones, then the sweep; sorted, duplicates merged. */
static int lengths(ctn_ctx *ctx, ctn_study *st, const ctn_study_options *o, double L0base)
{
    double C = hypot(st->span.l, st->span.h);
    double from = o->sweep_from > 0 ? o->sweep_from : C * (1 + 2e-4);
    double to = o->sweep_to > 0 ? o->sweep_to : 1.5 * C;
    size_t nm = o->nlengths ? o->nlengths : 1, k = 0;
    if (o->sweep && (!(from > C) || !(to > from) || !isfinite(to)))
        return ctn_error(ctx, CTN_ERR_INVALID, "the sweep must run from above the chord (%.10g) to a larger "
                         "length (got %.10g to %.10g)", C, from, to);
    st->row = ctn_calloc(ctx, nm + o->sweep, sizeof *st->row);
    if (!st->row) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < nm; i++, k++) {
        st->row[k].L0 = o->nlengths ? o->lengths[i] : L0base;
        st->row[k].marked = 1;
        if (!(st->row[k].L0 > 0) || !isfinite(st->row[k].L0))
            return ctn_error(ctx, CTN_ERR_INVALID, "lengths must be positive and finite (got %g)", st->row[k].L0);
    }
    for (size_t i = 0; i < o->sweep; i++, k++)
        st->row[k].L0 = o->sweep > 1 ? C + (from - C) * pow((to - C) / (from - C), (double)i / (double)(o->sweep - 1)) : from;
    qsort(st->row, k, sizeof *st->row, by_length);
    st->n = 0;
    for (size_t i = 0; i < k; i++) {
        if (st->n && fabs(st->row[i].L0 - st->row[st->n - 1].L0) <= 1e-12 * st->row[i].L0) {
            st->row[st->n - 1].marked |= st->row[i].marked;
            continue;
        }
        st->row[st->n++] = st->row[i];
    }
    return CTN_OK;
}

/* Solve the span at length row->L0 on n cable elements (0: one catenary element) and
 * fill the row's outcome and the values of every form. */
static int solve_length(ctn_ctx *ctx, const ctn_model *base, const ctn_solve_options *opt, const ctn_span *sp, size_t n,
                        ctn_study_row *row)
{
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_compare *c = NULL;
    ctn_solve_summary sum;
    int rc = ctn_cmp_build(ctx, base, sp, row->L0, n, sp->strain, &m);
    if (!rc) rc = ctn_cmp_solve(ctx, m, opt, 0, &s, &row->fallback);
    if (!rc) rc = ctn_compare_create(ctx, m, &c);
    if (!rc) {
        ctn_solution_summary(s, &sum);
        row->reason = sum.reason;
        row->iterations = sum.iterations;
        int fea = sum.reason == CTN_CONVERGED ? ctn_compare_set_fea(c, s) : CTN_OK;
        if (fea == CTN_ERR_NOMEM) rc = fea;
        else if (fea) ctn_ctx_clear(ctx);          /* no FEA values: the row says so */
        for (int f = 0; f < CTN_FORM_COUNT; f++)
            if (!ctn_compare_get(c, (ctn_form)f, &row->v[f])) row->present |= 1u << f;
    }
    ctn_compare_destroy(&c);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    return rc;
}

/* One row: the span's mesh, or one catenary element (and the mesh beside it). */
static int solve_row(ctn_ctx *ctx, const ctn_model *base, const ctn_solve_options *opt, const ctn_study *st,
                     ctn_study_row *row)
{
    if (!st->mesh) return solve_length(ctx, base, opt, &st->span, st->catenary ? 0 : st->span.n, row);
    ctn_study_row mesh = { .L0 = row->L0 };
    int rc = solve_length(ctx, base, opt, &st->span, st->span.n, &mesh);
    if (!rc) rc = solve_length(ctx, base, opt, &st->span, 0, row);
    row->mesh_reason = mesh.reason;
    row->has_mesh = (mesh.present & 1u << CTN_FORM_FEA) != 0;
    row->mesh = mesh.v[CTN_FORM_FEA];
    return rc;
}

/* What the rows are solved on: one catenary element for a catenary span or when asked
 * (the mesh beside it), which needs a span under self-weight only. */
static int element_kind(ctn_ctx *ctx, ctn_study *st, const ctn_compare *c, ctn_study_element element)
{
    if (element != CTN_STUDY_MESH && element != CTN_STUDY_CATENARY)
        return ctn_error(ctx, CTN_ERR_INVALID, "ctn_study_run: unknown element kind %d", (int)element);
    st->catenary = c->catenary || element == CTN_STUDY_CATENARY;
    st->mesh = st->catenary && !c->catenary;
    if (st->catenary && (c->span.loads & CTN_SPAN_HLOAD))
        return ctn_cmp_error(ctx, c->file, CTN_ERR_MODEL, "a catenary element carries its own weight only: a span under "
                             "hload cannot be studied on one");
    return CTN_OK;
}

static int copy_claims(ctn_ctx *ctx, ctn_study *st, const ctn_study_options *o)
{
    if (!o->nclaims) return CTN_OK;
    if (!o->claims) return ctn_error(ctx, CTN_ERR_INVALID, "claims: NULL array");
    st->claims = ctn_malloc(ctx, 2 * o->nclaims, sizeof *st->claims);
    if (!st->claims) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < 2 * o->nclaims; i++)
        if (!isfinite(st->claims[i] = o->claims[i]) || !(o->claims[i] > 0))
            return ctn_error(ctx, CTN_ERR_INVALID, "claims must be positive and finite");
    st->nclaims = o->nclaims;
    snprintf(st->claims_title, sizeof st->claims_title, "%s", o->claims_title ? o->claims_title : "reference points");
    return CTN_OK;
}

int ctn_study_run(ctn_ctx *ctx, const ctn_model *base, const ctn_study_options *opt,
                  ctn_study **out)
{
    if (!out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_study_run: out is NULL");
    *out = NULL;
    ctn_study_options def;
    if (!opt) ctn_study_options_default(&def), opt = &def;
    if (!base || (opt->nlengths && !opt->lengths)) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_study_run: bad arguments");
    ctn_compare *c = NULL;
    ctn_study *st = ctn_calloc(ctx, 1, sizeof *st);
    int rc = st ? ctn_compare_create(ctx, base, &c) : CTN_ERR_NOMEM;
    if (!rc && (c->span.loads & CTN_SPAN_POINT))
        rc = ctn_cmp_error(ctx, c->file, CTN_ERR_MODEL, "the study needs a span under self-weight or hload, not point loads");
    if (!rc) st->span = c->span;
    if (!rc) rc = element_kind(ctx, st, c, opt->element);
    if (!rc) rc = lengths(ctx, st, opt, c->span.L0);
    if (!rc) rc = copy_claims(ctx, st, opt);
    for (size_t i = 0; !rc && i < st->n; i++) rc = solve_row(ctx, base, opt->solve, st, &st->row[i]);
    ctn_compare_destroy(&c);
    if (rc) ctn_study_destroy(&st);
    *out = st;
    return rc;
}

void ctn_study_destroy(ctn_study **s)
{
    if (!s || !*s) return;
    ctn_free((*s)->row);
    ctn_free((*s)->claims);
    ctn_free(*s);
    *s = NULL;
}

const ctn_span *ctn_study_span(const ctn_study *s) { return s ? &s->span : NULL; }
size_t ctn_study_count(const ctn_study *s) { return s ? s->n : 0; }
ctn_study_element ctn_study_element_kind(const ctn_study *s)
{
    return s && s->catenary ? CTN_STUDY_CATENARY : CTN_STUDY_MESH;
}
const ctn_study_row *ctn_study_row_at(const ctn_study *s, size_t i) { return s && i < s->n ? &s->row[i] : NULL; }
