/* Elastic catenary: position and tension at an unstressed arc coordinate s, and at an
 * abscissa x through the root of x(s) = x. With V(s) = V_left - w s:
 *   x(s) = H s / EA + (H / w) [asinh(V_left / H) - asinh(V(s) / H)]
 *   y(s) = -s (V_left + V(s)) [1 / (2 EA) + 1 / (T(0) + T(s))]
 * (docs/analytic.md's form with T(0) - T(s) = w s (V_left + V(s)) / (T(0) + T(s))). */
#include "analytic/an.h"

#include <math.h>

int ctn_ecatenary_point(const ctn_ecatenary *cat, double s, double *x, double *y)
{
    if (!cat || !x || !y || ctn_an_in_range(s, cat->in.L0) != CTN_OK) return CTN_ERR_INVALID;
    double H = cat->H, w = cat->in.w, EA = cat->in.EA, Va = cat->V_left, Vs = Va - w * s;
    double Ta = hypot(H, Va), Ts = hypot(H, Vs);
    *x = H * s / EA + H / w * ctn_an_asinh_diff(H, Va, Vs, w * s);
    *y = -s * (Va + Vs) * (0.5 / EA + 1.0 / (Ta + Ts));
    return CTN_OK;
}

int ctn_ecatenary_tension_s(const ctn_ecatenary *cat, double s, double *T)
{
    if (!cat || !T || ctn_an_in_range(s, cat->in.L0) != CTN_OK) return CTN_ERR_INVALID;
    *T = hypot(cat->H, cat->V_left - cat->in.w * s);
    return CTN_OK;
}

typedef struct x_target {
    const ctn_ecatenary *cat;
    double x;
} x_target;

/* x(s) - x and dx/ds = H (1 / EA + 1 / T(s)) > 0. */
static int x_equation(void *data, double s, double *f, double *df)
{
    const x_target *t = data;
    const ctn_ecatenary *cat = t->cat;
    double xs, ys;
    int st = ctn_ecatenary_point(cat, s, &xs, &ys);
    if (st != CTN_OK) return st;
    *f = xs - t->x;
    *df = cat->H * (1.0 / cat->in.EA + 1.0 / hypot(cat->H, cat->V_left - cat->in.w * s));
    return CTN_OK;
}

int ctn_ecatenary_s_at(const ctn_ecatenary *cat, double x, double *s)
{
    if (!cat || !s || ctn_an_in_range(x, cat->in.l) != CTN_OK) return CTN_ERR_INVALID;
    x_target t = {cat, x};
    double L0 = cat->in.L0, f, df;
    if (x == 0.0) { *s = 0.0; return CTN_OK; }
    int st = x_equation(&t, L0, &f, &df);
    if (st != CTN_OK) return st;
    if (f <= 0.0) { *s = L0; return CTN_OK; }          /* x = l up to rounding */
    return ctn_an_root(x_equation, &t, 0.0, L0, L0 * x / cat->in.l, s);
}

int ctn_ecatenary_y(const ctn_ecatenary *cat, double x, double *y)
{
    double s, xs;
    if (!y) return CTN_ERR_INVALID;
    int st = ctn_ecatenary_s_at(cat, x, &s);
    return st != CTN_OK ? st : ctn_ecatenary_point(cat, s, &xs, y);
}

int ctn_ecatenary_tension(const ctn_ecatenary *cat, double x, double *T)
{
    double s;
    if (!T) return CTN_ERR_INVALID;
    int st = ctn_ecatenary_s_at(cat, x, &s);
    return st != CTN_OK ? st : ctn_ecatenary_tension_s(cat, s, T);
}
