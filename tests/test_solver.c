/* Solver layer: Newton-Raphson on whole models.
 * - the paper's four cables converge in <= 15 iterations, quadratically at the end,
 *   and the reactions balance the total weight to 1e-9;
 * - a bar under an axial load matches the closed form of each strain measure;
 * - a weightless cable with point loads (engineering strain) matches the funicular
 *   polygon computed independently here;
 * - compressed start: the indefinite tangent is reported with its node, no crash;
 * - the sag of a cable: a vertical hanging cable pushed sideways reports the largest
 *   distance of its nodes from the chord (not 0), in `sag` and `max_sag_from_chord`; on
 *   a level span with a node at mid-span both are that node's depth; without gravity
 *   "down" is the resultant load;
 * - every allocation failure gives CTN_ERR_NOMEM and no leak (ASan build). */
#include "catena.h"
#include "check.h"

#include <stdlib.h>

static const double paper_lengths[] = { 200.3340, 201.3545, 250.8777, 279.6157 };

static ctn_model *paper_model(ctn_ctx *ctx, double S, int n)
{
    ctn_model *m = NULL;
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = n, .length = S, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    if (ctn_model_create(ctx, &m) || ctn_model_set_units(m, "kN", "m") ||
        ctn_model_set_gravity(m, g) ||
        ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0) ||
        ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1) ||
        ctn_model_add_node(m, 1, A, CTN_FIX_ALL) || ctn_model_add_node(m, 2, B, CTN_FIX_ALL) ||
        ctn_model_add_cable(m, 1, 2, "strand", &spec, NULL, NULL)) {
        ctn_model_destroy(&m);
        return NULL;
    }
    return m;
}

/* Quadratic convergence in the last iterations: over the steps k with r_k/f < 1e-2 and
 * r_k+1/f above the round-off floor (1e-10), r_k+1/f <= C (r_k/f)^2 with a bounded
 * C = 100. A linearly converging iteration, r_k+1 = q r_k with q >= 0.1, breaks this as
 * soon as r_k/f < 1e-3. (The paper's cases show C between 0.04 and 28.) At least one
 * such step must exist. */
static void check_quadratic(const double *r, size_t n, double f, double S)
{
    int steps = 0;
    for (size_t k = 1; k + 1 < n; k++) {
        double a = r[k] / f, b = r[k + 1] / f;
        if (a >= 1e-2 || b <= 1e-10) continue;
        steps++;
        CHECK_MSG(b <= 100 * a * a, "S=%g: step %zu: %.3g -> %.3g is not quadratic", S, k, a, b);
    }
    CHECK_MSG(steps >= 1, "S=%g: no step in the asymptotic range", S);
}

static void test_paper_cases(void)
{
    for (int c = 0; c < 4; c++) {
        ctn_ctx *ctx = NULL;
        ctn_ctx_create(&ctx);
        ctn_model *m = paper_model(ctx, paper_lengths[c], 20);
        ctn_solution *s = NULL;
        ctn_solve_options opt;
        ctn_solve_options_default(&opt);
        opt.method = CTN_METHOD_NEWTON;             /* the paper's pure Newton */
        CHECK(m != NULL);
        CHECK(ctn_solve(ctx, m, &opt, &s) == CTN_OK);
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        CHECK_MSG(sum.reason == CTN_CONVERGED, "S=%g: %s", paper_lengths[c], ctn_reason_name(sum.reason));
        CHECK_MSG(sum.iterations <= 15, "S=%g: %d iterations", paper_lengths[c], sum.iterations);
        size_t nh;
        const double *h = ctn_solution_residual_history(s, &nh);
        check_quadratic(h, nh, sum.fext_norm, paper_lengths[c]);
        /* reactions balance the total weight w S (and nothing horizontal) */
        const double *r = ctn_solution_reactions(s);
        double sum_r[3] = { 0, 0, 0 };
        for (size_t i = 0; i < ctn_model_node_count(m); i++)
            for (int k = 0; k < 3; k++) sum_r[k] += r[3 * i + k];
        double W = 0.1 * paper_lengths[c];
        CHECK_CLOSE(sum_r[1], W, 1e-9, 0);
        CHECK(fabs(sum_r[0]) <= 1e-9 * W && fabs(sum_r[2]) <= 1e-9 * W);
        /* symmetric span: equal vertical reactions, each W/2 */
        CHECK_CLOSE(r[1], W / 2, 1e-9, 0);
        ctn_solution_destroy(&s);
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
}

/* Green-Lagrange bar: P = EA (lam^2 - 1)/2 lam, solved here by bisection. */
static double gl_stretch(double P_over_EA)
{
    double lo = 1, hi = 3;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if ((mid * mid - 1) / 2 * mid < P_over_EA) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static void test_bar(void)
{
    for (int strain = 0; strain < 2; strain++) {
        ctn_ctx *ctx = NULL;
        ctn_model *m = NULL;
        ctn_solution *s = NULL;
        double A[3] = { 0, 0, 0 }, B[3] = { 10, 0, 0 }, P = 250, EA = 1e4;
        double F[3] = { P, 0, 0 };
        ctn_ctx_create(&ctx);
        ctn_model_create(ctx, &m);
        ctn_model_add_material(m, "mat", EA, (ctn_strain)strain, 0);
        ctn_model_add_section(m, "sec", "mat", 1.0, 0);
        ctn_model_add_node(m, 1, A, CTN_FIX_ALL);
        ctn_model_add_node(m, 2, B, CTN_FIX_Y | CTN_FIX_Z);     /* one free DOF: x */
        ctn_model_add_element(m, 1, 1, 2, "sec", 10.0);
        ctn_model_add_load(m, 2, F);
        CHECK(ctn_solve(ctx, m, NULL, &s) == CTN_OK);
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        CHECK(sum.reason == CTN_CONVERGED);
        ctn_element_state st;
        ctn_solution_element(s, 0, &st);
        double lam = strain ? 1 + P / EA : gl_stretch(P / EA);
        CHECK_CLOSE(st.force, P, 1e-9, 0);
        CHECK_CLOSE(st.length, 10 * lam, 1e-12, 0);
        ctn_solution_destroy(&s);
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
}

#define FN 8   /* segments of the funicular test */

/* Independent funicular solution. The left support holds the cable with (-H, V)
 * (V upward); across joint k the load P_k (downward) turns the segment force, so
 * segment i pulls along (H, -(V - sum_{k<i} P_k)) and has the stretched length
 * L0_i (1 + |T_i|/EA). Find H, V so that the chain ends at (l, h). */
static void funicular_end(const double *P, const double *L0, double EA, double H, double V,
                          double e[2])
{
    e[0] = e[1] = 0;
    double vy = V;
    for (int i = 0; i < FN; i++) {
        if (i > 0) vy -= P[i - 1];
        double T = sqrt(H * H + vy * vy), len = L0[i] * (1 + T / EA);
        e[0] += len * H / T;
        e[1] -= len * vy / T;
    }
}

static void funicular_solve(const double *P, const double *L0, double EA, double l, double h,
                            double *H, double *V)
{
    for (int it = 0; it < 100; it++) {
        double e[2], ex[2], ey[2], dH = 1e-7 * fabs(*H), dV = 1e-7 * (fabs(*V) + fabs(*H));
        funicular_end(P, L0, EA, *H, *V, e);
        double r0 = e[0] - l, r1 = e[1] - h;
        if (fabs(r0) + fabs(r1) < 1e-13 * l) break;
        funicular_end(P, L0, EA, *H + dH, *V, ex);
        funicular_end(P, L0, EA, *H, *V + dV, ey);
        double a = (ex[0] - e[0]) / dH, b = (ey[0] - e[0]) / dV, c = (ex[1] - e[1]) / dH, d = (ey[1] - e[1]) / dV;
        double det = a * d - b * c;
        *H -= (d * r0 - b * r1) / det;
        *V -= (-c * r0 + a * r1) / det;
    }
}

static void test_funicular(void)
{
    double P[FN - 1] = { 3, 5, 2, 8, 1, 4, 6 };      /* downward joint loads */
    double L0[FN], X[FN + 1][3], EA = 2e4, l = 100, h = 15, H = 20, V = 10;
    for (int i = 0; i <= FN; i++) {                  /* start polygon, deep sag */
        double t = (double)i / FN;
        X[i][0] = l * t;
        X[i][1] = h * t - 80 * t * (1 - t);
        X[i][2] = 0;
    }
    for (int i = 0; i < FN; i++)                     /* unstressed: 1 % shorter than the start */
        L0[i] = 0.99 * hypot(X[i + 1][0] - X[i][0], X[i + 1][1] - X[i][1]);
    funicular_solve(P, L0, EA, l, h, &H, &V);
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    ctn_model_create(ctx, &m);
    ctn_model_add_material(m, "mat", EA, CTN_STRAIN_ENGINEERING, 0);
    ctn_model_add_section(m, "sec", "mat", 1.0, 0);
    for (int i = 0; i <= FN; i++) {
        ctn_model_add_node(m, i + 1, X[i], i == 0 || i == FN ? CTN_FIX_ALL : CTN_FIX_Z);
        double F[3] = { 0, i > 0 && i < FN ? -P[i - 1] : 0, 0 };
        ctn_model_add_load(m, i + 1, F);
    }
    for (int i = 0; i < FN; i++) ctn_model_add_element(m, i + 1, i + 1, i + 2, "sec", L0[i]);
    CHECK(ctn_solve(ctx, m, NULL, &s) == CTN_OK);
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
    const double *d = ctn_solution_displacements(s), *r = ctn_solution_reactions(s);
    CHECK_CLOSE(r[0], -H, 1e-9, 0);                  /* left support holds (-H, V) */
    CHECK_CLOSE(r[1], V, 1e-9, 0);
    double x = 0, y = 0, vy = V;
    for (int i = 0; i < FN; i++) {                   /* joints of the polygon */
        if (i > 0) vy -= P[i - 1];
        double T = sqrt(H * H + vy * vy), len = L0[i] * (1 + T / EA);
        x += len * H / T;
        y -= len * vy / T;
        CHECK_CLOSE(X[i + 1][0] + d[3 * (i + 1)], x, 1e-9, 1e-9 * l);
        CHECK_CLOSE(X[i + 1][1] + d[3 * (i + 1) + 1], y, 1e-9, 1e-9 * l);
        ctn_element_state st;
        ctn_solution_element(s, (size_t)i, &st);
        CHECK_CLOSE(st.force, T, 1e-9, 0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_indefinite(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = NULL;
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = 20, .length = 250.8777, .shape = CTN_SHAPE_STRAIGHT, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    ctn_model_create(ctx, &m);
    ctn_model_set_gravity(m, g);
    ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0);
    ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1);
    ctn_model_add_node(m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(m, 2, B, CTN_FIX_ALL);
    CHECK(ctn_model_add_cable(m, 1, 2, "strand", &spec, NULL, NULL) == CTN_OK);
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    ctn_solve_options_default(&opt);
    opt.method = CTN_METHOD_NEWTON;                 /* the paper's pure Newton */
    CHECK(ctn_solve(ctx, m, &opt, &s) == CTN_OK);
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    CHECK(sum.reason == CTN_DIVERGED_INDEFINITE);
    CHECK(sum.fail_node >= 3 && sum.fail_node <= 21 && sum.fail_dir >= 0);
    const double *d = ctn_solution_displacements(s);
    for (size_t i = 0; i < 3 * ctn_model_node_count(m); i++) CHECK(isfinite(d[i]));
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Fail the k-th allocation, for every k, through model building and solving. */
static void test_alloc_failures(void)
{
    long total = 0;
    for (long k = 1;; k++) {
        ctn_ctx *ctx = NULL;
        ctn_ctx_create(&ctx);
        ctn_ctx_fail_alloc_at(ctx, k);
        ctn_model *m = paper_model(ctx, 250.8777, 20);
        ctn_solution *s = NULL;
        int rc = m ? ctn_solve(ctx, m, NULL, &s) : ctn_ctx_code(ctx);
        long count = ctn_ctx_alloc_count(ctx);
        if (count < k) {                            /* no failure injected: done */
            CHECK(rc == CTN_OK && s != NULL);
            total = count;
            ctn_solution_destroy(&s);
            ctn_model_destroy(&m);
            ctn_ctx_destroy(&ctx);
            break;
        }
        CHECK_MSG(rc == CTN_ERR_NOMEM && s == NULL, "allocation %ld: rc %d", k, rc);
        ctn_solution_destroy(&s);
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
    CHECK(total > 10);
}

/* Largest distance of the solved nodes of m from the line through nodes 0 and 1. */
static double max_distance_from_chord(const ctn_model *m, const ctn_solution *s)
{
    const double *d = ctn_solution_displacements(s);
    double P[64][3], u[3], best = 0;
    size_t nn = ctn_model_node_count(m);
    for (size_t i = 0; i < nn && i < 64; i++) {
        ctn_node_info n;
        ctn_model_node(m, i, &n);
        for (int k = 0; k < 3; k++) P[i][k] = n.X[k] + d[3 * i + (size_t)k];
    }
    double len = 0;
    for (int k = 0; k < 3; k++) u[k] = P[1][k] - P[0][k], len += u[k] * u[k];
    len = sqrt(len);
    for (int k = 0; k < 3; k++) u[k] /= len;
    for (size_t i = 2; i < nn && i < 64; i++) {
        double r[3], t = 0, q = 0;
        for (int k = 0; k < 3; k++) r[k] = P[i][k] - P[0][k], t += r[k] * u[k];
        for (int k = 0; k < 3; k++) q += (r[k] - t * u[k]) * (r[k] - t * u[k]);
        best = fmax(best, sqrt(q));
    }
    return best;
}

/* A cable of n elements from (0,0,0) to B with self-weight w, a load F on the
 * generated node `loaded` (0: none), solved; the two sags and the nodes' distance. */
static void cable_sags(const double B[3], const double g[3], double w, int n, double len, ctn_cable_shape shape,
                       int loaded, const double F[3], double out[3])
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_summary sum;
    double A[3] = { 0, 0, 0 };
    ctn_cable_spec spec = { .n = n, .length = len, .shape = shape, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    out[0] = out[1] = out[2] = NAN;
    ctn_ctx_create(&ctx);
    int rc = ctn_model_create(ctx, &m) || ctn_model_set_gravity(m, g) ||
             ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_ENGINEERING, 0) ||
             ctn_model_add_section(m, "rod", "steel", 1e-4, w) || ctn_model_add_node(m, 1, A, CTN_FIX_ALL) ||
             ctn_model_add_node(m, 2, B, CTN_FIX_ALL) || ctn_model_add_cable(m, 1, 2, "rod", &spec, NULL, NULL) ||
             (loaded && ctn_model_add_load(m, loaded, F)) || ctn_solve(ctx, m, NULL, &s);
    CHECK_MSG(!rc, "%s", ctn_ctx_message(ctx));
    if (!rc) {
        ctn_solution_summary(s, &sum);
        CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
        CHECK(ctn_solution_cable_sag(m, s, 0, &out[0]) == CTN_OK);
        CHECK(ctn_solution_cable_max_sag_from_chord(m, s, 0, &out[1]) == CTN_OK);
        out[2] = max_distance_from_chord(m, s);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_sag(void)
{
    double g[3] = { 0, -1, 0 }, none[3] = { 0, 0, 0 }, out[3];
    /* vertical chord along gravity, a lateral load on the middle node (id 7 of 3..11) */
    double down[3] = { 0, -10, 0 }, side[3] = { 1, 0, 0.5 };
    cable_sags(down, g, 0.1, 10, 10.2, CTN_SHAPE_STRAIGHT, 7, side, out);
    CHECK_MSG(out[2] > 0.5, "the cable did not move sideways: %g", out[2]);
    CHECK_CLOSE(out[0], out[2], 1e-12, 0);
    CHECK_CLOSE(out[1], out[2], 1e-12, 0);
    /* the same chord slightly off vertical (1e-10): still the distance from the chord */
    double nearly[3] = { 1e-9, -10, 0 };
    cable_sags(nearly, g, 0.1, 10, 10.2, CTN_SHAPE_STRAIGHT, 7, side, out);
    CHECK_CLOSE(out[0], out[2], 1e-9, 0);
    /* level span, even n: the mid node is the deepest, straight below mid-chord */
    double level[3] = { 200, 0, 0 };
    cable_sags(level, g, 0.1, 20, 201.3545, CTN_SHAPE_ARC, 0, none, out);
    CHECK(out[0] > 10);
    CHECK_CLOSE(out[0], out[1], 1e-12, 0);
    CHECK_CLOSE(out[1], out[2], 1e-12, 0);
    /* no gravity: down is the resultant load; a weightless cable with a load at mid-span */
    double F[3] = { 0, 0, -5 };
    cable_sags(level, none, 0, 4, 201, CTN_SHAPE_STRAIGHT, 4, F, out);   /* node 4: the middle */
    CHECK(out[0] > 5);
    CHECK_CLOSE(out[0], out[2], 1e-12, 0);
}

int main(void)
{
    test_sag();
    test_paper_cases();
    test_bar();
    test_funicular();
    test_indefinite();
    test_alloc_failures();
    CHECK_DONE();
}
