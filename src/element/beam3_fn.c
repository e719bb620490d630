/* The scalar functions of the beam's rotations (beam3.h), smooth in y = t^2: a power
 * series near 0, the closed form of t = sqrt(y) beyond, with
 *   f'(y) = F'(t) / (2 t),  f''(y) = (F''(t) - F'(t) / t) / (4 t^2). */
#include "element/beam3.h"

#include <math.h>

/* f, f', f'' of sum_k c_k y^k, c_0 given and c_k = c_(k-1) r[k] (r[0] unused), summed
 * forward until the terms of f'' (the slowest, k (k - 1) c_k y^(k-2)) fall below 1e-17
 * of it (the series below alternate or shrink by a factor of y or less: a few terms at
 * the small local rotations of a meshed member), n terms at most. */
static void series(double c0, const double *r, int n, double y, double f[3])
{
    double c = c0, yk1 = 1, yk2 = 0;                    /* y^(k-1), y^(k-2) */
    f[0] = c0;
    f[1] = f[2] = 0;
    for (int k = 1; k < n; k++) {
        c *= r[k];
        double t2 = k * (k - 1) * c * yk2;
        f[2] += t2;
        f[1] += k * c * yk1;
        f[0] += c * yk1 * y;
        if (k >= 3 && fabs(t2) <= 1e-17 * fabs(f[2])) break;
        yk2 = yk1;
        yk1 *= y;
    }
}

static void from_t(double t, double F0, double F1, double F2, double f[3])
{
    f[0] = F0;
    f[1] = F1 / (2 * t);
    f[2] = (F2 - F1 / t) / (4 * t * t);
}

#define NSER 20
#define NLOG 40

/* The ratios c_k / c_(k-1) of the series: sin(t)/t, (-1)^k / (2k + 1)!; (1 - cos t)/t^2,
 * (-1)^k / (2k + 2)!; asin(s)/s, (2k - 1)^2 / ((2k) (2k + 1)) (constants). */
#define RA(k) (-1.0 / ((2.0 * (k)) * (2.0 * (k) + 1)))
#define RB(k) (-1.0 / ((2.0 * (k) + 1) * (2.0 * (k) + 2)))
#define RH(k) ((2.0 * (k) - 1) * (2.0 * (k) - 1) / ((2.0 * (k)) * (2.0 * (k) + 1)))
#define R10(R, k) R(k), R(k + 1), R(k + 2), R(k + 3), R(k + 4), R(k + 5), R(k + 6), R(k + 7), R(k + 8), R(k + 9)
static const double ratio_a[NSER + 1] = { 0, R10(RA, 1), R10(RA, 11) };
static const double ratio_b[NSER + 1] = { 0, R10(RB, 1), R10(RB, 11) };
static const double ratio_h[NLOG + 1] = { 0, R10(RH, 1), R10(RH, 11), R10(RH, 21), R10(RH, 31) };

void ctn_beam_rod_a(double y, double f[3])
{
    if (y < 1) {
        series(1, ratio_a, NSER, y, f);
        return;
    }
    double t = sqrt(y), s = sin(t), co = cos(t);
    from_t(t, s / t, (t * co - s) / (t * t), -s / t - 2 * co / (t * t) + 2 * s / (t * t * t), f);
}

void ctn_beam_rod_b(double y, double f[3])
{
    if (y < 1) {
        series(0.5, ratio_b, NSER, y, f);
        return;
    }
    double t = sqrt(y), s = sin(t), C = 1 - cos(t), t2 = t * t;
    from_t(t, C / t2, s / t2 - 2 * C / (t2 * t), cos(t) / t2 - 4 * s / (t2 * t) + 6 * C / (t2 * t2), f);
}

void ctn_beam_log_h(double y, double f[3])
{
    if (y < 0.25) {                                     /* asin(s)/s = sum c_k s^2k */
        series(1, ratio_h, NLOG, y, f);
        return;
    }
    double s = sqrt(y), r = sqrt(1 - y), as = asin(s);
    from_t(s, as / s, 1 / (s * r) - as / y, 1 / (r * r * r) - 2 / (y * r) + 2 * as / (y * s), f);
}
