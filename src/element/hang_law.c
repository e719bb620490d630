/* The chord of a hanging member from the force at its middle (hang_law.h).
 *
 * The catenary: with g = -up, the force at unstressed arc s from the member's second end
 * is N(s) = S + w (s - l0 / 2) g (w = W / l0): its part normal to gravity is constant,
 * h e_h, its part along gravity V(s) = S.g + w (s - l0 / 2) runs from V1 = S.g - W / 2
 * to V2 = S.g + W / 2. With R = sqrt(h^2 + V^2):
 *   int N / |N| ds = e_h (h / w) [asinh(V / h)] + g (1 / w) [R],
 *   int |N| ds = (1 / w) [(V R + h^2 asinh(V / h)) / 2],
 *   int |N|^2 ds = h^2 l0 + (1 / w) [V^3 / 3],
 * the brackets taken from V1 to V2; int N ds = l0 S. The chord is the first plus
 * l0 S / EA, the gradient in S of phi = int |N| + |N|^2 / (2 EA) ds (tests/test_hang.c
 * checks it by finite differences). */
#include "element/hang_law.h"

#include <math.h>

double ctn_hang_bar(double l0, double EA, const double S[3], double v[3], double H[9])
{
    double T = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]);
    if (!(T > 0 && EA > 0 && isfinite(T))) return NAN;
    double u[3] = { S[0] / T, S[1] / T, S[2] / T }, g = l0 / T, s = l0 / EA;
    for (int p = 0; p < 3; p++) {
        v[p] = l0 * u[p] + s * S[p];
        for (int q = 0; q < 3; q++) H[3 * p + q] = g * ((p == q) - u[p] * u[q]) + (p == q) * s;
    }
    return l0 * T + 0.5 * s * T * T;
}

/* h asinh(V / h), its limit 0 as h -> 0. */
static double h_asinh(double h, double V) { return h > 0 ? h * asinh(V / h) : 0.0; }

double ctn_hang_catenary(double l0, double EA, double W, const double up[3], const double S[3], double v[3],
                         double H[9])
{
    double T = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]);
    double phi = ctn_hang_bar(l0, EA, S, v, H);            /* H (and the bar's answer) */
    if (!(W > 1e-9 * T) || isnan(phi)) return phi;
    double w = W / l0, g[3] = { -up[0], -up[1], -up[2] }, Sg = S[0] * g[0] + S[1] * g[1] + S[2] * g[2];
    double P[3] = { S[0] - Sg * g[0], S[1] - Sg * g[1], S[2] - Sg * g[2] };
    double h = sqrt(P[0] * P[0] + P[1] * P[1] + P[2] * P[2]);
    double V1 = Sg - 0.5 * W, V2 = Sg + 0.5 * W, R1 = hypot(h, V1), R2 = hypot(h, V2);
    if (!(R1 > 0 && R2 > 0)) return NAN;
    double across = (h_asinh(h, V2) - h_asinh(h, V1)) / w;  /* h int ds / R, over h */
    for (int k = 0; k < 3; k++)
        v[k] = (h > 0 ? P[k] / h * across : 0.0) + g[k] * (R2 - R1) / w + l0 / EA * S[k];
    double Tint = (V2 * R2 + h * h_asinh(h, V2) - V1 * R1 - h * h_asinh(h, V1)) / (2 * w);
    double T2int = h * h * l0 + (V2 * V2 * V2 - V1 * V1 * V1) / (3 * w);
    return Tint + T2int / (2 * EA);
}
