/* Prestress as engineers state it (issue 9, item 1): `N0=` (a force), `s0=` (a stress) or
 * `eps0=` (a strain of the material's measure) in place of `l0=`, on `element`, `spring`
 * and `cable`: the unstressed length is computed so that the member carries it in the
 * geometry it is given, and a solve without load returns it to round-off (1e-12), for
 * both strain laws. At most one of l0=, N0=, s0=, eps0=; a tension-only member takes no
 * compression; a strain the law cannot reach is refused. */
#include "catena.h"
#include "check.h"

#include <stdio.h>

/* Forces of the elements of text, solved without load; count in *n. 0 on failure. */
static int solve_forces(const char *text, double *N, size_t cap, size_t *n)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    int ok = 0;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "pre.cable", text, strlen(text), &m, &opt);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (!rc) {
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        CHECK(sum.reason == CTN_CONVERGED);
        *n = ctn_model_element_count(m);
        for (size_t e = 0; e < *n && e < cap; e++) {
            ctn_element_state st;
            ctn_solution_element(s, e, &st);
            N[e] = st.force;
        }
        ok = 1;
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return ok;
}

static void test_elements(void)
{
    const char *laws[2] = { "", "strain=engineering" };
    for (int law = 0; law < 2; law++) {
        /* a two-element bar 3-4-0 pulled between fixed ends; node 2 free */
        const char *keys[3] = { "N0=50", "s0=500000", "eps0=2.5e-3" };
        for (int k = 0; k < 3; k++) {
            char text[512];
            snprintf(text, sizeof text,
                     "material m E=2e8 %s\nsection s material=m A=1e-4\n"
                     "node 1 0 0 0 fix=xyz\nnode 2 3 4 0\nnode 3 6 8 0 fix=xyz\n"
                     "element 1 1 2 section=s %s\nelement 2 2 3 section=s %s\n", laws[law], keys[k], keys[k]);
            double N[2], want = k == 0 ? 50 : k == 1 ? 50 : 0;
            size_t n = 0;
            if (!solve_forces(text, N, 2, &n)) continue;
            if (k == 2) want = law ? 2e4 * 2.5e-3 : 2e4 * 2.5e-3 * sqrt(1 + 2 * 2.5e-3);   /* EA eps (lambda) */
            for (size_t e = 0; e < n; e++) CHECK_CLOSE(N[e], want, 1e-12, 0);
        }
    }
}

/* A generated cable, straight and taut between fixed ends, every element prestressed. */
static void test_cable(void)
{
    const char *laws[2] = { "", "strain=engineering" };
    for (int law = 0; law < 2; law++) {
        char text[512];
        snprintf(text, sizeof text,
                 "material m E=1.6e8 %s tension-only\nsection s material=m A=2e-4\n"
                 "node 1 0 0 0 fix=xyz\nnode 2 30 0 40 fix=xyz\n"
                 "cable 1 2 section=s n=25 length=50 shape=straight N0=120\n", laws[law]);
        double N[25];
        size_t n = 0;
        if (!solve_forces(text, N, 25, &n)) continue;
        CHECK(n == 25);
        for (size_t e = 0; e < n; e++) CHECK_CLOSE(N[e], 120, 1e-12, 0);
    }
}

static void test_spring(void)
{
    const char *text = "node 1 0 0 0 fix=xyz\nnode 2 0 0 -2 fix=xyz\nspring 1 1 2 k=300 N0=-45\n";
    double N[1];
    size_t n = 0;
    if (solve_forces(text, N, 1, &n)) CHECK_CLOSE(N[0], -45, 1e-12, 0);
}

/* Refused definitions, at their line. */
static void test_errors(void)
{
    const char *bad[][2] = {
        { "element 1 1 2 section=s l0=9 N0=5", "pre.cable:7: element 1: give at most one of l0=, N0=, s0=, eps0=" },
        { "element 1 1 2 section=s N0=5 eps0=1e-3", "pre.cable:7: element 1: give at most one of" },
        { "element 1 1 2 section=t N0=-5", "pre.cable:7: element 1: a tension-only member cannot be prestressed in compression" },
        { "element 1 1 2 section=s eps0=-0.6", "pre.cable:7: element 1: no unstressed length gives that prestress" },
        { "spring 1 1 2 k=10 s0=5", "pre.cable:7: spring 1: a spring has no section" },
        { "spring 1 1 2 k=10 N0=1e3", "pre.cable:7: spring 1: no positive free length" },
        { "cable 1 2 section=s n=4 length=11 N0=5 s0=3", "pre.cable:7: cable: give at most one of N0=, s0=, eps0=" },
        { "cable 1 2 section=s n=4 length=11 l0=3", "pre.cable:7: unknown key 'l0'" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char text[512];
        snprintf(text, sizeof text,
                 "material m E=2e8\nmaterial r E=2e8 tension-only\nsection s material=m A=1e-4\n"
                 "section t material=r A=1e-4\nnode 1 0 0 0 fix=xyz\nnode 2 10 0 0 fix=xyz\n%s\n", bad[i][0]);
        ctn_ctx *ctx = NULL;
        ctn_model *m = NULL;
        ctn_ctx_create(&ctx);
        int rc = ctn_read_string(ctx, "pre.cable", text, strlen(text), &m, NULL);
        CHECK_MSG(rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), bad[i][1]), "'%s': %d %s", bad[i][0], rc,
                  ctn_ctx_message(ctx));
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
}

int main(void)
{
    test_elements();
    test_cable();
    test_spring();
    test_errors();
    CHECK_DONE();
}
