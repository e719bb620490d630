/* The closed forms that apply to a span (see catena/compare.h). */
#include "compare/cmp.h"

#include <math.h>

static void from_summary(const ctn_analytic_summary *s, double A, ctn_compare_values *v)
{
    v->sag = s->sag_mid;
    v->T_max = s->T_max;
    v->T_min = s->T_min;
    v->H = s->H;
    v->stress_max = s->T_max / A;
    v->stress_min = s->T_min / A;
}

/* Catenaries and parabolas of the total load W spread along L0 or along l. */
static void distributed(ctn_compare *c)
{
    const ctn_span *s = &c->span;
    double w = c->W / s->L0, q = c->W / s->l;
    ctn_catenary_in ci = { s->l, s->h, w, s->L0 };
    ctn_ecatenary_in ei = { s->l, s->h, w, s->EA, s->L0 };
    ctn_parabola_in pi = { s->l, s->h, q, s->L0, INFINITY };
    if (!ctn_catenary_solve(NULL, &ci, &c->cat)) {
        c->has |= 1u << CTN_FORM_CATENARY;
        from_summary(&c->cat.sum, s->A, &c->v[CTN_FORM_CATENARY]);
    }
    if (!ctn_ecatenary_solve(NULL, &ei, &c->ecat)) {
        c->has |= 1u << CTN_FORM_ECATENARY;
        from_summary(&c->ecat.sum, s->A, &c->v[CTN_FORM_ECATENARY]);
    }
    for (int k = 0; k < 2; k++) {
        pi.EA = k ? s->EA : INFINITY;
        ctn_form f = k ? CTN_FORM_EPARABOLA : CTN_FORM_PARABOLA;
        if (ctn_parabola_solve(NULL, &pi, &c->par[k])) continue;
        c->has |= 1u << f;
        from_summary(&c->par[k].sum, s->A, &c->v[f]);
    }
}

/* Funicular polygon k (0 inextensible, 1 elastic) of the interior joint loads. */
static int polygon(ctn_compare *c, int k)
{
    size_t n = c->span.n;
    ctn_funicular_in in = { c->span.l, c->span.h, n, c->l0, k ? c->EA : NULL, c->P + 2 };
    ctn_funicular out;
    ctn_form f = k ? CTN_FORM_EFUNICULAR : CTN_FORM_FUNICULAR;
    c->has &= ~(1u << f);                            /* solved again: with new loads */
    if (!c->poly[k] && !(c->poly[k] = ctn_malloc(c->ctx, 3 * n + 2, sizeof(double)))) return CTN_ERR_NOMEM;
    double *xy = c->poly[k], *N = xy + 2 * (n + 1);
    int rc = ctn_funicular_solve(NULL, &in, xy, N, &out);
    if (rc == CTN_ERR_NOMEM) return ctn_error(c->ctx, rc, "out of memory");
    if (rc || ctn_cmp_polyline_values(c, xy, N, &c->v[f])) {
        ctn_free(c->poly[k]);
        c->poly[k] = NULL;
        return CTN_OK;                       /* no such solution: the form is absent */
    }
    c->has |= 1u << f;
    return CTN_OK;
}

int ctn_cmp_solve_forms(ctn_compare *c)
{
    int point = (c->span.loads & CTN_SPAN_POINT) != 0;
    if (!point && c->W > 0) distributed(c);
    int rc = point ? polygon(c, 0) : CTN_OK;
    if (!rc) rc = polygon(c, 1);
    return rc;
}
