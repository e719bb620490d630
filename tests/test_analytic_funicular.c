/* Analytic layer: the funicular polygon (weightless chain with joint loads). Equilibrium
 * of every joint from the returned geometry and tensions, segment lengths, closure, the
 * symmetric two-segment case in closed form, the elastic law, and convergence of a
 * finely divided chain to the catenaries (O(1/n^2)). */
#include "catena/analytic.h"
#include "check.h"

#include <stdlib.h>

#define NMAX 1601

static double g_xy[2 * (NMAX + 1)], g_N[NMAX];

static ctn_funicular solve(const ctn_funicular_in *in)
{
    ctn_funicular f;
    int st = ctn_funicular_solve(NULL, in, g_xy, g_N, &f);
    CHECK_MSG(st == CTN_OK, "n %zu: %s", in->n, ctn_strerror(st));
    return f;
}

/* Unit vector of segment i and its length. */
static double seg(size_t i, double *e)
{
    double dx = g_xy[2 * i + 2] - g_xy[2 * i], dy = g_xy[2 * i + 3] - g_xy[2 * i + 1];
    double len = hypot(dx, dy);
    e[0] = dx / len;
    e[1] = dy / len;
    return len;
}

/* Joint equilibrium N_k e_k - N_{k-1} e_{k-1} + P_k = 0, lengths, closure, reactions. */
static void check_chain(const ctn_funicular_in *in, const ctn_funicular *f)
{
    double Tmax = f->sum.T_max, e0[2], e1[2], Rx, Ry;
    for (size_t k = 1; k < in->n; k++) {
        seg(k - 1, e0);
        seg(k, e1);
        double P[2] = {in->P ? in->P[2 * k - 2] : 0.0, in->P ? in->P[2 * k - 1] : 0.0};
        CHECK_CLOSE(g_N[k] * e1[0] - g_N[k - 1] * e0[0] + P[0], 0.0, 0.0, 1e-12 * Tmax);
        CHECK_CLOSE(g_N[k] * e1[1] - g_N[k - 1] * e0[1] + P[1], 0.0, 0.0, 1e-12 * Tmax);
    }
    for (size_t i = 0; i < in->n; i++) {
        double EA = in->EA ? in->EA[i] : INFINITY;
        CHECK_CLOSE(seg(i, e0), in->L0[i] * (1.0 + g_N[i] / EA), 1e-12, 0.0);
    }
    CHECK_CLOSE(g_xy[2 * in->n], in->l, 0.0, 1e-12 * f->sum.length);
    CHECK_CLOSE(g_xy[2 * in->n + 1], in->h, 0.0, 1e-12 * f->sum.length);
    Rx = f->sum.reaction_left[0] + f->sum.reaction_right[0];
    Ry = f->sum.reaction_left[1] + f->sum.reaction_right[1];
    for (size_t k = 1; in->P && k < in->n; k++) {
        Rx += in->P[2 * k - 2];
        Ry += in->P[2 * k - 1];
    }
    CHECK_CLOSE(Rx, 0.0, 0.0, 1e-12 * Tmax);
    CHECK_CLOSE(Ry, 0.0, 0.0, 1e-12 * Tmax);
    seg(0, e0);
    CHECK_CLOSE(hypot(f->sum.reaction_left[0], f->sum.reaction_left[1]), g_N[0], 1e-13, 0.0);
    CHECK_CLOSE(-f->sum.reaction_left[0], g_N[0] * e0[0], 1e-12, 1e-12 * Tmax);
}

/* Two equal segments, central load P, level: H = P l / (4 f), N = P L / (2 f). */
static void test_symmetric(void)
{
    double L[2] = {60.0, 60.0}, P[2] = {0.0, -10.0}, f = sqrt(60.0 * 60.0 - 50.0 * 50.0);
    ctn_funicular_in in = {100.0, 0.0, 2, L, NULL, P};
    ctn_funicular r = solve(&in);
    CHECK_CLOSE(r.sum.H, 10.0 * 100.0 / (4.0 * f), 1e-13, 0.0);
    CHECK_CLOSE(g_N[0], 10.0 * 60.0 / (2.0 * f), 1e-13, 0.0);
    CHECK_CLOSE(g_N[1], g_N[0], 1e-13, 0.0);
    CHECK_CLOSE(g_xy[3], -f, 1e-13, 0.0);
    CHECK_CLOSE(r.sum.sag, f, 1e-13, 0.0);
    CHECK_CLOSE(r.sum.sag_mid, f, 1e-13, 0.0);
    CHECK_CLOSE(r.sum.reaction_left[1], 5.0, 1e-13, 0.0);
    check_chain(&in, &r);
}

/* Unequal segments and loads on an inclined span, inextensible and elastic; 2D loads. */
static void test_general(void)
{
    double L[4] = {30.0, 45.0, 25.0, 60.0}, EA[4] = {2e3, 5e3, 1e4, 3e3};
    double Pv[6] = {0.0, -8.0, 0.0, -3.0, 0.0, -12.0}, P2[6] = {2.0, -8.0, -5.0, -3.0, 1.0, -12.0};
    const double h[] = {0.0, 40.0, -70.0};              /* chord < 160 */
    for (int i = 0; i < 3; i++) {
        ctn_funicular_in in = {140.0, h[i], 4, L, NULL, Pv};
        ctn_funicular r = solve(&in);
        check_chain(&in, &r);
        CHECK_CLOSE(r.sum.length, 160.0, 1e-13, 0.0);
        in.EA = EA;
        r = solve(&in);
        check_chain(&in, &r);
        CHECK(r.sum.length > r.sum.length0);
        in.P = P2;
        r = solve(&in);
        check_chain(&in, &r);
        in.EA = NULL;
        r = solve(&in);
        check_chain(&in, &r);
    }
}

/* EA -> infinity reproduces the inextensible chain; an unloaded elastic chain shorter
 * than the chord is straight with N = (C - sum L0) / sum (L0 / EA). */
static void test_limits(void)
{
    double L[3] = {50.0, 40.0, 35.0}, big[3] = {1e16, 1e16, 1e16}, P[4] = {1.0, -6.0, 0.0, -4.0};
    ctn_funicular_in in = {110.0, 20.0, 3, L, NULL, P};
    ctn_funicular a = solve(&in);
    in.EA = big;
    ctn_funicular b = solve(&in);
    CHECK_CLOSE(b.sum.H, a.sum.H, 1e-9, 0.0);
    CHECK_CLOSE(b.sum.sag, a.sum.sag, 1e-9, 0.0);
    double Ls[2] = {60.0, 40.0}, EA[2] = {1e4, 2e4}, C = hypot(100.0, 10.0);
    ctn_funicular_in st = {100.0, 10.0, 2, Ls, EA, NULL};
    ctn_funicular r = solve(&st);
    double N = (C - 100.0) / (60.0 / 1e4 + 40.0 / 2e4);
    CHECK_CLOSE(g_N[0], N, 1e-12, 0.0);
    CHECK_CLOSE(g_N[1], N, 1e-12, 0.0);
    CHECK_CLOSE(r.sum.H, N * 100.0 / C, 1e-12, 0.0);
    check_chain(&st, &r);
}

/* Chain of n equal links with the weight w S / n lumped at the joints: H tends to the
 * catenary's (elastic catenary's) H like 1 / n^2. */
static double chain_error(int n, double EA)
{
    double l = 200.0, h = 50.0, w = 0.1, S = 260.0, Href;
    double *L = malloc(sizeof(double) * (size_t)n), *E = malloc(sizeof(double) * (size_t)n);
    double *P = malloc(sizeof(double) * 2 * (size_t)n);
    for (int i = 0; i < n; i++) {
        L[i] = S / n;
        E[i] = EA;
        P[2 * i] = 0.0;
        P[2 * i + 1] = -w * S / n;
    }
    ctn_funicular_in in = {l, h, (size_t)n, L, E, P};
    ctn_funicular f = solve(&in);
    check_chain(&in, &f);
    ctn_ecatenary_in ei = {l, h, w, EA, S};
    ctn_ecatenary ec;
    CHECK(ctn_ecatenary_solve(NULL, &ei, &ec) == CTN_OK);
    Href = ec.H;
    free(L);
    free(E);
    free(P);
    return fabs(f.sum.H - Href) / Href;
}

static void test_catenary_limit(void)
{
    const double EA[] = {INFINITY, 1e4};
    for (int k = 0; k < 2; k++) {
        double prev = chain_error(50, EA[k]);
        for (int n = 100; n <= 1600; n *= 2) {
            double e = chain_error(n, EA[k]);
            CHECK_MSG(prev / e > 3.9 && prev / e < 4.1, "n %d ratio %g", n, prev / e);
            prev = e;
        }
        CHECK(prev < 2e-7);
    }
}

/* Slack segments: a chain whose right link is too long hangs from the left support and
 * has no taut solution (CTN_ERR_DOMAIN); a chain that draws Newton into a zero-force
 * kink although a taut solution exists must still be solved. */
static void test_slack(void)
{
    double L[2] = {10.0, 200.0}, P[2] = {0.0, -1.0};
    ctn_funicular_in in = {50.0, -33.0, 2, L, NULL, P};
    ctn_funicular f;
    CHECK(ctn_funicular_solve(NULL, &in, g_xy, g_N, &f) == CTN_ERR_DOMAIN);
    double L5[5] = {13.9998, 6.19755, 27.3841, 21.6443, 20.5189};
    double P5[8] = {0.0603349, -1.73673, 0.256824, -0.729316, -0.0626889, -1.24686,
                    -0.169312, -1.43596};
    ctn_funicular_in k = {26.76674489572958, 3.077315201831353, 5, L5, NULL, P5};
    ctn_funicular r = solve(&k);
    check_chain(&k, &r);
    CHECK(r.sum.T_min > 1e-3 * r.sum.T_max);
}

/* Evaluation on the polygon: y and tension between joints. */
static void test_eval(void)
{
    double L[2] = {60.0, 60.0}, P[2] = {0.0, -10.0}, y, T;
    ctn_funicular_in in = {100.0, 0.0, 2, L, NULL, P};
    ctn_funicular r = solve(&in);
    CHECK(ctn_funicular_y(2, g_xy, 25.0, &y) == CTN_OK);
    CHECK_CLOSE(y, 0.5 * g_xy[3], 1e-13, 0.0);
    CHECK(ctn_funicular_tension(2, g_xy, g_N, 75.0, &T) == CTN_OK);
    CHECK_CLOSE(T, g_N[1], 0.0, 0.0);
    CHECK(ctn_funicular_y(2, g_xy, 100.5, &y) == CTN_ERR_INVALID);
    CHECK(ctn_funicular_y(2, g_xy, NAN, &y) == CTN_ERR_INVALID);
    CHECK(r.i_T_max < 2 && r.i_T_min < 2 && r.n == 2 && r.iterations > 0);
}

int main(void)
{
    test_symmetric();
    test_general();
    test_limits();
    test_catenary_limit();
    test_slack();
    test_eval();
    CHECK_DONE();
}
