/* The C API as a program uses it (issue 28, item 8):
 *   - a cable from ctn_cable_spec_init is the `cable` directive's: the founding paper's
 *     L = 250.8777 m cable built through the API solves to the very displacements of the
 *     same model read from its file (bit for bit), in the same iterations;
 *   - a zero-initialised spec is the documented other start (guess 0, arc): it differs;
 *   - messages about a model built through the API have no ":0:" or "<input>" prefix;
 *   - the README's snippet: a model with a target read, resolved, then solved. */
#include "check.h"

#include <catena.h>

#include <stdlib.h>

static const char *file_text =
    "units kN m\nmaterial steel E=2.0e8\nsection strand material=steel A=3.14e-4 w=0.1\n"
    "gravity 0 -1 0\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n"
    "cable 1 2 section=strand n=20 length=250.8777\n";

static int build(ctn_ctx *ctx, const ctn_cable_spec *spec, ctn_model **m)
{
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    int rc = ctn_model_create(ctx, m);
    if (!rc) rc = ctn_model_set_units(*m, "kN", "m");
    if (!rc) rc = ctn_model_set_gravity(*m, g);
    if (!rc) rc = ctn_model_add_material(*m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0);
    if (!rc) rc = ctn_model_add_section(*m, "strand", "steel", 3.14e-4, 0.1);
    if (!rc) rc = ctn_model_add_node(*m, 1, A, CTN_FIX_X | CTN_FIX_Y | CTN_FIX_Z);
    if (!rc) rc = ctn_model_add_node(*m, 2, B, CTN_FIX_X | CTN_FIX_Y | CTN_FIX_Z);
    if (!rc) rc = ctn_model_add_cable(*m, 1, 2, "strand", spec, NULL, NULL);
    return rc;
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *mf = NULL, *ma = NULL, *mz = NULL;
    ctn_solution *sf = NULL, *sa = NULL, *sz = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    CHECK(ctn_read_string(ctx, "paper.cable", file_text, strlen(file_text), &mf, &opt) == CTN_OK);
    CHECK(ctn_solve(ctx, mf, &opt, &sf) == CTN_OK);

    ctn_cable_spec spec;
    ctn_cable_spec_init(&spec);
    spec.n = 20;
    spec.length = 250.8777;
    CHECK_MSG(build(ctx, &spec, &ma) == CTN_OK, "%s", ctn_ctx_message(ctx));
    ctn_solve_options dflt;
    ctn_solve_options_default(&dflt);
    CHECK_MSG(ctn_solve(ctx, ma, &dflt, &sa) == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (sf && sa) {
        ctn_solve_summary a, b;
        ctn_solution_summary(sf, &a);
        ctn_solution_summary(sa, &b);
        CHECK(a.reason == CTN_CONVERGED && b.reason == CTN_CONVERGED && a.iterations == b.iterations);
        size_t n = 3 * ctn_model_node_count(mf);
        CHECK(n == 3 * ctn_model_node_count(ma) &&
              !memcmp(ctn_solution_displacements(sf), ctn_solution_displacements(sa), n * sizeof(double)));
    }

    ctn_cable_spec zero;
    memset(&zero, 0, sizeof zero);
    zero.n = 20;
    zero.length = 250.8777;
    CHECK(build(ctx, &zero, &mz) == CTN_OK);
    ctn_node_info a, z;
    CHECK(ctn_model_node(ma, 5, &a) == CTN_OK && ctn_model_node(mz, 5, &z) == CTN_OK);
    CHECK_MSG(memcmp(a.guess, z.guess, sizeof a.guess), "a zero spec starts where the directive's defaults do");

    /* An error about an API model: no file, no line, no ":0:". */
    ctn_cable_spec bad;
    ctn_cable_spec_init(&bad);
    bad.n = 0;
    bad.length = 250;
    CHECK(ctn_model_add_cable(ma, 1, 2, "strand", &bad, NULL, NULL) != CTN_OK);
    const char *msg = ctn_ctx_message(ctx);
    CHECK_MSG(*msg && msg[0] != ':' && !strstr(msg, ":0:") && !strstr(msg, "<input>"), "'%s'", msg);
    ctn_solution_destroy(&sz);

    /* The README's snippet on a model with a target. */
    const char *sag_text = "units kN m\nmaterial steel E=2.0e8\nsection strand material=steel A=3.14e-4 w=0.1\n"
                           "gravity 0 -1 0\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n"
                           "cable 1 2 section=strand n=20 sag=5\n";
    ctn_model *ms = NULL;
    ctn_solution *ss = NULL;
    int rc = ctn_read_string(ctx, "sag.cable", sag_text, strlen(sag_text), &ms, &opt);
    if (!rc) rc = ctn_model_resolve_targets(ctx, ms, &opt, NULL);
    if (!rc) rc = ctn_solve(ctx, ms, &opt, &ss);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    double sag = 0;
    CHECK(!rc && ctn_solution_cable_sag(ms, ss, 0, &sag) == CTN_OK);
    CHECK_CLOSE(sag, 5.0, 1e-9, 0);

    ctn_solution_destroy(&ss);
    ctn_solution_destroy(&sf);
    ctn_solution_destroy(&sa);
    ctn_model_destroy(&ms);
    ctn_model_destroy(&mf);
    ctn_model_destroy(&ma);
    ctn_model_destroy(&mz);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
