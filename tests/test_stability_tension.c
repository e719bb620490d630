/* Stability shown by tension, without a factorization (src/solve/stability_tension.c):
 * - every example whose solve showed it so is stable by the LL'/LDL' inertia as well
 *   (the argument never claims what a factorization would deny), and it is shown on the
 *   nets and cables among them;
 * - a prestressed hypar net: shown by tension;
 * - a mast in compression, a node held only by unstressed springs: not shown by tension
 *   (a member not semi-definite, a DOF tied by no member in tension), left to the
 *   factorization, which finds them stable;
 * - a node held only by a slack member: left to the factorization, which names it. */
#include "catena.h"
#include "check.h"
#include "files.h"
#include "slack_model.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct outcome {
    int converged;
    ctn_stability rec;        /* what the solve recorded */
    ctn_stability fact;       /* ctn_problem_stability: always by a factorization */
} outcome;

static outcome solve_model(ctn_ctx *ctx, ctn_model *m, ctn_solve_options *opt)
{
    outcome o;
    memset(&o, 0, sizeof o);
    ctn_problem *p = NULL;
    ctn_solution *s = NULL;
    opt->modal.count = 0;                           /* modes would want the check's factor */
    int rc = ctn_model_resolve_targets(ctx, m, opt, NULL);
    if (!rc) rc = ctn_problem_create(ctx, m, opt, &p);
    if (!rc) rc = ctn_problem_solve(p, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (s) {
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        o.converged = sum.reason == CTN_CONVERGED && ctn_solution_stability(s, &o.rec) == CTN_OK;
        if (o.converged) CHECK(ctn_problem_stability(p, s, &o.fact) == CTN_OK);
    }
    ctn_solution_destroy(&s);
    ctn_problem_destroy(&p);
    return o;
}

static outcome solve_text(const char *text)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "test.cable", text, strlen(text), &m, &opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    outcome o;
    memset(&o, 0, sizeof o);
    if (!rc) o = solve_model(ctx, m, &opt);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return o;
}

typedef struct tally {
    int shown, stable;
} tally;

static void visit(const char *path, void *data)
{
    tally *t = data;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_file(ctx, path, &m, &opt);
    CHECK_MSG(rc == CTN_OK, "%s: %s", path, ctn_ctx_message(ctx));
    outcome o;
    memset(&o, 0, sizeof o);
    if (!rc) o = solve_model(ctx, m, &opt);
    if (o.converged) {
        CHECK_MSG(o.rec.stable == o.fact.stable, "%s: recorded %d, factorization %d", path, o.rec.stable,
                  o.fact.stable);
        CHECK_MSG(!o.rec.by_tension || (o.fact.stable && o.fact.negative == 0), "%s", path);
        t->shown += o.rec.by_tension;
        t->stable += o.fact.stable;
    }
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_examples(void)
{
    const char *dirs[] = { "examples/paper", "examples/robust", "examples/springs", "examples/catenary",
                           "examples/design", "examples/formfind" };
    tally t = { 0, 0 };
    each_example(dirs, sizeof dirs / sizeof *dirs, visit, &t);
    printf("examples: %d stable, %d of them shown by tension\n", t.stable, t.shown);
    CHECK_MSG(t.shown >= 8, "%d", t.shown);
}

/* An n x n hypar net (z = (x^2 - y^2) / 50 on a 20 m square), its members 0.2 % short,
 * boundary pinned, interior nodes loaded down. */
static char *hypar_text(int n)
{
    size_t cap = 4096 + (size_t)n * (size_t)n * 200;
    char *t = malloc(cap);
    if (!t) return NULL;
    size_t k = (size_t)snprintf(t, cap, "material rope E=1.6e8 tension-only\nsection s material=rope A=1e-4\n");
    double h = 20.0 / n;
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            double x = -10 + i * h, y = -10 + j * h;
            int edge = i == 0 || j == 0 || i == n || j == n;
            k += (size_t)snprintf(t + k, cap - k, "node %d %.10g %.10g %.10g%s\n", i * (n + 1) + j + 1, x, y,
                                  (x * x - y * y) / 50, edge ? " fix=xyz" : "");
            if (!edge) k += (size_t)snprintf(t + k, cap - k, "load %d 0 0 -0.5\n", i * (n + 1) + j + 1);
        }
    int id = 1;
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            int a = i * (n + 1) + j + 1;
            double xa = -10 + i * h, ya = -10 + j * h, za = (xa * xa - ya * ya) / 50;
            for (int dir = 0; dir < 2; dir++) {
                int i2 = i + (dir == 0), j2 = j + (dir == 1);
                if (i2 > n || j2 > n || ((i == 0 || i == n) && dir == 1) || ((j == 0 || j == n) && dir == 0))
                    continue;                       /* no members along the pinned edges */
                double xb = -10 + i2 * h, yb = -10 + j2 * h, zb = (xb * xb - yb * yb) / 50;
                double l = sqrt((xb - xa) * (xb - xa) + (yb - ya) * (yb - ya) + (zb - za) * (zb - za));
                k += (size_t)snprintf(t + k, cap - k, "element %d %d %d section=s l0=%.12g\n", id++, a,
                                      i2 * (n + 1) + j2 + 1, 0.998 * l);
            }
        }
    return t;
}

static void test_net(void)
{
    char *t = hypar_text(8);
    CHECK(t != NULL);
    if (!t) return;
    outcome o = solve_text(t);
    CHECK(o.converged && o.rec.stable && o.rec.by_tension && o.fact.stable);
    free(t);
}

/* A mast in compression held by four guys: stable, but its member's tangent is not
 * semi-definite (N < 0), so only a factorization can tell. */
static const char *mast_text =
    "material steel E=2.1e8\n"
    "material rope E=1.6e8 tension-only\n"
    "section mast material=steel A=5e-3\n"
    "section guy material=rope A=2e-4\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 0 0 30\n"
    "node 3 -20 0 0 fix=xyz\n"
    "node 4 20 0 0 fix=xyz\n"
    "node 5 0 -20 0 fix=xyz\n"
    "node 6 0 20 0 fix=xyz\n"
    "element 1 1 2 section=mast\n"
    "element 2 2 3 section=guy l0=36.0\n"
    "element 3 2 4 section=guy l0=36.0\n"
    "element 4 2 5 section=guy l0=36.0\n"
    "element 5 2 6 section=guy l0=36.0\n"
    "load 2 1 0 -50\n";

/* A taut cable, and node 4 held by three unstressed springs along x, y and z: stable,
 * but its DOFs are tied to the supports by no member in tension. */
static const char *springs_text =
    "material rope E=1e8 tension-only\n"
    "section s material=rope A=1e-4\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 10 0 0\n"
    "node 3 20 0 0 fix=xyz\n"
    "node 4 10 5 5\n"
    "node 5 11 5 5 fix=xyz\n"
    "node 6 10 6 5 fix=xyz\n"
    "node 7 10 5 6 fix=xyz\n"
    "element 1 1 2 section=s l0=9.99\n"
    "element 2 2 3 section=s l0=9.99\n"
    "spring 3 4 5 k=100\n"
    "spring 4 4 6 k=100\n"
    "spring 5 4 7 k=100\n"
    "load 2 0 0 -1\n";

static void test_left_to_factorization(void)
{
    outcome o = solve_text(mast_text);
    CHECK_MSG(o.converged && o.rec.stable && !o.rec.by_tension && o.fact.stable, "mast %d %d %d", o.rec.stable,
              o.rec.by_tension, o.fact.stable);
    o = solve_text(springs_text);
    CHECK_MSG(o.converged && o.rec.stable && !o.rec.by_tension && o.fact.stable, "springs %d %d %d",
              o.rec.stable, o.rec.by_tension, o.fact.stable);
    o = solve_text(slack_text);
    CHECK_MSG(o.converged && !o.rec.stable && !o.rec.by_tension && o.rec.semidefinite && o.rec.node == 4,
              "slack %d %d %d", o.rec.stable, o.rec.semidefinite, o.rec.node);
}

int main(void)
{
    test_examples();
    test_net();
    test_left_to_factorization();
    CHECK_DONE();
}
