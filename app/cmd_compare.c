/* catena compare MODEL [--json] [-o DIR] [-q]: the FEA of a single span against the
 * classical closed forms (catena/compare.h). */
#include "app.h"

#include <string.h>


static void print_table(const char *path, const ctn_compare *c, const ctn_solve_summary *sum)
{
    const ctn_span *s = ctn_compare_span(c);
    ctn_compare_values fea, v;
    ctn_compare_get(c, CTN_FORM_FEA, &fea);
    printf("%s\n", path);
    ctn_app_print_span(stdout, s);
    printf("FEA: converged after %d iterations\n\n", sum->iterations);
    ctn_app_print_header(stdout, s);
    ctn_app_print_values(stdout, "FEA", s, &fea);
    for (int f = 1; f < CTN_FORM_COUNT; f++) {
        if (ctn_compare_get(c, (ctn_form)f, &v)) continue;
        ctn_app_print_values(stdout, ctn_form_name((ctn_form)f), s, &v);
        ctn_app_print_diffs(stdout, &v, &fea);
    }
    printf("\nsag at mid-span; T_max at the support (FEA and polygons: the resultant support reaction);\n"
           "T_min at the vertex (FEA and polygons: the least loaded element); H horizontal force;\n"
           "stress = T / A (unstressed area); difference = (closed form - FEA) / FEA.\n");
}

static int print_json(const char *path, const ctn_compare *c, const ctn_solve_summary *sum)
{
    const ctn_span *s = ctn_compare_span(c);
    ctn_compare_values fea, v;
    ctn_compare_get(c, CTN_FORM_FEA, &fea);
    cJSON *root = cJSON_CreateObject(), *sp = root ? cJSON_AddObjectToObject(root, "span") : NULL;
    int ok = sp && cJSON_AddStringToObject(root, "model", path) &&
             cJSON_AddNumberToObject(sp, "horizontal_span", s->l) && cJSON_AddNumberToObject(sp, "rise", s->h) &&
             cJSON_AddNumberToObject(sp, "unstressed_length", s->L0) &&
             cJSON_AddNumberToObject(sp, "elements", (double)s->n) && cJSON_AddNumberToObject(sp, "EA", s->EA) &&
             cJSON_AddNumberToObject(sp, "area", s->A) && cJSON_AddNumberToObject(sp, "weight", s->w) &&
             cJSON_AddNumberToObject(sp, "hload", s->q) && cJSON_AddNumberToObject(sp, "mpa_factor", s->mpa) &&
             cJSON_AddStringToObject(sp, "force_unit", s->force_unit) &&
             cJSON_AddStringToObject(sp, "length_unit", s->length_unit) &&
             cJSON_AddNumberToObject(root, "iterations", sum->iterations) &&
             ctn_app_values_json(root, "fea", &fea, NULL);
    for (int f = 1; ok && f < CTN_FORM_COUNT; f++)
        if (!ctn_compare_get(c, (ctn_form)f, &v)) ok = ctn_app_values_json(root, ctn_form_key((ctn_form)f), &v, &fea) != NULL;
    int code = ctn_app_print_json(ok ? root : NULL);
    cJSON_Delete(root);
    return code;
}

/* Solve with the file's options; exit code (3 when not converged). */
static int solve(ctn_ctx *ctx, const char *path, const ctn_model *m, const ctn_solve_options *opt,
                 ctn_solution **s, ctn_solve_summary *sum)
{
    int rc = ctn_solve(ctx, m, opt, s);
    if (rc) return ctn_app_fail_model(ctx, rc, path);
    ctn_solution_summary(*s, sum);
    if (sum->reason == CTN_CONVERGED) return CTN_EXIT_OK;
    fprintf(stderr, "catena: %s: the FEA did not converge (%s): nothing to compare\n", path, ctn_reason_name(sum->reason));
    return CTN_EXIT_NOCONV;
}

static int report(ctn_ctx *ctx, const ctn_model_args *a, const ctn_compare *c, const ctn_solve_summary *sum)
{
    int code = CTN_EXIT_OK;
    if (a->outdir) {
        const char *names[2];
        int rc = ctn_compare_write_figures(ctx, c, a->outdir, names);
        if (rc) return ctn_app_fail(ctx, rc);
    }
    if (a->json) code = print_json(a->model, c, sum);
    else if (!a->quiet) print_table(a->model, c, sum);
    if (!code && a->outdir) {
        const char *const names[2] = { "compare_shape", "compare_stress" };
        code = ctn_app_render(ctx, a->outdir, names, 2, a->quiet || a->json);
    }
    return code;
}

int ctn_cmd_compare(int argc, char **argv)
{
    ctn_model_args a;
    if (ctn_app_model_args("compare", argc, argv, &a)) return CTN_EXIT_USAGE;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_compare *c = NULL;
    ctn_solve_summary sum;
    if (ctn_app_ctx_create(&ctx)) {
        fprintf(stderr, "catena: out of memory\n");
        return CTN_EXIT_IO;
    }
    ctn_solve_options opt;
    int rc = ctn_read_file(ctx, a.model, &m, &opt), code = CTN_EXIT_OK;
    if (!rc) rc = ctn_model_resolve_targets(ctx, m, &opt, NULL);
    if (!rc) rc = ctn_compare_create(ctx, m, &c);
    if (rc) code = ctn_app_fail_model(ctx, rc, a.model);
    if (!code) code = solve(ctx, a.model, m, &opt, &s, &sum);
    if (!code && (rc = ctn_compare_set_fea(c, s))) code = ctn_app_fail_model(ctx, rc, a.model);
    if (!code) code = report(ctx, &a, c, &sum);
    ctn_compare_destroy(&c);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return code;
}
