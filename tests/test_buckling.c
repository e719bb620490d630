/* Linear buckling (catena/analysis.h "buckling", docs/theory.md "Linear buckling"):
 * - a stiff pinned bar held at its top by lateral springs kx, ky under an axial load P:
 *   the factors kx L / P and ky L / P (the classical rigid-bar result; the bar's
 *   shortening P L / EA moves them by 1e-8), lowest first, each shape along its spring;
 * - the same bar of a soft Green-Lagrange material (P / EA = 1e-3): the factor of the
 *   pencil K_T + (lambda - 1) dK_T/dlambda in closed form (the bar's lateral stiffness
 *   S A / L0, S = N / (A s), N(s) = EA (s^3 - s) / 2, ds/dlambda from it): K_T is
 *   quadratic in d for this law, so the central difference is exact and the factor
 *   agrees to 1e-10;
 * - the von Mises two-bar truss loaded to a fraction alpha of its snap-through limit
 *   load P_lim (closed form): lambda alpha -> 1 (the factor tends to the limit load
 *   ratio 1 / alpha) with |lambda alpha - 1| / (1 - alpha) -> 1, and (lambda - 1) /
 *   (1 / alpha - 1) -> 2 with an error shrinking as sqrt(1 - alpha) (the stiffness
 *   vanishes as the square root of the distance to a limit point);
 * - the analysis object: registered as "buckling", count 0 refused, options not
 *   initialised refused, results replaced by a second run;
 * - errors: count above the free DOFs, more free DOFs than CTN_BUCKLING_MAX_DOFS, an
 *   unstable loaded state, a step without loads: CTN_ERR_MODEL at the `buckling` line;
 * - every allocation failure: CTN_ERR_NOMEM, no leak (ASan);
 * - Euler columns of corotational beams (E I = 2e6, L = 4, P = 1000, EA / P = 2e8: the
 *   pre-buckling path is linear): pinned-pinned pi^2 EI / L^2 and the cantilever
 *   pi^2 EI / (4 L^2) (in P), the error from above falling as h^2 (ratios 4 +- 0.2 from 4
 *   to 32 elements), Richardson's (4 lambda_2n - lambda_n) / 3 of 8 and 16 elements
 *   within 1e-4 (measured 4e-6); the second factor that of Iy = 2 Iz, twice the first. */
#include "catena.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The pinned bar of length L along z, its top held by springs of kx (along x) and ky
 * (along y) to supports `arm` away, P down at the top; `law` the material's strain. */
static int bar_model(char *buf, size_t size, double E, const char *law, double L, double kx, double ky, double P,
                     double arm, const char *extra)
{
    return snprintf(buf, size,
                    "material m E=%.17g strain=%s\n"
                    "section bar material=m A=1\n"
                    "node 1 0 0 0 fix=xyz\n"
                    "node 2 0 0 %.17g\n"
                    "node 3 %.17g 0 %.17g fix=xyz\n"
                    "node 4 0 %.17g %.17g fix=xyz\n"
                    "element 1 1 2 section=bar\n"
                    "spring 2 2 3 k=%.17g\n"
                    "spring 3 2 4 k=%.17g\n"
                    "load 2 0 0 %.17g\n"
                    "%s\n",
                    E, law, L, arm, L, arm, L, kx, ky, -P, extra);
}

/* Read and solve text; the solution (NULL and the status in *rc on failure). */
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

static void test_springs(double L, double kx, double ky, double P)
{
    char text[1024];
    bar_model(text, sizeof text, 1e8, "engineering", L, kx, ky, P, 5, "buckling count=2");
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK && s, "%s", ctn_ctx_message(ctx));
    CHECK(ctn_solution_buckling_count(s) == 2);
    double want[2] = { fmin(kx, ky) * L / P, fmax(kx, ky) * L / P };
    for (size_t k = 0; k < 2 && ctn_solution_buckling_count(s) == 2; k++) {
        ctn_buckling_mode b;
        CHECK(ctn_solution_buckling(s, k, &b) == CTN_OK);
        CHECK_CLOSE(b.factor, want[k], 1e-6, 0);
        CHECK(b.node == 2 && b.residual < 1e-12);
        int dir = (k == 0) == (kx < ky) ? 0 : 1;          /* the softer spring's first */
        CHECK_CLOSE(b.shape[3 + dir], 1.0, 1e-12, 0);
        CHECK(fabs(b.shape[3 + 1 - dir]) < 1e-9 && fabs(b.shape[5]) < 1e-9);
        for (int i = 0; i < 3; i++) CHECK(b.shape[i] == 0 && b.shape[6 + i] == 0);   /* supports */
    }
    ctn_buckling_mode b;
    CHECK(ctn_solution_buckling(s, 2, &b) == CTN_ERR_INVALID);
    ctn_buckling_summary bs;
    CHECK(ctn_solution_buckling_summary(s, &bs) == CTN_OK && bs.count == 2 && bs.asked == 2 && bs.ndof == 3);
    CHECK_CLOSE(bs.load_norm, P, 1e-15, 0);
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

/* The Green-Lagrange bar: the pencil's factor in closed form. */
static void test_green_lagrange(void)
{
    const double EA = 1e3, L = 10, P = 1, kx = 0.5, ky = 0.8, arm = 1e4;   /* the springs' tilt
                       under the bar's shortening moves lambda by O(1 / arm^2): 1e-11 here */
    char text[1024];
    bar_model(text, sizeof text, EA, "green-lagrange", L, kx, ky, P, arm, "buckling count=1");
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK && s, "%s", ctn_ctx_message(ctx));
    double st = 1;                                     /* EA (s^3 - s) / 2 = -P */
    for (int it = 0; it < 50; it++) st -= (EA * (st * st * st - st) / 2 + P) / (EA * (3 * st * st - 1) / 2);
    double ds = -P / (EA * (3 * st * st - 1) / 2);     /* ds/dlambda */
    double K = kx - P / (L * st), dK = -P / L * (1 / st - ds / (st * st));
    double want = 1 - K / dK;
    ctn_buckling_mode b;
    CHECK(ctn_solution_buckling(s, 0, &b) == CTN_OK);
    CHECK_CLOSE(b.factor, want, 1e-10, 0);
    CHECK(fabs(want - kx * L / P) > 1e-3 * want);      /* the law's effect is resolved */
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

/* The von Mises truss: apex at height b over a half-span a, EA, engineering strain.
 * P(y) = 2 EA y (1/l - 1/L0), l = sqrt(a^2 + y^2), is largest at l^3 = a^2 L0. */
static double von_mises_factor(double alpha, double *plim)
{
    const double a = 1, b = 0.1, EA = 1e4;
    double L0 = hypot(a, b), l = cbrt(a * a * L0), y = sqrt(l * l - a * a);
    *plim = 2 * EA * y * (1 / l - 1 / L0);
    char text[1024];
    snprintf(text, sizeof text,
             "material m E=%.17g strain=engineering\n"
             "section s material=m A=1\n"
             "node 1 %.17g 0 0 fix=xyz\n"
             "node 2 %.17g 0 0 fix=xyz\n"
             "node 3 0 %.17g 0 fix=z\n"
             "element 1 1 3 section=s\n"
             "element 2 3 2 section=s\n"
             "load 3 0 %.17g 0\n"
             "solve steps=20\n"
             "buckling count=1\n",
             EA, -a, a, b, -alpha * *plim);
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK && s, "%s", ctn_ctx_message(ctx));
    ctn_buckling_mode bm;
    double lam = ctn_solution_buckling(s, 0, &bm) ? NAN : bm.factor;
    CHECK(!isnan(lam) && bm.node == 3 && fabs(bm.shape[7]) == 1.0);   /* the apex, vertically */
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
    return lam;
}

static void test_von_mises(void)
{
    const double alpha[3] = { 0.99, 0.999, 0.9999 };
    double err[3], plim;
    for (int i = 0; i < 3; i++) {
        double lam = von_mises_factor(alpha[i], &plim), eps = 1 - alpha[i];
        CHECK_MSG(fabs(lam * alpha[i] - 1) <= 1.1 * eps && fabs(lam * alpha[i] - 1) >= 0.9 * eps,
                  "alpha %g: lambda %.17g", alpha[i], lam);
        err[i] = fabs((lam - 1) / (1 / alpha[i] - 1) - 2);
        CHECK_MSG(err[i] < 1, "alpha %g: (lambda - 1) / (1/alpha - 1) = %.17g", alpha[i], (lam - 1) / (1 / alpha[i] - 1));
    }
    for (int i = 0; i < 2; i++)                         /* sqrt(10) = 3.16 per decade */
        CHECK_MSG(err[i] / err[i + 1] > 2.5 && err[i] / err[i + 1] < 4, "errors %g %g", err[i], err[i + 1]);
}

/* The analysis object about a solution without a `buckling` line. */
static void test_object(void)
{
    char text[1024];
    bar_model(text, sizeof text, 1e8, "engineering", 10, 2, 3, 1, 5, "");
    CHECK(ctn_analysis_count() == 5 && !strcmp(ctn_analysis_type(3), "buckling"));
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_problem *p = NULL;
    ctn_solution *s = NULL;
    ctn_analysis *a = NULL;
    ctn_ctx_create(&ctx);
    CHECK(ctn_read_string(ctx, "bk.cable", text, strlen(text), &m, NULL) == CTN_OK);
    CHECK(ctn_problem_create(ctx, m, NULL, &p) == CTN_OK && ctn_problem_solve(p, &s) == CTN_OK);
    CHECK(ctn_solution_buckling_count(s) == 0);
    ctn_buckling_summary bs;
    CHECK(ctn_solution_buckling_summary(s, &bs) == CTN_ERR_INVALID);
    ctn_buckling_options bo;
    ctn_buckling_options_default(&bo);
    CHECK(bo.size == sizeof bo && bo.count == 0);
    CHECK(ctn_analysis_create(p, "buckling", &bo, &a) == CTN_ERR_INVALID && a == NULL);     /* count 0 */
    CHECK(strstr(ctn_ctx_message(ctx), "count must be >= 1"));
    bo.count = -1;
    CHECK(ctn_buckling_options_check(ctx, &bo) == CTN_ERR_INVALID);
    ctn_buckling_options raw = { .count = 1 };                              /* size 0 */
    CHECK(ctn_analysis_create(p, "buckling", &raw, &a) == CTN_ERR_INVALID && a == NULL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "buckling analysis options: size is 0"), "%s", ctn_ctx_message(ctx));
    bo.count = 1;
    CHECK(ctn_analysis_create(p, "buckling", &bo, &a) == CTN_OK && !strcmp(ctn_analysis_name(a), "buckling"));
    CHECK(ctn_analysis_run(a, &s) == CTN_OK && ctn_solution_buckling_count(s) == 1);
    ctn_buckling_mode b;
    CHECK(ctn_solution_buckling(s, 0, &b) == CTN_OK);
    CHECK_CLOSE(b.factor, 20.0, 1e-6, 0);
    ctn_analysis_destroy(&a);
    bo.count = 3;                                       /* a second run replaces the first */
    CHECK(ctn_analysis_create(p, "buckling", &bo, &a) == CTN_OK && ctn_analysis_run(a, &s) == CTN_OK);
    CHECK(ctn_solution_buckling_summary(s, &bs) == CTN_OK && bs.asked == 3 && bs.count >= 2 &&
          ctn_solution_buckling_count(s) == (size_t)bs.count);
    ctn_analysis_destroy(&a);
    ctn_solution *none = NULL;
    CHECK(ctn_analysis_create(p, "buckling", &bo, &a) == CTN_OK && ctn_analysis_run(a, &none) == CTN_ERR_INVALID);
    ctn_analysis_destroy(&a);
    ctn_solution_destroy(&s);
    ctn_problem_destroy(&p);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Text expected to fail with CTN_ERR_MODEL and a message containing want. */
static void expect_error(const char *text, const char *want)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_ERR_MODEL && !s && strstr(ctn_ctx_message(ctx), want), "status %d: %s (want %s)", rc,
              ctn_ctx_message(ctx), want);
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

static void test_errors(void)
{
    char text[1024];
    bar_model(text, sizeof text, 1e8, "engineering", 10, 2, 3, 1, 5, "buckling count=4");
    expect_error(text, "bk.cable:11: buckling: count=4 is more than the 3 free DOFs");
    bar_model(text, sizeof text, 1e8, "engineering", 10, 2, 3, 30, 5, "buckling count=1");   /* P > kx L */
    expect_error(text, "bk.cable:11: buckling: the loaded state is not stable");
    expect_error(text, "first at node 2, direction x");
    bar_model(text, sizeof text, 1e8, "engineering", 10, 2, 3, 0, 5, "buckling count=1");
    expect_error(text, "bk.cable:11: buckling: the last step has no loads on free DOFs");
    const char *big = "material m E=1e8\n"
                      "section s material=m A=1e-4 w=0.01\n"
                      "gravity 0 -1 0\n"
                      "node 1 0 0 0 fix=xyz\n"
                      "node 2 100 0 0 fix=xyz\n"
                      "cable 1 2 section=s n=700 length=101\n"
                      "buckling count=1\n";
    char want[128];
    snprintf(want, sizeof want, "bk.cable:7: buckling: the model has 2097 free DOFs, more than the %d",
             CTN_BUCKLING_MAX_DOFS);
    expect_error(big, want);
}

static void test_alloc(void)
{
    char text[1024];
    bar_model(text, sizeof text, 1e8, "engineering", 10, 2, 3, 1, 5, "buckling count=2");
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = NULL;
    ctn_solve_options opt;
    CHECK(ctn_read_string(ctx, "bk.cable", text, strlen(text), &m, &opt) == CTN_OK);
    int done = 0, failures = 0;
    for (long k = 1; !done && k < 5000; k++) {
        ctn_problem *p = NULL;
        ctn_solution *s = NULL;
        ctn_analysis *a = NULL;
        ctn_buckling_options bo;
        ctn_buckling_options_default(&bo);
        bo.count = 1;
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_problem_create(ctx, m, &opt, &p);
        if (!rc) rc = ctn_problem_solve(p, &s);
        if (!rc) rc = ctn_analysis_create(p, "buckling", &bo, &a);
        if (!rc) rc = ctn_analysis_run(a, &s);
        ctn_ctx_fail_alloc_at(ctx, 0);
        if (rc) {
            failures++;
            CHECK_MSG(rc == CTN_ERR_NOMEM, "allocation %ld: status %d (%s)", k, rc, ctn_ctx_message(ctx));
        } else {
            done = 1;
            CHECK(ctn_solution_buckling_count(s) == 1);
        }
        ctn_analysis_destroy(&a);
        ctn_solution_destroy(&s);
        ctn_problem_destroy(&p);
    }
    CHECK(done && failures > 10);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* The column along x of length 4 in n beams, P = 1000 down its axis: the lowest factor
 * (Iz = 1e-5) and the second (Iy = 2e-5) into lam[0], lam[1]. */
static void column(int cantilever, int n, double lam[2])
{
    char text[1024];
    snprintf(text, sizeof text,
             "material steel E=2e11 nu=0.3\n"
             "section s material=steel A=1 Iy=2e-5 Iz=1e-5 J=3e-5\n"
             "node 1 0 0 0 fix=%s\n"
             "node 2 4 0 0%s\n"
             "beam 1 1 2 section=s orient=0,0,1 n=%d\n"
             "load 2 -1000 0 0\n"
             "buckling count=2\n",
             cantilever ? "xyzrxryrz" : "xyzrx", cantilever ? "" : " fix=yz", n);
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK && s, "%s", ctn_ctx_message(ctx));
    for (size_t k = 0; k < 2; k++) {
        ctn_buckling_mode b;
        lam[k] = ctn_solution_buckling(s, k, &b) ? NAN : b.factor;
    }
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

/* Euler's load to 1e-4 from 4 elements (cantilever) or 8 (pinned); against the Euler
 * load of the column shortened by the critical load itself (L (1 - lambda P / EA): the
 * factor is the tangent's, about the loaded state), O(h^4) (the beam's bowing term gives
 * its consistent geometric stiffness). */
static void test_euler(int cantilever)
{
    const double pi = 3.14159265358979323846, EI = 2e11 * 1e-5, EA = 2e11, L = 4, P = 1000;
    const double k = cantilever ? 4 : 1;
    double exact = pi * pi * EI / (k * L * L) / P, shortened = exact, lam[4][2], err[4];
    for (int it = 0; it < 50; it++) {                   /* lambda = pi^2 EI / (k Lc^2 P) */
        double Lc = L * (1 - shortened * P / EA);
        shortened = pi * pi * EI / (k * Lc * Lc) / P;
    }
    for (int i = 0; i < 4; i++) {
        int n = 4 << i;
        column(cantilever, n, lam[i]);
        err[i] = (lam[i][0] - shortened) / shortened;
        CHECK_MSG(err[i] > -1e-7, "%s n=%d: %.17g below pi^2 EI", cantilever ? "cantilever" : "pinned", n, lam[i][0]);
        if (n >= (cantilever ? 4 : 8))
            CHECK_MSG(fabs(lam[i][0] / exact - 1) < 1e-4, "%s n=%d: %.17g against pi^2 EI / (k L^2 P) = %.17g",
                      cantilever ? "cantilever" : "pinned", n, lam[i][0], exact);
        CHECK_CLOSE(lam[i][1], 2 * lam[i][0], 0.01, 0);          /* Iy = 2 Iz */
    }
    for (int i = 0; i < 2; i++)
        CHECK_MSG(fabs(err[i] / err[i + 1] - 16) < 2, "%s: errors %g (n=%d), %g: not O(h^4)",
                  cantilever ? "cantilever" : "pinned", err[i], 4 << i, err[i + 1]);
}

int main(void)
{
    test_springs(10, 2, 3, 1);
    test_springs(3, 7, 5, 4);
    test_green_lagrange();
    test_von_mises();
    test_object();
    test_errors();
    test_alloc();
    test_euler(0);
    test_euler(1);
    CHECK_DONE();
}
