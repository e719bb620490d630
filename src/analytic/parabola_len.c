/* Parabolic cable lengths. Slope y'(x) = p(x) = m - k (1 - 2x/l), m = h / l,
 * k = q l / (2 H); p runs from m - k to m + k and dx = dp l / (2k).
 *
 * Stretched length, exact: with F(p) = p sqrt(1 + p^2) + asinh(p), g = sqrt(1 + p^2),
 *   L = l / (4k) [F(m+k) - F(m-k)]
 *     = l [m^2 / (g+ + g-) + (g+ + g-) / 4 + (asinh(m+k) - asinh(m-k)) / (4k)].
 *
 * Unstressed length (engineering strain, T = H g): with p = sinh(t), a = H / EA,
 *   L0 = (H / q) int cosh^2 t / (1 + a cosh t) dt   over [asinh(m-k), asinh(m+k)],
 *   dL0/dH = (1 / q) int [sinh t (m - sinh t) - a cosh^3 t] / (1 + a cosh t)^2 dt,
 * by composite Gauss-Legendre (analytic integrand: poles at |Im t| >= pi/2, panels of
 * width 0.5 give ~1e-20 relative truncation per panel). */
#include "analytic/an.h"

#include <math.h>

double ctn_an_parabola_length(double l, double m, double k)
{
    double gp = hypot(1.0, m + k), gm = hypot(1.0, m - k), gs = gp + gm;
    double A = ctn_an_asinh_diff(1.0, m + k, m - k, 2.0 * k);
    return l * (m * m / gs + 0.25 * gs + 0.25 * A / k);
}

/* dL/dk = (l (g+ + g-) / 2 - L) / k; small k: l k / (3 g0^3) (cancellation-free). */
double ctn_an_parabola_dlength(double l, double m, double k)
{
    double g0 = hypot(1.0, m);
    if (k < 1e-3 * g0) return l * k / (3.0 * g0 * g0 * g0);
    double gs = hypot(1.0, m + k) + hypot(1.0, m - k);
    return (0.5 * l * gs - ctn_an_parabola_length(l, m, k)) / k;
}

typedef struct l0_data {
    double m, a;
} l0_data;

static void l0_integrand(void *data, double t, double *f)
{
    const l0_data *d = data;
    double ch = cosh(t), sh = sinh(t), den = 1.0 + d->a * ch;
    f[0] = ch * ch / den;
    f[1] = (sh * (d->m - sh) - d->a * ch * ch * ch) / (den * den);
}

void ctn_an_parabola_length0(const ctn_parabola_in *in, double H, double *L0, double *dL0)
{
    double m = in->h / in->l, k = in->q * in->l / (2.0 * H), out[2];
    l0_data d = {m, H / in->EA};
    ctn_an_gauss(l0_integrand, &d, 2, asinh(m - k), asinh(m + k), 0.5, out);
    *L0 = H / in->q * out[0];
    *dL0 = out[1] / in->q;
}
