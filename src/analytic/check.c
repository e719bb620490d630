/* Argument checks and summary helpers shared by the analytic solutions. */
#include "analytic/an.h"

#include <math.h>

int ctn_an_check_finite(ctn_ctx *ctx, const char *what, const char *name, double v)
{
    if (isfinite(v)) return CTN_OK;
    return ctn_error(ctx, CTN_ERR_INVALID, "%s: %s must be finite (got %g)", what, name, v);
}

int ctn_an_check_pos(ctn_ctx *ctx, const char *what, const char *name, double v)
{
    if (isfinite(v) && v > 0.0) return CTN_OK;
    return ctn_error(ctx, CTN_ERR_INVALID, "%s: %s must be finite and > 0 (got %g)", what,
                     name, v);
}

int ctn_an_check_EA(ctn_ctx *ctx, const char *what, double EA)
{
    if (EA > 0.0 && !isnan(EA)) return CTN_OK;         /* +INFINITY: inextensible */
    return ctn_error(ctx, CTN_ERR_INVALID, "%s: EA must be > 0 or INFINITY (got %g)", what,
                     EA);
}

int ctn_an_in_range(double x, double xmax)
{
    return (x >= 0.0 && x <= xmax) ? CTN_OK : CTN_ERR_INVALID;
}

void ctn_an_reactions(ctn_analytic_summary *sum, double H, double V_left, double V_right)
{
    sum->H = H;
    sum->reaction_left[0] = -H;
    sum->reaction_left[1] = V_left;
    sum->reaction_right[0] = H;
    sum->reaction_right[1] = V_right;
}
