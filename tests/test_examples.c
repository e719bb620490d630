/* Examples double as regression tests: every examples/<dir>/<name>.cable is solved with
 * its own options and checked against its "#@ key values..." lines:
 *   converged 0|1            max_iterations N        steps N        slack N
 *   max_force V rtol         min_force V rtol        sag V rtol     (first cable)
 *   step_force K E V atol    (element index E at step K)
 *   load_factor_min V rtol   load_factor_max V rtol  (over the steps)
 *   load_factor V rtol       (where the run ended)
 *   buckling K V rtol        (buckling factor K, 1-based)
 * and, when converged and not arc-length, the reactions must balance the loads (to
 * round-off of the largest force, or reaction moment over the model's extent). */
#include "catena.h"
#include "check.h"
#include "files.h"

#include <dirent.h>
#include <stdlib.h>

static double force_extreme(const ctn_model *m, const ctn_solution *s, int want_max)
{
    double v = want_max ? -INFINITY : INFINITY;
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_state st;
        ctn_solution_element(s, e, &st);
        v = want_max ? fmax(v, st.force) : fmin(v, st.force);
    }
    return v;
}

static double load_factor_extreme(const ctn_solution *s, int want_max)
{
    double v = want_max ? -INFINITY : INFINITY;
    for (size_t k = 0; k < ctn_solution_step_count(s); k++) {
        ctn_step_result st;
        ctn_solution_step(s, k, &st);
        v = want_max ? fmax(v, st.load_factor) : fmin(v, st.load_factor);
    }
    return v;
}

static void check_balance(const char *path, const ctn_model *m, const ctn_solution *s)
{
    size_t n3 = 3 * ctn_model_node_count(m);
    double *f = calloc(n3, sizeof(double)), sum[3] = { 0, 0, 0 }, scale = 0;
    const double *r = ctn_solution_reactions(s);
    ctn_model_external_forces(m, f);
    const double *mo = ctn_solution_reaction_moments(s);   /* a model with rotations: */
    double extent = 0;                                       /* moments over its size */
    for (size_t i = 0; i < n3; i++) {
        ctn_node_info ni;
        ctn_model_node(m, i / 3, &ni);
        extent = fmax(extent, fabs(ni.X[i % 3]));
    }
    for (size_t i = 0; i < n3; i++) {
        sum[i % 3] += f[i] + r[i];
        scale = fmax(scale, fabs(f[i]) + fabs(r[i]) + (mo && extent > 0 ? fabs(mo[i]) / extent : 0));
    }
    for (int k = 0; k < 3; k++) CHECK_MSG(fabs(sum[k]) <= 1e-9 * scale, "%s: reactions off balance by %g", path, sum[k]);
    free(f);
}

/* One "#@" line. */
static void check_line(const char *path, const char *line, const ctn_model *m, const ctn_solution *s)
{
    char key[32];
    double a = 0, b = 0, c = 0, d = 0;
    int n = sscanf(line, "#@ %31s %lf %lf %lf %lf", key, &a, &b, &c, &d);
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    CHECK_MSG(n >= 2, "%s: bad expectation line '%s'", path, line);
    if (n < 2) return;
    if (!strcmp(key, "converged")) CHECK_MSG((sum.reason == CTN_CONVERGED) == (a != 0), "%s: %s", path, ctn_reason_name(sum.reason));
    else if (!strcmp(key, "max_iterations")) CHECK_MSG(sum.iterations <= a, "%s: %d iterations", path, sum.iterations);
    else if (!strcmp(key, "steps")) CHECK_MSG(ctn_solution_step_count(s) == (size_t)a, "%s: %zu steps", path, ctn_solution_step_count(s));
    else if (!strcmp(key, "max_force")) CHECK_CLOSE(force_extreme(m, s, 1), a, b, 0);
    else if (!strcmp(key, "min_force")) CHECK_CLOSE(force_extreme(m, s, 0), a, b, 0);
    else if (!strcmp(key, "load_factor_min")) CHECK_CLOSE(load_factor_extreme(s, 0), a, b, 0);
    else if (!strcmp(key, "load_factor_max")) CHECK_CLOSE(load_factor_extreme(s, 1), a, b, 0);
    else if (!strcmp(key, "load_factor")) CHECK_CLOSE(sum.load_factor, a, b, 0);
    else if (!strcmp(key, "sag")) {
        double sag = NAN;
        ctn_solution_cable_sag(m, s, 0, &sag);
        CHECK_CLOSE(sag, a, b, 0);
    } else if (!strcmp(key, "slack")) {
        size_t count = 0;
        for (size_t e = 0; e < ctn_model_element_count(m); e++) {
            ctn_element_state st;
            ctn_solution_element(s, e, &st);
            count += (size_t)st.slack;
        }
        CHECK_MSG(count == (size_t)a, "%s: %zu slack elements", path, count);
    } else if (!strcmp(key, "buckling") && n == 4) {
        ctn_buckling_mode bm;
        int ok = a >= 1 && ctn_solution_buckling(s, (size_t)a - 1, &bm) == CTN_OK;
        CHECK_MSG(ok, "%s: no buckling factor %g", path, a);
        if (ok) CHECK_CLOSE(bm.factor, b, c, 0);
    } else if (!strcmp(key, "step_force") && n == 5) {
        ctn_element_state st;
        CHECK(ctn_solution_step_element(s, (size_t)a, (size_t)b, &st) == CTN_OK);
        CHECK_CLOSE(st.force, c, 0, d);
    } else CHECK_MSG(0, "%s: unknown expectation '%s'", path, key);
}

static int run_example(const char *path)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_file(ctx, path, &m, &opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (!rc) rc = ctn_model_resolve_targets(ctx, m, &opt, NULL);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s: %s", path, ctn_ctx_message(ctx));
    int lines = 0;
    FILE *f = fopen(path, "r");
    char line[512];
    while (!rc && f && fgets(line, sizeof line, f))
        if (!strncmp(line, "#@", 2)) {
            line[strcspn(line, "\n")] = '\0';
            check_line(path, line, m, s);
            lines++;
        }
    if (f) fclose(f);
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    if (!rc && sum.reason == CTN_CONVERGED && opt.method != CTN_METHOD_ARCLENGTH) check_balance(path, m, s);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return lines;
}

static void visit(const char *path, void *data)
{
    (void)data;
    CHECK_MSG(run_example(path) > 0, "%s has no #@ expectation", path);
}

int main(void)
{
    const char *dirs[] = { "examples/paper", "examples/robust", "examples/springs", "examples/catenary", "examples/design",
                           "examples/beam", "examples/structures" };
    int files = each_example(dirs, sizeof dirs / sizeof *dirs, visit, NULL);
    CHECK(files >= 8);
    CHECK_DONE();
}
