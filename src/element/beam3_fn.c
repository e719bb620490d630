/* The scalar functions of the beam's rotations (beam3.h), smooth in y = t^2: a power
 * series near 0, the closed form of t = sqrt(y) beyond, with
 *   f'(y) = F'(t) / (2 t),  f''(y) = (F''(t) - F'(t) / t) / (4 t^2). */
#include "element/beam3.h"

#include <math.h>

/* f, f', f'' of sum_k c_k y^k (n terms). */
static void series(const double *c, int n, double y, double f[3])
{
    f[0] = f[1] = f[2] = 0;
    for (int k = n - 1; k >= 0; k--) {                  /* Horner for the three */
        if (k >= 2) f[2] = f[2] * y + c[k] * k * (k - 1);
        if (k >= 1) f[1] = f[1] * y + c[k] * k;
        f[0] = f[0] * y + c[k];
    }
}

static void from_t(double t, double F0, double F1, double F2, double f[3])
{
    f[0] = F0;
    f[1] = F1 / (2 * t);
    f[2] = (F2 - F1 / t) / (4 * t * t);
}

#define NSER 20

void ctn_beam_rod_a(double y, double f[3])
{
    if (y < 1) {
        double c[NSER], fact = 1;                       /* (-1)^k / (2k + 1)! */
        for (int k = 0; k < NSER; k++) {
            if (k) fact *= (2.0 * k) * (2.0 * k + 1);
            c[k] = (k % 2 ? -1 : 1) / fact;
        }
        series(c, NSER, y, f);
        return;
    }
    double t = sqrt(y), s = sin(t), co = cos(t);
    from_t(t, s / t, (t * co - s) / (t * t), -s / t - 2 * co / (t * t) + 2 * s / (t * t * t), f);
}

void ctn_beam_rod_b(double y, double f[3])
{
    if (y < 1) {
        double c[NSER], fact = 2;                       /* (-1)^k / (2k + 2)! */
        for (int k = 0; k < NSER; k++) {
            if (k) fact *= (2.0 * k + 1) * (2.0 * k + 2);
            c[k] = (k % 2 ? -1 : 1) / fact;
        }
        series(c, NSER, y, f);
        return;
    }
    double t = sqrt(y), s = sin(t), C = 1 - cos(t), t2 = t * t;
    from_t(t, C / t2, s / t2 - 2 * C / (t2 * t), cos(t) / t2 - 4 * s / (t2 * t) + 6 * C / (t2 * t2), f);
}

#define NLOG 40

void ctn_beam_log_h(double y, double f[3])
{
    if (y < 0.25) {
        double c[NLOG];                                 /* asin(s)/s = sum c_k s^2k */
        c[0] = 1;
        for (int k = 1; k < NLOG; k++) c[k] = c[k - 1] * (2.0 * k - 1) * (2.0 * k - 1) / ((2.0 * k) * (2.0 * k + 1));
        series(c, NLOG, y, f);
        return;
    }
    double s = sqrt(y), r = sqrt(1 - y), as = asin(s);
    from_t(s, as / s, 1 / (s * r) - as / y, 1 / (r * r * r) - 2 / (y * r) + 2 * as / (y * s), f);
}
