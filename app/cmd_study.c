/* catena study MODEL... [--lengths LIST] [--sweep N] [--from L] [--to L] [--levels LIST]
 *                       [--claims LIST] [--element mesh|catenary] [--json] [-o DIR] [-q]
 * The founding paper's study: the span of MODEL re-solved over a sweep of unstressed
 * lengths, FEA against the inextensible catenary (catena/compare.h, ctn_study_*). The
 * lengths of every MODEL given (same span otherwise) and of --lengths are marked. */
#include "app.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_LIST 64

typedef struct study_args {
    const char *model[MAX_LIST], *outdir;
    size_t nmodel, nlengths, nlevels, nclaims;
    double lengths[MAX_LIST], levels[MAX_LIST], claims[2 * MAX_LIST];
    ctn_study_options opt;
    ctn_solve_options solve;   /* the first model's `solve` line */
    int json, quiet;
} study_args;

static int list_option(const char *name, const char *value, double *out, size_t cap, size_t *n)
{
    if (!ctn_app_parse_list(value, out, cap, n)) return 0;
    fprintf(stderr, "catena study: %s takes a comma-separated list of at most %zu numbers, found '%s'\n", name,
            cap, value);
    return 1;
}

static int number_option(const char *name, const char *value, double *out)
{
    size_t n;
    if (!ctn_app_parse_list(value, out, 1, &n) && *out >= 0) return 0;
    fprintf(stderr, "catena study: %s takes a number >= 0, found '%s'\n", name, value);
    return 1;
}

static int parse_option(int argc, char **argv, int *i, study_args *a)
{
    const char *o = argv[*i], *v = *i + 1 < argc ? argv[*i + 1] : NULL;
    double x = 0;
    int bad = 1;
    if (!strcmp(o, "--json")) return a->json = 1, 0;
    if (!strcmp(o, "-q") || !strcmp(o, "--quiet")) return a->quiet = 1, 0;
    if (!v) bad = 1;
    else if (!strcmp(o, "-o")) a->outdir = v, bad = 0;
    else if (!strcmp(o, "--claims-title")) a->opt.claims_title = v, bad = 0;
    else if (!strcmp(o, "--lengths")) bad = list_option(o, v, a->lengths, MAX_LIST, &a->nlengths);
    else if (!strcmp(o, "--levels")) bad = list_option(o, v, a->levels, MAX_LIST, &a->nlevels);
    else if (!strcmp(o, "--claims")) bad = list_option(o, v, a->claims, 2 * MAX_LIST, &a->nclaims) || a->nclaims % 2;
    else if (!strcmp(o, "--element")) {
        bad = strcmp(v, "catenary") && strcmp(v, "mesh");
        a->opt.element = strcmp(v, "catenary") ? CTN_STUDY_MESH : CTN_STUDY_CATENARY;
    } else if (!strcmp(o, "--from")) bad = number_option(o, v, &a->opt.sweep_from);
    else if (!strcmp(o, "--to")) bad = number_option(o, v, &a->opt.sweep_to);
    else if (!strcmp(o, "--sweep")) {
        bad = number_option(o, v, &x) || x != floor(x) || x > 100000;
        a->opt.sweep = (size_t)x;
    }
    if (bad) fprintf(stderr, "catena study: unknown, incomplete or invalid option '%s'\n", o);
    else (*i)++;
    return bad;
}

static int parse_args(int argc, char **argv, study_args *a)
{
    memset(a, 0, sizeof *a);
    ctn_study_options_default(&a->opt);
    for (int i = 1; i < argc; i++) {
        if (argv[i][0] == '-' && argv[i][1]) {
            if (parse_option(argc, argv, &i, a)) return 1;
        } else if (a->nmodel < MAX_LIST) a->model[a->nmodel++] = argv[i];
        else return fprintf(stderr, "catena study: more than %d models\n", MAX_LIST), 1;
    }
    if (!a->nlevels) {
        static const double def[6] = { 50, 100, 150, 200, 250, 300 };
        memcpy(a->levels, def, sizeof def);
        a->nlevels = 6;
    }
    a->nclaims /= 2;
    if (!a->nmodel)
        fprintf(stderr, "usage: catena study MODEL... [--lengths LIST] [--sweep N] [--from L] [--to L]\n"
                        "                    [--levels LIST] [--claims S:E,...] [--claims-title TEXT]\n"
                        "                    [--element mesh|catenary] [--json] [-o DIR] [-q]\n");
    return a->nmodel ? 0 : 1;
}

/* 1 if span s differs from the base in anything but its length. */
static int other_span(const ctn_span *s, const ctn_span *b)
{
    return s->n != b->n || s->E != b->E || s->A != b->A || s->w != b->w || s->q != b->q ||
           s->strain != b->strain || fabs(s->l - b->l) > 1e-9 * b->l || fabs(s->h - b->h) > 1e-9 * b->l;
}

/* Read every model: the first is the base (*base, *span), the lengths of all are marked. */
static int read_models(ctn_ctx *ctx, study_args *a, ctn_model **base, ctn_span *span)
{
    for (size_t i = 0; i < a->nmodel; i++) {
        ctn_model *m = NULL;
        ctn_compare *c = NULL;
        ctn_solve_options opt;
        int rc = ctn_read_file(ctx, a->model[i], &m, &opt), code = CTN_EXIT_OK;
        if (!rc && i == 0) a->solve = opt;
        if (!rc) rc = ctn_compare_create(ctx, m, &c);
        if (rc) code = ctn_app_fail_model(ctx, rc, a->model[i]);
        else if (i == 0) *span = *ctn_compare_span(c);
        else if (other_span(ctn_compare_span(c), span)) {
            fprintf(stderr, "catena: %s: not the span of %s (only the cable length may differ)\n", a->model[i],
                    a->model[0]);
            code = CTN_EXIT_MODEL;
        }
        if (!code && a->nlengths < MAX_LIST) a->lengths[a->nlengths++] = ctn_compare_span(c)->L0;
        ctn_compare_destroy(&c);
        if (!code && i == 0) *base = m;
        else ctn_model_destroy(&m);
        if (code) return code;
    }
    return CTN_EXIT_OK;
}

/* The four figures, and with catenary elements beside a mesh the fifth. */
static int figures(ctn_ctx *ctx, const ctn_study *st, const study_args *a)
{
    const char *names[5] = { NULL, NULL, NULL, NULL, NULL };
    int rc = ctn_study_write_figures(ctx, st, a->outdir, names);
    if (!rc) rc = ctn_study_write_element_figure(ctx, st, a->outdir, &names[4]);
    if (rc) return ctn_app_fail(ctx, rc);
    return ctn_app_render(ctx, a->outdir, names, names[4] ? 5 : 4, a->quiet || a->json);
}

int ctn_cmd_study(int argc, char **argv)
{
    study_args a;
    if (parse_args(argc, argv, &a)) return CTN_EXIT_USAGE;
    ctn_ctx *ctx = NULL;
    ctn_model *base = NULL;
    ctn_study *st = NULL;
    ctn_span span;
    memset(&span, 0, sizeof span);
    if (ctn_app_ctx_create(&ctx)) {
        fprintf(stderr, "catena: out of memory\n");
        return CTN_EXIT_IO;
    }
    int code = read_models(ctx, &a, &base, &span), rc;
    a.opt.lengths = a.lengths;
    a.opt.nlengths = a.nlengths;
    a.opt.claims = a.claims;
    a.opt.nclaims = a.nclaims;
    a.opt.solve = &a.solve;
    if (!code && (rc = ctn_study_run(ctx, base, &a.opt, &st))) {
        if (rc == CTN_ERR_INVALID) code = ctn_app_fail(ctx, rc), code = CTN_EXIT_USAGE;  /* a bad length or sweep */
        else code = ctn_app_fail_model(ctx, rc, a.model[0]);
    }
    if (!code && a.json) code = ctn_app_study_json(st, a.model[0]);
    else if (!code && !a.quiet)
        ctn_app_study_report(st, a.model[0], a.opt.sweep, a.levels, a.nlevels, MAX_LIST, a.claims, a.nclaims);
    if (!code && a.outdir) code = figures(ctx, st, &a);
    ctn_study_destroy(&st);
    ctn_model_destroy(&base);
    ctn_ctx_destroy(&ctx);
    return code;
}
