/* Mesh convergence: FEA with engineering strain against the elastic catenary. */
#include "compare/cmp.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct ctn_convergence {
    ctn_span span;
    ctn_compare_values ref;    /* elastic catenary */
    size_t n;
    ctn_convergence_row *row;
    const ctn_solve_options *opt; /* of the FEA solves (during the run) */
};

static int by_n(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return (x > y) - (x < y);
}

static double rel_err(double a, double b) { return fabs(ctn_compare_rel(a, b)); }

/* Solve the span with row->n elements and fill the row. */
static int solve_row(ctn_ctx *ctx, const ctn_model *base, ctn_convergence *cv, ctn_convergence_row *row)
{
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_compare *c = NULL;
    ctn_solve_summary sum;
    int fallback = 0, rc = ctn_cmp_build(ctx, base, &cv->span, cv->span.L0, row->n, CTN_STRAIN_ENGINEERING, &m);
    if (!rc) rc = ctn_cmp_solve(ctx, m, cv->opt, 1e-12, &s, &fallback);
    if (!rc) rc = ctn_compare_create(ctx, m, &c);
    if (!rc) {
        ctn_solution_summary(s, &sum);
        row->reason = sum.reason;
        row->iterations = sum.iterations;
        int fea = sum.reason == CTN_CONVERGED ? ctn_compare_set_fea(c, s) : CTN_ERR_DOMAIN;
        if (fea == CTN_ERR_NOMEM) rc = fea;
        else if (fea) ctn_ctx_clear(ctx), row->reason = sum.reason == CTN_CONVERGED ? CTN_DIVERGED_NANORINF : sum.reason;
        else ctn_compare_get(c, CTN_FORM_FEA, &row->fea);
    }
    if (!rc && row->reason == CTN_CONVERGED) {
        row->err_sag = rel_err(row->fea.sag, cv->ref.sag);
        row->err_T = rel_err(row->fea.T_max, cv->ref.T_max);
        row->err_H = rel_err(row->fea.H, cv->ref.H);
    }
    ctn_compare_destroy(&c);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    return rc;
}

/* Reference and checks from the base model. */
static int setup(ctn_ctx *ctx, const ctn_model *base, ctn_convergence *cv)
{
    ctn_compare *c = NULL;
    int rc = ctn_compare_create(ctx, base, &c);
    if (!rc && c->span.loads != CTN_SPAN_WEIGHT)
        rc = ctn_cmp_error(ctx, c->file, CTN_ERR_MODEL, "the convergence study needs a span loaded by its self-weight only");
    if (!rc && ctn_compare_get(c, CTN_FORM_ECATENARY, &cv->ref))
        rc = ctn_cmp_error(ctx, c->file, CTN_ERR_DOMAIN, "the span has no elastic catenary solution");
    if (!rc) cv->span = c->span;
    ctn_compare_destroy(&c);
    return rc;
}

static int mesh_list(ctn_ctx *ctx, ctn_convergence *cv, const size_t *ns, size_t count)
{
    size_t *tmp = ctn_malloc(ctx, count, sizeof *tmp);
    cv->row = ctn_calloc(ctx, count, sizeof *cv->row);
    if (!tmp || !cv->row) {
        ctn_free(tmp);
        return CTN_ERR_NOMEM;
    }
    memcpy(tmp, ns, count * sizeof *tmp);
    qsort(tmp, count, sizeof *tmp, by_n);
    for (size_t i = 0; i < count; i++)
        if (!cv->n || tmp[i] != cv->row[cv->n - 1].n) cv->row[cv->n++].n = tmp[i];
    ctn_free(tmp);
    return CTN_OK;
}

int ctn_convergence_run(ctn_ctx *ctx, const ctn_model *base, const ctn_solve_options *opt,
                        const size_t *ns, size_t count, ctn_convergence **out)
{
    if (!out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_convergence_run: out is NULL");
    *out = NULL;
    if (!base || !ns || !count) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_convergence_run: bad arguments");
    for (size_t i = 0; i < count; i++)
        if (ns[i] < 2 || ns[i] > 50000000)
            return ctn_error(ctx, CTN_ERR_INVALID, "element counts must be between 2 and 50000000 (got %zu)", ns[i]);
    ctn_convergence *cv = ctn_calloc(ctx, 1, sizeof *cv);
    if (cv) cv->opt = opt;
    int rc = cv ? setup(ctx, base, cv) : CTN_ERR_NOMEM;
    if (!rc) rc = mesh_list(ctx, cv, ns, count);
    for (size_t i = 0; !rc && i < cv->n; i++) rc = solve_row(ctx, base, cv, &cv->row[i]);
    if (rc) ctn_convergence_destroy(&cv);
    *out = cv;
    return rc;
}

void ctn_convergence_destroy(ctn_convergence **c)
{
    if (!c || !*c) return;
    ctn_free((*c)->row);
    ctn_free(*c);
    *c = NULL;
}

const ctn_span *ctn_convergence_span(const ctn_convergence *c) { return c ? &c->span : NULL; }
const ctn_compare_values *ctn_convergence_reference(const ctn_convergence *c) { return c ? &c->ref : NULL; }
size_t ctn_convergence_count(const ctn_convergence *c) { return c ? c->n : 0; }
const ctn_convergence_row *ctn_convergence_row_at(const ctn_convergence *c, size_t i)
{
    return c && i < c->n ? &c->row[i] : NULL;
}

static double column(const ctn_convergence_row *r, int col)
{
    return col == 0 ? r->err_sag : col == 1 ? r->err_T : r->err_H;
}

int ctn_convergence_order(const ctn_convergence *c, int column_, double *order)
{
    if (!c || !order || column_ < 0 || column_ > 2) return CTN_ERR_INVALID;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    size_t k = 0;
    *order = 0;
    for (size_t i = 0; i < c->n; i++) {
        const ctn_convergence_row *r = &c->row[i];
        double e = column(r, column_);
        if (r->reason != CTN_CONVERGED || !(e > 1e-13)) continue;
        double x = log((double)r->n), y = -log(e);
        sx += x, sy += y, sxx += x * x, sxy += x * y, k++;
    }
    double den = (double)k * sxx - sx * sx;
    if (k < 2 || !(den > 0)) return CTN_ERR_DOMAIN;
    *order = ((double)k * sxy - sx * sy) / den;
    return CTN_OK;
}
