/* Analytic layer: the inextensible catenary against the paper's relations, independent
 * numerical checks of the shape (length by polylines, the catenary ODE by differences),
 * equilibrium of inclined spans, and the taut and slack limits. */
#include "catena/analytic.h"
#include "check.h"

static ctn_catenary solve(double l, double h, double w, double S)
{
    ctn_catenary cat;
    ctn_catenary_in in = {l, h, w, S};
    int st = ctn_catenary_solve(NULL, &in, &cat);
    CHECK_MSG(st == CTN_OK, "l %g h %g S %.17g: %s", l, h, S, ctn_strerror(st));
    return cat;
}

/* The paper: span 200 m, w = 0.1 kN/m; S = 2 c sinh(l/2c), T = w c cosh(l/2c). */
static void test_paper(void)
{
    const double S[] = {200.3340, 201.3545, 250.8777, 279.6157};
    for (int i = 0; i < 4; i++) {
        ctn_catenary cat = solve(200.0, 0.0, 0.1, S[i]);
        double c = cat.c, u = 100.0 / c;
        CHECK_CLOSE(2.0 * c * sinh(u), S[i], 1e-12, 0.0);
        CHECK_CLOSE(cat.sum.T_max, 0.1 * c * cosh(u), 1e-12, 0.0);
        CHECK_CLOSE(hypot(cat.sum.H, cat.sum.reaction_left[1]), 0.1 * c * cosh(u), 1e-12, 0.0);
        CHECK_CLOSE(cat.sum.H, 0.1 * c, 1e-15, 0.0);
        CHECK_CLOSE(cat.sum.sag, c * (cosh(u) - 1.0), 1e-12, 0.0);
        CHECK_CLOSE(cat.sum.sag_mid, cat.sum.sag, 1e-12, 0.0);
        CHECK_CLOSE(cat.sum.reaction_left[1], 0.05 * S[i], 1e-12, 0.0);
        CHECK_CLOSE(cat.sum.T_min, cat.sum.H, 1e-15, 0.0);
    }
}

/* Length by polylines with Richardson extrapolation (independent of the arc formula). */
static double polyline_length(const ctn_catenary *cat, int n)
{
    double len[2];
    for (int r = 0; r < 2; r++) {
        int m = n << r;
        double x0 = 0.0, y0 = 0.0, y;
        len[r] = 0.0;
        for (int i = 1; i <= m; i++) {
            double x = cat->in.l * i / m;
            ctn_catenary_y(cat, x, &y);
            len[r] += hypot(x - x0, y - y0);
            x0 = x;
            y0 = y;
        }
    }
    return (4.0 * len[1] - len[0]) / 3.0;
}

/* y'' = (w / H) sqrt(1 + y'^2) by central differences at a few stations. */
static void check_ode(const ctn_catenary *cat)
{
    double l = cat->in.l, e = 2e-4 * l;
    for (int i = 1; i < 8; i++) {
        double x = l * i / 8.0, ym, y0, yp;
        ctn_catenary_y(cat, x - e, &ym);
        ctn_catenary_y(cat, x, &y0);
        ctn_catenary_y(cat, x + e, &yp);
        double d1 = (yp - ym) / (2 * e), d2 = (yp - 2 * y0 + ym) / (e * e);
        CHECK_CLOSE(d2, cat->in.w / cat->sum.H * sqrt(1 + d1 * d1), 1e-5, 0.0);
    }
}

/* Sag: the reported maximum dominates a grid, agrees with chord - y; tensions bounded. */
static void check_sag_tension(const ctn_catenary *cat)
{
    const ctn_analytic_summary *s = &cat->sum;
    double l = cat->in.l, h = cat->in.h, y, d, T;
    ctn_catenary_y(cat, s->x_sag, &y);
    CHECK_CLOSE(s->sag, h * s->x_sag / l - y, 1e-9, 0.0);
    ctn_catenary_y(cat, 0.5 * l, &y);
    CHECK_CLOSE(s->sag_mid, 0.5 * h - y, 1e-9, 0.0);
    for (int i = 0; i <= 100; i++) {
        double x = l * i / 100.0;
        ctn_catenary_sag(cat, x, &d);
        ctn_catenary_tension(cat, x, &T);
        CHECK(d <= s->sag * (1 + 1e-14));
        CHECK(T >= s->T_min * (1 - 1e-14) && T <= s->T_max * (1 + 1e-14));
    }
}

static void check_inclined(double l, double h, double ratio)
{
    double w = 0.1, S = ratio * hypot(l, h), y, s, T;
    ctn_catenary cat = solve(l, h, w, S);
    const ctn_analytic_summary *r = &cat.sum;
    CHECK_CLOSE(r->reaction_left[1] + r->reaction_right[1], w * S, 1e-13, 0.0);
    CHECK(r->reaction_left[0] == -r->H && r->reaction_right[0] == r->H);
    ctn_catenary_y(&cat, 0.0, &y);
    CHECK(y == 0.0);
    ctn_catenary_y(&cat, l, &y);
    CHECK_CLOSE(y, h, 1e-13, 1e-13 * l);
    ctn_catenary_arc(&cat, l, &s);
    CHECK_CLOSE(s, S, 1e-13, 0.0);
    CHECK_CLOSE(polyline_length(&cat, 4000), S, 1e-10, 0.0);
    ctn_catenary_tension(&cat, 0.0, &T);
    CHECK_CLOSE(T, hypot(r->H, r->reaction_left[1]), 1e-13, 0.0);
    ctn_catenary_tension(&cat, l, &T);
    CHECK_CLOSE(T, hypot(r->H, r->reaction_right[1]), 1e-13, 0.0);
    for (int i = 0; i <= 4; i++) {                     /* T = w y + const (vertex axes) */
        double x = l * i / 4.0, Tx;
        ctn_catenary_y(&cat, x, &y);
        ctn_catenary_tension(&cat, x, &Tx);
        CHECK_CLOSE(Tx - w * y, hypot(r->H, r->reaction_left[1]), 1e-12, 0.0);
    }
    check_ode(&cat);
    check_sag_tension(&cat);
}

static void test_inclined(void)
{
    const double h[] = {0.0, 50.0, -80.0, 300.0, -2000.0};
    const double ratio[] = {1.001, 1.3, 3.0};
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 3; j++) check_inclined(200.0, h[i], ratio[j]);
}

/* Taut: the sag tends to the parabola's f = sqrt(3 C^3 (S - C) / (8 l^2)) with a relative
 * error O(S/C - 1); checking it down to S/C - 1 = 1e-15 shows the sag suffers no
 * cancellation (chord - y computed naively loses ~1e-10 here on inclined spans). */
static void test_taut(void)
{
    const double h[] = {0.0, 30.0, -150.0};
    for (int i = 0; i < 3; i++) {
        double l = 200.0, C = hypot(l, h[i]);
        for (double delta = 1e-6; delta > 5e-16; delta *= 0.1) {
            double S = C * (1.0 + delta);
            ctn_catenary cat = solve(l, h[i], 0.1, S);
            double f = sqrt(3.0 * C * C * C * (S - C) / (8.0 * l * l));
            CHECK_CLOSE(cat.sum.sag_mid, f, 0.5 * delta + 2e-14, 0.0);
            CHECK_CLOSE(cat.sum.sag, cat.sum.sag_mid, delta + 2e-14, 0.0);
            if (h[i] == 0.0) CHECK_CLOSE(2.0 * cat.c * sinh(cat.u), S, 1e-15, 0.0);
        }
    }
}

/* Slack: T_support = w (sag + c) (T = w y) and S = 2 c sinh(l / 2c), far into the range. */
static void test_slack(void)
{
    for (double r = 10.0; r < 1e250; r *= 1e30) {
        ctn_catenary cat = solve(200.0, 0.0, 0.1, 200.0 * r);
        CHECK_CLOSE(cat.sum.T_max, 0.1 * (cat.sum.sag + cat.c), 1e-12, 0.0);
        CHECK_CLOSE(2.0 * cat.c * sinh(cat.u), 200.0 * r, 1e-12, 0.0);
        CHECK(cat.sum.sag <= 100.0 * r * (1 + 1e-12) && cat.sum.sag > 0.45 * 200.0 * r);
    }
    ctn_catenary a = solve(200.0, 1e-9, 0.1, 250.0), b = solve(200.0, 0.0, 0.1, 250.0);
    CHECK_CLOSE(a.sum.H, b.sum.H, 1e-12, 0.0);         /* inclined formula -> level */
}

int main(void)
{
    test_paper();
    test_inclined();
    test_taut();
    test_slack();
    CHECK_DONE();
}
