/* Elastic catenary (Irvine): solve the two end conditions for H and V.
 *
 * With W = w L0, the vertical reactions written through D = V_right - V_left,
 *   V_left = (W - D) / 2,  V_right = (W + D) / 2,  T_left/right = sqrt(H^2 + V^2),
 * the end conditions x(L0) = l and y(L0) = h become
 *   l = H L0 / EA + (H / w) [asinh(V_left / H) + asinh(V_right / H)]           (x)
 *   h = D L0 [1 / (2 EA) + 1 / (T_left + T_right)]                             (y)
 * (y) is increasing in D, so D(H) is a safeguarded 1D root; (x) with D = D(H) is
 * increasing in H (the Schur complement of the positive definite flexibility matrix)
 * and is solved by a second safeguarded 1D root with the exact implicit derivative. */
#include "analytic/an.h"

#include <math.h>
#include <string.h>

static const char *const WHAT = "elastic catenary";

typedef struct ec_problem {
    const ctn_ecatenary_in *in;
    double W;                                          /* w L0 */
    double H;                                          /* current H of the inner solve */
} ec_problem;

/* Equation (y) for |h| at fixed H, as a function of D >= 0. */
static int d_equation(void *data, double D, double *f, double *df)
{
    const ec_problem *p = data;
    double H = p->H, L0 = p->in->L0, Va = 0.5 * (p->W - D), Vb = 0.5 * (p->W + D);
    double Ta = hypot(H, Va), Tb = hypot(H, Vb), Ts = Ta + Tb;
    double k = 0.5 / p->in->EA + 1.0 / Ts;
    *f = D * L0 * k - fabs(p->in->h);
    *df = L0 * k - D * L0 * 0.5 * (Vb / Tb - Va / Ta) / (Ts * Ts);
    return CTN_OK;
}

/* D(H): root of (y) in [0, D_hi] for |h|, sign of h restored ((y) is odd in (D, h)). */
static int solve_d(ec_problem *p, double H, double *D)
{
    double ah = fabs(p->in->h), L0 = p->in->L0, hi = 2.0 * p->in->EA * ah / L0;
    p->H = H;
    *D = 0.0;
    if (ah == 0.0) return CTN_OK;
    if (ah < L0) hi = fmin(hi, ah * (2.0 * H + p->W) / (L0 - ah));
    if (!isfinite(hi)) return CTN_ERR_NOCONV;
    int st = ctn_an_root(d_equation, p, 0.0, hi, 0.5 * hi, D);
    if (p->in->h < 0.0) *D = -*D;
    return st;
}

/* Equation (x) as a function of H, with D = D(H) and dD/dH = -g_H / g_D. */
static int h_equation(void *data, double H, double *f, double *df)
{
    ec_problem *p = data;
    const ctn_ecatenary_in *in = p->in;
    double D;
    int st = solve_d(p, H, &D);
    if (st != CTN_OK) return st;
    double Va = 0.5 * (p->W - D), Vb = 0.5 * (p->W + D), Ta = hypot(H, Va), Tb = hypot(H, Vb);
    double A = ctn_an_asinh_diff(H, Va, -Vb, p->W);    /* asinh(Va/H) + asinh(Vb/H) */
    double Ts = Ta + Tb, k = 0.5 / in->EA + 1.0 / Ts;
    *f = H * in->L0 / in->EA + H / in->w * A - in->l;
    double xH = in->L0 / in->EA + (A - Va / Ta - Vb / Tb) / in->w;
    double xD = H / (2.0 * in->w) * (1.0 / Tb - 1.0 / Ta);
    double gH = -D * in->L0 * H * (1.0 / Ta + 1.0 / Tb) / (Ts * Ts);
    double gD = in->L0 * k - D * in->L0 * 0.5 * (Vb / Tb - Va / Ta) / (Ts * Ts);
    *df = xH - xD * gH / gD;
    return CTN_OK;
}

/* Starting H: the inextensible catenary when L0 > chord, else the straight bar. */
static double initial_h(const ctn_ecatenary_in *in)
{
    double C = hypot(in->l, in->h);
    ctn_catenary cat;
    ctn_catenary_in ci = {in->l, in->h, in->w, in->L0};
    if (in->L0 > C && ctn_catenary_solve(NULL, &ci, &cat) == CTN_OK) return cat.sum.H;
    return in->EA * (C / in->L0 - 1.0) * in->l / C + in->w * in->L0;
}

static int check_input(ctn_ctx *ctx, const ctn_ecatenary_in *in)
{
    int st;
    if (!in) return ctn_error(ctx, CTN_ERR_INVALID, "%s: NULL input", WHAT);
    if ((st = ctn_an_check_pos(ctx, WHAT, "span l", in->l)) != CTN_OK) return st;
    if ((st = ctn_an_check_finite(ctx, WHAT, "height h", in->h)) != CTN_OK) return st;
    if ((st = ctn_an_check_pos(ctx, WHAT, "weight w", in->w)) != CTN_OK) return st;
    if ((st = ctn_an_check_EA(ctx, WHAT, in->EA)) != CTN_OK) return st;
    if ((st = ctn_an_check_pos(ctx, WHAT, "unstressed length L0", in->L0)) != CTN_OK)
        return st;
    if (isinf(in->EA) && !(in->L0 > hypot(in->l, in->h)))
        return ctn_error(ctx, CTN_ERR_DOMAIN, "%s: inextensible (EA = inf) and L0 = %.17g "
                         "is not longer than the chord %.17g", WHAT, in->L0,
                         hypot(in->l, in->h));
    return CTN_OK;
}

int ctn_ecatenary_solve(ctn_ctx *ctx, const ctn_ecatenary_in *in, ctn_ecatenary *out)
{
    if (!out) return ctn_error(ctx, CTN_ERR_INVALID, "%s: NULL output", WHAT);
    memset(out, 0, sizeof *out);
    int st = check_input(ctx, in);
    if (st != CTN_OK) return st;
    ec_problem p = {in, in->w * in->L0, 0.0};
    double H, D;
    st = ctn_an_solve_pos(h_equation, &p, initial_h(in), &H);
    if (st == CTN_OK) st = solve_d(&p, H, &D);
    if (st == CTN_OK) {
        out->in = *in;
        out->H = H;
        out->V_left = 0.5 * (p.W - D);
        out->V_right = p.W - out->V_left;             /* sums to w L0 to one ulp */
        st = ctn_an_ecatenary_summary(out);
    }
    if (st == CTN_OK) return CTN_OK;
    memset(out, 0, sizeof *out);
    return ctn_error(ctx, st, "%s: no convergence for H, V (l = %g, h = %g, L0 = %.17g, "
                     "EA = %g)", WHAT, in->l, in->h, in->L0, in->EA);
}
