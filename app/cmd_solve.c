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
    if (!rc) {
        if (!a.json && !a.quiet) {
            opt.monitor = ctn_print_iteration;
            opt.monitor_data = &iters;
            printf("%s: %zu nodes, %zu elements\n", a.model, ctn_model_node_count(m), ctn_model_element_count(m));
            printf("%-16s it  |f_ext - f_int|   |dd|        order\n", method_title(opt.method));
        }
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
