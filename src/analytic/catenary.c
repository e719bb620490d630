/* Inextensible catenary of given length: solve for the parameter c, fill the summary. */
#include "analytic/an.h"

#include <math.h>
#include <string.h>

static const char *const WHAT = "catenary";

/* f(u) = log(sinh(u)/u) - log(r), r = sqrt(S^2 - h^2) / l, increasing in u > 0. */
static int u_equation(void *data, double u, double *f, double *df)
{
    const double *log_r = data;
    *f = ctn_an_log_sinhc(u, df) - *log_r;
    return CTN_OK;
}

static int check_input(ctn_ctx *ctx, const ctn_catenary_in *in)
{
    int st;
    if (!in) return ctn_error(ctx, CTN_ERR_INVALID, "%s: NULL input", WHAT);
    if ((st = ctn_an_check_pos(ctx, WHAT, "span l", in->l)) != CTN_OK) return st;
    if ((st = ctn_an_check_finite(ctx, WHAT, "height h", in->h)) != CTN_OK) return st;
    if ((st = ctn_an_check_pos(ctx, WHAT, "weight w", in->w)) != CTN_OK) return st;
    return ctn_an_check_pos(ctx, WHAT, "length S", in->S);
}

/* u = l / (2c) from sinh(u)/u = r; r - 1 formed without cancellation. */
static int solve_u(const ctn_catenary_in *in, double *u)
{
    double l = in->l, S = in->S, ah = fabs(in->h), C = hypot(l, in->h);
    double rm1 = (S - C) / l * ((S + C) / (sqrt(S - ah) * sqrt(S + ah) + l));
    double log_r = log1p(rm1);
    double u0 = rm1 < 1.0 ? sqrt(6.0 * rm1) : log_r + log(2.0 * log_r + 2.0);
    return ctn_an_solve_pos(u_equation, &log_r, u0, u);
}

/* Tension extremes: largest at the steeper end, smallest at the vertex if inside. */
static void tension_extremes(const ctn_catenary *cat, ctn_analytic_summary *sum)
{
    double H = sum->H, l = cat->in.l, t0 = cat->m - cat->u, t1 = cat->m + cat->u;
    int right = fabs(t1) > fabs(t0);
    sum->T_max = H * cosh(right ? t1 : t0);
    sum->x_T_max = right ? l : 0.0;
    if (t0 <= 0.0 && t1 >= 0.0) {
        sum->T_min = H;
        sum->x_T_min = fmin(fmax(cat->x_vertex, 0.0), l);
    } else {
        sum->T_min = H * cosh(right ? t0 : t1);
        sum->x_T_min = right ? 0.0 : l;
    }
}

static void fill_summary(ctn_catenary *cat)
{
    ctn_analytic_summary *sum = &cat->sum;
    double l = cat->in.l, c = cat->c, H = cat->in.w * c;
    ctn_an_reactions(sum, H, -H * sinh(cat->m - cat->u), H * sinh(cat->m + cat->u));
    double xs = 0.5 * l + c * (asinh(cat->in.h / l) - cat->m); /* slope = chord slope */
    sum->x_sag = fmin(fmax(xs, 0.0), l);
    ctn_catenary_sag(cat, sum->x_sag, &sum->sag);
    ctn_catenary_sag(cat, 0.5 * l, &sum->sag_mid);
    sum->length = sum->length0 = cat->in.S;
    tension_extremes(cat, sum);
}

int ctn_catenary_solve(ctn_ctx *ctx, const ctn_catenary_in *in, ctn_catenary *out)
{
    if (!out) return ctn_error(ctx, CTN_ERR_INVALID, "%s: NULL output", WHAT);
    memset(out, 0, sizeof *out);
    int st = check_input(ctx, in);
    if (st != CTN_OK) return st;
    if (!(in->S > hypot(in->l, in->h)))
        return ctn_error(ctx, CTN_ERR_DOMAIN, "%s: length S = %.17g is not longer than the "
                         "chord %.17g", WHAT, in->S, hypot(in->l, in->h));
    double u;
    if ((st = solve_u(in, &u)) != CTN_OK)
        return ctn_error(ctx, st, "%s: no convergence for c (l = %g, h = %g, S = %.17g)",
                         WHAT, in->l, in->h, in->S);
    out->in = *in;
    out->u = u;
    out->c = in->l / (2.0 * u);
    out->m = atanh(in->h / in->S);
    out->x_vertex = 0.5 * in->l - out->c * out->m;
    fill_summary(out);
    return CTN_OK;
}
