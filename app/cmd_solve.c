/* catena solve MODEL [--json] [-o DIR] [-q] */
#include "app.h"

#include <string.h>


/* The results: files with -o, then JSON or the summary on stdout, checked. Exit code. */
static int emit(ctn_ctx *ctx, const ctn_model_args *a, const ctn_model *m, const ctn_solution *s)
{
    int rc = a->outdir ? ctn_write_results(ctx, a->outdir, m, s) : CTN_OK;
    if (!rc && a->json) {
        rc = ctn_write_json(ctx, stdout, m, s, 1);
        if (!rc) putchar('\n');
    } else if (!rc && !a->quiet) {
        ctn_print_summary(stdout, m, s);
    }
    return rc ? ctn_app_fail(ctx, rc) : ctn_app_flush(stdout, "stdout");
}

static const char *method_title(ctn_method m)
{
    return m == CTN_METHOD_NEWTON ? "Newton-Raphson" : m == CTN_METHOD_ARCLENGTH ? "arc-length" : "Newton (auto)";
}

/* The lengths found for cables set by a target, a line each. */
static void print_targets(const ctn_model *m)
{
    static const char *const key[] = { "length", "H", "sag", "tension" };
    for (size_t i = 0; i < ctn_model_cable_count(m); i++) {
        ctn_cable_info c;
        ctn_node_info a, b;
        if (ctn_model_cable(m, i, &c) || c.target == CTN_TARGET_NONE || ctn_model_node(m, (size_t)c.node[0], &a) ||
            ctn_model_node(m, (size_t)c.node[1], &b))
            continue;
        printf("cable %d-%d: %s=%g reached (%.12g), length found %.12g %s (%d outer iterations)\n", a.id, b.id,
               key[c.target], c.target_value, c.target_achieved, c.length, ctn_model_length_unit(m), c.target_iterations);
    }
}

int ctn_cmd_solve(int argc, char **argv)
{
    ctn_model_args a;
    if (ctn_app_model_args("solve", argc, argv, &a)) return CTN_EXIT_USAGE;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    if (ctn_ctx_create(&ctx)) {
        fprintf(stderr, "catena: out of memory\n");
        return CTN_EXIT_IO;
    }
    ctn_solve_options opt;
    int rc = ctn_read_file(ctx, a.model, &m, &opt), code = CTN_EXIT_OK;
    ctn_iter_log iters = { stdout, { 0, 0 } };
    if (!rc) rc = ctn_model_resolve_targets(ctx, m, &opt, NULL);
    if (!rc && !a.json && !a.quiet) print_targets(m);
    if (!rc) {
        if (!a.json && !a.quiet) {
            opt.monitor = ctn_print_iteration;
            opt.monitor_data = &iters;
            printf("%s: %zu nodes, %zu elements\n", a.model, ctn_model_node_count(m), ctn_model_element_count(m));
            printf("%-16s it  |f_ext - f_int|   |dd|        order\n", method_title(opt.method));
        }
        size_t nq = ctn_model_force_density_count(m);
        if (nq) fprintf(stderr, "catena: %s: note: %zu member%s carr%s q= or force=, which only `catena formfind` uses; "
                        "solve uses their l0\n", a.model, nq, nq == 1 ? "" : "s", nq == 1 ? "ies" : "y");
        rc = ctn_solve(ctx, m, &opt, &s);
    }
    if (rc) code = ctn_app_fail(ctx, rc);
    else if (!(code = emit(ctx, &a, m, s))) {
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        code = sum.reason == CTN_CONVERGED ? CTN_EXIT_OK : CTN_EXIT_NOCONV;
        if (code) fprintf(stderr, "catena: %s: not converged: %s\n", a.model, ctn_reason_name(sum.reason));
        if (code && sum.fail_element)
            fprintf(stderr, "catena: %s: element %d could not be evaluated at the last state tried (a chord of zero "
                            "length, or a catenary whose forces are beyond double precision)\n", a.model, sum.fail_element);
        else ctn_print_stability(stderr, a.model, s);
        ctn_print_warnings(stderr, a.model, m, s);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return code;
}
