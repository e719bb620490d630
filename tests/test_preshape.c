/* Pre-shaping chains (solve/preshape.c) whose two anchors are one node: a loop of cable
 * hung from a single support (found by the fuzz harness: the chain's node list held one
 * node more than the model has). Two and four members, each method: the solve ends with
 * a status, and where it converges the loop hangs below its support and the reaction
 * carries its weight. */
#include "model/model.h"
#include "catena.h"
#include "check.h"

#include <math.h>
#include <string.h>

static const char *loop2 =
    "units kN m\n"
    "material m E=1e7\n"
    "section s material=m A=1e-3 w=0.1\n"
    "gravity 0 -1 0\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 3 2 -1 0\n"
    "element 1 1 3 section=s l0=2.5\n"
    "element 2 3 1 section=s l0=2.5\n";

static const char *loop4 =
    "units kN m\n"
    "material m E=1e7\n"
    "section s material=m A=1e-3 w=0.1\n"
    "gravity 0 -1 0\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 1 -1 0.2\n"
    "node 3 0 -2 0\n"
    "node 4 -1 -1 -0.2\n"
    "element 1 1 2 section=s l0=1.5\n"
    "element 2 2 3 section=s l0=1.5\n"
    "element 3 3 4 section=s l0=1.5\n"
    "element 4 4 1 section=s l0=1.5\n";

static void run(const char *text, const char *name)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    CHECK(!ctn_ctx_create(&ctx));
    CHECK_MSG(!ctn_read_string(ctx, name, text, strlen(text), &m, NULL), "%s: %s", name, ctn_ctx_message(ctx));
    static const ctn_method methods[] = { CTN_METHOD_AUTO, CTN_METHOD_NEWTON };
    for (size_t k = 0; m && k < sizeof methods / sizeof *methods; k++) {
        ctn_solve_options opt;
        ctn_solve_options_default(&opt);
        opt.method = methods[k];
        ctn_solution *s = NULL;
        int rc = ctn_solve(ctx, m, &opt, &s);
        CHECK_MSG(rc == CTN_OK || *ctn_ctx_message(ctx), "%s: a failure without a message", name);
        ctn_solve_summary sum;
        if (!rc && s) ctn_solution_summary(s, &sum);
        if (!rc && s && sum.reason == CTN_CONVERGED) {
            const double *u = ctn_solution_displacements(s);
            double W = 0, R = 0;
            for (size_t e = 0; e < m->elements.n; e++) W += 0.1 * m->elements.v[e].l0;
            for (size_t i = 1; i < m->nodes.n; i++)                 /* below the support */
                CHECK_MSG(m->nodes.v[i].X[1] + u[3 * i + 1] < 0, "%s: node %zu above its support", name, i);
            R = ctn_solution_reactions(s)[1];
            CHECK_CLOSE(R, W, 1e-8, 0);
        }
        ctn_solution_destroy(&s);
        ctn_ctx_clear(ctx);
    }
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    run(loop2, "loop2.cable");
    run(loop4, "loop4.cable");
    CHECK_DONE();
}
