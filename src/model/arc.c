/* Circular arcs between two points (see arc.h). */
#include "model/arc.h"

#include <math.h>

#define CTN_PI 3.14159265358979323846

/* sin(a)/a - 1, accurate for small a. */
static double sinc_m1(double a)
{
    if (fabs(a) > 1e-2) return sin(a) / a - 1.0;
    double a2 = a * a;
    return a2 * (-1.0 / 6 + a2 * (1.0 / 120 - a2 / 5040));
}

/* Half-angle in (0, pi) with sin(alpha)/alpha = c/S, by bisection (monotone). */
static double half_angle(double c, double S)
{
    double excess = (S - c) / S, lo = 0.0, hi = CTN_PI;    /* 1 - c/S, no cancellation */
    for (int it = 0; it < 200 && hi - lo > 1e-17 * hi; it++) {
        double mid = 0.5 * (lo + hi);
        if (sinc_m1(mid) + excess > 0) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

int ctn_arc_make(const double A[3], const double B[3], const double g[3], double S,
                 ctn_arc *arc)
{
    double un = 0, gu = 0, nn = 0, g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    for (int k = 0; k < 3; k++) {
        arc->mid[k] = 0.5 * (A[k] + B[k]);
        arc->u[k] = B[k] - A[k];
        un += arc->u[k] * arc->u[k];
    }
    arc->chord = sqrt(un);
    arc->alpha = arc->R = 0;
    if (!(arc->chord > 0) || !(S >= arc->chord)) return -1;
    for (int k = 0; k < 3; k++) {
        arc->u[k] /= arc->chord;
        gu += g[k] * arc->u[k];
    }
    if (S == arc->chord) return 0;                     /* straight: no sag direction */
    if (!(g2 > 0)) return -1;
    for (int k = 0; k < 3; k++) {
        arc->n[k] = g[k] - gu * arc->u[k];
        nn += arc->n[k] * arc->n[k];
    }
    if (!(nn > 1e-20 * g2)) return -1;
    for (int k = 0; k < 3; k++) arc->n[k] /= sqrt(nn);
    if (S > arc->chord) {
        arc->alpha = half_angle(arc->chord, S);
        arc->R = arc->chord / (2 * sin(arc->alpha));
    }
    return 0;
}

void ctn_arc_point(const ctn_arc *arc, double t, double X[3])
{
    if (arc->alpha == 0) {
        for (int j = 0; j < 3; j++) X[j] = arc->mid[j] + (t - 0.5) * arc->chord * arc->u[j];
        return;
    }
    double a = arc->alpha, th = a * (2 * t - 1);                 /* -alpha .. alpha */
    double drop = 2 * sin(0.5 * (a + th)) * sin(0.5 * (a - th)); /* cos th - cos alpha */
    for (int j = 0; j < 3; j++) X[j] = arc->mid[j] + arc->R * (sin(th) * arc->u[j] + drop * arc->n[j]);
}

int ctn_arc_stretched(const ctn_arc *arc, const double A[3], const double B[3],
                      const double g[3], double S, double dt, double eps, ctn_arc *out)
{
    double S2 = S * (1 + eps);
    (void)arc;
    for (int it = 0; it < 50; it++) {                /* chord = arc * sin(phi)/phi */
        if (ctn_arc_make(A, B, g, S2, out)) return -1;
        double phi = out->alpha * dt, ratio = phi > 0 ? sin(phi) / phi : 1;
        double next = S * (1 + eps) / ratio;
        if (fabs(next - S2) <= 1e-15 * S2) break;
        S2 = next;
    }
    return 0;
}
