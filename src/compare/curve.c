/* Curves of the compared solutions: shape (x, y) and stress (x, T / A). */
#include "compare/cmp.h"

#include <math.h>

/* The polyline (joints then forces) of form f, or NULL. */
static const double *polyline(const ctn_compare *c, ctn_form f)
{
    if (f == CTN_FORM_FEA) return c->catenary ? NULL : c->fea;
    if (f == CTN_FORM_FUNICULAR) return c->poly[0];
    if (f == CTN_FORM_EFUNICULAR) return c->poly[1];
    return NULL;
}

size_t ctn_compare_curve_size(const ctn_compare *c, ctn_form f, ctn_curve k)
{
    if (!ctn_compare_has(c, f) || (k != CTN_CURVE_SHAPE && k != CTN_CURVE_STRESS)) return 0;
    if (polyline(c, f)) return k == CTN_CURVE_SHAPE ? c->span.n + 1 : c->span.n;
    return CTN_CMP_SAMPLES;
}

static void polyline_curve(const ctn_compare *c, const double *p, ctn_curve k, double *xy)
{
    size_t n = c->span.n;
    if (k == CTN_CURVE_SHAPE) {
        for (size_t i = 0; i < 2 * (n + 1); i++) xy[i] = p[i];
        return;
    }
    for (size_t i = 0; i < n; i++) {
        xy[2 * i] = 0.5 * (p[2 * i] + p[2 * i + 2]);
        xy[2 * i + 1] = p[2 * (n + 1) + i] / c->span.A;
    }
}

/* Point t in [0, 1] of a continuous form: (x, y) or (x, T). */
static int sample(const ctn_compare *c, ctn_form f, ctn_curve k, double t, double out[2])
{
    double x = t * c->span.l, T = 0, y = 0;
    int rc = CTN_OK;
    if (f == CTN_FORM_FEA) {                           /* one catenary element */
        ctn_cmp_catenary_sample(c, k == CTN_CURVE_STRESS, t, out);
        return CTN_OK;
    }
    if (f == CTN_FORM_ECATENARY) {
        double s = t * c->span.L0;
        rc = ctn_ecatenary_point(&c->ecat, s, &x, &y);
        if (!rc && k == CTN_CURVE_STRESS) rc = ctn_ecatenary_tension_s(&c->ecat, s, &T);
    } else if (f == CTN_FORM_CATENARY) {
        rc = k == CTN_CURVE_SHAPE ? ctn_catenary_y(&c->cat, x, &y) : ctn_catenary_tension(&c->cat, x, &T);
    } else {
        const ctn_parabola *p = &c->par[f == CTN_FORM_EPARABOLA];
        rc = k == CTN_CURVE_SHAPE ? ctn_parabola_y(p, x, &y) : ctn_parabola_tension(p, x, &T);
    }
    out[0] = x;
    out[1] = k == CTN_CURVE_SHAPE ? y : T / c->span.A;
    return rc;
}

int ctn_compare_curve(const ctn_compare *c, ctn_form f, ctn_curve k, double *xy)
{
    size_t m = ctn_compare_curve_size(c, f, k);
    if (!m || !xy) return CTN_ERR_INVALID;
    const double *p = polyline(c, f);
    if (p) {
        polyline_curve(c, p, k, xy);
        return CTN_OK;
    }
    for (size_t i = 0; i < m; i++) {
        int rc = sample(c, f, k, (double)i / (double)(m - 1), &xy[2 * i]);
        if (rc) return rc;
    }
    return CTN_OK;
}

void ctn_cmp_catenary_sample(const ctn_compare *c, int stress, double t, double out[2])
{
    const ctn_ecat *e = &c->fea_cat;
    double x, z, p[3], xy[2];
    ctn_ecat_point(e, t * e->L, &x, &z);
    for (int k = 0; k < 3; k++) p[k] = c->fea_x0[k] + x * c->fea_ex[k] + z * c->catp.up[k];
    ctn_cmp_to_plane(&c->span, p, xy);
    out[0] = xy[0];
    out[1] = stress ? hypot(e->H, e->Va - e->W * t) / c->span.A : xy[1];
}
