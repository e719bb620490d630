/* Analytic layer: the parabolic cable (load per horizontal length), inextensible and
 * elastic, level and inclined: the small-sag limit of the catenary, equilibrium, lengths
 * by independent polyline quadrature, and H y'' = q by finite differences. */
#include "catena/analytic.h"
#include "check.h"

static ctn_parabola solve(double l, double h, double q, double L0, double EA)
{
    ctn_parabola par;
    ctn_parabola_in in = {l, h, q, L0, EA};
    int st = ctn_parabola_solve(NULL, &in, &par);
    CHECK_MSG(st == CTN_OK, "l %g h %g L0 %.17g EA %g: %s", l, h, L0, EA, ctn_strerror(st));
    return par;
}

/* Relative difference of H between the parabola (q = w S / l) and the catenary of the
 * same length S = C (1 + 8/3 rho^2), rho ~ sag / span. */
static double h_difference(double h, double rho)
{
    double l = 200.0, w = 0.1, S = hypot(l, h) * (1.0 + 8.0 / 3.0 * rho * rho);
    ctn_catenary_in ci = {l, h, w, S};
    ctn_catenary cat;
    CHECK(ctn_catenary_solve(NULL, &ci, &cat) == CTN_OK);
    ctn_parabola par = solve(l, h, w * S / l, S, INFINITY);
    CHECK_CLOSE(par.sum.sag_mid, cat.sum.sag_mid, 4.0 * rho * rho, 0.0);
    return fabs(par.H - cat.sum.H) / cat.sum.H;
}

/* The difference falls like rho^2: each halving of rho divides it by 4. */
static void test_small_sag_limit(void)
{
    const double h[] = {0.0, 50.0, -80.0};
    for (int i = 0; i < 3; i++) {
        double prev = h_difference(h[i], 0.1);
        for (double rho = 0.05; rho > 0.003; rho *= 0.5) {
            double d = h_difference(h[i], rho);
            CHECK_MSG(prev / d > 3.8 && prev / d < 4.2, "h %g rho %g ratio %g", h[i], rho,
                      prev / d);
            CHECK(d < 2.0 * rho * rho);
            prev = d;
        }
    }
}

/* Polyline through y(x): stretched length, and unstressed length sum ds / (1 + T / EA)
 * with T at the chord mid-points; Richardson-extrapolated. */
static void polyline(const ctn_parabola *par, int n, double *len, double *len0)
{
    double a[2], b[2];
    for (int r = 0; r < 2; r++) {
        int m = n << r;
        double x0 = 0.0, y0 = 0.0, y, T;
        a[r] = b[r] = 0.0;
        for (int i = 1; i <= m; i++) {
            double x = par->in.l * i / m;
            ctn_parabola_y(par, x, &y);
            ctn_parabola_tension(par, 0.5 * (x + x0), &T);
            a[r] += hypot(x - x0, y - y0);
            b[r] += hypot(x - x0, y - y0) / (1.0 + T / par->in.EA);
            x0 = x;
            y0 = y;
        }
    }
    *len = (4.0 * a[1] - a[0]) / 3.0;
    *len0 = (4.0 * b[1] - b[0]) / 3.0;
}

static void check_case(double h, double ratio, double EA)
{
    double l = 200.0, q = 0.1, L0 = ratio * hypot(l, h), y, T, len, len0;
    ctn_parabola par = solve(l, h, q, L0, EA);
    const ctn_analytic_summary *r = &par.sum;
    CHECK_CLOSE(r->reaction_left[1] + r->reaction_right[1], q * l, 1e-14, 0.0);
    CHECK(r->reaction_left[0] == -par.H && r->reaction_right[0] == par.H);
    ctn_parabola_y(&par, 0.0, &y);
    CHECK(y == 0.0);
    ctn_parabola_y(&par, l, &y);
    CHECK_CLOSE(y, h, 0.0, 1e-13 * l);
    ctn_parabola_tension(&par, 0.0, &T);
    CHECK_CLOSE(T, hypot(par.H, r->reaction_left[1]), 1e-14, 0.0);
    ctn_parabola_tension(&par, l, &T);
    CHECK_CLOSE(T, hypot(par.H, r->reaction_right[1]), 1e-14, 0.0);
    ctn_parabola_y(&par, 0.5 * l, &y);
    CHECK_CLOSE(r->sag_mid, 0.5 * h - y, 1e-12, 0.0);
    CHECK_CLOSE(r->sag, q * l * l / (8.0 * par.H), 1e-15, 0.0);
    polyline(&par, 4000, &len, &len0);
    CHECK_CLOSE(len, r->length, 1e-10, 0.0);
    CHECK_CLOSE(len0, L0, 1e-10, 0.0);
    for (int i = 1; i < 8; i++) {                      /* H y'' = q (y up, load down) */
        double x = l * i / 8.0, e = 1.0, ym, yp;
        ctn_parabola_y(&par, x - e, &ym);
        ctn_parabola_y(&par, x, &y);
        ctn_parabola_y(&par, x + e, &yp);
        CHECK_CLOSE(par.H * (yp - 2 * y + ym) / (e * e), q, 1e-8, 0.0);
        ctn_parabola_tension(&par, x, &T);
        CHECK(T >= r->T_min * (1 - 1e-14) && T <= r->T_max * (1 + 1e-14));
    }
}

static void test_cases(void)
{
    const double h[] = {0.0, 40.0, -120.0, 500.0};
    for (int i = 0; i < 4; i++) {
        check_case(h[i], 1.02, INFINITY);
        check_case(h[i], 1.5, INFINITY);
        check_case(h[i], 1.02, 1e4);
        check_case(h[i], 0.998, 1e4);                  /* elastic, shorter than the chord */
        check_case(h[i], 4.0, 50.0);                   /* slack and soft */
    }
}

/* EA -> infinity reproduces the inextensible parabola. */
static void test_inextensible_limit(void)
{
    const double h[] = {0.0, 70.0};
    for (int i = 0; i < 2; i++) {
        double L0 = 1.01 * hypot(200.0, h[i]);
        ctn_parabola a = solve(200.0, h[i], 0.1, L0, 1e16);
        ctn_parabola b = solve(200.0, h[i], 0.1, L0, INFINITY);
        CHECK_CLOSE(a.H, b.H, 1e-9, 0.0);
        CHECK_CLOSE(a.sum.sag, b.sum.sag, 1e-9, 0.0);
        CHECK_CLOSE(b.sum.length, L0, 0.0, 0.0);
    }
}

int main(void)
{
    test_small_sag_limit();
    test_cases();
    test_inextensible_limit();
    CHECK_DONE();
}
