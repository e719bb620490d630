/* Mesh convergence: the FEA with engineering strain converges to Irvine's elastic
 * catenary at second order.
 * - the paper's span (a slack and a taut length), n = 10 ... 1000 elements, pure Newton:
 *   mid-span sag (ctn_solution_cable_sag) and support tension (resultant reaction)
 *   against ctn_ecatenary_solve; the observed order between successive doublings is
 *   2 +- 0.1 and at n = 1000 both agree within 1e-6 relative;
 * - ctn_convergence_run reports the same errors and an order of 2 +- 0.05;
 * - an inclined span in 3D (z up, w a mass per length): the library's reference is the
 *   elastic catenary of l = 150, h = 30 solved here, and sag, tension and H converge at
 *   order 2 +- 0.05 (the sag read between nodes);
 * - allocation failures in ctn_convergence_run give CTN_ERR_NOMEM and no leak. */
#include "catena.h"
#include "check.h"

static const int meshes[] = { 10, 20, 40, 80, 160, 320, 1000 };
#define NMESH (sizeof meshes / sizeof *meshes)

static ctn_model *span_model(ctn_ctx *ctx, double S, int n)
{
    ctn_model *m = NULL;
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = n, .length = S, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    if (ctn_model_create(ctx, &m) || ctn_model_set_units(m, "kN", "m") || ctn_model_set_gravity(m, g) ||
        ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_ENGINEERING, 0) ||
        ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1) ||
        ctn_model_add_node(m, 1, A, CTN_FIX_ALL) || ctn_model_add_node(m, 2, B, CTN_FIX_ALL) ||
        ctn_model_add_cable(m, 1, 2, "strand", &spec, NULL, NULL))
        ctn_model_destroy(&m);
    return m;
}

/* Relative errors of the FEA with n elements: sag and support tension. */
static int fea_errors(double S, int n, const ctn_ecatenary *ref, double err[2])
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = span_model(ctx, S, n);
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    ctn_solve_summary sum;
    ctn_solve_options_default(&opt);
    opt.method = CTN_METHOD_NEWTON;
    opt.tol = 1e-12;
    int ok = m && !ctn_solve(ctx, m, &opt, &s);
    if (ok) ctn_solution_summary(s, &sum);
    ok = ok && sum.reason == CTN_CONVERGED;
    double sag = 0;
    if (ok) ok = !ctn_solution_cable_sag(m, s, 0, &sag);
    if (ok) {
        const double *r = ctn_solution_reactions(s);
        double T = fmax(hypot(r[0], r[1]), hypot(r[3], r[4]));
        err[0] = fabs(sag - ref->sum.sag_mid) / ref->sum.sag_mid;
        err[1] = fabs(T - ref->sum.T_max) / ref->sum.T_max;
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return ok;
}

static void test_order(double S, double err1000[2])
{
    ctn_ecatenary_in in = { 200, 0, 0.1, 2.0e8 * 3.14e-4, S };
    ctn_ecatenary ref;
    double e[NMESH][2];
    CHECK(ctn_ecatenary_solve(NULL, &in, &ref) == CTN_OK);
    for (size_t i = 0; i < NMESH; i++) CHECK_MSG(fea_errors(S, meshes[i], &ref, e[i]), "S=%g n=%d", S, meshes[i]);
    for (size_t i = 1; i < NMESH; i++)
        for (int k = 0; k < 2; k++) {
            double p = log(e[i - 1][k] / e[i][k]) / log((double)meshes[i] / meshes[i - 1]);
            CHECK_MSG(fabs(p - 2) < 0.1, "S=%g %s: order %.3f between n=%d and n=%d", S, k ? "tension" : "sag", p,
                      meshes[i - 1], meshes[i]);
        }
    CHECK_MSG(e[NMESH - 1][0] < 1e-6, "S=%g: sag error %.3g at n=1000", S, e[NMESH - 1][0]);
    CHECK_MSG(e[NMESH - 1][1] < 1e-6, "S=%g: support tension error %.3g at n=1000", S, e[NMESH - 1][1]);
    err1000[0] = e[NMESH - 1][0];
    err1000[1] = e[NMESH - 1][1];
}

/* The library's study agrees with the errors measured above. */
static void test_library(double S, const double err1000[2])
{
    ctn_solve_options newton;                 /* the paper's pure Newton */
    ctn_solve_options_default(&newton);
    newton.method = CTN_METHOD_NEWTON;
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *base = span_model(ctx, S, 20);
    ctn_convergence *cv = NULL;
    size_t ns[NMESH];
    for (size_t i = 0; i < NMESH; i++) ns[NMESH - 1 - i] = (size_t)meshes[i];   /* unsorted on purpose */
    CHECK(base && ctn_convergence_run(ctx, base, &newton, ns, NMESH, &cv) == CTN_OK);
    CHECK(ctn_convergence_count(cv) == NMESH);
    for (size_t i = 0; i < ctn_convergence_count(cv); i++) {
        const ctn_convergence_row *r = ctn_convergence_row_at(cv, i);
        CHECK(r->n == (size_t)meshes[i] && r->reason == CTN_CONVERGED);
    }
    const ctn_convergence_row *last = ctn_convergence_row_at(cv, NMESH - 1);
    CHECK(last != NULL);
    if (last) {
        CHECK_CLOSE(last->err_sag, err1000[0], 1e-3, 1e-13);
        CHECK_CLOSE(last->err_T, err1000[1], 1e-3, 1e-13);
    }
    for (int k = 0; k < 3; k++) {
        double p = 0;
        CHECK(ctn_convergence_order(cv, k, &p) == CTN_OK);
        CHECK_MSG(fabs(p - 2) < 0.05, "S=%g: fitted order %.4f (column %d)", S, p, k);
    }
    ctn_convergence_destroy(&cv);
    CHECK(cv == NULL);
    ctn_model_destroy(&base);
    ctn_ctx_destroy(&ctx);
}

static void test_inclined(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = NULL;
    double A[3] = { 0, 0, 0 }, B[3] = { 120, 90, 30 }, g[3] = { 0, 0, -9.81 };
    ctn_cable_spec spec = { .n = 10, .length = 170, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    int rc = ctn_model_create(ctx, &m) || ctn_model_set_gravity(m, g) ||
             ctn_model_add_material(m, "rope", 1.2e8, CTN_STRAIN_GREEN_LAGRANGE, 0) ||
             ctn_model_add_section(m, "s", "rope", 2e-4, 0.05) || ctn_model_add_node(m, 1, A, CTN_FIX_ALL) ||
             ctn_model_add_node(m, 2, B, CTN_FIX_ALL) || ctn_model_add_cable(m, 1, 2, "s", &spec, NULL, NULL);
    CHECK(rc == 0);
    ctn_ecatenary_in in = { 150, 30, 0.05 * 9.81, 1.2e8 * 2e-4, 170 };
    ctn_ecatenary ref;
    CHECK(ctn_ecatenary_solve(NULL, &in, &ref) == CTN_OK);
    size_t ns[5] = { 10, 20, 40, 80, 160 };
    ctn_convergence *cv = NULL;
    CHECK(!rc && ctn_convergence_run(ctx, m, NULL, ns, 5, &cv) == CTN_OK);
    const ctn_compare_values *r = ctn_convergence_reference(cv);
    CHECK(r != NULL);
    if (r) {
        CHECK_CLOSE(r->sag, ref.sum.sag_mid, 1e-12, 0);
        CHECK_CLOSE(r->T_max, ref.sum.T_max, 1e-12, 0);
        CHECK_CLOSE(r->H, ref.H, 1e-12, 0);
    }
    for (int k = 0; k < 3; k++) {
        double p = 0;
        CHECK(ctn_convergence_order(cv, k, &p) == CTN_OK);
        CHECK_MSG(fabs(p - 2) < 0.05, "inclined: fitted order %.4f (column %d)", p, k);
    }
    ctn_convergence_destroy(&cv);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_alloc(void)
{
    ctn_solve_options newton;                 /* the paper's pure Newton */
    ctn_solve_options_default(&newton);
    newton.method = CTN_METHOD_NEWTON;
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *base = span_model(ctx, 250.8777, 20);
    size_t ns[2] = { 4, 8 };
    int done = 0, failures = 0;
    for (long k = 1; k < 20000 && base && !done; k++) {
        ctn_convergence *cv = NULL;
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_convergence_run(ctx, base, &newton, ns, 2, &cv);
        ctn_ctx_fail_alloc_at(ctx, 0);
        if (rc) {
            failures++;
            CHECK_MSG(rc == CTN_ERR_NOMEM && cv == NULL, "allocation %ld: status %d", k, rc);
        } else done = 1;
        ctn_convergence_destroy(&cv);
        ctn_ctx_clear(ctx);
    }
    CHECK(done && failures >= 10);
    ctn_model_destroy(&base);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    static const double lengths[2] = { 250.8777, 201.3545 };
    for (int i = 0; i < 2; i++) {
        double e[2] = { 0, 0 };
        test_order(lengths[i], e);
        test_library(lengths[i], e);
    }
    test_inclined();
    test_alloc();
    CHECK_DONE();
}
