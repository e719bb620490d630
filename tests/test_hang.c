/* The chord of a hanging member from the force at its middle (element/hang_law.c) and
 * the dangling chain's funicular (start/hang.c):
 * - the chord is the gradient of phi: central differences of phi over random forces and
 *   gravity directions, slack and taut, steep, nearly vertical and folded (the force
 *   along gravity changing sign inside the member), for the bar and the catenary;
 * - the catenary's chord against the catenary element itself (catenary_solve.c, an
 *   independent solution of Irvine's equations): placed on that chord, the element's
 *   force at its second node is the force S (its lumped half weight included), 1e-9;
 * - a dangling chain of two catenaries with a free tip, and one whose tip is held on a
 *   plane: every free node of the placement is in equilibrium under the elements' own
 *   forces, the loads and (held tip) a reaction normal to the plane only. */
// ctest-cost: 0.1
#include "check.h"
#include "catenary_props.h"
#include "element/hang_law.h"
#include "start/hang.h"

#include <stdlib.h>

static void unit(unsigned *seed, double g[3])
{
    double n = 0;
    for (int i = 0; i < 3; i++) g[i] = urand(seed, -1, 1), n += g[i] * g[i];
    for (int i = 0; i < 3; i++) g[i] /= sqrt(n);
}

static double law(int cat, double L, double EA, double W, const double up[3], const double S[3], double v[3])
{
    double H[9];
    return cat ? ctn_hang_catenary(L, EA, W, up, S, v, H) : ctn_hang_bar(L, EA, S, v, H);
}

static void test_gradient(void)
{
    unsigned seed = 7;
    int bad = 0;
    for (int trial = 0; trial < 400; trial++) {
        int cat = trial % 4 != 0;
        double g[3], up[3], S[3], v[3], L = urand(&seed, 1, 100), EA = urand(&seed, 1e2, 1e6), W = urand(&seed, 0.1, 50);
        unit(&seed, g);
        for (int i = 0; i < 3; i++) up[i] = -g[i];
        double along = urand(&seed, -1.5, 1.5) * W, across = trial % 5 == 1 ? 1e-6 * W : urand(&seed, 0, 2) * W;
        double t[3], d = 0, tn = 0;                     /* a direction normal to gravity */
        unit(&seed, t);
        for (int i = 0; i < 3; i++) d += t[i] * g[i];
        for (int i = 0; i < 3; i++) t[i] -= d * g[i], tn += t[i] * t[i];
        for (int i = 0; i < 3; i++) S[i] = along * g[i] + across * t[i] / sqrt(tn);
        double phi = law(cat, L, EA, W, up, S, v);
        if (!isfinite(phi)) { bad++; continue; }
        double Tn = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]), h = 1e-6 * Tn, scale = L * (1 + Tn / EA);
        for (int k = 0; k < 3; k++) {
            double Sp[3] = { S[0], S[1], S[2] }, Sm[3] = { S[0], S[1], S[2] }, w[3];
            Sp[k] += h;
            Sm[k] -= h;
            double fd = (law(cat, L, EA, W, up, Sp, w) - law(cat, L, EA, W, up, Sm, w)) / (2 * h);
            CHECK_CLOSE(v[k], fd, 0, 1e-6 * scale);
        }
    }
    CHECK_MSG(bad == 0, "%d forces gave no chord", bad);
}

static void test_against_element(void)
{
    unsigned seed = 11;
    for (int trial = 0; trial < 200; trial++) {
        double g[3], up[3], S[3], v[3], H[9], L = urand(&seed, 5, 200), EA = urand(&seed, 1e3, 1e6),
               W = urand(&seed, 0.5, 40);
        unit(&seed, g);
        for (int i = 0; i < 3; i++) up[i] = -g[i];
        double t[3], d = 0, tn = 0, along = urand(&seed, -1.4, 1.4) * W, across = urand(&seed, 0.05, 3) * W;
        unit(&seed, t);
        for (int i = 0; i < 3; i++) d += t[i] * g[i];
        for (int i = 0; i < 3; i++) t[i] -= d * g[i], tn += t[i] * t[i];
        for (int i = 0; i < 3; i++) S[i] = along * g[i] + across * t[i] / sqrt(tn);
        CHECK(isfinite(ctn_hang_catenary(L, EA, W, up, S, v, H)));
        ctn_catenary_props p = props(L, EA, W, g);
        double X[6] = { 0, 0, 0, v[0], v[1], v[2] }, u[6] = { 0 }, f[6];
        CHECK(ctn_catenary2_ops.eval(&p, 0, X, u, f, NULL, NULL) == 0);
        double Sn = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]) + W;
        for (int i = 0; i < 3; i++) CHECK_CLOSE(f[3 + i], S[i], 0, 1e-9 * Sn);
    }
}

/* A chain of two catenary elements hung from the origin: member j's chord from the op. */
typedef struct two { ctn_catenary_props p[2]; } two;

static double member(const void *ud, size_t j, const double S[3], double v[3], double H[9])
{
    const two *t = ud;
    return ctn_catenary2_ops.hang(&t->p[j], S, v, H);
}

static void test_chain(void)
{
    double g[3] = { 0, 0, -1 };
    two t = { { props(30, 1e4, 6, g), props(20, 1e4, 2, g) } };
    /* nodal loads: the lumped half weights and a pull at the tip */
    double f[6] = { 0, 0, -(3 + 1), 2, 0.5, -1 - 1.5 }, x[6];
    for (int held = 0; held < 2; held++) {
        ctn_hang h = { 2, member, &t, 50, f, { 0, 0, 0 }, held ? 4u : 0u, { 0, 0, -10 } };
        CHECK(ctn_hang_place(&h, x));
        if (held) CHECK_CLOSE(x[5], -10, 0, 1e-10 * 50);
        double X[6], u[6] = { 0 }, f1[6], f2[6], sum[6] = { 0 };
        memset(X, 0, 3 * sizeof(double));
        memcpy(X + 3, x, 3 * sizeof(double));
        CHECK(ctn_catenary2_ops.eval(&t.p[0], 0, X, u, f1, NULL, NULL) == 0);
        memcpy(X, x, 6 * sizeof(double));
        CHECK(ctn_catenary2_ops.eval(&t.p[1], 0, X, u, f2, NULL, NULL) == 0);
        for (int i = 0; i < 3; i++) {
            sum[i] = f[i] - f1[3 + i] - f2[i];          /* node 1: loads - internal forces */
            sum[3 + i] = f[3 + i] - f2[3 + i];          /* the tip */
        }
        for (int i = 0; i < 6; i++) {
            if (held && i == 5) continue;               /* the plane's reaction */
            CHECK_CLOSE(sum[i], 0, 0, 1e-9 * 10);
        }
        if (held) CHECK(fabs(sum[5]) > 1e-3);           /* the plane does carry the tip */
    }
}

int main(void)
{
    test_gradient();
    test_against_element();
    test_chain();
    CHECK_DONE();
}
