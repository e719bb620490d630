/* Analytic layer: the safeguarded root finder, bracketing and the stable special
 * functions, against independent long-double references. */
#include "analytic/an.h"
#include "check.h"

#include <float.h>

/* x^3 - a, a > 0 */
static int cube(void *data, double x, double *f, double *df)
{
    double a = *(const double *)data;
    *f = x * x * x - a;
    *df = 3.0 * x * x;
    return CTN_OK;
}

/* Steep tanh: pure Newton overshoots and diverges from far away. */
static int steep(void *data, double x, double *f, double *df)
{
    (void)data;
    double t = tanh(50.0 * (x - 0.3));
    *f = t;
    *df = 50.0 * (1.0 - t * t);
    return CTN_OK;
}

/* A jump at 1/3 with a useless derivative: only bisection can find it. */
static int jump(void *data, double x, double *f, double *df)
{
    (void)data;
    *f = x < 1.0 / 3.0 ? -1.0 : 1.0;
    *df = 0.0;
    return CTN_OK;
}

static int nan_fn(void *data, double x, double *f, double *df)
{
    (void)data; (void)x;
    *f = NAN;
    *df = 1.0;
    return CTN_OK;
}

static int failing(void *data, double x, double *f, double *df)
{
    (void)data; (void)x; (void)f; (void)df;
    return CTN_ERR_DOMAIN;
}

static int log_minus(void *data, double x, double *f, double *df)
{
    *f = log(x) - *(const double *)data;
    *df = 1.0 / x;
    return CTN_OK;
}

static int negative(void *data, double x, double *f, double *df)
{
    (void)data; (void)x;
    *f = -1.0;
    *df = 0.0;
    return CTN_OK;
}

static void test_root(void)
{
    double a = 2.0, r = 0.0;
    CHECK(ctn_an_root(cube, &a, 0.0, 2.0, 1.9, &r) == CTN_OK);
    CHECK_CLOSE(r, cbrt(2.0), 4 * DBL_EPSILON, 0.0);
    CHECK(ctn_an_root(steep, NULL, -10.0, 10.0, 9.0, &r) == CTN_OK);
    CHECK_CLOSE(r, 0.3, 8 * DBL_EPSILON, 0.0);
    CHECK(ctn_an_root(jump, NULL, 0.0, 1.0, 0.9, &r) == CTN_OK);
    CHECK_CLOSE(r, 1.0 / 3.0, 8 * DBL_EPSILON, 0.0);
    CHECK(ctn_an_root(nan_fn, NULL, 0.0, 1.0, 0.5, &r) == CTN_ERR_NOCONV);
    CHECK(ctn_an_root(failing, NULL, 0.0, 1.0, 0.5, &r) == CTN_ERR_DOMAIN);
}

static void test_bracket(void)
{
    double t = 300.0, lo, hi, r;
    CHECK(ctn_an_bracket(log_minus, &t, 1.0, &lo, &hi) == CTN_OK);
    CHECK(lo < exp(300.0) && exp(300.0) < hi && hi <= 2.0 * lo);
    CHECK(ctn_an_solve_pos(log_minus, &t, 1.0, &r) == CTN_OK);
    CHECK_CLOSE(r, exp(300.0), 1e-12, 0.0);   /* log x has ulp ~ eps * 300 */
    t = -650.0;
    CHECK(ctn_an_solve_pos(log_minus, &t, 1.0, &r) == CTN_OK);
    CHECK_CLOSE(r, exp(-650.0), 1e-12, 0.0);
    CHECK(ctn_an_bracket(negative, NULL, 1.0, &lo, &hi) == CTN_ERR_NOCONV);
}

/* sinh(u)/u - 1: two-term series for tiny u, long double elsewhere. */
static void test_shc1(void)
{
    const double tiny[] = {1e-12, 1e-6, 1e-4};
    for (int i = 0; i < 3; i++) {
        double u = tiny[i];
        CHECK_CLOSE(ctn_an_shc1(u), u * u / 6.0 + u * u * u * u / 120.0, 1e-15, 0.0);
    }
    const double mid[] = {0.3, 0.7, 0.999, 1.0, 3.0, -0.5};
    for (int i = 0; i < 6; i++) {
        long double u = mid[i];
        CHECK_CLOSE(ctn_an_shc1(mid[i]), (double)(sinhl(u) / u - 1.0L), 2e-15, 0.0);
    }
    CHECK(ctn_an_shc1(0.0) == 0.0);
}

static void test_log_sinhc(void)
{
    const double u[] = {1e-8, 0.2, 0.9, 1.0, 5.0, 40.0};
    for (int i = 0; i < 6; i++) {
        long double v = u[i];
        double d, h = 1e-6 * u[i], dp, dm;
        double f = ctn_an_log_sinhc(u[i], &d);
        if (u[i] > 1e-3) CHECK_CLOSE(f, (double)logl(sinhl(v) / v), 4e-15, 0.0);
        else CHECK_CLOSE(f, u[i] * u[i] / 6.0, 1e-14, 0.0);
        double fd = (ctn_an_log_sinhc(u[i] + h, &dp) - ctn_an_log_sinhc(u[i] - h, &dm)) / (2 * h);
        CHECK_CLOSE(d, fd, 1e-7, 0.0);
    }
    double d;
    CHECK_CLOSE(ctn_an_log_sinhc(1000.0, &d), 1000.0 - log(2000.0), 1e-15, 0.0);
    CHECK(isfinite(d));
}

/* asinh differences: opposite signs against long double, close values against the
 * integral of 1/sqrt(H^2 + v^2) by the mean value, exact to O((p-q)^3). */
static void test_asinh_diff(void)
{
    long double H = 2.0L;
    CHECK_CLOSE(ctn_an_asinh_diff(2.0, 3.0, -5.0, 8.0),
                (double)(asinhl(3.0L / H) - asinhl(-5.0L / H)), 1e-15, 0.0);
    const double base[] = {1e3, -1e3, 0.5};
    for (int i = 0; i < 3; i++) {
        double p = base[i], dq = 1e-7, q = p - dq, m = 0.5 * (p + q), T = hypot(2.0, m);
        double expect = dq / T * (1.0 + dq * dq * (2.0 * m * m - 4.0) / (24.0 * T * T * T * T));
        CHECK_CLOSE(ctn_an_asinh_diff(2.0, p, q, dq), expect, 1e-14, 0.0);
    }
}

int main(void)
{
    test_root();
    test_bracket();
    test_shc1();
    test_log_sinhc();
    test_asinh_diff();
    CHECK_DONE();
}
