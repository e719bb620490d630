/* Parabolic cable: shape, tension and summary.
 *   y(x) = h x / l - q x (l - x) / (2H),  p(x) = y'(x) = h / l - q (l - 2x) / (2H),
 *   T(x) = H sqrt(1 + p(x)^2). */
#include "analytic/an.h"

#include <math.h>

int ctn_parabola_y(const ctn_parabola *par, double x, double *y)
{
    if (!par || !y || ctn_an_in_range(x, par->in.l) != CTN_OK) return CTN_ERR_INVALID;
    const ctn_parabola_in *in = &par->in;
    *y = in->h * (x / in->l) - in->q * x * (in->l - x) / (2.0 * par->H);
    return CTN_OK;
}

int ctn_parabola_tension(const ctn_parabola *par, double x, double *T)
{
    if (!par || !T || ctn_an_in_range(x, par->in.l) != CTN_OK) return CTN_ERR_INVALID;
    const ctn_parabola_in *in = &par->in;
    *T = par->H * hypot(1.0, in->h / in->l - in->q * (in->l - 2.0 * x) / (2.0 * par->H));
    return CTN_OK;
}

/* Largest tension at the steeper end; smallest where p = 0 if on the span. */
static void tension_extremes(const ctn_parabola *par, ctn_analytic_summary *sum)
{
    double l = par->in.l, H = par->H, m = par->in.h / l, k = par->in.q * l / (2.0 * H);
    int right = fabs(m + k) > fabs(m - k);
    sum->T_max = H * hypot(1.0, right ? m + k : m - k);
    sum->x_T_max = right ? l : 0.0;
    if (m - k <= 0.0 && m + k >= 0.0) {
        sum->T_min = H;
        sum->x_T_min = fmin(fmax(0.5 * l - H * m / par->in.q, 0.0), l);
    } else {
        sum->T_min = H * hypot(1.0, right ? m - k : m + k);
        sum->x_T_min = right ? 0.0 : l;
    }
}

void ctn_an_parabola_summary(ctn_parabola *par)
{
    ctn_analytic_summary *sum = &par->sum;
    const ctn_parabola_in *in = &par->in;
    double l = in->l, H = par->H, half = 0.5 * in->q * l, Hm = H * in->h / l;
    ctn_an_reactions(sum, H, half - Hm, half + Hm);
    sum->sag = sum->sag_mid = in->q * l * l / (8.0 * H);
    sum->x_sag = 0.5 * l;
    sum->length = isinf(in->EA) ? in->L0
                                : ctn_an_parabola_length(l, in->h / l, in->q * l / (2.0 * H));
    sum->length0 = in->L0;
    tension_extremes(par, sum);
}
