/* Catenary and pulley elements in solved models:
 * - a net of three catenary elements against the same net of fine cable elements: the
 *   cable FE converges to it at second order in the mesh, and its Richardson
 *   extrapolation meets it;
 * - the same net with its loads ramped in increments and in two steps: the same state;
 * - a vertical catenary carrying a weight: Irvine's vertical closed form;
 * - pulleys: a load riding on a weightless cable (equal angles, equal tension), a weight
 *   hanging over a fixed pulley (tension = weight), a cable over two pulleys (reactions
 *   the resultants of the tension), and the cable going slack when the load lifts. */
#include "catena.h"
#include "check.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct run {
    ctn_ctx *ctx;
    ctn_model *m;
    ctn_solution *s;
} run;

static int solve_text(const char *text, run *r)
{
    ctn_solve_options opt;
    memset(r, 0, sizeof *r);
    ctn_ctx_create(&r->ctx);
    int rc = ctn_read_string(r->ctx, "model.cable", text, strlen(text), &r->m, &opt);
    if (!rc) rc = ctn_solve(r->ctx, r->m, &opt, &r->s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(r->ctx));
    if (rc) return 1;
    ctn_solve_summary sum;
    ctn_solution_summary(r->s, &sum);
    CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
    return sum.reason != CTN_CONVERGED;
}

static void done(run *r)
{
    ctn_solution_destroy(&r->s);
    ctn_model_destroy(&r->m);
    ctn_ctx_destroy(&r->ctx);
}

/* Displacement of node id. */
static const double *disp(const run *r, int id)
{
    size_t i = 0;
    ctn_model_node_index(r->m, id, &i);
    return ctn_solution_displacements(r->s) + 3 * i;
}

#define NET_HEAD "units kN m\nmaterial steel E=2.0e8 strain=engineering\nsection strand material=steel A=3.14e-4 w=0.1\n" \
                 "gravity 0 -1 0.2\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 10 fix=xyz\nnode 3 300 -50 -20 fix=xyz\nnode 4 100 -40 0\n"

/* Node 4 of the net: catenary elements (n = 0) or cables of n, n, 2n elements. */
static int net(int n, const char *extra, double u[3])
{
    char text[2048];
    if (n == 0)
        snprintf(text, sizeof text, NET_HEAD "catenary 1 1 4 section=strand length=110\ncatenary 2 4 2 section=strand length=112\n"
                 "catenary 3 4 3 section=strand length=230\nload 4 0 -5 1\n%s", extra);
    else
        snprintf(text, sizeof text, NET_HEAD "cable 1 4 section=strand n=%d length=110\ncable 4 2 section=strand n=%d length=112\n"
                 "cable 4 3 section=strand n=%d length=230\nload 4 0 -5 1\nsolve maxit=400\n%s", n, n, 2 * n, extra);
    run r;
    int rc = solve_text(text, &r);
    if (!rc) memcpy(u, disp(&r, 4), 3 * sizeof(double));
    done(&r);
    return rc;
}

static double dist(const double *a, const double *b)
{
    return sqrt(pow(a[0] - b[0], 2) + pow(a[1] - b[1], 2) + pow(a[2] - b[2], 2));
}

static void test_net(void)
{
    double uc[3], u1[3], u2[3], ur[3], us[3], ut[3];
    if (net(0, "", uc) || net(25, "", u1) || net(50, "", u2)) return;
    for (int k = 0; k < 3; k++) ur[k] = u2[k] + (u2[k] - u1[k]) / 3;    /* Richardson, O(h^2) */
    double e1 = dist(u1, uc), e2 = dist(u2, uc), er = dist(ur, uc);
    printf("net: |u_FE - u_cat| = %.3e (n = 25), %.3e (n = 50), Richardson %.3e\n", e1, e2, er);
    CHECK(e1 / e2 > 3.6 && e1 / e2 < 4.4);                            /* second order */
    CHECK(er < 0.02 * e2);
    if (net(0, "solve steps=7\n", us)) return;                          /* ramped */
    CHECK(dist(us, uc) <= 1e-9 * (1 + dist(uc, (double[3]){ 0, 0, 0 })));
    if (net(0, "step second\nload 4 0 -1 0\n", ut)) return;             /* then a second step */
    double uo[3];
    if (net(0, "load 4 0 -1 0\n", uo)) return;
    CHECK(dist(ut, uo) <= 1e-9 * (1 + dist(uo, (double[3]){ 0, 0, 0 })));
}

/* A catenary hanging from node 1 with a weight P at node 2 below: H = 0, tension P at
 * the bottom and P + W at the top, node 2 at -(L + L (P + W/2) / EA). */
static void test_vertical(void)
{
    const char *text = "material m E=1e6 strain=engineering\nsection s material=m A=0.01 w=2\ngravity 0 0 -1\n"
                       "node 1 1 2 3 fix=xyz\nnode 2 1 2 -7\ncatenary 5 1 2 section=s length=10\nload 2 0 0 -30\n"
                       "solve tol=1e-14\n";                              /* to the round-off floor */
    run r;
    if (solve_text(text, &r)) { done(&r); return; }
    const double *u = disp(&r, 2);
    double L = 10, EA = 1e4, P = 30, W = 20;
    CHECK_CLOSE(u[2] - 0, -(L + L * (P + W / 2) / EA) + 10, 0, 1e-12 * L);
    CHECK(fabs(u[0]) < 1e-12 && fabs(u[1]) < 1e-12);
    ctn_catenary_result c = { .size = sizeof c };
    CHECK(ctn_solution_catenary(r.m, r.s, 0, 0, &c) == CTN_OK);
    CHECK(c.H == 0);
    CHECK_CLOSE(c.tension[0], P + W, 1e-12, 0);
    CHECK_CLOSE(c.tension[1], P, 1e-12, 0);
    CHECK_CLOSE(c.length, L + L * (P + W / 2) / EA, 1e-13, 0);
    ctn_stability st;
    CHECK(ctn_solution_stability(r.s, &st) == CTN_OK && st.stable);
    done(&r);
}

/* Clothes-line: supports at (0,0,0) and (s,0,h), a load F on a free pulley node: equal
 * angles theta to the horizontal on both sides, cos theta = s / Ls, T = F / (2 sin theta),
 * Ls = L (1 + T / EA); the pulley at l1 (cos theta, -sin theta), l1 = (Ls - h / sin) / 2. */
static void test_riding_load(void)
{
    const char *text = "material m E=2e5 strain=engineering\nsection s material=m A=0.01\n"
                       "node 1 0 0 0 fix=xyz\nnode 2 10 0 2 fix=xyz\nnode 3 4 0 -3\n"
                       "pulley 1 1 3 2 section=s length=12.5\nload 3 0 0 -50\n";
    double s = 10, h = 2, L = 12.5, EA = 2e3, F = 50, Ls = L, T = 0, sn = 0, cs = 0;
    for (int it = 0; it < 200; it++) {                                  /* fixed point */
        cs = s / Ls;
        sn = sqrt(1 - cs * cs);
        T = F / (2 * sn);
        Ls = L * (1 + T / EA);
    }
    double l1 = (Ls - h / sn) / 2;
    run r;
    if (solve_text(text, &r)) { done(&r); return; }
    const double *u = disp(&r, 3);
    CHECK_CLOSE(4 + u[0], l1 * cs, 0, 1e-11);
    CHECK_CLOSE(-3 + u[2], -l1 * sn, 0, 1e-11);
    CHECK(fabs(u[1]) < 1e-12);
    ctn_element_state es;
    ctn_solution_element(r.s, 0, &es);
    CHECK_CLOSE(es.force, T, 1e-11, 0);
    CHECK_CLOSE(es.length, Ls, 1e-12, 0);
    done(&r);
}

/* A weight F hanging over a fixed pulley (and over two): the tension is F everywhere,
 * the weight hangs L (1 + F / EA) - (the cable's length before it) below the last pulley,
 * and each pulley's reaction is the resultant of the tension on its two sides. */
static void test_hanging_weight(void)
{
    const char *one = "material m E=1e5 strain=engineering\nsection s material=m A=0.01\n"
                      "node 1 0 0 0 fix=xyz\nnode 2 5 0 0 fix=xyz\nnode 3 5 0 -4\npulley 9 1 2 3 section=s length=9\nload 3 0 0 -20\n";
    const char *two = "material m E=1e5 strain=engineering\nsection s material=m A=0.01\n"
                      "node 1 0 0 0 fix=xyz\nnode 2 4 0 0 fix=xyz\nnode 3 8 0 3 fix=xyz\nnode 4 8 0 -2\n"
                      "pulley 9 1 2 3 4 section=s length=15\nload 4 0 0 -20\n";
    double EA = 1e3, F = 20;
    run r;
    if (!solve_text(one, &r)) {
        CHECK_CLOSE(-4 + disp(&r, 3)[2], -(9 * (1 + F / EA) - 5), 0, 1e-12);
        ctn_element_state es;
        ctn_solution_element(r.s, 0, &es);
        CHECK_CLOSE(es.force, F, 1e-12, 0);
        const double *R = ctn_solution_reactions(r.s) + 3;               /* node 2, the pulley */
        CHECK_CLOSE(R[0], F, 1e-12, 0);
        CHECK_CLOSE(R[2], F, 1e-12, 0);
    }
    done(&r);
    if (!solve_text(two, &r)) {
        CHECK_CLOSE(-2 + disp(&r, 4)[2], 3 - (15 * (1 + F / EA) - 4 - 5), 0, 1e-12);
        const double *R2 = ctn_solution_reactions(r.s) + 3, *R3 = R2 + 3;  /* pulleys 2 and 3 */
        CHECK_CLOSE(R2[0], F - F * 0.8, 1e-12, 1e-12);                  /* e01 = x, e12 = (0.8, 0.6) */
        CHECK_CLOSE(R2[2], -F * 0.6, 1e-12, 0);
        CHECK_CLOSE(R3[0], F * 0.8, 1e-12, 0);
        CHECK_CLOSE(R3[2], F * 0.6 + F, 1e-12, 0);
    }
    done(&r);
}

/* A pulley node held up by the cable and down by a spring; step 2 lifts it: the cable
 * goes slack (no force, flagged) and the spring alone balances the load. */
static void test_lift_off(void)
{
    const char *text = "material m E=2e5 strain=engineering\nsection s material=m A=0.01\n"
                       "node 1 0 0 0 fix=xyz\nnode 2 10 0 0 fix=xyz\nnode 3 5 0 -1 fix=xy\nnode 4 5 0 -3 fix=xyz\n"
                       "pulley 1 1 3 2 section=s length=10.2\nspring 2 3 4 k=100\nstep hold\nload 3 0 0 -10\n"
                       "step lift\nload 3 0 0 40\n";
    run r;
    if (solve_text(text, &r)) { done(&r); return; }
    ctn_element_state es, sp;
    CHECK(ctn_solution_step_element(r.s, 0, 0, &es) == CTN_OK && es.force > 0 && !es.slack);
    CHECK(ctn_solution_step_element(r.s, 1, 0, &es) == CTN_OK && es.force == 0 && es.slack);
    CHECK(ctn_solution_step_element(r.s, 1, 1, &sp) == CTN_OK);
    CHECK_CLOSE(sp.force, 30, 1e-12, 0);                                /* stretched by the 30 up */
    CHECK_CLOSE(disp(&r, 3)[2], 30.0 / 100, 1e-12, 0);
    done(&r);
}

int main(void)
{
    test_net();
    test_vertical();
    test_riding_load();
    test_hanging_weight();
    test_lift_off();
    CHECK_DONE();
}
