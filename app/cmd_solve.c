/* catena solve MODEL [--json] [-o DIR] [-q] [--reactions N|all] */
#include "app.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Take `--reactions N|all` out of argv (the rest are the shared model options): the
 * most reaction rows of the summary in *limit (-1: all). 0, or 1 after a message. */
static int take_reactions(int *argc, char **argv, long *limit)
{
    *limit = CTN_APP_REACTIONS;
    for (int i = 1; i < *argc; i++) {
        if (strcmp(argv[i], "--reactions")) continue;
        const char *v = i + 1 < *argc ? argv[i + 1] : "";
        long n = -1;
        if (strcmp(v, "all")) {
            char *end;
            errno = 0;
            n = strtol(v, &end, 10);
            if (end == v || *end || n < 0 || errno) {
                fprintf(stderr, "catena solve: --reactions takes a count or 'all' (found '%s')\n", v);
                return 1;
            }
        }
        *limit = n;
        for (int j = i; j + 2 <= *argc; j++) argv[j] = argv[j + 2];
        *argc -= 2;
        i--;
    }
    return 0;
}

/* What the solve monitor feeds: the iteration log (when printed) and the progress line
 * (when the log is not on a terminal already). */
typedef struct solve_monitor {
    ctn_iter_log log;
    int log_on, progress_on;
    ctn_app_progress *progress;
} solve_monitor;

static void monitor(void *data, const ctn_iterate *it)
{
    solve_monitor *sm = data;
    if (sm->log_on) ctn_print_iteration(&sm->log, it);
    if (sm->progress_on) ctn_app_progress_iteration(sm->progress, it);
}

/* The results: files with -o, then JSON or the summary on stdout, checked. Exit code. */
static int emit(ctn_ctx *ctx, const ctn_model_args *a, const ctn_model *m, const ctn_solution *s,
                ctn_app_progress *progress)
{
    /* A result the writers would refuse is refused in every output mode alike: the
     * same message, naming the model, and the same exit code (3: the solve failed). */
    if (ctn_result_check(ctx, m, s)) {
        ctn_app_progress_done(progress);
        ctn_app_fail_model(ctx, CTN_ERR_INVALID, a->model);
        return CTN_EXIT_NOCONV;
    }
    ctn_app_progress_phase(progress, "writing");
    /* rank 0 writes the set; in a job of several ranks every rank its VTU piece */
    int rc = a->outdir && (ctn_app_mpi_rank() == 0 || ctn_app_mpi_size() > 1) ? ctn_write_results(ctx, a->outdir, m, s) : CTN_OK;
    ctn_app_progress_done(progress);
    ctn_ctx_set_progress(ctx, NULL, NULL);          /* stdout may share the terminal */
    if (!rc && a->json) {
        rc = ctn_write_json(ctx, stdout, m, s, 1);
        if (!rc) putchar('\n');
    } else if (!rc && !a->quiet) {
        ctn_print_summary(stdout, m, s);
        ctn_print_reactions(stdout, m, s, a->reactions);
    }
    return rc ? ctn_app_fail(ctx, rc) : ctn_app_flush(stdout, "stdout");
}

static const char *method_title(ctn_method m)
{
    return m == CTN_METHOD_NEWTON ? "Newton-Raphson" : m == CTN_METHOD_ARCLENGTH ? "arc-length" : "Newton (auto)";
}

/* The lengths found for cables and catenary elements set by a target, a line each. */
static void print_targets(const ctn_model *m)
{
    static const char *const key[] = { "length", "H", "sag", "tension" };
    size_t nc = ctn_model_cable_count(m), ne = ctn_model_element_count(m);
    for (size_t i = 0; i < nc + ne; i++) {
        ctn_cable_info c;
        ctn_element_info e;
        ctn_node_info a, b;
        if ((i < nc ? ctn_model_cable(m, i, &c) : ctn_model_element_target(m, i - nc, &c)) || c.target == CTN_TARGET_NONE ||
            ctn_model_node(m, (size_t)c.node[0], &a) || ctn_model_node(m, (size_t)c.node[1], &b))
            continue;
        if (i < nc) printf("cable %d-%d", a.id, b.id);
        else if (!ctn_model_element(m, i - nc, &e)) printf("catenary %d (nodes %d-%d)", e.id, a.id, b.id);
        printf(": %s=%g reached (%.12g), length found %.12g %s (%d outer iterations)\n", key[c.target], c.target_value,
               c.target_achieved, c.length, ctn_model_length_unit(m), c.target_iterations);
    }
}

int ctn_cmd_solve(int argc, char **argv)
{
    ctn_model_args a;
    long reactions;
    if (take_reactions(&argc, argv, &reactions) || ctn_app_model_args("solve", argc, argv, &a)) return CTN_EXIT_USAGE;
    a.reactions = reactions;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    if (ctn_app_ctx_create(&ctx)) {
        fprintf(stderr, "catena: out of memory\n");
        return CTN_EXIT_IO;
    }
    ctn_solve_options opt;
    ctn_app_progress progress;
    ctn_app_progress_init(&progress);
    ctn_ctx_set_progress(ctx, ctn_app_progress_report, &progress);
    int rc = ctn_read_file(ctx, a.model, &m, &opt), code = CTN_EXIT_OK;
    ctn_app_progress_done(&progress);
    solve_monitor sm = { { stdout, { 0, 0 } }, !a.json && !a.quiet, 0, &progress };
    sm.progress_on = !sm.log_on || !isatty(STDOUT_FILENO);
    if (!rc) rc = ctn_model_validate(m);   /* a bad model prints no summary header before its error */
    if (!rc) rc = ctn_model_resolve_targets(ctx, m, &opt, NULL);
    if (!rc && !a.json && !a.quiet) print_targets(m);
    if (!rc) {
        opt.monitor = monitor;
        opt.monitor_data = &sm;
        if (sm.log_on) {
            printf("%s: %zu nodes, %zu elements\n", a.model, ctn_model_node_count(m), ctn_model_element_count(m));
            printf("%-16s it  |f_ext - f_int|   |dd|        order\n", method_title(opt.method));
        }
        size_t nq = ctn_model_force_density_count(m);
        if (nq) fprintf(stderr, "catena: %s: note: %zu member%s carr%s q= or force=, which only `catena formfind` uses; "
                        "solve uses their l0\n", a.model, nq, nq == 1 ? "" : "s", nq == 1 ? "ies" : "y");
        ctn_app_progress_phase(&progress, "solving");
        rc = ctn_solve(ctx, m, &opt, &s);
        ctn_app_progress_done(&progress);
    }
    if (rc) code = ctn_app_fail(ctx, rc);
    else ctn_app_mpi_report(s);
    if (!rc && !(code = emit(ctx, &a, m, s, &progress))) {
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        code = sum.reason == CTN_CONVERGED ? CTN_EXIT_OK : CTN_EXIT_NOCONV;
        if (code) fprintf(stderr, "catena: %s: not converged: %s\n", a.model, ctn_reason_name(sum.reason));
        if (code) ctn_print_dynamics_failure(stderr, a.model, s);
        const char *failed = NULL;
        if (!code && !ctn_cases_converged(s, &failed)) {
            code = CTN_EXIT_NOCONV;
            fprintf(stderr, "catena: %s: load case '%s' not converged (its last converged state is written)\n", a.model,
                    failed);
        }
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
