/* lineload (issue 27 item 2): a load per unit unstressed length in a fixed direction.
 * A level span under its weight w (along -y) and a wind load qz per unstressed length
 * (along z) hangs in the plane of the chord and the resultant r = (0, -w, qz): the span's
 * plane swings by atan(qz / w), and in that plane the cable is the catenary of |r|.
 * - exact, discrete: the FE chain (engineering strain, q l0 / 2 lumped at each end) is
 *   the funicular polygon of the joint loads |r| l0_e in the swung plane (an independent
 *   2 x 2 Newton solve in src/analytic/funicular.c): joints and forces to 1e-10;
 * - continuous: as the mesh is refined the chain tends to Irvine's elastic catenary of
 *   weight |r| per unstressed length: H, the support tension and the sag (at the joints)
 *   to 1e-6 with 800 elements;
 * - the plane: every node off the swung plane by less than 1e-12 of the span;
 * - the reactions carry |r| L0 exactly, split by the two components. */
#include "catena.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SPAN 200.0
#define L0 204.0
#define W 0.1
#define QZ 0.06
#define EA (2.0e8 * 3.14e-4)

/* The span of n elements under weight and wind, solved; NULL on failure. */
static ctn_solution *solve_span(ctn_ctx *ctx, int n, ctn_model **mo)
{
    char text[1024];
    snprintf(text, sizeof text,
             "units kN m\ngravity 0 -1 0\nmaterial steel E=2.0e8 strain=engineering\n"
             "section strand material=steel A=3.14e-4 w=%.17g\nnode 1 0 0 0 fix=xyz\nnode 2 %.17g 0 0 fix=xyz\n"
             "cable 1 2 section=strand n=%d length=%.17g\nlineload all qz=%.17g\nsolve tol=1e-12\n",
             W, SPAN, n, L0, QZ);
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    *mo = NULL;
    int rc = ctn_read_string(ctx, "span", text, strlen(text), mo, &opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (!rc) rc = ctn_solve(ctx, *mo, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    ctn_solve_summary sum;
    if (s) {
        ctn_solution_summary(s, &sum);
        CHECK_MSG(sum.reason == CTN_CONVERGED, "n=%d: %s", n, ctn_reason_name(sum.reason));
    }
    return s;
}

/* The unit vectors of the swung plane: ex along the chord, eu "up" (against r), en normal. */
static void plane(double eu[3], double en[3])
{
    double r = sqrt(W * W + QZ * QZ);
    eu[0] = 0, eu[1] = W / r, eu[2] = -QZ / r;
    en[0] = 0, en[1] = QZ / r, en[2] = W / r;
}

static void test_funicular(void)
{
    const int n = 20;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    ctn_solution *s = solve_span(ctx, n, &m);
    double L0e[n], EAe[n], P[2 * (n - 1)], xy[2 * (n + 1)], N[n], eu[3], en[3];
    double r = sqrt(W * W + QZ * QZ);
    for (int i = 0; i < n; i++) L0e[i] = L0 / n, EAe[i] = EA;
    for (int i = 0; i < n - 1; i++) P[2 * i] = 0, P[2 * i + 1] = -r * L0 / n;
    ctn_funicular_in in = { SPAN, 0, (size_t)n, L0e, EAe, P };
    ctn_funicular fu;
    CHECK(ctn_funicular_solve(ctx, &in, xy, N, &fu) == CTN_OK);
    plane(eu, en);
    const double *d = s ? ctn_solution_displacements(s) : NULL;
    for (int i = 0; d && i < n; i++) {
        ctn_element_info e;
        ctn_element_state es;
        ctn_model_element(m, (size_t)i, &e);
        ctn_solution_element(s, (size_t)i, &es);
        CHECK_CLOSE(es.force, N[i], 1e-10, 0);
        ctn_node_info p;
        ctn_model_node(m, (size_t)e.nodes[0], &p);
        double x[3];
        for (int k = 0; k < 3; k++) x[k] = p.X[k] + d[3 * (size_t)e.nodes[0] + (size_t)k];
        CHECK_CLOSE(x[0], xy[2 * i], 0, 1e-10 * SPAN);
        CHECK_CLOSE(x[0] * 0 + x[1] * eu[1] + x[2] * eu[2], xy[2 * i + 1], 0, 1e-10 * SPAN);
        CHECK_CLOSE(x[1] * en[1] + x[2] * en[2], 0, 0, 1e-12 * SPAN);
    }
    if (d) {                                            /* the reactions carry r L0 */
        const double *R = ctn_solution_reactions(s);
        size_t a = 0, b = 1;
        CHECK_CLOSE(R[3 * a + 1] + R[3 * b + 1], W * L0, 1e-12, 0);
        CHECK_CLOSE(R[3 * a + 2] + R[3 * b + 2], -QZ * L0, 1e-12, 0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Against the elastic catenary of |r|: H, the largest tension and the sag, to 1e-6. */
static void test_catenary(void)
{
    double r = sqrt(W * W + QZ * QZ), eu[3], en[3];
    ctn_ecatenary_in in = { SPAN, 0, r, EA, L0 };
    ctn_ecatenary cat;
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    CHECK(ctn_ecatenary_solve(ctx, &in, &cat) == CTN_OK);
    plane(eu, en);
    int n = 800;
    ctn_model *m = NULL;
    ctn_solution *s = solve_span(ctx, n, &m);
    if (s) {
        const double *R = ctn_solution_reactions(s), *d = ctn_solution_displacements(s);
        double H = -R[0], Tmax = sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2]), sag = 0;   /* node 1 */
        for (size_t i = 0; i < ctn_model_node_count(m); i++) {
            ctn_node_info p;
            ctn_model_node(m, i, &p);
            sag = fmax(sag, -((p.X[1] + d[3 * i + 1]) * eu[1] + (p.X[2] + d[3 * i + 2]) * eu[2]));
        }
        printf("n=%d H %.12g (%.3g) Tmax %.12g (%.3g) sag %.12g (%.3g)\n", n, H, H / cat.H - 1, Tmax,
               Tmax / cat.sum.T_max - 1, sag, sag / cat.sum.sag - 1);
        CHECK_CLOSE(H, cat.H, 1e-6, 0);
        CHECK_CLOSE(Tmax, cat.sum.T_max, 1e-6, 0);
        CHECK_CLOSE(sag, cat.sum.sag, 1e-6, 0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* ice: a 10 mm radial sleeve of 900 kg/m3 on a 28.1 mm conductor weighs
 * 900 x 9.80665 x pi x 0.010 x 0.0381 N/m; the iced span is the catenary of w + that. */
static void test_ice(void)
{
    const double wi = 900 * 9.80665 * 3.14159265358979323846 * 0.010 * (0.0281 + 0.010) / 1000;   /* kN/m */
    char text[1024];
    snprintf(text, sizeof text,
             "units kN m\ngravity 0 0 -1\nmaterial acsr E=6.9e7 strain=engineering\n"
             "section drake material=acsr A=4.68e-4 w=0.01594\nnode 1 0 0 0 fix=xyz\nnode 2 350 0 0 fix=xyz\n"
             "cable 1 2 section=drake n=800 length=351\nice all thickness=10mm density=900kg/m3 d=28.1mm\n"
             "solve tol=1e-12\n");
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "ice", text, strlen(text), &m, &opt);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    ctn_ecatenary_in in = { 350, 0, 0.01594 + wi, 6.9e7 * 4.68e-4, 351 };
    ctn_ecatenary cat;
    CHECK(ctn_ecatenary_solve(ctx, &in, &cat) == CTN_OK);
    if (s) {
        const double *R = ctn_solution_reactions(s);
        CHECK_CLOSE(R[2] + R[5], (0.01594 + wi) * 351, 1e-12, 0);     /* the weight, exactly */
        CHECK_CLOSE(-R[0], cat.H, 1e-6, 0);
        CHECK_CLOSE(sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2]), cat.sum.T_max, 1e-6, 0);
        printf("ice: H %.10g against %.10g (%+.2e)\n", -R[0], cat.H, -R[0] / cat.H - 1);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_funicular();
    test_catenary();
    test_ice();
    CHECK_DONE();
}
