/* Funicular polygon: argument checks, the chains that cannot be taut, and the driver
 * (Newton in funicular_newton.c, closure equation in funicular_eq.c). */
#include "analytic/an.h"

#include <math.h>
#include <string.h>

static const char *const WHAT = "funicular";

/* Per-segment data: lengths > 0, EA > 0 (or INFINITY), finite loads. */
static int check_arrays(ctn_ctx *ctx, const ctn_funicular_in *in)
{
    for (size_t i = 0; i < in->n; i++) {
        if (!(isfinite(in->L0[i]) && in->L0[i] > 0.0))
            return ctn_error(ctx, CTN_ERR_INVALID, "%s: L0[%zu] must be finite and > 0 "
                             "(got %g)", WHAT, i, in->L0[i]);
        if (in->EA && (isnan(in->EA[i]) || !(in->EA[i] > 0.0)))
            return ctn_error(ctx, CTN_ERR_INVALID, "%s: EA[%zu] must be > 0 or INFINITY "
                             "(got %g)", WHAT, i, in->EA[i]);
    }
    for (size_t k = 0; in->P && k + 1 < in->n; k++)
        if (!isfinite(in->P[2 * k]) || !isfinite(in->P[2 * k + 1]))
            return ctn_error(ctx, CTN_ERR_INVALID, "%s: load of joint %zu must be finite",
                             WHAT, k + 1);
    return CTN_OK;
}

static int check_input(ctn_ctx *ctx, const ctn_funicular_in *in)
{
    int st;
    if (!in) return ctn_error(ctx, CTN_ERR_INVALID, "%s: NULL input", WHAT);
    if ((st = ctn_an_check_pos(ctx, WHAT, "span l", in->l)) != CTN_OK) return st;
    if ((st = ctn_an_check_finite(ctx, WHAT, "height h", in->h)) != CTN_OK) return st;
    if (in->n < 1 || !in->L0)
        return ctn_error(ctx, CTN_ERR_INVALID, "%s: need n >= 1 segments and their lengths L0",
                         WHAT);
    return check_arrays(ctx, in);
}

/* Chains that cannot be taut: inextensible and not longer than the chord, or unloaded
 * and not shorter than the chord (or inextensible). */
static int check_domain(ctn_ctx *ctx, const ctn_funicular_in *in)
{
    double Ltot = 0.0, C = hypot(in->l, in->h);
    int elastic = 0, loaded = 0;
    for (size_t i = 0; i < in->n; i++) {
        Ltot += in->L0[i];
        elastic |= in->EA && isfinite(in->EA[i]);
    }
    for (size_t k = 0; in->P && k + 1 < in->n; k++)
        loaded |= in->P[2 * k] != 0.0 || in->P[2 * k + 1] != 0.0;
    if (!elastic && !(Ltot > C))
        return ctn_error(ctx, CTN_ERR_DOMAIN, "%s: inextensible chain of length %.17g is not "
                         "longer than the chord %.17g", WHAT, Ltot, C);
    if (!loaded && (!elastic || !(Ltot < C)))
        return ctn_error(ctx, CTN_ERR_DOMAIN, "%s: unloaded chain of unstressed length %.17g "
                         "and chord %.17g would be slack", WHAT, Ltot, C);
    return CTN_OK;
}

int ctn_funicular_solve(ctn_ctx *ctx, const ctn_funicular_in *in, double *xy, double *N,
                        ctn_funicular *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!out || !xy || !N) return ctn_error(ctx, CTN_ERR_INVALID, "%s: NULL output", WHAT);
    int st = check_input(ctx, in);
    if (st == CTN_OK) st = check_domain(ctx, in);
    if (st != CTN_OK) return st;
    double F[2];
    int its;
    size_t slack = 0;
    st = ctn_an_funicular_newton(in, F, &its, &slack);
    if (st == CTN_ERR_DOMAIN)
        return ctn_error(ctx, st, "%s: segment %zu is slack (zero force) at equilibrium; "
                         "no taut solution", WHAT, slack);
    if (st != CTN_OK)
        return ctn_error(ctx, st, "%s: Newton did not converge in %d iterations", WHAT, its);
    ctn_an_funicular_shape(in, F, xy, N);
    ctn_an_funicular_summary(in, F, xy, N, out);
    out->iterations = its;
    return CTN_OK;
}
