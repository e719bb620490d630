/* The span's plane (from gravity, or the resultant load) and its loads: self-weight,
 * a load per unit horizontal length, point loads. */
#include "compare/cmp.h"
#include "post/sag.h"

#include <math.h>
#include <string.h>

double ctn_cmp_dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void ctn_cmp_to_plane(const ctn_span *s, const double p[3], double xy[2])
{
    double d[3] = { p[0] - s->origin[0], p[1] - s->origin[1], p[2] - s->origin[2] };
    xy[0] = ctn_cmp_dot3(d, s->ex);
    xy[1] = ctn_cmp_dot3(d, s->ey);
}

/* Current support positions (reference + prescribed displacements of the last step). */
static int support_positions(ctn_compare *c, const ctn_model *m, const double *u)
{
    for (int k = 0; k < 2; k++) {
        ctn_node_info nd;
        size_t i = c->node[k ? c->span.n : 0];
        ctn_model_node(m, i, &nd);
        for (int j = 0; j < 3; j++) c->span.X[k][j] = nd.X[j] + u[3 * i + (size_t)j];
    }
    memcpy(c->span.origin, c->span.X[0], sizeof c->span.origin);
    return CTN_OK;
}

/* ey against gravity (or the resultant load: ctn_sag_down), ex along the chord's
 * horizontal part. */
static int plane(ctn_compare *c, const ctn_model *m)
{
    ctn_span *s = &c->span;
    ctn_sag_down(m, c->down);
    if (ctn_cmp_dot3(c->down, c->down) == 0)
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "the span has neither gravity nor loads: no closed form to compare with");
    for (int k = 0; k < 3; k++) s->ey[k] = -c->down[k];
    double ch[3], up = 0;
    for (int k = 0; k < 3; k++) ch[k] = s->X[1][k] - s->X[0][k];
    up = ctn_cmp_dot3(ch, s->ey);
    for (int k = 0; k < 3; k++) ch[k] -= up * s->ey[k];
    s->l = sqrt(ctn_cmp_dot3(ch, ch));
    s->h = up;
    if (!(s->l > 1e-9 * fabs(up)) || !(s->l > 0))
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "the span's chord is vertical: no horizontal span to compare");
    for (int k = 0; k < 3; k++) s->ex[k] = ch[k] / s->l;
    return CTN_OK;
}

/* Lumped self-weight of the span's elements on node j of the chain (j = 0..n). */
static void self_weight(const ctn_compare *c, const ctn_model *m, size_t j, double out[3])
{
    double W = 0;
    ctn_element_info e;
    if (j > 0 && !ctn_model_element(m, c->elem[j - 1], &e)) W += 0.5 * e.w * e.l0;
    if (j < c->span.n && !ctn_model_element(m, c->elem[j], &e)) W += 0.5 * e.w * e.l0;
    for (int k = 0; k < 3; k++) out[k] = W * c->span.g[k];
}

/* Half the reference horizontal projections of the elements at chain node j. */
static double hprojection(const ctn_compare *c, const ctn_model *m, size_t j)
{
    double sum = 0;
    for (size_t k = j > 0 ? j - 1 : 0; k <= j && k < c->span.n; k++) {
        ctn_node_info a, b;
        ctn_model_node(m, c->node[k], &a);
        ctn_model_node(m, c->node[k + 1], &b);
        double d[3] = { b.X[0] - a.X[0], b.X[1] - a.X[1], b.X[2] - a.X[2] };
        double v = ctn_cmp_dot3(d, c->span.ey), p2 = ctn_cmp_dot3(d, d) - v * v;
        sum += 0.5 * sqrt(p2 > 0 ? p2 : 0);
    }
    return sum;
}

/* Classify the loads left after self-weight: none, uniform hload, or point loads. */
static void classify(ctn_compare *c, const ctn_model *m, const double *rest, double scale)
{
    size_t n = c->span.n;
    double num = 0, den = 0, dev = 0, mag = 0;
    for (size_t j = 0; j <= n; j++) {
        double p = hprojection(c, m, j);
        num -= ctn_cmp_dot3(&rest[3 * j], c->span.ey);
        den += p;
        mag = fmax(mag, sqrt(ctn_cmp_dot3(&rest[3 * j], &rest[3 * j])));
    }
    double q = den > 0 ? num / den : 0;
    for (size_t j = 0; j <= n; j++) {
        double p = hprojection(c, m, j), r[3];
        for (int k = 0; k < 3; k++) r[k] = rest[3 * j + (size_t)k] + q * p * c->span.ey[k];
        dev = fmax(dev, sqrt(ctn_cmp_dot3(r, r)));
    }
    if (mag <= 1e-13 * scale) return;
    if (dev <= 1e-10 * scale && q != 0) {
        c->span.q = q;
        c->span.loads |= CTN_SPAN_HLOAD;
    } else {
        c->span.loads |= CTN_SPAN_POINT;
    }
}

/* Loads of the chain's nodes in the plane; CTN_ERR_MODEL if they leave it. */
static int plane_loads(ctn_compare *c, const double *f)
{
    double ez[3], scale = 0, out = 0;
    const double *x = c->span.ex, *y = c->span.ey;
    ez[0] = x[1] * y[2] - x[2] * y[1];
    ez[1] = x[2] * y[0] - x[0] * y[2];
    ez[2] = x[0] * y[1] - x[1] * y[0];
    c->W = 0;
    for (size_t j = 0; j <= c->span.n; j++) {
        const double *p = &f[3 * c->node[j]];
        scale = fmax(scale, sqrt(ctn_cmp_dot3(p, p)));
        out = fmax(out, fabs(ctn_cmp_dot3(p, ez)));
        c->P[2 * j] = ctn_cmp_dot3(p, x);
        c->P[2 * j + 1] = ctn_cmp_dot3(p, y);
        c->W -= c->P[2 * j + 1];
    }
    if (out > 1e-10 * scale)
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "the span's loads leave the vertical plane of its "
                         "supports: no plane closed form applies");
    return CTN_OK;
}

static int loads(ctn_compare *c, const ctn_model *m, const double *f)
{
    int rc = plane_loads(c, f);
    size_t n = c->span.n;
    double *rest = rc ? NULL : ctn_malloc(c->ctx, 3 * (n + 1), sizeof *rest), scale = 0;
    if (!rc && !rest) rc = CTN_ERR_NOMEM;
    for (size_t j = 0; !rc && j <= n; j++) {
        double sw[3];
        self_weight(c, m, j, sw);
        for (int k = 0; k < 3; k++) rest[3 * j + (size_t)k] = f[3 * c->node[j] + (size_t)k] - sw[k];
        scale = fmax(scale, sqrt(ctn_cmp_dot3(&f[3 * c->node[j]], &f[3 * c->node[j]])));
    }
    if (!rc) {
        ctn_element_info e;
        ctn_model_element(m, c->elem[0], &e);
        c->span.w = e.w * sqrt(ctn_cmp_dot3(c->span.g, c->span.g));
        if (c->span.w > 0) c->span.loads |= CTN_SPAN_WEIGHT;
        classify(c, m, rest, scale);
    }
    ctn_free(rest);
    return rc;
}

/* Kinks of the chain: nodes with a concentrated load (the sag's reading, sag.h). */
static int kinks(ctn_compare *c, const ctn_model *m, double *work)
{
    c->kink = ctn_malloc(c->ctx, c->span.n + 1, 1);
    if (!c->kink) return CTN_ERR_NOMEM;
    ctn_sag_node_loads(m, work);
    for (size_t j = 0; j <= c->span.n; j++) {
        const double *F = &work[3 * c->node[j]];
        c->kink[j] = F[0] != 0 || F[1] != 0 || F[2] != 0;
    }
    return CTN_OK;
}

int ctn_cmp_span_loads(ctn_compare *c, const ctn_model *m)
{
    size_t nn = ctn_model_node_count(m), last = ctn_model_step_count(m) - 1;
    double *f = ctn_malloc(c->ctx, 3 * nn, sizeof *f), *u = ctn_malloc(c->ctx, 3 * nn, sizeof *u);
    int rc = f && u ? kinks(c, m, f) : CTN_ERR_NOMEM;
    if (!rc) rc = ctn_model_step_loads(m, last, f, u);
    ctn_model_gravity(m, c->span.g);
    if (!rc) rc = support_positions(c, m, u);
    if (!rc) rc = plane(c, m);
    if (!rc) rc = loads(c, m, f);
    ctn_free(f);
    ctn_free(u);
    return rc;
}
