/* Analytic layer: the elastic catenary. The differential equations of the cable,
 *   dx/ds = (H / T) (1 + T / EA),  dz/ds = ((V - w s) / T) (1 + T / EA),
 *   T = sqrt(H^2 + (V - w s)^2),  z = depth below the left support,
 * are integrated numerically (RK4, independent of the closed form) with the solved H, V
 * and must land on the right support; plus equilibrium, the EA -> infinity limit, the
 * taut (L0 < chord) and slack cases and docs/analytic.md's mid-span formula. */
#include "catena/analytic.h"
#include "check.h"

static ctn_ecatenary solve(double l, double h, double w, double EA, double L0)
{
    ctn_ecatenary cat;
    ctn_ecatenary_in in = {l, h, w, EA, L0};
    int st = ctn_ecatenary_solve(NULL, &in, &cat);
    CHECK_MSG(st == CTN_OK, "l %g h %g EA %g L0 %.17g: %s", l, h, EA, L0, ctn_strerror(st));
    return cat;
}

/* Right-hand side: (dx/ds, dz/ds, d(stretched length)/ds). */
static void rhs(const ctn_ecatenary *cat, double s, double *f)
{
    double V = cat->V_left - cat->in.w * s, T = hypot(cat->H, V), k = 1.0 + T / cat->in.EA;
    f[0] = cat->H / T * k;
    f[1] = V / T * k;
    f[2] = k;
}

/* RK4 from s = 0 to s = s_end in n steps; state (x, z, length). */
static void integrate(const ctn_ecatenary *cat, double s_end, int n, double *u)
{
    double ds = s_end / n;
    u[0] = u[1] = u[2] = 0.0;
    for (int i = 0; i < n; i++) {
        double s = i * ds, k1[3], k2[3], k3[3], k4[3];
        rhs(cat, s, k1);
        rhs(cat, s + 0.5 * ds, k2);                    /* the state does not enter f */
        rhs(cat, s + 0.5 * ds, k3);
        rhs(cat, s + ds, k4);
        for (int j = 0; j < 3; j++) u[j] += ds / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
}

static void check_closure(double l, double h, double EA, double ratio)
{
    double w = 0.1, C = hypot(l, h), u[3], x, y;
    ctn_ecatenary cat = solve(l, h, w, EA, ratio * C);
    integrate(&cat, cat.in.L0, 4000, u);
    CHECK_CLOSE(u[0], l, 0.0, 1e-9 * C);
    CHECK_CLOSE(-u[1], h, 0.0, 1e-9 * C);
    CHECK_CLOSE(u[2], cat.sum.length, 1e-9, 0.0);
    integrate(&cat, cat.in.L0 / 3.0, 4000, u);         /* an interior material point */
    ctn_ecatenary_point(&cat, cat.in.L0 / 3.0, &x, &y);
    CHECK_CLOSE(x, u[0], 0.0, 1e-9 * C);
    CHECK_CLOSE(y, -u[1], 0.0, 1e-9 * C);
}

static void test_closure(void)
{
    const double h[] = {0.0, 50.0, -80.0, 400.0};
    const double ratio[] = {0.999, 1.0, 1.01, 1.3, 5.0};
    const double EA[] = {1e3, 1e5, 1e9};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 5; j++)
            for (int k = 0; k < 3; k++) check_closure(200.0, h[i], EA[k], ratio[j]);
}

/* Supports: T = sqrt(H^2 + V^2), V_left + V_right = w L0, H constant, y through both. */
static void check_supports(double h, double EA, double ratio)
{
    double l = 200.0, w = 0.1, L0 = ratio * hypot(l, h), T, x, y;
    ctn_ecatenary cat = solve(l, h, w, EA, L0);
    const ctn_analytic_summary *r = &cat.sum;
    CHECK_CLOSE(r->reaction_left[1] + r->reaction_right[1], w * L0, 1e-14, 0.0);
    CHECK(r->reaction_left[0] == -cat.H && r->reaction_right[0] == cat.H && r->H == cat.H);
    ctn_ecatenary_tension_s(&cat, 0.0, &T);
    CHECK_CLOSE(T, hypot(cat.H, r->reaction_left[1]), 1e-14, 0.0);
    ctn_ecatenary_tension_s(&cat, L0, &T);
    CHECK_CLOSE(T, hypot(cat.H, r->reaction_right[1]), 1e-14, 0.0);
    ctn_ecatenary_point(&cat, L0, &x, &y);
    CHECK_CLOSE(x, l, 1e-13, 0.0);
    CHECK_CLOSE(y, h, 0.0, 1e-13 * l);
    for (int i = 0; i <= 10; i++) {                    /* y(x) through s(x), extremes */
        double s = L0 * i / 10.0, yx, Tx;
        ctn_ecatenary_point(&cat, s, &x, &y);
        x = fmin(x, l);                                /* x(L0) = l up to rounding */
        CHECK(ctn_ecatenary_y(&cat, x, &yx) == CTN_OK);
        CHECK(ctn_ecatenary_tension(&cat, x, &Tx) == CTN_OK);
        CHECK_CLOSE(yx, y, 0.0, 1e-12 * l);
        CHECK(Tx >= r->T_min * (1 - 1e-12) && Tx <= r->T_max * (1 + 1e-12));
        CHECK(h * x / l - y <= r->sag * (1 + 1e-12));
    }
}

static void test_supports(void)
{
    const double h[] = {0.0, 60.0, -300.0};
    for (int i = 0; i < 3; i++) {
        check_supports(h[i], 1e4, 1.2);
        check_supports(h[i], 1e6, 0.995);
        check_supports(h[i], 1e2, 3.0);
    }
}

/* EA -> infinity reproduces the inextensible catenary (another code path). */
static void test_inextensible_limit(void)
{
    const double h[] = {0.0, 50.0, -120.0};
    const double ratio[] = {1.0005, 1.05, 2.0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double S = ratio[j] * hypot(200.0, h[i]);
            ctn_catenary_in ci = {200.0, h[i], 0.1, S};
            ctn_catenary ref;
            CHECK(ctn_catenary_solve(NULL, &ci, &ref) == CTN_OK);
            ctn_ecatenary a = solve(200.0, h[i], 0.1, 1e16, S);
            ctn_ecatenary b = solve(200.0, h[i], 0.1, INFINITY, S);
            CHECK_CLOSE(a.H, ref.sum.H, 1e-9, 0.0);
            CHECK_CLOSE(a.sum.sag, ref.sum.sag, 1e-9, 0.0);
            CHECK_CLOSE(a.sum.sag_mid, ref.sum.sag_mid, 1e-9, 0.0);
            CHECK_CLOSE(a.V_left, ref.sum.reaction_left[1], 1e-9, 0.0);
            CHECK_CLOSE(b.H, ref.sum.H, 1e-12, 0.0);
            CHECK_CLOSE(b.sum.sag, ref.sum.sag, 1e-11, 0.0);
            CHECK_CLOSE(b.sum.length, S, 1e-15, 0.0);
        }
}

/* Level span: V = w L0 / 2 and the elastic catenary's z(L0/2) = w L0^2 / (8 EA) + (T_support - H) / w. */
static void test_level_midspan(void)
{
    const double EA[] = {50.0, 1e4, 1e8};
    for (int k = 0; k < 3; k++) {
        double w = 0.1, L0 = 230.0;
        ctn_ecatenary cat = solve(200.0, 0.0, w, EA[k], L0);
        double V = cat.V_left;
        CHECK_CLOSE(V, 0.5 * w * L0, 1e-15, 0.0);
        CHECK_CLOSE(cat.sum.sag_mid, w * L0 * L0 / (8 * EA[k]) + (hypot(cat.H, V) - cat.H) / w,
                    1e-12, 0.0);
        CHECK_CLOSE(cat.sum.x_sag, 100.0, 1e-12, 0.0);
    }
}

/* Taut: a short cable is stretched straight-ish, N ~ EA (C / L0 - 1) plus the strain the
 * small sag needs (about 0.5 % here); the stretched length lies between the extremes. */
static void test_taut(void)
{
    double l = 100.0, h = 30.0, C = hypot(l, h), EA = 1e5, L0 = 0.999 * C;
    ctn_ecatenary cat = solve(l, h, 0.01, EA, L0);
    double N = EA * (C / L0 - 1.0);
    CHECK_CLOSE(cat.sum.T_max, N, 1e-2, 0.0);
    CHECK_CLOSE(cat.H, N * l / C, 1e-2, 0.0);
    CHECK(cat.sum.length > C && cat.sum.length < C * (1 + 1e-4));
    CHECK(cat.sum.length >= L0 * (1 + cat.sum.T_min / EA));
    CHECK(cat.sum.length <= L0 * (1 + cat.sum.T_max / EA));
}

int main(void)
{
    test_closure();
    test_supports();
    test_inextensible_limit();
    test_level_midspan();
    test_taut();
    CHECK_DONE();
}
