/* Tests of whole models given as text: read, resolve the targets, solve (the steps of
 * `catena solve`), and release. Include after check.h. */
#ifndef CTN_TEST_RUN_TEXT_H
#define CTN_TEST_RUN_TEXT_H

#include "catena.h"
#include "check.h"

typedef struct run {
    ctn_ctx *ctx;
    ctn_model *m;
    ctn_solution *s;
    int rc;            /* the first failure, CTN_OK if none */
} run;

/* Read text (as file `name`), resolve its targets and solve; a solve that ends
 * unconverged is a failed check. */
static run run_text(const char *name, const char *text)
{
    run r = { NULL, NULL, NULL, 0 };
    ctn_solve_options opt;
    ctn_ctx_create(&r.ctx);
    r.rc = ctn_read_string(r.ctx, name, text, strlen(text), &r.m, &opt);
    if (!r.rc) r.rc = ctn_model_resolve_targets(r.ctx, r.m, &opt, NULL);
    if (!r.rc) r.rc = ctn_solve(r.ctx, r.m, &opt, &r.s);
    if (!r.rc) {
        ctn_solve_summary sum;
        ctn_solution_summary(r.s, &sum);
        CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
    }
    return r;
}

static void done(run *r)
{
    ctn_solution_destroy(&r->s);
    ctn_model_destroy(&r->m);
    ctn_ctx_destroy(&r->ctx);
}

#endif
