/* Catenary elements set by a target (H=, sag=, tension=; issue 11): the unstressed
 * length found by ctn_model_resolve_targets against the length that meets the target in
 * Irvine's elastic catenary, found here independently (bisection on the closed form of
 * catena/analytic.h), for level and inclined chords and gravity along -z or -y; a mast
 * held by catenary guys and a cable guy found together, each guy's end tension checked
 * on the closed form at the solved chord; the summary record, the JSON and the errors. */
/* ctest-cost: 50 (about the seconds it takes under ASan: ctest -j starts it early) */
#include "catena.h"
#include "check.h"
#include "run_text.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Read a model given as text, every allocation of the library allowed (0) or the k-th
 * after the read failing; then its targets resolved and, with solve, the solve. */
static int read_resolve(ctn_ctx *ctx, const char *name, const char *text, long k, int solve, ctn_model **m,
                        ctn_solution **s)
{
    ctn_solve_options opt;
    int rc = ctn_read_string(ctx, name, text, strlen(text), m, &opt);
    ctn_ctx_fail_alloc_at(ctx, rc ? 0 : k);
    if (!rc) rc = ctn_model_resolve_targets(ctx, *m, &opt, NULL);
    if (!rc && solve) rc = ctn_solve(ctx, *m, &opt, s);
    ctn_ctx_fail_alloc_at(ctx, 0);
    return rc;
}

enum { KIND_H = 0, KIND_SAG = 1, KIND_TENSION = 2 };

/* The quantity of a solved closed-form catenary: H, the largest sag below the chord, the
 * larger end tension. */
static double closed_quantity(const ctn_ecatenary *c, int kind)
{
    if (kind == KIND_H) return c->H;
    if (kind == KIND_SAG) return c->sum.sag;
    return fmax(hypot(c->H, c->V_left), hypot(c->H, c->V_right));
}

/* The unstressed length whose elastic catenary (span l, rise h, weight w per unstressed
 * length, EA) has quantity `kind` equal to v: bisection on [lo, hi] (the taut branch,
 * where H and the tension fall and the sag grows with the length) to the resolution of
 * the length. */
static double closed_length(double l, double h, double w, double EA, int kind, double v, double lo, double hi)
{
    for (int it = 0; it < 200 && hi - lo > 2e-16 * hi; it++) {
        double mid = 0.5 * (lo + hi);
        ctn_ecatenary_in in = { l, h, w, EA, mid };
        ctn_ecatenary c;
        if (ctn_ecatenary_solve(NULL, &in, &c)) return NAN;
        if ((kind == KIND_SAG) == (closed_quantity(&c, kind) < v)) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

typedef struct span_case {
    const char *gravity;     /* gravity line */
    double w;                /* section weight; w |g| is the closed form's */
    double g;                /* |g| */
    double B[3];             /* second node; the first is the origin */
    double l, h;             /* its horizontal and upward chord */
} span_case;

static const char *span_text(char *buf, size_t size, const span_case *sc, const char *key)
{
    snprintf(buf, size,
             "units kN m\n%s\nmaterial steel E=2e8 strain=engineering\nsection s material=steel A=3.14e-4 w=%.17g\n"
             "node 1 0 0 0 fix=xyz\nnode 2 %.17g %.17g %.17g fix=xyz\ncatenary 7 1 2 section=s %s\n",
             sc->gravity, sc->w, sc->B[0], sc->B[1], sc->B[2], key);
    return buf;
}

/* One span and one target: the length found against the closed form, the target
 * reached, the element's own results, and the length found solved again. */
static void check_span(const span_case *sc, int kind)
{
    static const char *const keys[3] = { "H=30", "sag=12", "tension=45" };
    static const double values[3] = { 30, 12, 45 };
    char text[1024], key[64];
    run r = run_text("span.cable", span_text(text, sizeof text, sc, keys[kind]));
    CHECK_MSG(r.rc == CTN_OK, "%s: %s", keys[kind], ctn_ctx_message(r.ctx));
    if (r.rc) { done(&r); return; }
    ctn_cable_info t;
    ctn_element_info e;
    ctn_catenary_result cr = { .size = sizeof cr };
    CHECK(ctn_model_element_target(r.m, 0, &t) == CTN_OK && ctn_model_element(r.m, 0, &e) == CTN_OK);
    CHECK(t.target == (ctn_cable_target)(kind + 1) && t.first == 0 && t.count == 1 && t.target_iterations >= 1);
    CHECK(t.length == e.l0);
    CHECK_CLOSE(t.target_achieved, values[kind], 1e-10, 0);
    double chord = hypot(sc->l, sc->h), EA = 2e8 * 3.14e-4;
    double Lc = closed_length(sc->l, sc->h, sc->w * sc->g, EA, kind, values[kind], 0.995 * chord, 1.3 * chord);
    printf("%-10s l=%-9.5g h=%-4g  L found %.12f  closed form %.12f  rel. difference %.2e  (%d outer iterations)\n",
           keys[kind], sc->l, sc->h, t.length, Lc, fabs(t.length - Lc) / Lc, t.target_iterations);
    CHECK_CLOSE(t.length, Lc, 1e-10, 0);
    /* the element's reported forces at the solution meet the target too */
    CHECK(ctn_solution_catenary(r.m, r.s, 0, 0, &cr) == CTN_OK);
    if (kind == KIND_H) CHECK_CLOSE(cr.H, 30, 1e-10, 0);
    if (kind == KIND_TENSION) CHECK_CLOSE(fmax(cr.tension[0], cr.tension[1]), 45, 1e-10, 0);
    done(&r);
    /* the length found, given as length=, gives the target back */
    snprintf(key, sizeof key, "length=%.17g", t.length);
    r = run_text("again.cable", span_text(text, sizeof text, sc, key));
    CHECK(r.rc == CTN_OK);
    if (!r.rc && !ctn_solution_catenary(r.m, r.s, 0, 0, &cr)) {
        ctn_ecatenary_in in = { sc->l, sc->h, sc->w * sc->g, EA, t.length };
        ctn_ecatenary c;
        CHECK(ctn_ecatenary_solve(NULL, &in, &c) == CTN_OK);
        CHECK_CLOSE(closed_quantity(&c, kind), values[kind], 1e-9, 0);
        CHECK_CLOSE(cr.H, c.H, 1e-10, 0);
    }
    done(&r);
}

static void test_spans(void)
{
    const double g = 9.81;
    span_case cases[4] = {
        { "gravity 0 0 -1", 0.1, 1, { 200, 0, 0 }, 200, 0 },
        { "gravity 0 0 -1", 0.1, 1, { 200, 0, 60 }, 200, 60 },
        { "gravity 0 -9.81 0", 0.1 / g, g, { 200, 0, 30 }, hypot(200, 30), 0 },     /* up is +y */
        { "gravity 0 -9.81 0", 0.1 / g, g, { 150, -45, 100 }, hypot(150, 100), -45 },
    };
    for (int c = 0; c < 4; c++)
        for (int kind = 0; kind < 3; kind++) check_span(&cases[c], kind);
}

/* The end tensions of a guy from anchor A to the top T (solved positions) with unstressed
 * length L, on the closed form: the larger of the two. */
static double guy_tension(const double A[3], const double T[3], double L, double w, double EA)
{
    ctn_ecatenary_in in = { hypot(T[0] - A[0], T[1] - A[1]), T[2] - A[2], w, EA, L };
    ctn_ecatenary c;
    if (ctn_ecatenary_solve(NULL, &in, &c)) return NAN;
    return closed_quantity(&c, KIND_TENSION);
}

/* A mast held by three guys found together: two catenary elements and one 10-element
 * cable, each to its own support tension, the top free and pushed sideways. */
static void test_guyed(void)
{
    const char *text =
        "units kN m\ngravity 0 0 -1\nmaterial steel E=1.6e8 strain=engineering\n"
        "material mast E=2e8\nsection guy material=steel A=2e-4 w=0.02\nsection pole material=mast A=0.01\n"
        "node 1 0 0 0 fix=xyz\nnode 2 0 0 40\nnode 3 30 0 0 fix=xyz\nnode 4 -15 25.98 0 fix=xyz\n"
        "node 5 -15 -25.98 0 fix=xyz\nelement 1 1 2 section=pole\n"
        "catenary 2 3 2 section=guy tension=20\ncatenary 3 4 2 section=guy tension=25\n"
        "cable 5 2 section=guy n=10 tension=30\nload 2 2 0 0\n";
    run r = run_text("guyed.cable", text);
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
    if (r.rc) { done(&r); return; }
    ctn_cable_info t, c;
    ctn_step_result st;
    ctn_solution_step(r.s, 0, &st);
    double top[3], want[2] = { 20, 25 }, anchors[2][3] = { { 30, 0, 0 }, { -15, 25.98, 0 } };
    for (int k = 0; k < 3; k++) top[k] = (k == 2 ? 40 : 0) + st.d[3 + k];   /* node 2 is the second node */
    for (size_t i = 1; i <= 2; i++) {
        CHECK(ctn_model_element_target(r.m, i, &t) == CTN_OK && t.target == CTN_TARGET_TENSION);
        CHECK_CLOSE(t.target_achieved, want[i - 1], 1e-10, 0);
        double T = guy_tension(anchors[i - 1], top, t.length, 0.02, 1.6e8 * 2e-4);
        printf("guy %zu: length %.10f, tension on the closed form at the solved top %.12f (target %g)\n", i, t.length, T,
               want[i - 1]);
        CHECK_CLOSE(T, want[i - 1], 1e-10, 0);
    }
    CHECK(ctn_model_element_target(r.m, 0, &t) == CTN_OK && t.target == CTN_TARGET_NONE);
    CHECK(ctn_model_cable(r.m, 0, &c) == CTN_OK && c.target == CTN_TARGET_TENSION);
    CHECK_CLOSE(c.target_achieved, 30, 1e-10, 0);
    CHECK(t.target_iterations == 0 && c.target_iterations >= 1);
    /* the whole structure in equilibrium: the reactions carry the weights and the load */
    double W = 0.02 * (c.length + t.length), R[3] = { 0, 0, 0 };
    ctn_model_element_target(r.m, 1, &t);
    W += 0.02 * t.length;
    ctn_model_element_target(r.m, 2, &t);
    W += 0.02 * t.length;
    for (size_t n = 0; n < ctn_model_node_count(r.m); n++)
        for (int k = 0; k < 3; k++) R[k] += st.react[3 * n + (size_t)k];
    CHECK_CLOSE(R[0], -2, 1e-9, 0);
    CHECK_CLOSE(R[1], 0, 0, 1e-9);
    CHECK_CLOSE(R[2], W, 1e-9, 0);
    /* the JSON carries the target record of each catenary guy */
    char *json = NULL;
    CHECK(ctn_result_json(r.ctx, r.m, r.s, 0, &json) == CTN_OK);
    int records = 0;
    for (const char *p = json; p && (p = strstr(p, "\"target\":{\"kind\":\"tension\"")); p++) records++;
    CHECK_MSG(records == 3, "%d target records", records);   /* two catenaries, one cable */
    ctn_json_free(json);
    done(&r);
}

/* The model fails to resolve its targets (resolve) or to solve without it, with code
 * and a message holding what. */
static void expect_error(const char *text, int resolve, int code, const char *what)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    int rc = resolve ? read_resolve(ctx, "bad.cable", text, 0, 0, &m, &s) : ctn_read_string(ctx, "bad.cable", text,
                                                                                         strlen(text), &m, NULL);
    if (!resolve && !rc) rc = ctn_solve(ctx, m, NULL, &s);
    CHECK_MSG(rc == code && strstr(ctn_ctx_message(ctx), what), "rc %d: %s (expected '%s')", rc, ctn_ctx_message(ctx), what);
    CHECK(s == NULL);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* The least end tension of the level span (EA = 62 800 kN, w = 0.1 kN/m, l = 200 m) over
 * its unstressed length, on the closed form: golden-section search. */
static double closed_min_tension(double *Lmin)
{
    const double r = 0.5 * (sqrt(5.0) - 1);
    double a = 210, b = 320, x[2] = { b - r * (b - a), a + r * (b - a) }, f[2];
    for (int i = 0; i < 2; i++) {
        ctn_ecatenary_in in = { 200, 0, 0.1, 2e8 * 3.14e-4, x[i] };
        ctn_ecatenary c;
        f[i] = ctn_ecatenary_solve(NULL, &in, &c) ? NAN : closed_quantity(&c, KIND_TENSION);
    }
    while (b - a > 1e-10 * b) {
        int k = f[0] < f[1] ? 0 : 1;
        if (k == 0) { b = x[1]; x[1] = x[0]; f[1] = f[0]; x[0] = b - r * (b - a); }
        else        { a = x[0]; x[0] = x[1]; f[0] = f[1]; x[1] = a + r * (b - a); }
        ctn_ecatenary_in in = { 200, 0, 0.1, 2e8 * 3.14e-4, x[k] };
        ctn_ecatenary c;
        f[k] = ctn_ecatenary_solve(NULL, &in, &c) ? NAN : closed_quantity(&c, KIND_TENSION);
    }
    *Lmin = 0.5 * (x[0] + x[1]);
    return fmin(f[0], f[1]);
}

/* A group of catenary elements sums their curves' stretched lengths, not their chords:
 * the level span of 200 m with 210 m unstressed, against Irvine's closed form. */
static void test_group_length(void)
{
    const char *text = "units kN m\ngravity 0 0 -1\nmaterial steel E=2e8 strain=engineering\n"
                       "section s material=steel A=3.14e-4 w=0.1\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n"
                       "catenary 7 1 2 section=s length=210 group=span\n";
    ctn_group_result g;
    ctn_ecatenary_in in = { 200, 0, 0.1, 2e8 * 3.14e-4, 210 };
    ctn_ecatenary c;
    run r = run_text("group.cable", text);
    CHECK(r.rc == CTN_OK && ctn_ecatenary_solve(NULL, &in, &c) == CTN_OK);
    CHECK(r.s && ctn_solution_group(r.m, r.s, 0, 0, &g) == CTN_OK);
    if (r.s) CHECK_CLOSE(g.stressed_length, c.sum.length, 1e-10, 0);    /* a chord would be 200 */
    done(&r);
}

static void test_errors(void)
{
    char text[1024];
    span_case level = { "gravity 0 0 -1", 0.1, 1, { 200, 0, 0 }, 200, 0 };
    expect_error(span_text(text, sizeof text, &level, "tension=5"), 1, CTN_ERR_MODEL,
                 "bad.cable:7: catenary 7: no unstressed length gives tension=5: over unstressed lengths");
    {                                  /* the least tension it names, on the closed form */
        ctn_ctx *cx = NULL;
        ctn_model *mm = NULL;
        ctn_solution *ss = NULL;
        double Lc, Tc = closed_min_tension(&Lc), T = NAN, L = NAN;
        ctn_ctx_create(&cx);
        CHECK(read_resolve(cx, "bad.cable", text, 0, 0, &mm, &ss) == CTN_ERR_MODEL);
        const char *at = strstr(ctn_ctx_message(cx), "ranges from ");
        CHECK_MSG(at && sscanf(at, "ranges from %lf (length %lf)", &T, &L) == 2, "%s", ctn_ctx_message(cx));
        CHECK_CLOSE(T, Tc, 1e-5, 0);                   /* printed to 6 digits */
        CHECK_CLOSE(L, Lc, 1e-4, 0);                   /* a flat minimum */
        ctn_model_destroy(&mm);
        ctn_ctx_destroy(&cx);
    }
    expect_error(span_text(text, sizeof text, &level, "sag=0.01"), 1, CTN_ERR_MODEL,
                 "bad.cable:7: catenary 7: no unstressed length gives sag=0.01 within the elastic range");
    expect_error(span_text(text, sizeof text, &level, "sag=10"), 0, CTN_ERR_INVALID,
                 "bad.cable:7: catenary 7 is set by a target: find its length first");
    /* through the API: a target on another family, or with a length */
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    CHECK(ctn_read_string(ctx, "api.cable", text, strlen(text), &m, NULL) == CTN_OK);
    int nodes[2] = { 1, 2 };
    ctn_element_spec e;
    ctn_element_spec_init(&e);
    e.id = 8;
    e.nnodes = 2;
    e.nodes = nodes;
    e.section = "s";
    e.target = CTN_TARGET_H;
    e.target_value = 30;
    size_t ne = ctn_model_element_count(m);
    CHECK(ctn_model_add_element_spec(m, &e) == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "only catenary elements"));
    e.type = "catenary";
    e.l0 = 210;
    CHECK(ctn_model_add_element_spec(m, &e) == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "give no length"));
    e.l0 = CTN_L0_DEFAULT;
    e.target_value = -1;
    CHECK(ctn_model_add_element_spec(m, &e) == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "positive and finite"));
    CHECK(ctn_model_element_count(m) == ne);          /* nothing added */
    e.target_value = 30;
    CHECK(ctn_model_add_element_spec(m, &e) == CTN_OK);
    ctn_cable_info t;
    CHECK(ctn_model_element_target(m, ne, &t) == CTN_OK && t.target == CTN_TARGET_H && t.target_value == 30);
    CHECK(ctn_model_element_target(m, ne + 1, &t) == CTN_ERR_INVALID);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Every allocation of the root find and the solve after it may fail: CTN_ERR_NOMEM and
 * no leak (the sanitizer build checks), until the run needs no more allocations. */
static void test_alloc_failures(void)
{
    const char *text =
        "units kN m\ngravity 0 0 -1\nmaterial steel E=1.6e8 strain=engineering\nmaterial mast E=2e8\n"
        "section guy material=steel A=2e-4 w=0.02\nsection pole material=mast A=0.01\nnode 1 0 0 0 fix=xyz\n"
        "node 2 0 0 40\nnode 3 30 0 0 fix=xyz\nnode 4 -30 0 0 fix=xyz\nnode 5 0 30 0 fix=xyz\nnode 6 0 -30 0 fix=xyz\n"
        "element 1 1 2 section=pole\ncatenary 2 3 2 section=guy tension=20\ncatenary 3 4 2 section=guy tension=20\n"
        "cable 5 2 section=guy n=4 H=15\ncable 6 2 section=guy n=4 H=15\nload 2 1 0 0\n";
    int nomem = 0, ok = 0;
    for (long k = 1; k < 100000 && !ok; k += k < 300 ? 1 : 13) {   /* every one, then a sample */
        ctn_ctx *ctx = NULL;
        ctn_model *m = NULL;
        ctn_solution *s = NULL;
        ctn_ctx_create(&ctx);
        int rc = read_resolve(ctx, "alloc.cable", text, k, 1, &m, &s);
        CHECK_MSG(rc == CTN_OK || rc == CTN_ERR_NOMEM, "k=%ld: rc %d: %s", k, rc, ctn_ctx_message(ctx));
        nomem += rc == CTN_ERR_NOMEM;
        ok = rc == CTN_OK;
        ctn_solution_destroy(&s);
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
    CHECK_MSG(ok && nomem > 10, "ok %d, %d allocation failures", ok, nomem);
}

/* The comparisons read a span's length: before the targets are resolved they refuse
 * the model as the solve does, naming the cable's line; after, they take the length found. */
static void test_compare_waits_for_targets(void)
{
    const char *text = "units kN m\nmaterial steel E=2.0e8\nsection strand material=steel A=3.14e-4 w=0.1\n"
                       "gravity 0 -1 0\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n"
                       "cable 1 2 section=strand n=20 sag=5\n";
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_compare *c = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    CHECK(ctn_read_string(ctx, "sag.cable", text, strlen(text), &m, &opt) == CTN_OK);
    CHECK(ctn_compare_create(ctx, m, &c) == CTN_ERR_INVALID && !c);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "sag.cable:7: cable 1-2 is set by a target: find its length first"), "%s",
              ctn_ctx_message(ctx));
    CHECK(ctn_model_resolve_targets(ctx, m, &opt, NULL) == CTN_OK);
    ctn_cable_info ci;
    CHECK(ctn_model_cable(m, 0, &ci) == CTN_OK);
    CHECK(ctn_compare_create(ctx, m, &c) == CTN_OK);
    if (c) CHECK_CLOSE(ctn_compare_span(c)->L0, ci.length, 1e-15, 0);
    ctn_compare_destroy(&c);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_spans();
    test_guyed();
    test_group_length();
    test_errors();
    test_compare_waits_for_targets();
    test_alloc_failures();
    CHECK_DONE();
}
