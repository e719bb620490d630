/* The catenary element (element/catenary2.c):
 * - end forces against the closed form of the elastic catenary: Irvine's end conditions
 *   evaluated in long double at the element's H, V (level, inclined, steep, any gravity
 *   direction), the closed-form solution (analytic/) to 1e-12, and the vertical chord's
 *   own closed forms (taut and folded);
 * - no weight: the bar N = EA (l - L) / L, and no force at all when slack;
 * - the tangent against central differences of the end forces over random chords,
 *   gravity directions and lengths, near-taut, very slack, steep, and W -> 0;
 * - the energy's gradient is the force; the forces balance the weight;
 * - the temperature op lengthens L and keeps the weight (catenary and pulley). */
#include "check.h"
#include "catena/analytic.h"
#include "catenary_props.h"
#include "element/pulley.h"

#include <stdlib.h>

/* Irvine's end conditions at (H, Va), in long double: the chord they give. */
static void irvine_chord(double L, double EA, double W, double H, double Va, long double *l, long double *h)
{
    long double q = (long double)W / L, Vb = (long double)W - Va, Ta = hypotl(H, Va), Tb = hypotl(H, Vb);
    *l = (long double)H * L / EA + (long double)H / q * (asinhl(Va / (long double)H) + asinhl(Vb / (long double)H));
    *h = (Vb * Vb - (long double)Va * Va) / (2 * EA * q) + (Tb - Ta) / q;
}

/* Element state of chord (l horizontal along x, h up = -g with g = -z). */
static int solve_chord(double L, double EA, double W, double l, double h, ctn_ecat *c)
{
    double g[3] = { 0, 0, -1 }, X[6] = { 0, 0, 0, l, 0, h }, u[6] = { 0 }, ex[3];
    ctn_catenary_props p = props(L, EA, W, g);
    int bar;
    return ctn_catenary_state(&p, X, u, c, ex, &bar);
}

static void test_closed_form(void)
{
    static const double cases[][5] = {          /* L, EA, W, l, h */
        { 250.8777, 2e8 * 3.14e-4, 25.08777, 200, 0 },       /* the paper's span */
        { 120, 1e5, 30, 100, 40 },                          /* inclined */
        { 100, 1e5, 30, 20, -90 },                          /* steep, downhill */
        { 100, 1e5, 5, 99.9, 1 },                           /* near taut */
        { 100, 1e4, 50, 101, 2 },                           /* stretched beyond L */
        { 500, 1e7, 100, 30, 10 },                          /* very slack */
        { 100, 1e6, 1e-9, 80, 30 },                         /* almost weightless, slack */
        { 10, 1e3, 2, 1e-3, 9 },                            /* nearly vertical */
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        const double *c = cases[k];
        ctn_ecat s;
        CHECK_MSG(solve_chord(c[0], c[1], c[2], c[3], c[4], &s) == 0, "case %zu", k);
        long double l, h;
        irvine_chord(c[0], c[1], c[2], s.H, s.Va, &l, &h);
        double scale = hypot(c[3], c[4]);
        CHECK_CLOSE((double)l, c[3], 0, 1e-12 * scale);
        CHECK_CLOSE((double)h, c[4], 0, 1e-12 * scale);
        CHECK_CLOSE(s.Va + s.Vb, c[2], 1e-15, 0);
        ctn_ecatenary_in in = { c[3], c[4], c[2] / c[0], c[1], c[0] };
        ctn_ecatenary an;
        if (c[2] > 1e-6) {                                   /* the closed-form solver */
            CHECK(ctn_ecatenary_solve(NULL, &in, &an) == CTN_OK);
            CHECK_CLOSE(s.H, an.H, 1e-12, 0);
            CHECK_CLOSE(s.Va, an.V_left, 1e-12, 1e-12 * an.H);
            double sag = ctn_ecat_sag(&s);
            CHECK_CLOSE(sag, an.sum.sag_mid, 1e-10, 1e-12 * scale);
        }
    }
}

/* Any gravity direction: the same span turned in space with its gravity gives the same
 * H, Va, Vb (1e-12) and end forces along the turned directions. */
static void test_any_gravity(void)
{
    unsigned seed = 3;
    static const double cases[][5] = { { 120, 1e5, 30, 100, 40 }, { 100, 1e5, 30, 20, -90 }, { 500, 1e7, 100, 30, 10 } };
    for (int trial = 0; trial < 60; trial++) {
        const double *c = cases[trial % 3];
        ctn_ecat ref;
        CHECK(solve_chord(c[0], c[1], c[2], c[3], c[4], &ref) == 0);
        double g[3], t[3], n = 0, d = 0, tn = 0;
        for (int i = 0; i < 3; i++) g[i] = urand(&seed, -1, 1), n += g[i] * g[i];
        for (int i = 0; i < 3; i++) g[i] /= sqrt(n);
        for (int i = 0; i < 3; i++) t[i] = urand(&seed, -1, 1), d += t[i] * g[i];
        for (int i = 0; i < 3; i++) t[i] -= d * g[i], tn += t[i] * t[i];
        for (int i = 0; i < 3; i++) t[i] /= sqrt(tn);                    /* horizontal unit */
        double X[6], u[6] = { 0 }, f[6];
        for (int i = 0; i < 3; i++) {
            X[i] = urand(&seed, -50, 50);
            X[3 + i] = X[i] + c[3] * t[i] - c[4] * g[i];                  /* up = -g */
        }
        ctn_catenary_props p = props(c[0], c[1], c[2], g);
        CHECK(ctn_catenary2_ops.eval(&p, 0, X, u, f, NULL, NULL) == 0);
        for (int i = 0; i < 3; i++)                                      /* f2 = H ex + D/2 up */
            CHECK_CLOSE(f[3 + i], ref.H * t[i] - 0.5 * (ref.Vb - ref.Va) * g[i], 0, 1e-12 * (ref.H + ref.Vb));
    }
}

/* Vertical chords: H = 0. Taut (h > L): Tb = EA (h/L - 1) + W/2 at the top, Ta = Tb - W.
 * Folded (h < L): h = L D (1/(2EA) + 1/W), D = Vb - Va. */
static void test_vertical(void)
{
    double L = 10, EA = 1e3, W = 4;
    ctn_ecat s;
    CHECK(solve_chord(L, EA, W, 0, 10.5, &s) == 0);
    CHECK(s.H == 0);
    CHECK_CLOSE(s.Vb, EA * (10.5 / L - 1) + W / 2, 1e-13, 0);
    CHECK_CLOSE(-s.Va, s.Vb - W, 1e-13, 1e-13);
    CHECK(solve_chord(L, EA, W, 0, 6, &s) == 0);
    CHECK(s.H == 0);
    CHECK_CLOSE(s.Vb - s.Va, 6 / (L * (0.5 / EA + 1 / W)), 1e-13, 0);
    CHECK(solve_chord(L, EA, W, 0, -6, &s) == 0);         /* node 2 below node 1 */
    CHECK_CLOSE(s.Vb - s.Va, -6 / (L * (0.5 / EA + 1 / W)), 1e-13, 0);
}

/* Without weight: the bar, and zero force when slack. */
static void test_weightless(void)
{
    double g[3] = { 0, 0, -1 }, X[6] = { 0, 0, 0, 3, 4, 0 }, u[6] = { 0 }, f[6], K[21];
    ctn_catenary_props p = props(4.5, 1000, 0, g);
    ctn_elem_state st;
    CHECK(ctn_catenary2_ops.eval(&p, 0, X, u, f, K, &st) == 0);
    CHECK_CLOSE(st.N, 1000 * (5 / 4.5 - 1), 1e-14, 0);
    CHECK_CLOSE(f[3], st.N * 0.6, 1e-14, 0);
    p.l0 = 5.5;
    CHECK(ctn_catenary2_ops.eval(&p, 0, X, u, f, K, &st) == 0);
    CHECK(st.N == 0 && st.slack && st.energy == 0);
    double kmax = 0;
    for (int i = 0; i < 21; i++) kmax = fmax(kmax, fabs(K[i]));
    CHECK(kmax == 0 && f[0] == 0 && f[5] == 0);
    /* W -> 0: the catenary tends to the bar */
    p.l0 = 4.5;
    p.W = 1e-10;
    p.up[2] = 1;
    ctn_elem_state sw;
    double fw[6];
    CHECK(ctn_catenary2_ops.eval(&p, 0, X, u, fw, NULL, &sw) == 0);
    CHECK_CLOSE(sw.N, 1000 * (5 / 4.5 - 1), 1e-9, 0);
}

/* Random catenaries: lengths from near taut to very slack, any gravity direction. */
static void sample(unsigned *seed, int kind, ctn_catenary_props *p, double X[6])
{
    double g[3], n = 0;
    for (int i = 0; i < 3; i++) g[i] = urand(seed, -1, 1), n += g[i] * g[i];
    for (int i = 0; i < 3; i++) g[i] /= sqrt(n);
    for (int i = 0; i < 6; i++) X[i] = urand(seed, -10, 10);
    if (kind == 3)                                          /* nearly along gravity */
        for (int i = 0; i < 3; i++) X[3 + i] = X[i] + 8 * g[i] + urand(seed, -1e-3, 1e-3);
    double C = sqrt(pow(X[3] - X[0], 2) + pow(X[4] - X[1], 2) + pow(X[5] - X[2], 2));
    double ratio[5] = { urand(seed, 0.98, 1.3), 1 - 1e-7, urand(seed, 2, 6), urand(seed, 0.9, 1.5), 1.001 };
    double EA = urand(seed, 1e3, 1e6), W = kind == 4 ? 1e-9 * EA : urand(seed, 0.01, 0.5) * EA * urand(seed, 1e-4, 1);
    *p = props(C * ratio[kind], EA, W, g);
}

static void unpack(const double *P, double K[6][6])
{
    for (int i = 0; i < 6; i++)
        for (int j = i; j < 6; j++) K[i][j] = K[j][i] = P[ctn_packed_index(6, i, j)];
}

static void test_tangent(void)
{
    unsigned seed = 99;
    for (int trial = 0; trial < 500; trial++) {
        ctn_catenary_props p;
        double X[6], u[6] = { 0 }, f[6], P[21], K[6][6], emax = 0, kmax = 0;
        int kind = trial % 5;
        sample(&seed, kind, &p, X);
        CHECK(ctn_catenary2_ops.eval(&p, 0, X, u, f, P, NULL) == 0);
        unpack(P, K);
        double scale = sqrt(pow(X[3] - X[0], 2) + pow(X[4] - X[1], 2) + pow(X[5] - X[2], 2));
        for (int j = 0; j < 6; j++) {
            /* nearly vertical: the lateral stiffness H / l varies on the scale of l ~ 1e-3 */
            double up[6] = { 0 }, um[6] = { 0 }, fp[6], fm[6], h = (kind == 3 ? 1e-8 : 1e-6) * scale;
            up[j] = h;
            um[j] = -h;
            ctn_catenary2_ops.eval(&p, 0, X, up, fp, NULL, NULL);
            ctn_catenary2_ops.eval(&p, 0, X, um, fm, NULL, NULL);
            for (int i = 0; i < 6; i++) {
                emax = fmax(emax, fabs(K[i][j] - (fp[i] - fm[i]) / (2 * h)));
                kmax = fmax(kmax, fabs(K[i][j]));
            }
        }
        CHECK_MSG(emax <= 1e-6 * kmax, "trial %d kind %d: tangent error %.3g of %.3g", trial, kind, emax, kmax);
    }
}

/* dU/du = f; the end forces balance: f1 + f2 = 0 (the weight is the nodes' load). */
static void test_energy(void)
{
    unsigned seed = 7;
    for (int trial = 0; trial < 200; trial++) {
        ctn_catenary_props p;
        double X[6], u[6] = { 0 }, f[6];
        ctn_elem_state st;
        sample(&seed, trial % 4, &p, X);
        CHECK(ctn_catenary2_ops.eval(&p, 0, X, u, f, NULL, &st) == 0);
        for (int i = 0; i < 3; i++) CHECK(f[i] == -f[3 + i]);
        double scale = sqrt(pow(X[3] - X[0], 2) + pow(X[4] - X[1], 2) + pow(X[5] - X[2], 2));
        for (int j = 0; j < 6; j++) {
            double up[6] = { 0 }, um[6] = { 0 }, fd[6], h = 1e-5 * scale;
            ctn_elem_state sp, sm;
            up[j] = h;
            um[j] = -h;
            ctn_catenary2_ops.eval(&p, 0, X, up, fd, NULL, &sp);
            ctn_catenary2_ops.eval(&p, 0, X, um, fd, NULL, &sm);
            CHECK_CLOSE((sp.energy - sm.energy) / (2 * h), f[j], 0, 1e-6 * st.N);
        }
    }
}

static void test_temperature(void)
{
    double g[3] = { 0, 0, -1 };
    ctn_catenary_props p = props(100, 1e5, 20, g);
    p.alpha = 1.2e-5;
    ctn_catenary2_ops.temperature(&p, 50);
    CHECK_CLOSE(p.l0, 100 * (1 + 1.2e-5 * 50), 1e-15, 0);
    CHECK(p.W == 20 && p.l0_ref == 100);
    ctn_catenary2_ops.temperature(&p, 0);
    CHECK(p.l0 == 100);
    /* heated by 50 K: the same as a catenary of the longer length and the same weight */
    double X[6] = { 0, 0, 0, 90, 0, 10 }, u[6] = { 0 }, f[6], f2[6];
    ctn_catenary_props q = props(100 * (1 + 1.2e-5 * 50), 1e5, 20, g);
    ctn_catenary2_ops.temperature(&p, 50);
    CHECK(ctn_catenary2_ops.eval(&p, 0, X, u, f, NULL, NULL) == 0 && ctn_catenary2_ops.eval(&q, 0, X, u, f2, NULL, NULL) == 0);
    for (int i = 0; i < 6; i++) CHECK(f[i] == f2[i]);
    ctn_pulley_props pp;                                /* the pulley: its cable's l0 */
    memset(&pp, 0, sizeof pp);
    pp.cable.l0 = pp.l0_ref = 10;
    pp.alpha = 1e-5;
    ctn_pulley_ops.temperature(&pp, -20);
    CHECK_CLOSE(pp.cable.l0, 10 * (1 - 2e-4), 1e-15, 0);
}

int main(void)
{
    test_closed_form();
    test_any_gravity();
    test_vertical();
    test_weightless();
    test_tangent();
    test_energy();
    test_temperature();
    CHECK_DONE();
}
