/* Shared helpers of the compare, study and convergence commands: number lists, the span
 * line, the quantity table, JSON of compared values, rendering the figures. */
#include "app.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int ctn_app_parse_list(const char *s, double *out, size_t cap, size_t *n)
{
    *n = 0;
    while (s && *s) {
        char *end;
        errno = 0;
        double v = strtod(s, &end);
        if (end == s || errno || !isfinite(v) || (*end && *end != ',' && *end != ':') || *n >= cap) return 1;
        out[(*n)++] = v;
        s = *end ? end + 1 : end;
    }
    return *n ? 0 : 1;
}

static const char *strain_name(ctn_strain s)
{
    return s == CTN_STRAIN_ENGINEERING ? "engineering strain" : "Green-Lagrange strain";
}

void ctn_app_print_span(FILE *out, const ctn_span *s)
{
    const char *L = s->length_unit, *F = s->force_unit;
    fprintf(out, "span: supports %d and %d, horizontal %.10g %s, rise %.10g %s, unstressed length %.10g %s, "
            "%zu elements%s\n", s->support[0], s->support[1], s->l, L, s->h, L, s->L0, L, s->n,
            s->generated ? " (cable directive)" : "");
    fprintf(out, "      EA = %.6g %s, A = %.6g %s^2, %s", s->EA, F, s->A, L, strain_name(s->strain));
    if (s->loads & CTN_SPAN_WEIGHT) fprintf(out, ", self-weight %.6g %s/%s", s->w, F, L);
    if (s->loads & CTN_SPAN_HLOAD) fprintf(out, ", hload %.6g %s/%s", s->q, F, L);
    if (s->loads & CTN_SPAN_POINT) fprintf(out, ", point loads");
    fputc('\n', out);
}

/* Stress in MPa when the model has units. */
double ctn_app_stress(const ctn_span *s, double stress) { return s->mpa > 0 ? stress * s->mpa : stress; }

void ctn_app_print_values(FILE *out, const char *label, const ctn_span *s, const ctn_compare_values *v)
{
    fprintf(out, "%-19s %11.6g %11.6g %10.5g %11.6g %10.5g %11.6g\n", label, v->sag, v->T_max,
            ctn_app_stress(s, v->stress_max), v->T_min, ctn_app_stress(s, v->stress_min), v->H);
}

static void diff(FILE *out, double a, double b, int width, int prec)
{
    fprintf(out, " %+*.*f", width, prec, 100 * ctn_compare_rel(a, b));
}

void ctn_app_print_diffs(FILE *out, const ctn_compare_values *v, const ctn_compare_values *ref)
{
    fprintf(out, "%-19s", "  difference [%]");
    diff(out, v->sag, ref->sag, 11, 2);
    diff(out, v->T_max, ref->T_max, 11, 2);
    diff(out, v->stress_max, ref->stress_max, 10, 2);
    diff(out, v->T_min, ref->T_min, 11, 2);
    diff(out, v->stress_min, ref->stress_min, 10, 2);
    diff(out, v->H, ref->H, 11, 2);
    fputc('\n', out);
}

void ctn_app_print_header(FILE *out, const ctn_span *s)
{
    const char *L = *s->length_unit ? s->length_unit : "L", *F = *s->force_unit ? s->force_unit : "F";
    const char *S = s->mpa > 0 ? "MPa" : "F/L^2";
    char u[6][16];
    snprintf(u[0], sizeof u[0], "[%s]", L);
    snprintf(u[1], sizeof u[1], "[%s]", F);
    snprintf(u[2], sizeof u[2], "[%s]", S);
    snprintf(u[3], sizeof u[3], "[%s]", F);
    snprintf(u[4], sizeof u[4], "[%s]", S);
    snprintf(u[5], sizeof u[5], "[%s]", F);
    fprintf(out, "%-19s %11s %11s %10s %11s %10s %11s\n", "", "sag", "T_max", "stress_max", "T_min",
            "stress_min", "H");
    fprintf(out, "%-19s %11s %11s %10s %11s %10s %11s\n", "", u[0], u[1], u[2], u[3], u[4], u[5]);
}

cJSON *ctn_app_values_json(cJSON *parent, const char *key, const ctn_compare_values *v,
                           const ctn_compare_values *ref)
{
    cJSON *o = cJSON_AddObjectToObject(parent, key);
    if (!o) return NULL;
    const char *k[6] = { "sag", "max_tension", "min_tension", "horizontal_force", "max_stress", "min_stress" };
    double x[6] = { v->sag, v->T_max, v->T_min, v->H, v->stress_max, v->stress_min };
    double r[6] = { ref ? ref->sag : 0, ref ? ref->T_max : 0, ref ? ref->T_min : 0, ref ? ref->H : 0,
                    ref ? ref->stress_max : 0, ref ? ref->stress_min : 0 };
    cJSON *d = ref ? cJSON_AddObjectToObject(o, "relative_difference") : NULL;
    for (int i = 0; i < 6; i++) {
        if (!cJSON_AddNumberToObject(o, k[i], isfinite(x[i]) ? x[i] : 0)) return NULL;
        if (d && !cJSON_AddNumberToObject(d, k[i], ctn_compare_rel(x[i], r[i]))) return NULL;
    }
    return ref && !d ? NULL : o;
}

int ctn_app_print_json(cJSON *root)
{
    char *text = root ? cJSON_Print(root) : NULL;
    if (!text) {
        fprintf(stderr, "catena: out of memory building the JSON output\n");
        return CTN_EXIT_IO;
    }
    fputs(text, stdout);
    fputc('\n', stdout);
    cJSON_free(text);
    return ctn_app_flush(stdout, "stdout");
}

int ctn_app_render(ctn_ctx *ctx, const char *dir, const char *const *names, size_t n, int quiet)
{
    int missing = 0;
    for (size_t i = 0; i < n; i++) {
        int done = 0, rc = ctn_plot_render(ctx, dir, names[i], &done);
        if (rc) return ctn_app_fail(ctx, rc);
        if (!done) missing = 1;
        else if (!quiet) printf("figure: %s/%s.svg\n", dir, names[i]);
    }
    if (missing) {
        fprintf(stderr, "catena: gnuplot not found (Debian: apt-get install gnuplot-nox); the figures' data "
                "and scripts are in %s. Render them with:\n  cd %s &&", dir, dir);
        for (size_t i = 0; i < n; i++) fprintf(stderr, " gnuplot %s.gp%s", names[i], i + 1 < n ? " &&" : "\n");
    }
    return CTN_EXIT_OK;
}
