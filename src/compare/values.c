/* Values of a polyline (FEA nodes, funicular joints) in the span's plane. */
#include "compare/cmp.h"
#include "post/sag.h"

#include <math.h>

/* A compare chain for ctn_sag_chain: its points come from point(c, ud, j, x). */
typedef struct cmp_chain {
    const ctn_compare *c;
    ctn_cmp_point_fn point;
    const void *ud;
} cmp_chain;

static void chain_point(const void *ud, size_t j, double x[3])
{
    const cmp_chain *cc = ud;
    cc->point(cc->c, cc->ud, j, x);
}

static int chain_kink(const void *ud, size_t j) { return ((const cmp_chain *)ud)->c->kink[j]; }

int ctn_cmp_sag(const ctn_compare *c, ctn_cmp_point_fn point, const void *ud, double *sag)
{
    cmp_chain cc = { c, point, ud };
    ctn_sag_chain ch = { c->span.n, chain_point, chain_kink, &cc, { c->down[0], c->down[1], c->down[2] } };
    return ctn_sag_mid(&ch, sag);
}

/* Joint j of a polyline xy (= ud) in the span's plane, as a point in space. */
static void plane_point(const ctn_compare *c, const void *ud, size_t j, double x[3])
{
    const ctn_span *s = &c->span;
    const double *xy = ud;
    for (int k = 0; k < 3; k++) x[k] = s->origin[k] + xy[2 * j] * s->ex[k] + xy[2 * j + 1] * s->ey[k];
}

/* Reaction of the support at joint j (0 or n) on the chain, load P of the joint included:
 * R = -N e - P, e the unit vector of the joint's segment pointing into the span. */
static void reaction(const ctn_compare *c, const double *xy, const double *N, size_t j, double R[2])
{
    size_t n = c->span.n, seg = j ? n - 1 : 0, other = j ? n - 1 : 1;
    double d[2] = { xy[2 * other] - xy[2 * j], xy[2 * other + 1] - xy[2 * j + 1] };
    double len = hypot(d[0], d[1]);
    for (int k = 0; k < 2; k++) R[k] = -(len > 0 ? N[seg] * d[k] / len : 0) - c->P[2 * j + (size_t)k];
}

int ctn_cmp_polyline_values(const ctn_compare *c, const double *xy, const double *N,
                            ctn_compare_values *v)
{
    size_t n = c->span.n;
    double Ra[2], Rb[2];
    int rc = ctn_cmp_sag(c, plane_point, xy, &v->sag);
    if (rc) return rc;
    reaction(c, xy, N, 0, Ra);
    reaction(c, xy, N, n, Rb);
    v->T_max = fmax(hypot(Ra[0], Ra[1]), hypot(Rb[0], Rb[1]));
    v->H = fabs(Ra[0]);
    v->T_min = N[0];
    for (size_t i = 1; i < n; i++) v->T_min = fmin(v->T_min, N[i]);
    v->stress_max = v->T_max / c->span.A;
    v->stress_min = v->T_min / c->span.A;
    return isfinite(v->T_max) && isfinite(v->sag) && isfinite(v->T_min) ? CTN_OK : CTN_ERR_DOMAIN;
}
