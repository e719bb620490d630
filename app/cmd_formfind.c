/* catena formfind MODEL [-o OUT] [--tol T] [--maxit N] [-q] */
#include "app.h"

#include <stdlib.h>
#include <string.h>

typedef struct ff_args {
    const char *model, *out;
    int quiet;
    ctn_formfind_options opt;
} ff_args;

/* A number option's value; 0, or 1 after a message. */
static int number(const char *opt, const char *v, double lo, double *out)
{
    char *end = NULL;
    double x = v ? strtod(v, &end) : 0;
    if (v && *v && end && !*end && x >= lo && x < 1e300) {
        *out = x;
        return 0;
    }
    fprintf(stderr, "catena formfind: %s takes a number >= %g (found '%s')\n", opt, lo, v ? v : "");
    return 1;
}

static int parse_args(int argc, char **argv, ff_args *a)
{
    memset(a, 0, sizeof *a);
    ctn_formfind_options_init(&a->opt);
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        double x = 0;
        if (!strcmp(s, "-q") || !strcmp(s, "--quiet")) a->quiet = 1;
        else if (!strcmp(s, "-o") && v) a->out = argv[++i];
        else if (!strcmp(s, "--tol") && v) {
            if (number(s, argv[++i], 1e-300, &a->opt.tol)) return 1;
        } else if (!strcmp(s, "--maxit") && v) {
            if (number(s, argv[++i], 1, &x) || x != (int)x || x > 1e6) {
                fprintf(stderr, "catena formfind: --maxit takes an integer from 1 to 1000000\n");
                return 1;
            }
            a->opt.maxit = (int)x;
        } else if (s[0] == '-' && s[1]) {
            fprintf(stderr, "catena formfind: unknown or incomplete option '%s'\n", s);
            return 1;
        } else if (!a->model) a->model = s;
        else {
            fprintf(stderr, "catena formfind: more than one model given ('%s')\n", s);
            return 1;
        }
    }
    if (!a->model) fprintf(stderr, "usage: catena formfind MODEL [-o OUT] [--tol T] [--maxit N] [-q]\n");
    return a->model ? 0 : 1;
}

static void print_iteration(void *data, const ctn_formfind_iterate *it)
{
    fprintf(data, "%6d  %14.3e  %14.3e\n", it->iteration, it->force_mismatch, it->load_change);
}

static void print_summary(const ff_args *a, const ctn_model *m, const ctn_formfind_report *r)
{
    const char *F = ctn_model_force_unit(m);
    printf("found in %d iteration%s, %d factorization%s: force mismatch %.3g, load change %.3g, "
           "equilibrium residual %.3g (relative)\n", r->iterations, r->iterations == 1 ? "" : "s",
           r->factorizations, r->factorizations == 1 ? "" : "s", r->force_mismatch, r->load_change, r->residual);
    printf("member forces q l: %.6g to %.6g %s\n", r->force_min, r->force_max, F);
    if (a->out) printf("written: %s\n", a->out);
    else printf("not written (no -o OUT)\n");
}

/* Not converged: say how far the targets are and why the iteration stopped. */
static void print_failure(const ff_args *a, const ctn_model *m, const ctn_formfind_report *r)
{
    ctn_element_info info;
    double target = 0;
    ctn_model_element(m, r->worst, &info);
    ctn_model_force_density(m, r->worst, NULL, &target);
    fprintf(stderr, "catena: %s: not converged: %s after %d iterations: largest force mismatch %.3g (element %d, "
            "target %g), load change %.3g; nothing written\n", a->model,
            r->reason == CTN_FF_STALLED ? "the force mismatch stopped falling (the targets are probably not compatible "
                                          "with equilibrium)" : "the iteration limit was reached",
            r->iterations, r->force_mismatch, info.id, target, r->load_change);
}

int ctn_cmd_formfind(int argc, char **argv)
{
    ff_args a;
    if (parse_args(argc, argv, &a)) return CTN_EXIT_USAGE;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    if (ctn_app_ctx_create(&ctx)) {
        fprintf(stderr, "catena: out of memory\n");
        return CTN_EXIT_IO;
    }
    if (!a.quiet) {
        a.opt.monitor = print_iteration;
        a.opt.monitor_data = stdout;
        printf("%s: form finding by force density\n    it  force mismatch     load change\n", a.model);
    }
    ctn_formfind_report r;
    int rc = ctn_formfind_file(ctx, a.model, a.out, &a.opt, &r, &m), code = CTN_EXIT_OK;
    if (rc) code = ctn_app_fail_model(ctx, rc, a.model);
    else if (r.reason != CTN_FF_CONVERGED) {
        print_failure(&a, m, &r);
        code = CTN_EXIT_NOCONV;
    } else if (!a.quiet) {
        printf("%zu nodes (%zu free), %zu members (%zu with a target force)\n", ctn_model_node_count(m), r.free_nodes,
               ctn_model_element_count(m), r.targets);
        print_summary(&a, m, &r);
    }
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return code ? code : ctn_app_flush(stdout, "stdout");
}
