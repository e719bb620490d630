/* Parabolic cable: H from the length (inextensible, closed form in k = q l / (2H)) or
 * from the unstressed length (elastic, quadrature in H). Both equations are increasing in
 * their unknown and solved by the safeguarded root finder. */
#include "analytic/an.h"

#include <math.h>
#include <string.h>

static const char *const WHAT = "parabola";

/* Inextensible: L(k) - L0, increasing in k. */
static int k_equation(void *data, double k, double *f, double *df)
{
    const ctn_parabola_in *in = data;
    double m = in->h / in->l;
    *f = ctn_an_parabola_length(in->l, m, k) - in->L0;
    *df = ctn_an_parabola_dlength(in->l, m, k);
    return CTN_OK;
}

/* Elastic: L0 - L0(H), increasing in H. */
static int h_equation(void *data, double H, double *f, double *df)
{
    const ctn_parabola_in *in = data;
    double L0, dL0;
    ctn_an_parabola_length0(in, H, &L0, &dL0);
    *f = in->L0 - L0;
    *df = -dL0;
    return CTN_OK;
}

/* H of the inextensible parabola of length in->L0 > chord. Start: L - C ~ l k^2/(6 g0^3). */
static int solve_inextensible(const ctn_parabola_in *in, double *H)
{
    ctn_parabola_in data = *in;
    double C = hypot(in->l, in->h), g0 = C / in->l, k;
    double k0 = sqrt(6.0 * g0 * g0 * g0 * (in->L0 - C) / in->l);
    int st = ctn_an_solve_pos(k_equation, &data, k0, &k);
    *H = in->q * in->l / (2.0 * k);
    return st;
}

/* H of the elastic parabola; start from the inextensible one or the straight bar. */
static int solve_elastic(const ctn_parabola_in *in, double *H)
{
    ctn_parabola_in data = *in;
    double C = hypot(in->l, in->h), H0 = in->EA * (C / in->L0 - 1.0) * in->l / C;
    H0 += in->q * in->l;
    if (in->L0 > C && solve_inextensible(in, &H0) != CTN_OK) H0 = in->q * in->l;
    return ctn_an_solve_pos(h_equation, &data, H0, H);
}

static int check_input(ctn_ctx *ctx, const ctn_parabola_in *in)
{
    int st;
    if (!in) return ctn_error(ctx, CTN_ERR_INVALID, "%s: NULL input", WHAT);
    if ((st = ctn_an_check_pos(ctx, WHAT, "span l", in->l)) != CTN_OK) return st;
    if ((st = ctn_an_check_finite(ctx, WHAT, "height h", in->h)) != CTN_OK) return st;
    if ((st = ctn_an_check_pos(ctx, WHAT, "load q", in->q)) != CTN_OK) return st;
    if ((st = ctn_an_check_pos(ctx, WHAT, "length L0", in->L0)) != CTN_OK) return st;
    if ((st = ctn_an_check_EA(ctx, WHAT, in->EA)) != CTN_OK) return st;
    if (isinf(in->EA) && !(in->L0 > hypot(in->l, in->h)))
        return ctn_error(ctx, CTN_ERR_DOMAIN, "%s: inextensible and L0 = %.17g is not longer "
                         "than the chord %.17g", WHAT, in->L0, hypot(in->l, in->h));
    return CTN_OK;
}

int ctn_parabola_solve(ctn_ctx *ctx, const ctn_parabola_in *in, ctn_parabola *out)
{
    if (!out) return ctn_error(ctx, CTN_ERR_INVALID, "%s: NULL output", WHAT);
    memset(out, 0, sizeof *out);
    int st = check_input(ctx, in);
    if (st != CTN_OK) return st;
    double H;
    st = isinf(in->EA) ? solve_inextensible(in, &H) : solve_elastic(in, &H);
    if (st != CTN_OK)
        return ctn_error(ctx, st, "%s: no convergence for H (l = %g, h = %g, L0 = %.17g, "
                         "EA = %g)", WHAT, in->l, in->h, in->L0, in->EA);
    out->in = *in;
    out->H = H;
    ctn_an_parabola_summary(out);
    return CTN_OK;
}
