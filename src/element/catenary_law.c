/* The elastic catenary's closed forms as means over the vertical tension V in [-b, a]
 * (a + b = w, the weight of the part; a the upward force at its start, b at its end):
 *   m0 = mean of T,  m1 = mean of 1 / T,  m2 = mean of V^2 / T^3,  m3 = mean of H^2 / T^3,
 * T = sqrt(H^2 + V^2). When [-b, a] holds V = 0 the antiderivatives' values at the two
 * ends add (no cancellation); when it does not, the difference of the values at x > y > 0
 * (the interval mirrored, T is even) is rewritten by exact identities, e.g.
 *   asinh(x/H) - asinh(y/H) = asinh(z),  z = (x - y)(x + y) / (x Ty + y Tx),
 * so that a narrow interval (w -> 0) loses no digits. */
#include "element/catenary.h"

#include <math.h>

/* asinh(V / H), H >= 0, without overflow of the ratio. */
static double asinh_ratio(double V, double H)
{
    if (fabs(V) < 1e150 * H) return asinh(V / H);
    return V == 0 ? 0.0 : copysign(log(2 * fabs(V)) - log(H), V);
}

/* asinh(z) / z. */
static double asinhc(double z)
{
    double z2 = z * z;
    if (fabs(z) < 1e-3) return 1 - z2 / 6 + 3 * z2 * z2 / 40 - 5 * z2 * z2 * z2 / 112;
    return asinh(z) / z;
}

/* phi(V) = asinh(V/H) - V/T, the antiderivative of V^2 / T^3 (series when |V| << H). */
static double phi(double V, double H, double T)
{
    double v = H > 0 ? V / H : 0;
    if (H > 0 && fabs(v) < 0.25) {                     /* v^3/3 - 3 v^5/10 + 15 v^7/56 ... */
        double v2 = v * v, term = v * v2, c = 1, sum = 0;
        for (int k = 0; k < 16; k++) {
            sum += c * term / (2 * k + 3);
            c *= -(2.0 * k + 3) / (2.0 * k + 2);      /* binomial(-3/2, k + 1) */
            term *= v2;
        }
        return sum;
    }
    return asinh_ratio(V, H) - (T > 0 ? V / T : 0);
}

/* Divided difference of phi between v = x/H and y/H, 0 <= y < x < H/4, times H:
 * the mean of V^2 / T^3 over [y, x] by the series, term by term (all positive). */
static double phi_mean_small(double x, double y, double H)
{
    double a = x / H, b = y / H, c = 1, sum = 0;
    double dd = a * a + a * b + b * b, bn = b * b * b;          /* dd of v^3; b^3 */
    for (int k = 0; k < 16; k++) {
        sum += c * dd / (2 * k + 3);
        c *= -(2.0 * k + 3) / (2.0 * k + 2);
        dd = a * a * dd + bn * (a + b);        /* (a^(n+2) - b^(n+2)) / (a - b) */
        bn *= b * b;
    }
    return sum / H;
}

/* The means m[0..3] over V in [-b, a], a + b = w > 0. */
static void means(double H, double a, double b, double w, double m[4])
{
    double Ta = hypot(H, a), Tb = hypot(H, b);
    if (a >= 0 && b >= 0) {                            /* V = 0 inside: values add */
        double Ga = 0.5 * (a * Ta + (H > 0 ? H * H * asinh_ratio(a, H) : 0));
        double Gb = 0.5 * (b * Tb + (H > 0 ? H * H * asinh_ratio(b, H) : 0));
        m[0] = (Ga + Gb) / w;
        m[1] = H > 0 ? (asinh_ratio(a, H) + asinh_ratio(b, H)) / w : INFINITY;
        m[3] = ((Ta > 0 ? a / Ta : 0) + (Tb > 0 ? b / Tb : 0)) / w;
        m[2] = H > 0 ? (phi(a, H, Ta) + phi(b, H, Tb)) / w : INFINITY;
        return;
    }
    double x = a > 0 ? a : b, y = a > 0 ? -b : -a;     /* mirrored: x - y = w, x > y > 0 */
    double Tx = a > 0 ? Ta : Tb, Ty = a > 0 ? Tb : Ta;
    double den = x * Ty + y * Tx, s = x + y;
    double A = asinhc(w * s / den) * s / den;          /* (asinh(x/H) - asinh(y/H)) / w */
    m[1] = A;
    m[3] = H * H * s / (Tx * Ty * den);
    m[2] = x < 0.25 * H ? phi_mean_small(x, y, H) : A - m[3];
    m[0] = 0.5 * (s * (H * H + x * x + y * y) / (x * Tx + y * Ty) + H * H * A);
}

void ctn_ecat_law(ctn_ecat *c, double *l, double *h)
{
    double m[4], L = c->L, H = c->H;
    c->Va = c->W - c->Vb;
    double Va = c->Va, Vb = c->Vb, Ta = hypot(H, Va), Tb = hypot(H, Vb);
    means(H, Va, Vb, c->W, m);
    *l = H > 0 ? H * L / c->EA + H * L * m[1] : 0;
    *h = L * (Vb - Va) * (0.5 / c->EA + 1 / (Ta + Tb));
    c->Fhh = L / c->EA + L * m[2];
    c->Fhv = H > 0 ? L * H * (Va - Vb) / (Ta * Tb * (Ta + Tb)) : 0;
    c->Fvv = L / c->EA + L * m[3];
}

double ctn_ecat_energy(const ctn_ecat *c)
{
    double m[4], L = c->L, H = c->H, Va = c->Va, Vb = c->Vb;
    means(H, Va, Vb, c->W, m);
    double T2 = H * H * L + L * (Va * Va - Va * Vb + Vb * Vb) / 3;    /* int T^2 ds */
    double C = L * m[0] + T2 / (2 * c->EA);                          /* complementary */
    return H * c->l + 0.5 * (Vb - Va) * c->h - C;
}

void ctn_ecat_point(const ctn_ecat *c, double s, double *x, double *z)
{
    double q = c->W / c->L, Vs = c->Va - q * s, m[4];
    if (s <= 0) { *x = *z = 0; return; }
    means(c->H, c->Va, -Vs, q * s, m);
    *x = c->H > 0 ? c->H * s / c->EA + c->H * s * m[1] : 0;
    *z = -s * (c->Va + Vs) * (0.5 / c->EA + 1 / (hypot(c->H, c->Va) + hypot(c->H, Vs)));
}

double ctn_ecat_length(const ctn_ecat *c)
{
    double m[4];
    means(c->H, c->Va, c->Vb, c->W, m);
    return c->L + c->L * m[0] / c->EA;                /* L + (1/EA) int T ds */
}
