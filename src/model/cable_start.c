/* Newton start of a generated cable on Irvine's elastic catenary (start=catenary): the
 * span's closed-form shape under the cable's self-weight, with engineering strain, in the
 * vertical plane through the chord. It differs from the finite element solution by the
 * discretization and the strain measure only, so Newton needs a few iterations from it
 * at any n (3 for the benchmark's cable, against 12 from the arc). */
#include "catena/analytic.h"
#include "model/cable_start.h"

#include <math.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Unit vectors: up (against gravity) and along (the chord's horizontal projection). */
static int frame(const double A[3], const double B[3], const double g[3], double up[3],
                 double along[3], double *l, double *h)
{
    double gn = sqrt(dot3(g, g)), c[3] = { B[0] - A[0], B[1] - A[1], B[2] - A[2] };
    if (!(gn > 0)) return -1;
    for (int k = 0; k < 3; k++) up[k] = -g[k] / gn;
    *h = dot3(c, up);
    for (int k = 0; k < 3; k++) along[k] = c[k] - *h * up[k];
    *l = sqrt(dot3(along, along));
    if (!(*l > 1e-9 * sqrt(dot3(c, c)))) return -1;           /* vertical chord */
    for (int k = 0; k < 3; k++) along[k] /= *l;
    return 0;
}

/* Unstressed arc length of node k of n: k L0 / n, exactly L0 at the end (rounding must not
 * step outside the curve). */
static double node_s(const ctn_ecatenary *c, int k, int n)
{
    return k >= n ? c->in.L0 : fmin(c->in.L0 * k / n, c->in.L0);
}

/* Smallest strain of the chords k S/n .. (k+1) S/n of the polygon on the curve; -INFINITY
 * if a point cannot be evaluated. */
static double min_chord_strain(const ctn_ecatenary *c, double S, int n)
{
    double m = INFINITY, x0, y0, x1, y1;
    if (ctn_ecatenary_point(c, 0.0, &x0, &y0)) return -INFINITY;
    for (int k = 1; k <= n; k++, x0 = x1, y0 = y1) {
        if (ctn_ecatenary_point(c, node_s(c, k, n), &x1, &y1)) return -INFINITY;
        m = fmin(m, hypot(x1 - x0, y1 - y0) / (S / n) - 1);
    }
    return m;
}

int ctn_catenary_start(ctn_ctx *ctx, const double A[3], const double B[3], const double g[3],
                       double w, double EA, double S, int n, double eps, ctn_catenary_place *out)
{
    ctn_ecatenary_in in;
    if (!(w > 0) || frame(A, B, g, out->up, out->along, &in.l, &in.h)) return -1;
    in.w = w * sqrt(dot3(g, g));
    in.EA = EA;
    in.L0 = S;
    for (int k = 0; k < 3; k++) out->A[k] = A[k];
    out->n = n;
    for (int pass = 0; pass < 8; pass++) {       /* lengthen until every chord is stretched */
        if (ctn_ecatenary_solve(ctx, &in, &out->cat)) {
            ctn_ctx_clear(ctx);                          /* no catenary: the arc instead */
            return -1;
        }
        double m = min_chord_strain(&out->cat, S, n);
        if (m >= eps) return 0;
        if (!isfinite(m) || m < -0.5) return -1;          /* no sensible polygon: the arc */
        in.L0 *= 1 + 1.5 * (eps - m);
    }
    return -1;
}

void ctn_catenary_start_point(const ctn_catenary_place *p, int k, double X[3])
{
    double x, y;
    if (ctn_ecatenary_point(&p->cat, node_s(&p->cat, k, p->n), &x, &y)) x = y = 0;   /* checked by the start */
    for (int j = 0; j < 3; j++) X[j] = p->A[j] + x * p->along[j] + y * p->up[j];
}
