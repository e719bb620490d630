/* catena convergence MODEL [--n LIST] [--json] [-o DIR] [-q]: the span of MODEL meshed
 * with n elements (engineering strain) against the elastic catenary; observed orders. */
#include "app.h"

#include <math.h>
#include <string.h>

#define MAX_N 64

typedef struct conv_args {
    const char *model, *outdir;
    size_t n[MAX_N], count;
    int json, quiet;
} conv_args;

static int parse_n(const char *v, conv_args *a)
{
    double x[MAX_N];
    if (ctn_app_parse_list(v, x, MAX_N, &a->count)) return 1;
    for (size_t i = 0; i < a->count; i++) {
        if (!(x[i] >= 2 && x[i] <= 50000000) || x[i] != floor(x[i])) return 1;
        a->n[i] = (size_t)x[i];
    }
    return 0;
}

static int parse_args(int argc, char **argv, conv_args *a)
{
    static const size_t def[] = { 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000 };
    memset(a, 0, sizeof *a);
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--json")) a->json = 1;
        else if (!strcmp(argv[i], "-q") || !strcmp(argv[i], "--quiet")) a->quiet = 1;
        else if (!strcmp(argv[i], "-o") && i + 1 < argc) a->outdir = argv[++i];
        else if (!strcmp(argv[i], "--n") && i + 1 < argc) {
            if (parse_n(argv[++i], a)) {
                fprintf(stderr, "catena convergence: --n takes a comma-separated list of integers from 2 to "
                                "50000000, found '%s'\n", argv[i]);
                return 1;
            }
        } else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "catena convergence: unknown or incomplete option '%s'\n", argv[i]);
            return 1;
        } else if (!a->model) a->model = argv[i];
        else {
            fprintf(stderr, "catena convergence: more than one model given ('%s')\n", argv[i]);
            return 1;
        }
    }
    if (!a->count) memcpy(a->n, def, sizeof def), a->count = sizeof def / sizeof *def;
    if (!a->model) fprintf(stderr, "usage: catena convergence MODEL [--n LIST] [--json] [-o DIR] [-q]\n");
    return a->model ? 0 : 1;
}

/* Local order between rows i-1 and i of one error column, or 0. */
static double local_order(const ctn_convergence_row *p, const ctn_convergence_row *r, int col)
{
    double a = col == 0 ? p->err_sag : col == 1 ? p->err_T : p->err_H;
    double b = col == 0 ? r->err_sag : col == 1 ? r->err_T : r->err_H;
    if (!(a > 0 && b > 0) || p->reason != CTN_CONVERGED) return 0;
    return log(a / b) / log((double)r->n / (double)p->n);
}

static void print_table(const ctn_convergence *c, const char *path)
{
    const ctn_span *s = ctn_convergence_span(c);
    const ctn_compare_values *ref = ctn_convergence_reference(c);
    printf("%s\n", path);
    ctn_app_print_span(stdout, s);
    printf("FEA with engineering strain against the elastic catenary: sag %.12g %s, support tension %.12g %s, "
           "H %.12g %s\n\n", ref->sag, s->length_unit, ref->T_max, s->force_unit, ref->H, s->force_unit);
    printf("%8s %4s %12s %10s %6s %10s %6s %10s %6s\n", "n", "it", "sag", "err sag", "order", "err T_max",
           "order", "err H", "order");
    for (size_t i = 0; i < ctn_convergence_count(c); i++) {
        const ctn_convergence_row *r = ctn_convergence_row_at(c, i), *p = i ? ctn_convergence_row_at(c, i - 1) : NULL;
        printf("%8zu %4d", r->n, r->iterations);
        if (r->reason != CTN_CONVERGED) { printf("  not converged: %s\n", ctn_reason_name(r->reason)); continue; }
        double e[3] = { r->err_sag, r->err_T, r->err_H };
        printf(" %12.8f", r->fea.sag);
        for (int k = 0; k < 3; k++) {
            printf(" %10.3e", e[k]);
            if (p && local_order(p, r, k) != 0) printf(" %6.2f", local_order(p, r, k));
            else printf(" %6s", "");
        }
        putchar('\n');
    }
    double o[3];
    for (int k = 0; k < 3; k++)
        if (ctn_convergence_order(c, k, &o[k])) o[k] = 0;
    printf("\nobserved order (least-squares slope of log error against log n): sag %.3f, support tension %.3f, "
           "H %.3f\n", o[0], o[1], o[2]);
}

static int print_json(const ctn_convergence *c, const char *path)
{
    cJSON *root = cJSON_CreateObject(), *rows = root ? cJSON_AddArrayToObject(root, "rows") : NULL;
    int ok = rows && cJSON_AddStringToObject(root, "model", path) &&
             ctn_app_values_json(root, "elastic_catenary", ctn_convergence_reference(c), NULL);
    const char *keys[3] = { "order_sag", "order_max_tension", "order_horizontal_force" };
    for (int k = 0; ok && k < 3; k++) {
        double o;
        if (!ctn_convergence_order(c, k, &o)) ok = cJSON_AddNumberToObject(root, keys[k], o) != NULL;
    }
    for (size_t i = 0; ok && i < ctn_convergence_count(c); i++) {
        const ctn_convergence_row *r = ctn_convergence_row_at(c, i);
        cJSON *o = cJSON_CreateObject();
        ok = o && cJSON_AddItemToArray(rows, o);
        if (!ok) { cJSON_Delete(o); break; }
        ok = cJSON_AddNumberToObject(o, "elements", (double)r->n) &&
             cJSON_AddBoolToObject(o, "converged", r->reason == CTN_CONVERGED) &&
             cJSON_AddNumberToObject(o, "iterations", r->iterations) &&
             cJSON_AddNumberToObject(o, "error_sag", r->err_sag) &&
             cJSON_AddNumberToObject(o, "error_max_tension", r->err_T) &&
             cJSON_AddNumberToObject(o, "error_horizontal_force", r->err_H) &&
             ctn_app_values_json(o, "fea", &r->fea, NULL);
    }
    int code = ctn_app_print_json(ok ? root : NULL);
    cJSON_Delete(root);
    return code;
}

int ctn_cmd_convergence(int argc, char **argv)
{
    conv_args a;
    if (parse_args(argc, argv, &a)) return CTN_EXIT_USAGE;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_convergence *c = NULL;
    if (ctn_app_ctx_create(&ctx)) {
        fprintf(stderr, "catena: out of memory\n");
        return CTN_EXIT_IO;
    }
    ctn_solve_options opt;
    int rc = ctn_read_file(ctx, a.model, &m, &opt), code = CTN_EXIT_OK;
    if (!rc) rc = ctn_convergence_run(ctx, m, &opt, a.n, a.count, &c);
    if (rc) code = ctn_app_fail_model(ctx, rc, a.model);
    if (!code && a.outdir && (rc = ctn_convergence_write_figures(ctx, c, a.outdir))) code = ctn_app_fail(ctx, rc);
    if (!code && a.json) code = print_json(c, a.model);
    else if (!code && !a.quiet) print_table(c, a.model);
    if (!code && a.outdir) {
        const char *const names[1] = { "convergence" };
        code = ctn_app_render(ctx, a.outdir, names, 1, a.quiet || a.json);
    }
    for (size_t i = 0; !code && i < ctn_convergence_count(c); i++)
        if (ctn_convergence_row_at(c, i)->reason != CTN_CONVERGED) code = CTN_EXIT_NOCONV;
    ctn_convergence_destroy(&c);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return code;
}
