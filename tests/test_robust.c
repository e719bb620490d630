/* Robust solution (issue 4).
 * - the paper's four cables from a straight start and from the unstressed arc, with the
 *   globalized method, and from the elastic-catenary start with pure Newton, equal the
 *   paper-procedure answer to 1e-9;
 * - a shallow von Mises truss traced through its limit point and snap-through by
 *   arc-length, every path point on the closed-form load-displacement curve;
 * - a tension-only guy whose far support approaches until it goes slack, and back, in
 *   load steps with prescribed displacements: forces match the closed form;
 * - slack members do not bias taut ones: same forces as the model without them;
 * - a mechanism gives the node and direction (pure Newton), and the globalized method
 *   finds the pendulum equilibrium. */
#include "catena.h"
#include "check.h"

static const double lengths[] = { 200.3340, 201.3545, 250.8777, 279.6157 };

static ctn_model *cable_from(ctn_ctx *ctx, double S, ctn_cable_shape shape, double guess,
                             ctn_cable_start start)
{
    ctn_model *m = NULL;
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = 20, .length = S, .shape = shape, .guess_strain = guess, .start = start, .prestress = CTN_PRESTRESS_NONE };
    ctn_model_create(ctx, &m);
    ctn_model_set_gravity(m, g);
    ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0);
    ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1);
    ctn_model_add_node(m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(m, 2, B, CTN_FIX_ALL);
    ctn_model_add_cable(m, 1, 2, "strand", &spec, NULL, NULL);
    return m;
}

static ctn_model *cable(ctn_ctx *ctx, double S, ctn_cable_shape shape, double guess)
{
    return cable_from(ctx, S, shape, guess, CTN_START_ARC);
}

/* Solve with a method; current positions into x (3 nn). Returns the reason. */
static ctn_reason solve_positions(ctn_ctx *ctx, ctn_model *m, ctn_method method, double *x)
{
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    ctn_solve_summary sum;
    ctn_solve_options_default(&opt);
    opt.method = method;
    if (ctn_solve(ctx, m, &opt, &s)) return CTN_DIVERGED_NANORINF;
    ctn_solution_summary(s, &sum);
    const double *d = ctn_solution_displacements(s);
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info n;
        ctn_model_node(m, i, &n);
        for (int k = 0; k < 3; k++) x[3 * i + k] = n.X[k] + d[3 * i + k];
    }
    ctn_solution_destroy(&s);
    return sum.reason;
}

static void test_any_start(void)
{
    for (int c = 0; c < 4; c++) {
        ctn_ctx *ctx = NULL;
        ctn_ctx_create(&ctx);
        double ref[63], x[63];
        ctn_model *m = cable(ctx, lengths[c], CTN_SHAPE_ARC, 1e-3);
        CHECK(solve_positions(ctx, m, CTN_METHOD_NEWTON, ref) == CTN_CONVERGED);
        ctn_model_destroy(&m);
        for (int start = 0; start < 3; start++) {
            m = start == 2 ? cable_from(ctx, lengths[c], CTN_SHAPE_ARC, 1e-3, CTN_START_CATENARY)
              : start ? cable(ctx, lengths[c], CTN_SHAPE_ARC, 0.0)       /* unstressed arc */
                      : cable(ctx, lengths[c], CTN_SHAPE_STRAIGHT, 0.0); /* on the chord */
            /* the catenary start is good enough for the paper's pure Newton */
            ctn_reason r = solve_positions(ctx, m, start == 2 ? CTN_METHOD_NEWTON : CTN_METHOD_AUTO, x);
            CHECK_MSG(r == CTN_CONVERGED, "S=%g start %d: %s", lengths[c], start, ctn_reason_name(r));
            double err = 0;
            for (int i = 0; i < 63; i++) err = fmax(err, fabs(x[i] - ref[i]));
            CHECK_MSG(err <= 1e-9 * 200, "S=%g start %d: positions differ by %.3g m", lengths[c], start, err);
            ctn_model_destroy(&m);
        }
        ctn_ctx_destroy(&ctx);
    }
}

/* von Mises truss: supports (-a,0), (a,0), apex (0,h) loaded by lambda (0,-P).
 * Engineering strain: lambda P = -2 N (h - v) / l, N = EA (l/l0 - 1), l = |(a, h-v)|. */
static double vm_lambda(double v, double a, double h, double EA, double P)
{
    double l0 = hypot(a, h), l = hypot(a, h - v), N = EA * (l / l0 - 1);
    return -2 * N * (h - v) / l / P;
}

static void test_von_mises(void)
{
    double a = 10, h = 1, EA = 1e4, P = 1;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    ctn_model_create(ctx, &m);
    ctn_model_add_material(m, "bar", EA, CTN_STRAIN_ENGINEERING, 0);
    ctn_model_add_section(m, "sec", "bar", 1.0, 0);
    double A[3] = { -a, 0, 0 }, B[3] = { a, 0, 0 }, C[3] = { 0, h, 0 }, F[3] = { 0, -P, 0 };
    ctn_model_add_node(m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(m, 2, B, CTN_FIX_ALL);
    ctn_model_add_node(m, 3, C, CTN_FIX_X | CTN_FIX_Z);
    ctn_model_add_element(m, 1, 1, 3, "sec", CTN_L0_DEFAULT);
    ctn_model_add_element(m, 2, 2, 3, "sec", CTN_L0_DEFAULT);
    ctn_model_add_load(m, 3, F);
    double lim = 0;                              /* limit load: max of lambda(v), v in [0, h] */
    for (int i = 0; i <= 100000; i++) lim = fmax(lim, vm_lambda(h * i / 1e5, a, h, EA, P));
    ctn_solve_options opt;
    ctn_solve_options_default(&opt);
    opt.method = CTN_METHOD_ARCLENGTH;
    opt.arclength = 0.05;
    opt.arcsteps = 1000;
    opt.lambda_max = 1.5 * lim;
    CHECK(ctn_solve(ctx, m, &opt, &s) == CTN_OK);
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
    double vprev = -1, lmax_before = 0, vmax = 0;
    int monotone = 1, negative = 0;
    for (size_t k = 0; k < ctn_solution_step_count(s); k++) {
        ctn_step_result st;
        ctn_solution_step(s, k, &st);
        double v = -st.d[3 * 2 + 1];
        CHECK_CLOSE(st.load_factor, vm_lambda(v, a, h, EA, P), 1e-8, 1e-8 * lim);
        monotone &= v > vprev;
        vprev = v;
        vmax = fmax(vmax, v);
        negative |= st.load_factor < 0;
        if (v < h) lmax_before = fmax(lmax_before, st.load_factor);
    }
    CHECK(monotone);                             /* no snap-back for this truss */
    CHECK(negative);                             /* the path went through the unstable branch */
    CHECK(vmax > 2 * h);                         /* snapped through to the inverted side */
    CHECK_CLOSE(lmax_before, lim, 2e-2, 0);      /* passed the limit point on the curve */
    CHECK(sum.load_factor >= 1.5 * lim);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Guy line: A (-10,0,0) - P - B (10,0,0), tension-only, l0 = 9.9 each, a load F to +x
 * on P (free in x only). B moves left by delta and back. While B is taut:
 * u = (F l0/EA - delta)/2, N_A = N_B + F; once slack: N_A = F, N_B = 0. */
static void test_slack_and_back(void)
{
    double EA = 1e3, l0 = 9.9, F = 2.0;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    ctn_model_create(ctx, &m);
    ctn_model_add_material(m, "rope", EA, CTN_STRAIN_ENGINEERING, 1);
    ctn_model_add_section(m, "sec", "rope", 1.0, 0);
    double A[3] = { -10, 0, 0 }, Pn[3] = { 0, 0, 0 }, B[3] = { 10, 0, 0 }, L[3] = { F, 0, 0 };
    ctn_model_add_node(m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(m, 2, Pn, CTN_FIX_Y | CTN_FIX_Z);
    ctn_model_add_node(m, 3, B, CTN_FIX_ALL);
    ctn_model_add_element(m, 1, 1, 2, "sec", l0);
    ctn_model_add_element(m, 2, 2, 3, "sec", l0);
    ctn_model_add_load(m, 2, L);
    const double moves[] = { -0.1, -0.2, -0.2, 0.2, 0.2, 0.1 };   /* B's x increments */
    char name[16];
    for (int k = 0; k < 6; k++) {
        double u[3] = { moves[k], 0, 0 };
        snprintf(name, sizeof name, "move%d", k);
        ctn_model_add_step(m, name, 4);
        ctn_model_add_displacement(m, 3, CTN_FIX_X, u);
    }
    CHECK(ctn_solve(ctx, m, NULL, &s) == CTN_OK);
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
    CHECK(ctn_solution_step_count(s) == 6);
    double delta = 0;
    int slack_seen = 0;
    for (size_t k = 0; k < ctn_solution_step_count(s); k++) {
        delta -= moves[k];
        ctn_element_state ea, eb;
        ctn_step_result st;
        ctn_solution_step(s, k, &st);
        ctn_solution_step_element(s, k, 0, &ea);
        ctn_solution_step_element(s, k, 1, &eb);
        double u = (F * l0 / EA - delta) / 2, NB = EA * ((10 - delta - u) / l0 - 1);
        if (NB > 0) {
            CHECK_CLOSE(st.d[3], u, 1e-9, 1e-12);
            CHECK_CLOSE(eb.force, NB, 1e-9, 1e-12);
            CHECK_CLOSE(ea.force, NB + F, 1e-9, 1e-12);
            CHECK(!eb.slack);
        } else {
            slack_seen = 1;
            CHECK(eb.slack && eb.force == 0);
            CHECK_CLOSE(ea.force, F, 1e-9, 0);
            CHECK_CLOSE(st.d[3], l0 * (1 + F / EA) - 10, 1e-9, 1e-12);
        }
    }
    CHECK(slack_seen);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* A loaded node held by three pretensioned guys in the x-y plane; a fourth guy, 1 %
 * longer than its span, on the side the load pushes the node towards, stays slack.
 * Its presence must not change the taut guys' forces. */
static void tripod(ctn_ctx *ctx, int with_slack, double N[3])
{
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_model_create(ctx, &m);
    ctn_model_add_material(m, "rope", 5e3, CTN_STRAIN_GREEN_LAGRANGE, 1);
    ctn_model_add_section(m, "sec", "rope", 1.0, 0);
    double P[3] = { 0, 0, 0 }, F[3] = { 3, 1, 0 };
    double S[4][3] = { { 10, 0, 0 }, { -5, 8, 0 }, { -5, -8, 0 }, { 8, -6, 0 } };
    double factor[4] = { 0.999, 0.999, 0.999, 1.01 };
    ctn_model_add_node(m, 1, P, CTN_FIX_Z);
    for (int i = 0; i < 3 + with_slack; i++) {
        ctn_model_add_node(m, 2 + i, S[i], CTN_FIX_ALL);
        ctn_model_add_element(m, 1 + i, 1, 2 + i, "sec", factor[i] * sqrt(S[i][0] * S[i][0] + S[i][1] * S[i][1]));
    }
    ctn_model_add_load(m, 1, F);
    CHECK(ctn_solve(ctx, m, NULL, &s) == CTN_OK);
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    CHECK(sum.reason == CTN_CONVERGED);
    for (int i = 0; i < 3; i++) {
        ctn_element_state st;
        ctn_solution_element(s, (size_t)i, &st);
        N[i] = st.force;
    }
    if (with_slack) {
        ctn_element_state st;
        ctn_solution_element(s, 3, &st);
        CHECK(st.slack && st.force == 0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
}

static void test_slack_bias(void)
{
    ctn_ctx *ctx = NULL;
    double a[3], b[3];
    ctn_ctx_create(&ctx);
    tripod(ctx, 0, a);
    tripod(ctx, 1, b);
    for (int i = 0; i < 3; i++) {
        CHECK(a[i] > 0);
        CHECK_CLOSE(b[i], a[i], 1e-12, 0);
    }
    ctn_ctx_destroy(&ctx);
}

static void test_mechanism(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    ctn_model_create(ctx, &m);
    ctn_model_add_material(m, "bar", 1e4, CTN_STRAIN_GREEN_LAGRANGE, 0);
    ctn_model_add_section(m, "sec", "bar", 1.0, 0);
    double A[3] = { 0, 0, 0 }, B[3] = { 5, 0, 0 }, F[3] = { 0, -2, 0 };
    ctn_model_add_node(m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(m, 7, B, CTN_FIX_Z);
    ctn_model_add_element(m, 1, 1, 7, "sec", CTN_L0_DEFAULT);
    ctn_model_add_load(m, 7, F);
    ctn_solve_options opt;
    ctn_solve_options_default(&opt);
    opt.method = CTN_METHOD_NEWTON;
    CHECK(ctn_solve(ctx, m, &opt, &s) == CTN_OK);
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    CHECK(sum.reason == CTN_DIVERGED_INDEFINITE);
    CHECK(sum.fail_node == 7 && sum.fail_dir == 1);           /* node 7, direction y */
    ctn_solution_destroy(&s);
    /* globalized: the bar swings down to hang along the load, N = |F| */
    opt.method = CTN_METHOD_AUTO;
    CHECK(ctn_solve(ctx, m, &opt, &s) == CTN_OK);
    ctn_solution_summary(s, &sum);
    CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
    ctn_element_state st;
    ctn_solution_element(s, 0, &st);
    const double *d = ctn_solution_displacements(s);
    CHECK_CLOSE(st.force, 2.0, 1e-9, 0);
    CHECK_CLOSE(B[0] + d[3], 0.0, 0, 1e-9);                  /* straight below node 1 */
    CHECK(B[1] + d[4] < 0);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_any_start();
    test_von_mises();
    test_slack_and_back();
    test_slack_bias();
    test_mechanism();
    CHECK_DONE();
}
