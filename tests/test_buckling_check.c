/* The non-linear check beside linear buckling (`buckling count=N check=1`,
 * analysis/buckling/buckling_check.c), against closed forms:
 * - a cantilever column (L = 4, EI = 2e6, 8 beam elements) under P = 1e4 at its tip:
 *   the linear factor and Southwell's factor of the imperfect path both near
 *   pi^2 EI / (4 L^2 P) = 30.8425 (the post-buckling path of a column is stable: the
 *   check reports Southwell's factor, kind 2);
 * - the von Mises two-bar truss (half-span 1, rise 0.1, EA = 1e4) loaded to half its
 *   snap-through limit P_lim = 2 EA y* (1/l* - 1/L0), l*^3 = a^2 L0: the linear factor
 *   (2.783) is far above the true limit; the check's limit (kind 1) is that of the
 *   imperfect truss, lambda (P + g) = P_lim with g = 1e-3 L_ref k / (lambda_1 - 1) the
 *   imperfection's load (k = -dP/dy at the solved state, L_ref the model's size), to
 *   the bisection's resolution: below the linear factor, the point.
 * ctest-cost: 2 */
#include "check.h"
#include "catena.h"

#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

static ctn_solution *solve_text(ctn_ctx *ctx, const char *text, int *rc)
{
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    *rc = ctn_read_string(ctx, "bk.cable", text, strlen(text), &m, &opt);
    if (!*rc) *rc = ctn_solve(ctx, m, &opt, &s);
    ctn_model_destroy(&m);
    return s;
}

/* The linear factor and the check's summary of a model. 1 if it failed. */
static int check_of(const char *text, double *lam1, ctn_buckling_summary *bs)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    ctn_buckling_mode b;
    int bad = rc || !s || ctn_solution_buckling(s, 0, &b) || ctn_solution_buckling_summary(s, bs);
    CHECK_MSG(!bad, "%s", ctn_ctx_message(ctx));
    if (!bad) *lam1 = b.factor;
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
    return bad;
}

static void test_column(void)
{
    const double EI = 2e11 * 1e-5, L = 4, P = 1e4, want = PI * PI * EI / (4 * L * L * P);
    double lam1;
    ctn_buckling_summary bs;
    if (check_of("material steel E=2e11 nu=0.3\n"
                 "section s material=steel A=1e-2 Iy=1e-5 Iz=1e-5 J=2e-5\n"
                 "node 1 0 0 0 fix=xyzrxryrz\nnode 2 0 0 4\n"
                 "beam 1 1 2 section=s orient=1,0,0 n=8\n"
                 "load 2 0 0 -1e4\n"
                 "buckling count=1 check=1\n", &lam1, &bs))
        return;
    printf("column: linear %.6f, Southwell %.6f, closed form %.6f\n", lam1, bs.nl_factor, want);
    CHECK(bs.nl_kind == 2);
    CHECK_CLOSE(lam1, want, 1e-3, 0);                  /* 8 elements: 2.8e-4 high */
    CHECK_CLOSE(bs.nl_factor, want, 2.5e-3, 0);        /* measured 1.6e-3 high */
    CHECK_CLOSE(bs.nl_imperfection, 4e-3, 1e-9, 0);    /* 1e-3 of the model's size */
}

static void test_arch(void)
{
    const double a = 1, b = 0.1, EA = 1e4;
    double L0 = hypot(a, b), ls = cbrt(a * a * L0), ys = sqrt(ls * ls - a * a), plim = 2 * EA * ys * (1 / ls - 1 / L0);
    double P = 0.5 * plim, lo = ys, hi = b, lam1;
    char text[1024];
    snprintf(text, sizeof text,
             "material m E=%.17g strain=engineering\nsection s material=m A=1\n"
             "node 1 %.17g 0 0 fix=xyz\nnode 2 %.17g 0 0 fix=xyz\nnode 3 0 %.17g 0 fix=z\n"
             "element 1 1 3 section=s\nelement 2 3 2 section=s\n"
             "load 3 0 %.17g 0\nsolve steps=20\nbuckling count=1 check=1\n", EA, -a, a, b, -P);
    ctn_buckling_summary bs;
    if (check_of(text, &lam1, &bs)) return;
    for (int i = 0; i < 200; i++) {                     /* the solved apex: P(y) = P */
        double y = 0.5 * (lo + hi), l = hypot(a, y);
        if (2 * EA * y * (1 / l - 1 / L0) > P) lo = y;
        else hi = y;
    }
    double y = 0.5 * (lo + hi), l = hypot(a, y), k = -2 * EA * ((1 / l - 1 / L0) - y * y / (l * l * l));
    double g = 1e-3 * sqrt(4 * a * a + b * b) * k / (lam1 - 1), want = plim / (P + g);
    printf("arch: linear %.6f, non-linear limit %.7f, imperfect truss %.7f, perfect %.1f\n", lam1, bs.nl_factor, want,
           plim / P);
    CHECK(bs.nl_kind == 1);
    CHECK(bs.nl_factor < want && bs.nl_factor > want * (1 - 2e-4));   /* the largest stable */
    CHECK(bs.nl_factor < plim / P && plim / P < lam1);
}

int main(void)
{
    test_column();
    test_arch();
    CHECK_DONE();
}
