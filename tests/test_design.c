/* Designing cable systems (issue 9): temperature, cables set by a target (H=, sag=,
 * tension=), groups and capacity. Checked against closed forms (a bar between fixed
 * supports, a free hanging bar), the elastic catenary (Irvine) with the FE mesh error
 * measured on two meshes, a solve with the length found, and sums over the elements. */
#include "catena.h"
#include "check.h"
#include "run_text.h"

#include <math.h>
#include <stdio.h>

/* Read text, resolve its targets and solve; rc the first failure. */
static run solve_text(const char *text) { return run_text("design.cable", text); }

static double force_of(const run *r, size_t k, size_t e)
{
    ctn_element_state st;
    CHECK(ctn_solution_step_element(r->s, k, e, &st) == CTN_OK);
    return st.force;
}

/* A bar between fixed supports heated by dT: engineering strain gives
 * N = EA (1 / (1 + alpha dT) - 1) exactly; Green-Lagrange N = EA (lam^2 - 1) lam / 2 with
 * lam = 1 / (1 + alpha dT). Ramped over substeps, each step's state. */
static void test_bar_between_supports(void)
{
    const char *laws[2] = { "engineering", "green-lagrange" };
    for (int law = 0; law < 2; law++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "material m E=2e8 strain=%s alpha=1.2e-5\nsection s material=m A=1e-3\n"
                 "node 1 0 0 0 fix=xyz\nnode 2 3 0 0\nnode 3 10 0 0 fix=xyz\n"
                 "element 1 1 2 section=s\nelement 2 2 3 section=s\nload 2 0 0 0\n"
                 "step heat substeps=3\ntemperature all dT=50\nstep cool\ntemperature 1 dT=-80\n"
                 "temperature 2 dT=-80\n",
                 laws[law]);
        run r = solve_text(text);
        CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
        if (r.rc) { done(&r); continue; }
        double EA = 2e8 * 1e-3, dTs[2] = { 50, -30 };
        for (size_t k = 0; k < 2; k++) {
            double lam = 1 / (1 + 1.2e-5 * dTs[k]);
            double N = law == 0 ? EA * (lam - 1) : EA * (lam * lam - 1) * lam / 2;
            for (size_t e = 0; e < 2; e++) CHECK_CLOSE(force_of(&r, k, e), N, 1e-12, 1e-9);
        }
        done(&r);
    }
}

/* A bar hanging from a support with a weight F at its free end: heated, its length
 * grows by alpha dT times its loaded length: l = l0 (1 + alpha dT) (1 + F / EA). The
 * self-weight stays that of the cold bar (the mass is conserved). */
static void test_free_hanging(void)
{
    const char *text =
        "gravity 0 0 -1\nmaterial m E=1e5 strain=engineering alpha=2e-5\nsection s material=m A=1e-2 w=0\n"
        "node 1 0 0 0 fix=xyz\nnode 2 0 0 -20 fix=xy\nelement 1 1 2 section=s\nload 2 0 0 -50\n"
        "step base\nstep hot\ntemperature 1 dT=70\n";
    run r = solve_text(text);
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
    if (!r.rc) {
        ctn_step_result s0, s1;
        ctn_solution_step(r.s, 0, &s0);
        ctn_solution_step(r.s, 1, &s1);
        double EA = 1e3, l_cold = 20 * (1 + 50 / EA), l_hot = 20 * (1 + 2e-5 * 70) * (1 + 50 / EA);
        CHECK_CLOSE(20 - s0.d[5], l_cold, 1e-13, 0);
        CHECK_CLOSE(20 - s1.d[5], l_hot, 1e-13, 0);
        CHECK_CLOSE(l_hot - l_cold, 2e-5 * 70 * l_cold, 1e-9, 0);
    }
    done(&r);
    /* a weighted chain: its weight does not change when it is heated */
    const char *chain =
        "gravity 0 0 -1\nmaterial m E=1e5 strain=engineering alpha=2e-5\nsection s material=m A=1e-2 w=3\n"
        "node 1 0 0 0 fix=xyz\nnode 2 0 0 -20\ncable 1 2 section=s n=8 length=20 shape=straight\n"
        "step base\nstep hot\ntemperature all dT=70\n";
    r = solve_text(chain);
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
    if (!r.rc) {
        ctn_step_result s0, s1;
        ctn_solution_step(r.s, 0, &s0);
        ctn_solution_step(r.s, 1, &s1);
        CHECK_CLOSE(s1.react[2], 60, 1e-12, 0);
        CHECK_CLOSE(s0.react[2], 60, 1e-12, 0);
        /* every material point's force is unchanged, so the whole stretched length grows
         * by the factor 1 + alpha dT */
        CHECK_CLOSE(20 - s1.d[5], (20 - s0.d[5]) * (1 + 2e-5 * 70), 1e-12, 0);
    }
    done(&r);
}

static const char *span_model(char *buf, size_t size, int n, double h, const char *target)
{
    snprintf(buf, size,
             "units kN m\ngravity 0 0 -1\nmaterial steel E=2e8 strain=engineering\n"
             "section s material=steel A=3.14e-4 w=0.1\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 %g fix=xyz\n"
             "cable 1 2 section=s n=%d %s\n",
             h, n, target);
    return buf;
}

/* The found length of a span with a target, and the target reached. */
static int span_length(int n, double h, const char *target, double *L, double *reached)
{
    char text[1024];
    run r = solve_text(span_model(text, sizeof text, n, h, target));
    CHECK_MSG(r.rc == CTN_OK, "%s: %s", target, ctn_ctx_message(r.ctx));
    int ok = r.rc == CTN_OK;
    if (ok) {
        ctn_cable_info c;
        ctn_model_cable(r.m, 0, &c);
        *L = c.length;
        *reached = c.target_achieved;
        CHECK(c.target_iterations >= 1);
    }
    done(&r);
    return ok;
}

/* Targets land on the target within 1e-10; the length agrees with the elastic catenary
 * to the mesh's error, which falls as h^2 (ratio near 4 from n = 20 to 40); solving with
 * the length found gives the target back. */
static void test_targets(void)
{
    const char *targets[3] = { "H=30", "sag=12", "tension=45" };
    double value[3] = { 30, 12, 45 }, hs[2] = { 0, 60 };
    for (int hi = 0; hi < 2; hi++)
        for (int t = 0; t < 3; t++) {
            double L20 = 0, L40 = 0, q = 0;
            if (!span_length(20, hs[hi], targets[t], &L20, &q)) continue;
            CHECK_CLOSE(q, value[t], 1e-10, 0);
            if (!span_length(40, hs[hi], targets[t], &L40, &q)) continue;
            CHECK_CLOSE(q, value[t], 1e-10, 0);
            /* the elastic catenary's length for the same target: bisection on L0 */
            double lo = 195, hi_ = 300;
            for (int it = 0; it < 200; it++) {
                double mid = 0.5 * (lo + hi_), Q = 0;
                ctn_ecatenary_in in = { 200, hs[hi], 0.1, 2e8 * 3.14e-4, mid };
                ctn_ecatenary cat;
                if (ctn_ecatenary_solve(NULL, &in, &cat)) break;
                if (t == 0) Q = cat.H;
                else if (t == 1) Q = cat.sum.sag;
                else Q = fmax(sqrt(cat.H * cat.H + cat.V_left * cat.V_left), sqrt(cat.H * cat.H + cat.V_right * cat.V_right));
                /* H, T fall and the sag grows with the length (on the taut side) */
                if ((t == 1) == (Q < value[t])) lo = mid;
                else hi_ = mid;
            }
            double Lc = 0.5 * (lo + hi_), e20 = fabs(L20 - Lc), e40 = fabs(L40 - Lc);
            printf("target %-10s h=%-3g  L(catenary) %.10f  error n=20 %.3e  n=40 %.3e  ratio %.2f\n", targets[t], hs[hi], Lc,
                   e20, e40, e20 / e40);
            CHECK(e20 < 1e-3 * Lc);
            CHECK(e40 < e20);
            CHECK(e20 / e40 > 3 && e20 / e40 < 5);
            /* solving with the length found gives the target back */
            char buf[64], text[1024];
            snprintf(buf, sizeof buf, "length=%.17g", L20);
            run r = solve_text(span_model(text, sizeof text, 20, hs[hi], buf));
            CHECK(r.rc == CTN_OK);
            if (!r.rc && t == 0) {
                ctn_step_result s0;
                ctn_solution_step(r.s, 0, &s0);
                CHECK_CLOSE(fabs(s0.react[0]), value[t], 1e-9, 0);    /* H at support 1 */
            }
            done(&r);
        }
}

/* A target with a point load and several cables found together: a mast held by three
 * guys, each pretensioned to its own tension; the top is free. */
static void test_guyed(void)
{
    const char *text =
        "units kN m\ngravity 0 0 -1\nmaterial steel E=1.6e8 strain=engineering\n"
        "material mast E=2e8\nsection guy material=steel A=2e-4 w=0.02\nsection pole material=mast A=0.01\n"
        "node 1 0 0 0 fix=xyz\nnode 2 0 0 40\nnode 3 30 0 0 fix=xyz\nnode 4 -15 25.98 0 fix=xyz\n"
        "node 5 -15 -25.98 0 fix=xyz\nelement 1 1 2 section=pole\n"
        "cable 3 2 section=guy n=10 tension=20 group=guys\ncable 4 2 section=guy n=10 tension=25 group=guys\n"
        "cable 5 2 section=guy n=10 tension=30 group=guys\nload 2 2 0 0\n";
    run r = solve_text(text);
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
    if (!r.rc) {
        double want[3] = { 20, 25, 30 };
        for (size_t i = 0; i < 3; i++) {
            ctn_cable_info c;
            ctn_model_cable(r.m, i, &c);
            CHECK_CLOSE(c.target_achieved, want[i], 1e-10, 0);
        }
    }
    done(&r);
}

static void test_unreachable(void)
{
    char text[1024];
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    span_model(text, sizeof text, 20, 0, "tension=5");
    CHECK(ctn_read_string(ctx, "low.cable", text, strlen(text), &m, &opt) == CTN_OK);
    CHECK(ctn_model_resolve_targets(ctx, m, &opt, NULL) == CTN_ERR_MODEL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "low.cable:7") && strstr(ctn_ctx_message(ctx), "ranges from"), "%s",
              ctn_ctx_message(ctx));
    ctn_model_destroy(&m);                  /* a sag below the taut limit: only past 10 % strain */
    span_model(text, sizeof text, 20, 0, "sag=0.01");
    CHECK(ctn_read_string(ctx, "taut.cable", text, strlen(text), &m, &opt) == CTN_OK);
    CHECK(ctn_model_resolve_targets(ctx, m, &opt, NULL) == CTN_ERR_MODEL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "taut.cable:7") && strstr(ctn_ctx_message(ctx), "reachable range ends at sag="),
              "%s", ctn_ctx_message(ctx));
    /* without resolving, a model with targets is refused */
    ctn_model_destroy(&m);
    span_model(text, sizeof text, 20, 0, "sag=10");
    CHECK(ctn_read_string(ctx, "t.cable", text, strlen(text), &m, &opt) == CTN_OK);
    ctn_solution *s = NULL;
    CHECK(ctn_solve(ctx, m, &opt, &s) == CTN_ERR_INVALID);
    CHECK(s == NULL);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Groups' sums and maxima against their elements; utilisation = force / (mbl / safety). */
static void test_groups_capacity(void)
{
    const char *text =
        "units kN m\ngravity 0 0 -1\nmaterial steel E=2e8 strain=engineering tension-only\n"
        "section a material=steel A=3e-4 w=0.1 mbl=100 safety=2\nsection b material=steel A=2e-4 w=0.05\n"
        "node 1 0 0 0 fix=xyz\nnode 2 100 0 0 fix=xyz\nnode 3 0 20 0 fix=xyz\nnode 4 60 20 0 fix=xyz\n"
        "cable 1 2 section=a n=10 length=104 group=main\ncable 3 4 section=b n=4 length=61\n"
        "group second 11-12 13 14\nhload q=0.2 elements=main\n";
    run r = solve_text(text);
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
    if (!r.rc) {
        size_t k = ctn_solution_step_count(r.s) - 1;
        CHECK(ctn_model_group_count(r.m) == 2);
        for (size_t g = 0; g < 2; g++) {
            ctn_group_result gr;
            CHECK(ctn_solution_group(r.m, r.s, k, g, &gr) == CTN_OK);
            double fhi = -INFINITY, flo = INFINITY, len = 0, cur = 0, wt = 0, umax = 0;
            size_t count = 0;
            for (size_t i = 0; i < ctn_model_element_count(r.m); i++) {
                ctn_element_info e;
                ctn_element_state st;
                ctn_model_element(r.m, i, &e);
                ctn_solution_step_element(r.s, k, i, &st);
                if (!e.group || strcmp(e.group, gr.name)) continue;
                count++;
                fhi = fmax(fhi, st.force);
                flo = fmin(flo, st.force);
                len += e.l0;
                cur += st.length;
                wt += e.w * e.l0;
                if (e.capacity > 0) {
                    CHECK_CLOSE(e.capacity, 50, 1e-15, 0);
                    umax = fmax(umax, st.force / 50);
                }
            }
            CHECK(gr.elements == count && count > 0);
            CHECK(gr.max_force == fhi && gr.min_force == flo);
            CHECK_CLOSE(gr.length, len, 1e-14, 0);
            CHECK_CLOSE(gr.stressed_length, cur, 1e-14, 0);
            CHECK_CLOSE(gr.weight, wt, 1e-14, 0);
            CHECK(gr.has_capacity == (g == 0));
            if (g == 0) CHECK(gr.max_utilisation == umax && umax > 0);
        }
        size_t e;
        double u;
        CHECK(ctn_solution_worst_utilisation(r.m, r.s, k, &e, &u) == CTN_OK && e < 10);
    }
    done(&r);
}

/* The catenary element heated like the cable: the same span as one exact catenary and as
 * 100 cable elements (engineering strain), before and after dT = 80 K: the horizontal
 * tensions agree to the mesh's error (1e-4) in both states, and heating changes them. */
static void test_catenary_temperature(void)
{
    const char *base =
        "units kN m\ngravity 0 0 -1\nmaterial steel E=2e8 strain=engineering alpha=1.2e-5\n"
        "section s material=steel A=3e-4 w=0.05\nnode 1 0 0 0 fix=xyz\nnode 2 100 0 30 fix=xyz\n%s\n"
        "step base\nstep hot\ntemperature all dT=80\n";
    const char *members[2] = { "catenary 1 1 2 section=s length=106", "cable 1 2 section=s n=100 length=106" };
    double H[2][2];
    for (int v = 0; v < 2; v++) {
        char text[1024];
        snprintf(text, sizeof text, base, members[v]);
        run r = solve_text(text);
        CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
        for (size_t k = 0; k < 2 && !r.rc; k++) {
            ctn_step_result st;
            ctn_solution_step(r.s, k, &st);
            H[v][k] = -st.react[0];
        }
        done(&r);
    }
    for (int k = 0; k < 2; k++) CHECK_CLOSE(H[0][k], H[1][k], 1e-4, 0);
    CHECK(H[0][1] < 0.98 * H[0][0]);
}

/* The verification example of OpenSees' CatenaryCable element (its manual page: a
 * modification of Salehi Ahmad Abad et al. 2013): two catenaries of 50 m between three
 * nodes in 3D, E A = 3e7, a load of 1 per unit length downward, alpha = 6.5e-6 and a
 * temperature rise of 100; node 2 is held in y only. Published: node 2 moves (8.58693, 0,
 * 2.82578). */
static void test_opensees_catenary_temperature(void)
{
    const char *text =
        "gravity 0 0 -1\nmaterial m E=3e7 strain=engineering alpha=6.5e-6\nsection s material=m A=1 w=1\n"
        "node 1 0 0 90 fix=xyz\nnode 2 15 0 40 fix=y\nnode 3 30 60 30 fix=xyz\n"
        "catenary 1 1 2 section=s length=50\ncatenary 2 2 3 section=s length=50\n"
        "temperature all dT=100\nsolve steps=10\n";
    run r = solve_text(text);
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
    if (!r.rc) {
        const double *d = ctn_solution_displacements(r.s);
        CHECK_CLOSE(d[3], 8.58693, 0, 5e-6);
        CHECK(d[4] == 0);
        CHECK_CLOSE(d[5], 2.82578, 0, 5e-6);
    }
    done(&r);
}

static void test_errors(void)
{
    const char *bad[][2] = {
        { "material m E=1 alpha=0.5\n", "alpha" },
        { "material m E=1\nsection s material=m A=1 mbl=-3\n", "mbl" },
        { "material m E=1\nsection s material=m A=1 safety=2\n", "safety" },
        { "material m E=1\nsection s material=m A=1 mbl=3 safety=0\n", "safety" },
        { "material m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0\nelement 1 1 2 section=s group=9x\n", "group name" },
        { "material m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0\nelement 1 1 2 section=s\ngroup g 5\n", "undefined element 5" },
        { "material m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0\nelement 1 1 2 section=s\ntemperature nope dT=3\n", "not 'all'" },
        { "material m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0\nelement 1 1 2 section=s\ntemperature all\n", "dT" },
        { "material m E=1 alpha=1e-3\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0\nelement 1 1 2 section=s\ntemperature all dT=-900\n", "half" },
        { "gravity 0 0 -1\nmaterial m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=2 sag=0.1 length=2\n", "give one of" },
        { "gravity 0 0 -1\nmaterial m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=2 sag=-1\n", "positive" },
        { "material m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=2 H=1 shape=straight\n", "gravity" },
        { "gravity 0 0 -1\nmaterial m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=2 H=1 N0=3\n", "N0" },
        { "gravity 0 0 -1\nmaterial m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=2 length=2\nhload q=1 elements=snow\n", "undefined group" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        ctn_ctx *ctx = NULL;
        ctn_model *m = NULL;
        ctn_solve_options opt;
        ctn_ctx_create(&ctx);
        int rc = ctn_read_string(ctx, "bad.cable", bad[i][0], strlen(bad[i][0]), &m, &opt);
        CHECK_MSG(rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), bad[i][1]) && strstr(ctn_ctx_message(ctx), "bad.cable:"),
                  "case %zu: rc %d: %s", i, rc, ctn_ctx_message(ctx));
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
}

int main(void)
{
    test_bar_between_supports();
    test_free_hanging();
    test_targets();
    test_guyed();
    test_unreachable();
    test_groups_capacity();
    test_catenary_temperature();
    test_opensees_catenary_temperature();
    test_errors();
    CHECK_DONE();
}
