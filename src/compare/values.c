/* Values of a polyline (FEA nodes, funicular joints) in the span's plane. */
#include "compare/cmp.h"

#include <math.h>

/* Height at xm of the parabola through joints i - 1, i, i + 1 (Lagrange form). */
static double parabola_at(const double *xy, size_t i, double xm)
{
    double x0 = xy[2 * i - 2], x1 = xy[2 * i], x2 = xy[2 * i + 2];
    double y0 = xy[2 * i - 1], y1 = xy[2 * i + 1], y2 = xy[2 * i + 3];
    if (x0 == x1 || x1 == x2 || x0 == x2) return y1;
    return y0 * (xm - x1) * (xm - x2) / ((x0 - x1) * (x0 - x2)) + y1 * (xm - x0) * (xm - x2) / ((x1 - x0) * (x1 - x2)) +
           y2 * (xm - x0) * (xm - x1) / ((x2 - x0) * (x2 - x1));
}

/* Mid-span sag: the chord's mid-point height minus the polyline's at x = l/2. Under point
 * loads the chain is straight between joints (linear interpolation); under distributed
 * loads the nodes sample a curve, read by the parabola through the three nodes nearest
 * to mid-span (interpolation error O(h^3), below the discretization's O(h^2)). */
static int mid_sag(const ctn_span *s, size_t n, const double *xy, double *sag)
{
    double xm = 0.5 * s->l;
    for (size_t i = 0; i < n; i++) {
        double xa = xy[2 * i], xb = xy[2 * i + 2], ya = xy[2 * i + 1], yb = xy[2 * i + 3];
        if (!((xa <= xm && xm <= xb) || (xb <= xm && xm <= xa))) continue;
        double t = xb != xa ? (xm - xa) / (xb - xa) : 0.5, y = ya + t * (yb - ya);
        if (!(s->loads & CTN_SPAN_POINT) && n >= 2) {
            size_t c = t < 0.5 ? i : i + 1;                 /* the node nearest to mid-span */
            y = parabola_at(xy, c == 0 ? 1 : c == n ? n - 1 : c, xm);
        }
        *sag = 0.5 * s->h - y;
        return CTN_OK;
    }
    return CTN_ERR_DOMAIN;
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
    int rc = mid_sag(&c->span, n, xy, &v->sag);
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
