/* Rebuilding a span as a fresh model (other length, other mesh, other strain measure)
 * and solving it. */
#include "compare/cmp.h"

#include <math.h>

/* The span's supports, section and loads with n cable elements, or (n == 0) one
 * catenary element. */
static int add_span(ctn_model *m, const ctn_model *base, const ctn_span *sp, double L0, size_t n,
                    ctn_strain strain)
{
    ctn_element_info e;
    int rc = ctn_model_element(base, 0, &e), first = 0, last = 0, ends[2] = { 1, 2 };
    double chord = hypot(sp->l, sp->h);
    ctn_cable_spec spec = { .n = (int)n, .length = L0, .shape = L0 > chord ? CTN_SHAPE_ARC : CTN_SHAPE_STRAIGHT, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    ctn_element_spec cat;
    ctn_element_spec_init(&cat);
    cat.type = "catenary";
    cat.id = first = last = 1;
    cat.nnodes = 2;
    cat.nodes = ends;
    cat.section = "span";
    cat.l0 = L0;
    if (!rc && *sp->force_unit && *sp->length_unit) rc = ctn_model_set_units(m, sp->force_unit, sp->length_unit);
    if (!rc) rc = ctn_model_set_gravity(m, sp->g);
    if (!rc) rc = ctn_model_add_material(m, "span", e.E, strain, e.tension_only);
    if (!rc) rc = ctn_model_add_section(m, "span", "span", e.A, e.w);
    if (!rc) rc = ctn_model_add_node(m, 1, sp->X[0], CTN_FIX_ALL);
    if (!rc) rc = ctn_model_add_node(m, 2, sp->X[1], CTN_FIX_ALL);
    if (!rc) rc = n ? ctn_model_add_cable(m, 1, 2, "span", &spec, &first, &last) : ctn_model_add_element_spec(m, &cat);
    if (!rc && sp->q != 0) rc = ctn_model_add_hload(m, sp->q, first, last);
    return rc;
}

int ctn_cmp_build(ctn_ctx *ctx, const ctn_model *base, const ctn_span *span, double L0,
                  size_t n, ctn_strain strain, ctn_model **out)
{
    *out = NULL;
    if (n > 50000000 || !(L0 > 0) || !isfinite(L0))
        return ctn_error(ctx, CTN_ERR_INVALID, "cannot rebuild the span with %zu elements and length %g", n, L0);
    if (span->loads & CTN_SPAN_POINT)
        return ctn_cmp_error(ctx, ctn_model_file(base), CTN_ERR_MODEL, "a span with point loads cannot be rebuilt with another "
                         "length or mesh (only self-weight and hload are carried over)");
    ctn_model *m = NULL;
    int rc = ctn_model_create(ctx, &m);
    if (!rc) rc = ctn_model_set_origin(m, ctn_model_file(base), 0);  /* messages name the base's file */
    if (!rc) rc = add_span(m, base, span, L0, n, strain);
    if (rc) ctn_model_destroy(&m);
    *out = m;
    return rc;
}

int ctn_cmp_solve(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *base, double tol,
                  ctn_solution **s, int *fallback)
{
    ctn_solve_options opt;
    ctn_solve_summary sum;
    if (base) opt = *base;
    else ctn_solve_options_default(&opt);
    opt.monitor = NULL;
    opt.monitor_data = NULL;
    if (tol > 0) opt.tol = tol;
    *fallback = 0;
    int rc = ctn_solve(ctx, m, &opt, s);
    if (rc) return rc;
    ctn_solution_summary(*s, &sum);
    if (sum.reason == CTN_CONVERGED || opt.method == CTN_METHOD_AUTO) return CTN_OK;
    ctn_solution_destroy(s);
    opt.method = CTN_METHOD_AUTO;
    opt.maxcuts = -1;
    *fallback = 1;
    return ctn_solve(ctx, m, &opt, s);
}
