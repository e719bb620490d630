/* Solver layer through the seams opened by the problem object:
 * - a problem outlives its solve: solving it twice gives the same bits, and the
 *   stability of the solution is asked of the same problem afterwards;
 * - stability: a stable cable; a mast held by two guys in one plane under a vertical load
 *   (an inverted pendulum out of plane: unstable, node and direction named); a node held
 *   only by slack members (semi-definite); the inertia count;
 * - the linear solvers by name: LDL' gives the same equilibrium as LL' on a definite
 *   problem; an unknown name is refused;
 * - the spring family solved against closed forms: a weight on a vertical spring, two
 *   springs in series, a spring as the elastic support of a cable (equilibrium);
 * - a node DOF map with mixed DOF counts (as a 6-DOF family would make);
 * - every allocation failure on the way (create, solve, stability): CTN_ERR_NOMEM, no leak. */
#include "assemble/dofmap.h"
#include "catena.h"
#include "check.h"
#include "slack_model.h"

#include <stdlib.h>

static ctn_model *read_model(ctn_ctx *ctx, const char *text, ctn_solve_options *opt)
{
    ctn_model *m = NULL;
    int rc = ctn_read_string(ctx, "test.cable", text, strlen(text), &m, opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    return m;
}

static const char *paper_text =
    "units kN m\n"
    "material steel E=2.0e8\n"
    "section strand material=steel A=3.14e-4 w=0.1\n"
    "gravity 0 -1 0\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 200 0 0 fix=xyz\n"
    "cable 1 2 section=strand n=20 length=250.8777 shape=arc\n"
    "solve method=newton tol=1e-10\n";

static void test_reuse(void)
{
    ctn_ctx *ctx = NULL;
    ctn_problem *p = NULL;
    ctn_solution *s1 = NULL, *s2 = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, paper_text, &opt);
    CHECK(opt.method == CTN_METHOD_NEWTON && opt.tol == 1e-10);   /* the file's solve line */
    CHECK(m && ctn_problem_create(ctx, m, &opt, &p) == CTN_OK);
    CHECK(p && ctn_problem_solve(p, &s1) == CTN_OK && ctn_problem_solve(p, &s2) == CTN_OK);
    if (s1 && s2) {
        size_t n3 = 3 * ctn_model_node_count(m);
        CHECK(!memcmp(ctn_solution_displacements(s1), ctn_solution_displacements(s2), n3 * sizeof(double)));
        ctn_solve_summary a, b;
        ctn_solution_summary(s1, &a);
        ctn_solution_summary(s2, &b);
        CHECK(a.reason == CTN_CONVERGED && a.iterations == b.iterations && a.iterations == 9);
        CHECK(a.factorizations == a.iterations && a.solves == a.iterations);   /* pure Newton */
        ctn_stability st;
        CHECK(ctn_problem_stability(p, s1, &st) == CTN_OK);
        CHECK(st.stable == 1 && st.negative == 0 && !st.semidefinite && st.node == 0 && st.dir == -1);
    }
    ctn_solution_destroy(&s1);
    ctn_solution_destroy(&s2);
    ctn_problem_destroy(&p);
    CHECK(p == NULL);
    ctn_problem_destroy(&p);                       /* harmless no-op */
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* A mast (a two-way bar) held at its top by two guys in the x-z plane, loaded down. */
static const char *mast_text =
    "material steel E=2.1e8\n"
    "material rope E=1.6e8 tension-only\n"
    "section mast material=steel A=5e-3\n"
    "section guy material=rope A=2e-4\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 0 0 30 \n"
    "node 3 -20 0 0 fix=xyz\n"
    "node 4 20 0 0 fix=xyz\n"
    "element 1 1 2 section=mast\n"
    "element 2 2 3 section=guy l0=36.0\n"
    "element 3 2 4 section=guy l0=36.0\n"
    "load 2 0 0 -50\n";

/* Solve text with a problem and ask it for the stability of the solution (which the
 * solve also recorded: both must agree). 0 on failure. */
static int stability_of(const char *text, ctn_stability *st)
{
    ctn_ctx *ctx = NULL;
    ctn_problem *p = NULL;
    ctn_solution *s = NULL;
    ctn_solve_summary sum;
    ctn_stability rec;
    int ok = 0;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, text, NULL);
    CHECK(m && ctn_problem_create(ctx, m, NULL, &p) == CTN_OK && ctn_problem_solve(p, &s) == CTN_OK);
    if (s) {
        ctn_solution_summary(s, &sum);
        CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
        ok = ctn_problem_stability(p, s, st) == CTN_OK;
        CHECK(ok && ctn_solution_stability(s, &rec) == CTN_OK && rec.stable == st->stable && sum.stable == st->stable);
    }
    ctn_solution_destroy(&s);
    ctn_problem_destroy(&p);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return ok;
}

static void test_unstable_mast(void)
{
    ctn_stability st;
    if (!stability_of(mast_text, &st)) return;
    CHECK_MSG(!st.stable && st.negative == 1 && !st.semidefinite, "stable %d negative %ld", st.stable, st.negative);
    CHECK_MSG(st.node == 2 && st.dir == 1, "node %d dir %d", st.node, st.dir);    /* top, out of plane */
}

static void test_semidefinite(void)
{
    ctn_stability st;
    if (!stability_of(slack_text, &st)) return;
    CHECK_MSG(!st.stable && st.semidefinite && st.node == 4, "stable %d semidefinite %d node %d", st.stable,
              st.semidefinite, st.node);
}

static void test_linear_solvers(void)
{
    ctn_ctx *ctx = NULL;
    ctn_solution *a = NULL, *b = NULL;
    ctn_problem *p = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, paper_text, &opt);
    CHECK(m && ctn_solve(ctx, m, &opt, &a) == CTN_OK);
    opt.linear_solver = "cholmod-ldl";
    CHECK(m && ctn_solve(ctx, m, &opt, &b) == CTN_OK);
    if (a && b) {
        const double *da = ctn_solution_displacements(a), *db = ctn_solution_displacements(b);
        double err = 0, dmax = 0;
        for (size_t i = 0; i < 3 * ctn_model_node_count(m); i++) {
            err = fmax(err, fabs(da[i] - db[i]));
            dmax = fmax(dmax, fabs(da[i]));
        }
        CHECK_MSG(err <= 1e-9 * dmax, "LL' and LDL' differ by %g", err);
    }
    opt.linear_solver = "mumps";
    CHECK(ctn_problem_create(ctx, m, &opt, &p) == CTN_ERR_INVALID && p == NULL);
    CHECK(strstr(ctn_ctx_message(ctx), "unknown linear solver 'mumps'") != NULL);
    ctn_solution_destroy(&a);
    ctn_solution_destroy(&b);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* The z displacement of node id in s. */
static double uz(const ctn_model *m, const ctn_solution *s, int id)
{
    size_t i;
    return ctn_model_node_index(m, id, &i) ? NAN : ctn_solution_displacements(s)[3 * i + 2];
}

static void test_springs(void)
{
    ctn_ctx *ctx = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    /* a weight W on a vertical spring k of free length 2 (given 2.5 apart: l0 given) and,
     * in series, two springs k1, k2 holding W: stretches W/k and W (1/k1 + 1/k2) */
    const char *text = "node 1 0 0 0 fix=xyz\n"
                       "node 2 0 0 -2.5 fix=xy\n"
                       "spring 1 1 2 k=400 l0=2\n"
                       "load 2 0 0 -30\n"
                       "node 3 5 0 0 fix=xyz\n"
                       "node 4 5 0 -1 fix=xy\n"
                       "node 5 5 0 -2 fix=xy\n"
                       "spring 2 3 4 k=100\n"
                       "spring 3 4 5 k=300\n"
                       "load 5 0 0 -12\n";
    ctn_model *m = read_model(ctx, text, NULL);
    CHECK(m && ctn_solve(ctx, m, NULL, &s) == CTN_OK);
    if (s) {
        ctn_element_state es;
        ctn_element_info info;
        CHECK_CLOSE(uz(m, s, 2), -(2.0 + 30.0 / 400 - 2.5), 1e-12, 1e-14);
        CHECK_CLOSE(uz(m, s, 5), -12.0 * (1.0 / 100 + 1.0 / 300), 1e-12, 1e-14);
        CHECK(ctn_solution_element(s, 0, &es) == CTN_OK && ctn_model_element(m, 0, &info) == CTN_OK);
        CHECK_CLOSE(es.force, 30.0, 1e-12, 0);
        CHECK(!strcmp(info.type, "spring") && info.k == 400 && info.l0 == 2 && !info.has_section);
        CHECK(es.stress == 0 && !es.slack);
        const double *r = ctn_solution_reactions(s);
        CHECK_CLOSE(r[2], 30.0, 1e-12, 0);                      /* node 1 holds the weight */
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* A spring as the elastic support of a cable: the reactions balance the weight and the
 * spring's force is the cable's end tension along it. */
static void test_spring_support(void)
{
    ctn_ctx *ctx = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    const char *text = "material steel E=2e8\n"
                       "section c material=steel A=1e-4 w=0.2\n"
                       "gravity 0 0 -1\n"
                       "node 1 0 0 0 fix=xyz\n"
                       "node 2 40 0 0 fix=yz\n"
                       "node 3 41 0 0 fix=xyz\n"
                       "cable 1 2 section=c n=16 length=41\n"
                       "spring 100 2 3 k=50\n";
    ctn_model *m = read_model(ctx, text, NULL);
    CHECK(m && ctn_solve(ctx, m, NULL, &s) == CTN_OK);
    if (s) {
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        CHECK(sum.reason == CTN_CONVERGED);
        const double *r = ctn_solution_reactions(s);
        double rz = 0, rx = 0;
        for (size_t i = 0; i < ctn_model_node_count(m); i++) {
            rz += r[3 * i + 2];
            rx += r[3 * i];
        }
        CHECK_CLOSE(rz, 0.2 * 41, 1e-10, 0);                     /* the weight */
        CHECK(fabs(rx) <= 1e-9 * 0.2 * 41);
        ctn_element_state sp, last;
        size_t ne = ctn_model_element_count(m);
        CHECK(ctn_solution_element(s, ne - 1, &sp) == CTN_OK && ctn_solution_element(s, ne - 2, &last) == CTN_OK);
        /* node 2 slides in x only: the spring's force = the x part of the cable's end
         * tension (its last element's force along its current direction) */
        ctn_element_info li;
        ctn_node_info a, b;
        ctn_model_element(m, ne - 2, &li);
        ctn_model_node(m, (size_t)li.nodes[0], &a);
        ctn_model_node(m, (size_t)li.nodes[1], &b);
        const double *d = ctn_solution_displacements(s);
        double dx = (b.X[0] + d[3 * (size_t)li.nodes[1]]) - (a.X[0] + d[3 * (size_t)li.nodes[0]]);
        CHECK(b.id == 2);
        CHECK_CLOSE(sp.force, last.force * dx / last.length, 1e-9, 0);
        CHECK(sp.force > 0 && sp.length > 1.0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* The DOF map with nodes of 3 and 6 DOFs: layout, numbering and conversions. */
static void test_mixed_dofmap(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_dofmap map;
    double X[3] = { 0, 0, 0 };
    unsigned char nd[3] = { 3, 6, 3 };
    ctn_ctx_create(&ctx);
    ctn_model_create(ctx, &m);
    ctn_model_add_node(m, 1, X, CTN_FIX_ALL);
    X[0] = 1;
    ctn_model_add_node(m, 2, X, CTN_FIX_Z);
    X[0] = 2;
    ctn_model_add_node(m, 3, X, 0);
    CHECK(ctn_dofmap_build(ctx, m, nd, &map) == CTN_OK);
    CHECK(map.uniform == 0 && map.nstate == 12 && map.ndof == 8);
    CHECK(ctn_dofmap_node(&map, 1) == 3 && ctn_dofmap_count(&map, 1) == 6 && ctn_dofmap_node(&map, 2) == 9);
    CHECK(map.eq[3] == 0 && map.eq[4] == 1 && map.eq[5] == -1 && map.eq[6] == 2 && map.eq[11] == 7);
    CHECK(map.dof_node[2] == 1 && map.dof_dir[2] == 3 && map.dof_node[7] == 2 && map.dof_dir[7] == 2);
    double v3[9] = { 1, 2, 3, 4, 5, 6, 7, 8, 9 }, st[12], back[9];
    ctn_dofmap_from3(&map, v3, st);
    CHECK(st[3] == 4 && st[5] == 6 && st[6] == 0 && st[8] == 0 && st[9] == 7);
    ctn_dofmap_to3(&map, st, back);
    CHECK(!memcmp(v3, back, sizeof v3));
    ctn_dofmap_free(&map);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Every allocation failure from create to stability: NOMEM and nothing leaked. */
static void test_alloc(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx, mast_text, NULL);
    int done = 0, failures = 0;
    for (long k = 1; k < 100000 && m && !done; k++) {
        ctn_problem *p = NULL;
        ctn_solution *s = NULL;
        ctn_stability st;
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_problem_create(ctx, m, NULL, &p);
        if (!rc) rc = ctn_problem_solve(p, &s);
        if (!rc) rc = ctn_problem_stability(p, s, &st);
        ctn_ctx_fail_alloc_at(ctx, 0);
        if (rc) {
            failures++;
            CHECK_MSG(rc == CTN_ERR_NOMEM, "allocation %ld: status %d (%s)", k, rc, ctn_ctx_message(ctx));
        } else {
            done = 1;
        }
        ctn_solution_destroy(&s);
        ctn_problem_destroy(&p);
    }
    CHECK(done && failures > 10);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_reuse();
    test_unstable_mast();
    test_semidefinite();
    test_linear_solvers();
    test_springs();
    test_spring_support();
    test_mixed_dofmap();
    test_alloc();
    CHECK_DONE();
}
