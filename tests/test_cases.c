/* Load cases and combinations (issue 27 item 1):
 * - a case reproduces, bit for bit, the same loads stated as a cumulative step after its
 *   installed state: displacements, reactions and element forces compared with memcmp,
 *   with every kind of load (nodal, lineload, hload on the deformed projection,
 *   temperature, a displaced support), with substeps, and with a later step solved in
 *   between (the case starts from the named state, not from the last one);
 * - a combination of one case times 1 is that case, and times 2 the case with its loads
 *   doubled, bit for bit (both factors are exact in binary); a case without from=
 *   starts from the last step defined above it;
 * - a combination 1.35 G + 1.5 W equals a step with the factored loads typed as numbers
 *   to 1e-12 (the factored sums round differently), and differs from the sum of the two
 *   cases' increments (the cable is not linear);
 * - the envelope names the governing cases. */
#include "catena.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HEAD "units kN m\ngravity 0 -1 0\nmaterial steel E=2.0e8 alpha=1.2e-5\n" \
             "section strand material=steel A=3.14e-4 w=0.1\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n" \
             "cable 1 2 section=strand n=20 length=204 group=main\nstep install\nload 8 0 -1 0\n"
#define LOADS "load 11 0 -5 2\nlineload main qz=0.05\nhload q=0.02 elements=3-8\ntemperature all dT=-20\n" \
              "displace 2 x=0.1\n"

static ctn_solution *solve(ctn_ctx *ctx, const char *text, ctn_model **m)
{
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    int rc = ctn_read_string(ctx, "cases", text, strlen(text), m, &opt);
    if (!rc) rc = ctn_solve(ctx, *m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (s) {
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        CHECK(sum.reason == CTN_CONVERGED);
    }
    return s;
}

/* Step ka of a against step kb of b: 0 when bit for bit equal. */
static int differ(const ctn_solution *a, size_t ka, const ctn_solution *b, size_t kb, size_t nn, size_t ne)
{
    ctn_step_result x, y;
    if (!a || !b || ctn_solution_step(a, ka, &x) || ctn_solution_step(b, kb, &y)) return 1;
    int d = memcmp(x.d, y.d, 3 * nn * sizeof(double)) || memcmp(x.react, y.react, 3 * nn * sizeof(double));
    for (size_t e = 0; e < ne; e++) {
        ctn_element_state p, q;
        ctn_solution_step_element(a, ka, e, &p);
        ctn_solution_step_element(b, kb, e, &q);
        d |= memcmp(&p.force, &q.force, sizeof p.force) || memcmp(&p.length, &q.length, sizeof p.length);
    }
    return d || x.reason != CTN_CONVERGED;
}

/* The largest difference of the displacements of two step states, relative to the largest. */
static double reldiff(const ctn_solution *a, size_t ka, const ctn_solution *b, size_t kb, size_t nn)
{
    ctn_step_result x, y;
    if (!a || !b || ctn_solution_step(a, ka, &x) || ctn_solution_step(b, kb, &y)) return INFINITY;
    double big = 0, dif = 0;
    for (size_t i = 0; i < 3 * nn; i++) big = fmax(big, fabs(x.d[i])), dif = fmax(dif, fabs(x.d[i] - y.d[i]));
    return dif / big;
}

static void test_bit_for_bit(void)
{
    const char *cases = HEAD "step later\nload 6 0 -3 0\ncase wind from=install substeps=3\n" LOADS
                             "case ice\nlineload all qy=-0.05\ncombination one 1*ice\ncombination two 2*ice\n"
                             "case ice2 from=later\nlineload all qy=-0.1\n";
    const char *steps = HEAD "step wind substeps=3\n" LOADS;
    /* the same kinds of load as the cases' model: an hload on the deformed projection
     * anywhere makes every step's linear solves GMRES ones (docs/format.md) */
    const char *steps2 = HEAD "step later\nload 6 0 -3 0\nstep ice2\nlineload all qy=-0.1\nstep h\n"
                              "hload q=0.02 elements=3-8\n";
    ctn_ctx *ctx = NULL;
    ctn_model *ma = NULL, *mb = NULL, *mc = NULL;
    ctn_ctx_create(&ctx);
    ctn_solution *a = solve(ctx, cases, &ma), *b = solve(ctx, steps, &mb), *c = solve(ctx, steps2, &mc);
    CHECK(a && ctn_solution_case_count(a) == 5);
    if (a && b && c && ctn_solution_case_count(a) == 5) {
        size_t nn = ctn_model_node_count(ma), ne = ctn_model_element_count(ma);
        const char *name = NULL;
        int from = -1, comb = -1;
        CHECK(ctn_model_case_info(ma, 0, &name, &from, &comb) == CTN_OK && !strcmp(name, "wind") && from == 0 && !comb);
        CHECK(ctn_model_case_info(ma, 1, &name, &from, &comb) == CTN_OK && !strcmp(name, "ice") && from == 1);
        CHECK(ctn_model_case_info(ma, 3, &name, &from, &comb) == CTN_OK && !strcmp(name, "one") && comb == 1);
        CHECK_MSG(!differ(ctn_solution_case(a, 0), 0, b, 1, nn, ne), "case wind against step wind");
        CHECK_MSG(!differ(ctn_solution_case(a, 3), 0, ctn_solution_case(a, 1), 0, nn, ne), "1*ice against ice");
        CHECK_MSG(!differ(ctn_solution_case(a, 4), 0, ctn_solution_case(a, 2), 0, nn, ne), "2*ice against ice2");
        CHECK_MSG(!differ(ctn_solution_case(a, 2), 0, c, 2, nn, ne), "case ice2 against step ice2");
        CHECK_MSG(!differ(a, 0, b, 0, nn, ne), "the installed states");
        CHECK(reldiff(ctn_solution_case(a, 2), 0, c, 1, nn) > 1e-3);   /* not the state it starts from */
    }
    ctn_solution_destroy(&a);
    ctn_solution_destroy(&b);
    ctn_solution_destroy(&c);
    ctn_model_destroy(&ma);
    ctn_model_destroy(&mb);
    ctn_model_destroy(&mc);
    ctn_ctx_destroy(&ctx);
}

static void test_combination(void)
{
    const char *cases = HEAD "case G\nlineload all qy=-0.04\nload 11 0 -2 0\ncase W\nlineload all qz=0.03\n"
                             "combination ULS 1.35*G + 1.5*W\n";
    const char *step = HEAD "step ULS\nlineload all qy=-0.054\nload 11 0 -2.7 0\nlineload all qz=0.045\n";
    ctn_ctx *ctx = NULL;
    ctn_model *ma = NULL, *mb = NULL;
    ctn_ctx_create(&ctx);
    ctn_solution *a = solve(ctx, cases, &ma), *b = solve(ctx, step, &mb);
    if (a && b && ctn_solution_case_count(a) == 3) {
        size_t nn = ctn_model_node_count(ma);
        double r = reldiff(ctn_solution_case(a, 2), 0, b, 1, nn);
        printf("1.35 G + 1.5 W against the factored step: %.3g\n", r);
        CHECK(r < 1e-12);
        /* not a superposition: u(ULS) - u(0) differs from 1.35 (u(G) - u(0)) + 1.5 (u(W) - u(0)) */
        ctn_step_result g, w, u, s0;
        ctn_solution_step(ctn_solution_case(a, 0), 0, &g);
        ctn_solution_step(ctn_solution_case(a, 1), 0, &w);
        ctn_solution_step(ctn_solution_case(a, 2), 0, &u);
        ctn_solution_step(a, 0, &s0);
        double big = 0, dif = 0;
        for (size_t i = 0; i < 3 * nn; i++) {
            double lin = s0.d[i] + 1.35 * (g.d[i] - s0.d[i]) + 1.5 * (w.d[i] - s0.d[i]);
            big = fmax(big, fabs(u.d[i] - s0.d[i]));
            dif = fmax(dif, fabs(u.d[i] - lin));
        }
        CHECK(dif > 1e-3 * big);
        /* the envelope: the largest force in ULS, the smallest in the installed state's
         * lightest case */
        char *json = NULL;
        CHECK(ctn_result_json(ctx, ma, a, 0, &json) == CTN_OK);
        CHECK(json && strstr(json, "\"envelope\":{\"elements\":[{\"id\":1,") != NULL);
        CHECK(json && strstr(json, "\"max_case\":\"ULS\"") != NULL);
        CHECK(json && strstr(json, "\"combinations\":[{\"name\":\"ULS\"") != NULL);
        ctn_json_free(json);
    }
    ctn_solution_destroy(&a);
    ctn_solution_destroy(&b);
    ctn_model_destroy(&ma);
    ctn_model_destroy(&mb);
    ctn_ctx_destroy(&ctx);
}

/* A catenary element in a temperature case: its reported H (solved from the chord at the
 * case's length) is the support's horizontal reaction of the case. */
static void test_catenary_case(void)
{
    const char *text = "units kN m\ngravity 0 0 -1\nmaterial acsr E=6.9e7 strain=engineering alpha=1.9e-5\n"
                       "section drake material=acsr A=4.68e-4 w=0.01594\nnode 1 0 0 0 fix=xyz\n"
                       "node 2 350 0 0 fix=xyz\ncatenary 1 1 2 section=drake length=351\nstep install\n"
                       "case hot\ntemperature all dT=65\ncombination hot2 2*hot\n";
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    ctn_solution *s = solve(ctx, text, &m);
    for (size_t i = 0; s && i < ctn_solution_case_count(s); i++) {
        const ctn_solution *cs = ctn_solution_case(s, i);
        ctn_catenary_result c = { .size = sizeof c };
        ctn_step_result st;
        CHECK(ctn_solution_step(cs, 0, &st) == CTN_OK && ctn_solution_catenary(m, cs, 0, 0, &c) == CTN_OK);
        CHECK_CLOSE(c.H, -st.react[0], 1e-9, 0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_catenary_case();
    test_bit_for_bit();
    test_combination();
    CHECK_DONE();
}
