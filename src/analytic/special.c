/* Special functions of the analytic module, written to avoid cancellation and overflow. */
#include "analytic/an.h"

#include <float.h>
#include <math.h>

double ctn_an_shc1(double u)
{
    if (fabs(u) >= 1.0) return sinh(u) / u - 1.0;
    double u2 = u * u, term = u2 / 6.0, sum = 0.0;     /* sum u^2k / (2k+1)!, k >= 1 */
    for (int k = 1; k < 30 && term > DBL_EPSILON * 0.25 * sum; k++) {
        sum += term;
        term *= u2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    }
    return sum;
}

/* coth(u) - 1/u = (u cosh u - sinh u) / (u sinh u), numerator by its series, |u| < 1. */
static double dlog_sinhc_small(double u)
{
    if (u < 1e-100) return u / 3.0;                   /* u^2 would underflow */
    double u2 = u * u, term = u * u2 / 6.0, num = 0.0; /* u^(2k+1) / (2k+1)! */
    for (int k = 1; k < 30 && term > DBL_EPSILON * 0.25 * fabs(num); k++) {
        num += 2.0 * k * term;                         /* sum 2k u^(2k+1) / (2k+1)! */
        term *= u2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    }
    return num / (u * u * (1.0 + ctn_an_shc1(u)));     /* u sinh u = u^2 (1 + shc1) */
}

double ctn_an_log_sinhc(double u, double *d)
{
    if (u == 0.0) { *d = 0.0; return 0.0; }
    if (u < 1.0) {
        *d = dlog_sinhc_small(u);
        return log1p(ctn_an_shc1(u));
    }
    *d = 1.0 / tanh(u) - 1.0 / u;
    return u - log(2.0 * u) + log1p(-exp(-2.0 * u));   /* log(sinh(u) / u) */
}

double ctn_an_asinh_diff(double H, double p, double q, double pmq)
{
    if ((p > 0.0 && q > 0.0) || (p < 0.0 && q < 0.0)) {
        double Tp = hypot(H, p), Tq = hypot(H, q);
        return asinh(pmq * (p + q) / (p * Tq + q * Tp)); /* sinh(A - B) expanded */
    }
    return asinh(p / H) - asinh(q / H);                /* opposite signs: no cancellation */
}
