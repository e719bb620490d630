/* The FEA's values and curves from a solution of the compared model. */
#include "compare/cmp.h"

#include <math.h>

/* Support reaction of chain node j (0 or n): magnitude and horizontal component. */
static void support(const ctn_compare *c, const double *react, size_t j, double *T, double *H)
{
    const double *R = &react[3 * c->node[j]];
    *T = sqrt(ctn_cmp_dot3(R, R));
    *H = fabs(ctn_cmp_dot3(R, c->span.ex));
}

/* Deformed position of chain node j, displacements d (= ud) of the whole model. */
static void fea_point(const ctn_compare *c, const void *ud, size_t j, double x[3])
{
    const double *d = ud;
    for (int k = 0; k < 3; k++) x[k] = c->Xref[3 * j + (size_t)k] + d[3 * c->node[j] + (size_t)k];
}

int ctn_compare_set_fea(ctn_compare *c, const ctn_solution *s)
{
    if (!c || !s) return CTN_ERR_INVALID;
    size_t n = c->span.n;
    c->has &= ~(1u << CTN_FORM_FEA);
    if (!c->fea && !(c->fea = ctn_malloc(c->ctx, 3 * n + 2, sizeof(double)))) return CTN_ERR_NOMEM;
    const double *d = ctn_solution_displacements(s), *react = ctn_solution_reactions(s);
    int rc = c->follow && (c->span.loads & CTN_SPAN_HLOAD) ? ctn_cmp_follow_loads(c, d) : CTN_OK;
    if (rc) return rc;
    if (c->catenary) return ctn_cmp_catenary_fea(c, d);
    double *xy = c->fea, *N = xy + 2 * (n + 1);
    for (size_t j = 0; j <= n; j++) {
        double p[3];
        for (int k = 0; k < 3; k++) p[k] = c->Xref[3 * j + (size_t)k] + d[3 * c->node[j] + (size_t)k];
        ctn_cmp_to_plane(&c->span, p, &xy[2 * j]);
    }
    for (size_t k = 0; k < n; k++) {
        ctn_element_state st;
        if (ctn_solution_element(s, c->elem[k], &st)) return ctn_error(c->ctx, CTN_ERR_INVALID, "solution of another model");
        N[k] = st.force;
    }
    ctn_compare_values *v = &c->v[CTN_FORM_FEA];
    if (ctn_cmp_polyline_values(c, xy, N, v) || ctn_cmp_sag(c, fea_point, d, &v->sag))  /* in space: as solve */
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_DOMAIN, "the deformed cable does not cross mid-span or holds a NaN");
    double Ta, Tb, Ha, Hb;
    support(c, react, 0, &Ta, &Ha);
    support(c, react, n, &Tb, &Hb);
    v->T_max = fmax(Ta, Tb);
    v->H = Ha;
    v->stress_max = v->T_max / c->span.A;
    if (!isfinite(v->T_max) || !isfinite(v->H)) return ctn_cmp_error(c->ctx, c->file, CTN_ERR_DOMAIN, "the FEA reactions are not finite");
    c->has |= 1u << CTN_FORM_FEA;
    return CTN_OK;
}

int ctn_cmp_catenary_fea(ctn_compare *c, const double *d)
{
    double X[6], u[6];
    int bar;
    ctn_ecat *e = &c->fea_cat;
    for (int j = 0; j < 2; j++)
        for (int k = 0; k < 3; k++) {
            X[3 * j + k] = c->Xref[3 * (size_t)j + (size_t)k];
            u[3 * j + k] = d[3 * c->node[j] + (size_t)k];
        }
    if (ctn_catenary_state(&c->catp, X, u, e, c->fea_ex, &bar) || bar)
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_DOMAIN, "the catenary element has no weight or cannot be solved");
    for (int k = 0; k < 3; k++) c->fea_x0[k] = X[k] + u[k];
    ctn_compare_values *v = &c->v[CTN_FORM_FEA];
    double Ta = hypot(e->H, e->Va), Tb = hypot(e->H, e->Vb);
    v->sag = ctn_ecat_sag(e);
    v->H = e->H;
    v->T_max = fmax(Ta, Tb);
    v->T_min = e->Va >= 0 && e->Vb >= 0 ? e->H : fmin(Ta, Tb);   /* the vertex on the span, or an end */
    v->stress_max = v->T_max / c->span.A;
    v->stress_min = v->T_min / c->span.A;
    if (!isfinite(v->sag) || !isfinite(v->T_max))
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_DOMAIN, "the catenary element's values are not finite");
    c->has |= 1u << CTN_FORM_FEA;
    return CTN_OK;
}
