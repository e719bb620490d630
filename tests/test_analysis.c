/* Analyses as objects (catena/analysis.h):
 * - the registry lists static, stability, modal and buckling; an unknown name is refused, naming
 *   the known ones;
 * - the static analysis object gives the bits of ctn_problem_solve; a run-time key
 *   (maxit) may differ from the problem's, a set-up key (method) may not;
 * - stability and modal objects store in the solution what ctn_problem_stability and
 *   ctn_problem_modes give, bit for bit; they refuse a solution that did not converge;
 * - versioned options: size 0 and a size beyond this library's are refused; a caller
 *   built against an older, shorter struct gets the defaults for the keys it lacks;
 * - every allocation failure in create and run: CTN_ERR_NOMEM, no leak (ASan). */
#include "catena.h"
#include "check.h"

#include <stddef.h>
#include <stdlib.h>

static const char *text =
    "units kN m\n"
    "material steel E=2.0e8\n"
    "section strand material=steel A=3.14e-4 w=0.1 mass=0.0102\n"
    "gravity 0 -1 0\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 200 0 0 fix=xyz\n"
    "cable 1 2 section=strand n=20 length=201.3545\n";

static ctn_model *read_model(ctn_ctx *ctx, ctn_solve_options *opt)
{
    ctn_model *m = NULL;
    int rc = ctn_read_string(ctx, "test.cable", text, strlen(text), &m, opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    return m;
}

static void test_registry(void)
{
    CHECK(ctn_analysis_count() == 5);
    CHECK(!strcmp(ctn_analysis_type(0), "static") && !strcmp(ctn_analysis_type(1), "stability") &&
          !strcmp(ctn_analysis_type(2), "modal") && !strcmp(ctn_analysis_type(3), "buckling") &&
          !strcmp(ctn_analysis_type(4), "dynamics") && ctn_analysis_type(5) == NULL);
    ctn_ctx *ctx = NULL;
    ctn_problem *p = NULL;
    ctn_analysis *a = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, NULL);
    CHECK(ctn_problem_create(ctx, m, NULL, &p) == CTN_OK);
    CHECK(ctn_analysis_create(p, "transient", NULL, &a) == CTN_ERR_INVALID && a == NULL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "unknown analysis 'transient' (known: static, stability, modal, buckling, dynamics)"), "%s",
              ctn_ctx_message(ctx));
    ctn_problem_destroy(&p);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_static(void)
{
    ctn_ctx *ctx = NULL;
    ctn_problem *p = NULL;
    ctn_solution *s1 = NULL, *s2 = NULL, *s3 = NULL;
    ctn_analysis *a = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, NULL);
    CHECK(ctn_problem_create(ctx, m, NULL, &p) == CTN_OK);
    CHECK(ctn_problem_solve(p, &s1) == CTN_OK);
    CHECK(ctn_analysis_create(p, "static", NULL, &a) == CTN_OK && !strcmp(ctn_analysis_name(a), "static"));
    CHECK(ctn_analysis_run(a, &s2) == CTN_OK && s2);
    size_t n3 = 3 * ctn_model_node_count(m);
    CHECK(s1 && s2 && !memcmp(ctn_solution_displacements(s1), ctn_solution_displacements(s2), n3 * sizeof(double)));
    ctn_analysis_destroy(&a);
    CHECK(a == NULL);

    ctn_solve_options o;                        /* a run-time key: maxit 1 stops early */
    ctn_solve_options_default(&o);
    o.maxit = 1;
    o.maxcuts = 0;
    CHECK(ctn_analysis_create(p, "static", &o, &a) == CTN_OK);
    CHECK(ctn_analysis_run(a, &s3) == CTN_OK);
    ctn_solve_summary sum;
    ctn_solution_summary(s3, &sum);
    CHECK(sum.reason == CTN_DIVERGED_MAXIT);
    ctn_analysis_destroy(&a);
    ctn_solution_summary(s1, &sum);            /* the problem's own options are intact */
    ctn_solution_destroy(&s3);
    CHECK(ctn_problem_solve(p, &s3) == CTN_OK);
    CHECK(!memcmp(ctn_solution_displacements(s1), ctn_solution_displacements(s3), n3 * sizeof(double)));

    o.maxit = 50;                               /* a set-up key: the method */
    o.method = CTN_METHOD_ARCLENGTH;
    CHECK(ctn_analysis_create(p, "static", &o, &a) == CTN_ERR_INVALID && a == NULL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "its method differs from the problem's"), "%s", ctn_ctx_message(ctx));
    o.method = CTN_METHOD_AUTO;                 /* an option out of range */
    o.tol = -1;
    CHECK(ctn_analysis_create(p, "static", &o, &a) == CTN_ERR_INVALID && a == NULL);

    ctn_solution_destroy(&s1);
    ctn_solution_destroy(&s2);
    ctn_solution_destroy(&s3);
    ctn_problem_destroy(&p);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_after_solve(void)
{
    ctn_ctx *ctx = NULL;
    ctn_problem *p = NULL;
    ctn_solution *s = NULL, *bad = NULL;
    ctn_analysis *a = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, NULL);
    CHECK(ctn_problem_create(ctx, m, NULL, &p) == CTN_OK && ctn_problem_solve(p, &s) == CTN_OK);

    ctn_stability ref, got;
    CHECK(ctn_problem_stability(p, s, &ref) == CTN_OK && ref.stable == 1);
    ctn_stability_options so;
    ctn_stability_options_default(&so);
    CHECK(so.size == sizeof so);
    CHECK(ctn_analysis_create(p, "stability", &so, &a) == CTN_OK);
    CHECK(ctn_analysis_run(a, &s) == CTN_OK);
    CHECK(ctn_solution_stability(s, &got) == CTN_OK && !memcmp(&ref, &got, sizeof ref));
    ctn_solution *none = NULL;
    CHECK(ctn_analysis_run(a, &none) == CTN_ERR_INVALID);
    ctn_analysis_destroy(&a);

    ctn_modal_options mo;
    ctn_modal_options_default(&mo);
    CHECK(mo.size == sizeof mo && mo.count == 0 && mo.solver == CTN_EIGEN_AUTO);
    CHECK(ctn_analysis_create(p, "modal", &mo, &a) == CTN_ERR_INVALID && a == NULL);   /* count 0 */
    mo.count = 4;
    CHECK(ctn_problem_modes(p, s, &mo) == CTN_OK);
    double f[4];
    for (size_t k = 0; k < 4; k++) {
        ctn_mode md;
        CHECK(ctn_solution_mode(s, k, &md) == CTN_OK);
        f[k] = md.frequency;
    }
    CHECK(ctn_analysis_create(p, "modal", &mo, &a) == CTN_OK);
    CHECK(ctn_analysis_run(a, &s) == CTN_OK && ctn_solution_mode_count(s) == 4);
    for (size_t k = 0; k < 4; k++) {
        ctn_mode md;
        CHECK(ctn_solution_mode(s, k, &md) == CTN_OK && md.frequency == f[k] && md.frequency > 0);
    }

    ctn_solve_options o;                        /* a solution that did not converge */
    ctn_solve_options_default(&o);
    o.maxit = 1;
    o.maxcuts = 0;
    ctn_analysis *st = NULL;
    CHECK(ctn_analysis_create(p, "static", &o, &st) == CTN_OK && ctn_analysis_run(st, &bad) == CTN_OK);
    CHECK(ctn_analysis_run(a, &bad) == CTN_ERR_INVALID);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "modal analysis: the solution did not converge"), "%s", ctn_ctx_message(ctx));
    ctn_analysis_destroy(&st);
    ctn_analysis_destroy(&a);
    ctn_solution_destroy(&bad);
    ctn_solution_destroy(&s);
    ctn_problem_destroy(&p);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* A caller built against an older header: its struct ends before `threads`. */
static void test_versions(void)
{
    ctn_ctx *ctx = NULL;
    ctn_problem *p = NULL;
    ctn_solution *s1 = NULL, *s2 = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, NULL);
    ctn_solve_options o;
    ctn_solve_options_default(&o);
    CHECK(o.size == sizeof o);
    o.size = 0;
    CHECK(ctn_problem_create(ctx, m, &o, &p) == CTN_ERR_INVALID && p == NULL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "solve options: size is 0"), "%s", ctn_ctx_message(ctx));
    o.size = sizeof o + 8;
    CHECK(ctn_problem_create(ctx, m, &o, &p) == CTN_ERR_INVALID && p == NULL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "a newer catena"), "%s", ctn_ctx_message(ctx));

    unsigned char *old = malloc(sizeof o);      /* the older layout, garbage past its end */
    ctn_solve_options_default(&o);
    o.size = offsetof(ctn_solve_options, threads);
    memset(old, 0xff, sizeof o);
    memcpy(old, &o, o.size);
    CHECK(ctn_problem_create(ctx, m, (const ctn_solve_options *)old, &p) == CTN_OK);
    CHECK(ctn_problem_solve(p, &s1) == CTN_OK);
    ctn_problem_destroy(&p);
    CHECK(ctn_problem_create(ctx, m, NULL, &p) == CTN_OK && ctn_problem_solve(p, &s2) == CTN_OK);
    size_t n3 = 3 * ctn_model_node_count(m);
    CHECK(s1 && s2 && !memcmp(ctn_solution_displacements(s1), ctn_solution_displacements(s2), n3 * sizeof(double)));
    free(old);

    ctn_modal_options mo = { .count = 2 };      /* not initialised by its _default */
    CHECK(ctn_problem_modes(p, s2, &mo) == CTN_ERR_INVALID);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "modal options: size is 0"), "%s", ctn_ctx_message(ctx));
    ctn_solution_destroy(&s1);
    ctn_solution_destroy(&s2);
    ctn_problem_destroy(&p);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_alloc(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, NULL);
    int done = 0, failures = 0;
    for (long k = 1; !done && k < 5000; k++) {
        ctn_problem *p = NULL;
        ctn_solution *s = NULL;
        ctn_analysis *a = NULL, *b = NULL, *c = NULL;
        ctn_modal_options mo;
        ctn_modal_options_default(&mo);
        mo.count = 3;
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_problem_create(ctx, m, NULL, &p);
        if (!rc) rc = ctn_analysis_create(p, "static", NULL, &a);
        if (!rc) rc = ctn_analysis_run(a, &s);
        if (!rc) rc = ctn_analysis_create(p, "stability", NULL, &b);
        if (!rc) rc = ctn_analysis_run(b, &s);
        if (!rc) rc = ctn_analysis_create(p, "modal", &mo, &c);
        if (!rc) rc = ctn_analysis_run(c, &s);
        ctn_ctx_fail_alloc_at(ctx, 0);
        if (rc) {
            failures++;
            CHECK_MSG(rc == CTN_ERR_NOMEM, "allocation %ld: status %d (%s)", k, rc, ctn_ctx_message(ctx));
        } else {
            done = 1;
        }
        ctn_analysis_destroy(&a);
        ctn_analysis_destroy(&b);
        ctn_analysis_destroy(&c);
        ctn_solution_destroy(&s);
        ctn_problem_destroy(&p);
    }
    CHECK(done && failures > 10);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_registry();
    test_static();
    test_after_solve();
    test_versions();
    test_alloc();
    CHECK_DONE();
}
