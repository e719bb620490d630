/* Figures of the length study (the paper's Figs. 10-12): data files and scripts. */
#include "compare/study.h"
#include "catena/plot.h"

#include <math.h>
#include <stdio.h>

#define NCOL 6
#define ECOL 10

static double chord(const ctn_study *s) { return hypot(s->span.l, s->span.h); }
static double mpa(const ctn_study *s) { return s->span.mpa > 0 ? s->span.mpa : 1; }
/* What the FEA form of the rows is called. */
static const char *fea_name(const ctn_study *s) { return s->catenary ? "catenary element" : "FEA"; }

/* One data row: L0, L0 - chord, sag, stress max, min, H. */
static void put_row(const ctn_study *s, double L0, const ctn_compare_values *v, double *d)
{
    double row[NCOL] = { L0, L0 - chord(s), v->sag, v->stress_max * mpa(s), v->stress_min * mpa(s), v->H };
    for (int j = 0; j < NCOL; j++) d[j] = row[j];
}

static void form_head(const ctn_study *s, const char *what, char *head, size_t size)
{
    snprintf(head, size, "catena study: %s\nL0 [%s]  L0-chord [%s]  mid-span sag [%s]  support stress [%s]  "
             "minimum stress [%s]  H [%s]", what, s->span.length_unit, s->span.length_unit, s->span.length_unit,
             s->span.mpa > 0 ? "MPa" : "model units", s->span.mpa > 0 ? "MPa" : "model units", s->span.force_unit);
}

/* Rows of form f (marked rows only if marked): L0, L0 - chord, sag, stress max, min, H. */
static int write_form(ctn_ctx *ctx, const ctn_study *s, const char *dir, ctn_form f, int marked)
{
    double *d = ctn_malloc(ctx, NCOL * (s->n ? s->n : 1), sizeof *d);
    size_t k = 0;
    if (!d) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < s->n; i++) {
        const ctn_study_row *r = &s->row[i];
        if (!(r->present >> f & 1u) || (marked && !r->marked)) continue;
        put_row(s, r->L0, &r->v[f], d + NCOL * k++);
    }
    char file[64], head[320], what[96];
    snprintf(file, sizeof file, "study_%s%s.dat", marked ? "marked_" : "", ctn_form_key(f));
    snprintf(what, sizeof what, "%s%s", f == CTN_FORM_FEA ? fea_name(s) : ctn_form_name(f), marked ? ", marked lengths" : "");
    form_head(s, what, head, sizeof head);
    int rc = ctn_plot_write_data(ctx, dir, file, head, NCOL, k, d);
    ctn_free(d);
    return rc;
}

/* The span's mesh beside the catenary element (study_mesh.dat), rows where it converged. */
static int write_mesh(ctn_ctx *ctx, const ctn_study *s, const char *dir)
{
    double *d = ctn_malloc(ctx, NCOL * (s->n ? s->n : 1), sizeof *d);
    size_t k = 0;
    if (!d) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < s->n; i++)
        if (s->row[i].has_mesh) put_row(s, s->row[i].L0, &s->row[i].mesh, d + NCOL * k++);
    char head[320], what[96];
    snprintf(what, sizeof what, "FE mesh of %zu cable elements", s->span.n);
    form_head(s, what, head, sizeof head);
    int rc = ctn_plot_write_data(ctx, dir, "study_mesh.dat", head, NCOL, k, d);
    ctn_free(d);
    return rc;
}

/* Rows of the taut branch with FEA and catenary: L0, L0 - chord, FEA and catenary support stress, then the
 * relative differences catenary - FEA in % (support stress, minimum stress, sag) and
 * their absolute values. */
static int write_errors(ctn_ctx *ctx, const ctn_study *s, const char *dir)
{
    const unsigned both = (1u << CTN_FORM_FEA) | (1u << CTN_FORM_CATENARY);
    double *d = ctn_malloc(ctx, ECOL * (s->n ? s->n : 1), sizeof *d);
    size_t k = 0;
    if (!d) return CTN_ERR_NOMEM;
    for (size_t i = 0; i <= ctn_study_taut_end(s) && i < s->n; i++) {
        const ctn_study_row *r = &s->row[i];
        if ((r->present & both) != both) continue;
        const ctn_compare_values *f = &r->v[CTN_FORM_FEA], *c = &r->v[CTN_FORM_CATENARY];
        double e[3] = { 100 * ctn_compare_rel(c->stress_max, f->stress_max),
                        100 * ctn_compare_rel(c->stress_min, f->stress_min), 100 * ctn_compare_rel(c->sag, f->sag) };
        double row[ECOL] = { r->L0, r->L0 - chord(s), f->stress_max * mpa(s), c->stress_max * mpa(s),
                             e[0], e[1], e[2], fabs(e[0]), fabs(e[1]), fabs(e[2]) };
        for (int j = 0; j < ECOL; j++) d[ECOL * k + (size_t)j] = row[j];
        k++;
    }
    char head[320];
    snprintf(head, sizeof head, "catena study: catenary against %s on the taut branch, relative differences (catenary - %s) "
             "/ %s in %%\nL0  L0-chord  %s support stress  catenary support stress  d_max  d_min  d_sag  |d_max|  |d_min|  "
             "|d_sag|", fea_name(s), fea_name(s), fea_name(s), fea_name(s));
    int rc = ctn_plot_write_data(ctx, dir, "study_error.dat", head, ECOL, k, d);
    if (!rc) rc = ctn_plot_write_data(ctx, dir, "study_claims.dat",
        "reference points: stress level, relative difference in %", 2, s->nclaims, s->claims);
    ctn_free(d);
    return rc;
}

/* One figure against L0 - chord: column col of FEA, catenary, elastic catenary, marked. */
static int length_figure(ctn_ctx *ctx, const ctn_study *s, const char *dir, const char *name, int col,
                         const char *ylabel, const char *title, const char *key)
{
    char xl[128];
    snprintf(xl, sizeof xl, "excess length L_0 - chord [%s] (chord %.6g %s)", s->span.length_unit, chord(s),
             s->span.length_unit);
    char fea[64], marked[80], mesh[64];
    snprintf(fea, sizeof fea, "%s%s", fea_name(s), s->catenary ? " (one per length)" : "");
    snprintf(marked, sizeof marked, "%s, marked lengths", fea_name(s));
    snprintf(mesh, sizeof mesh, "FE mesh, %zu cable elements", s->span.n);
    ctn_plot_series ser[6] = {
        { "study_fea.dat", 2, col, fea, CTN_PLOT_LINES, 1 },
        { "study_catenary.dat", 2, col, "inextensible catenary", CTN_PLOT_LINES, 2 },
        { "study_elastic_catenary.dat", 2, col, "elastic catenary", CTN_PLOT_DASHED, 3 },
        { "study_marked_fea.dat", 2, col, marked, CTN_PLOT_POINTS, 1 },
        { "study_marked_catenary.dat", 2, col, "catenary, marked lengths", CTN_PLOT_POINTS, 2 },
        { "study_mesh.dat", 2, col, mesh, CTN_PLOT_POINTS, 4 } };
    ctn_plot_figure fig = { name, title, xl, ylabel, 1, col == 3, key, "set autoscale xfix", s->mesh ? 6 : 5, ser };
    return ctn_plot_write_script(ctx, dir, &fig);
}

static int error_figure(ctn_ctx *ctx, const ctn_study *s, const char *dir)
{
    char xl[128];
    snprintf(xl, sizeof xl, "stress level: support stress [%s]", s->span.mpa > 0 ? "MPa" : "model units");
    const char *lv = s->catenary ? "element" : "FEA";
    char t[3][64], title[128], ylabel[96];
    snprintf(t[0], sizeof t[0], "support stress, level = %s", lv);
    snprintf(t[1], sizeof t[1], "vertex stress, level = %s", lv);
    snprintf(t[2], sizeof t[2], "mid-span sag, level = %s", lv);
    snprintf(title, sizeof title, "Catenary against %s on the taut branch: |difference| vs stress level",
             s->catenary ? "the catenary element" : "FEA");
    snprintf(ylabel, sizeof ylabel, "|catenary - %s| / %s [%%]", lv, lv);
    ctn_plot_series ser[5] = {
        { "study_error.dat", 3, 8, t[0], CTN_PLOT_LINESPOINTS, 1 },
        { "study_error.dat", 3, 9, t[1], CTN_PLOT_LINESPOINTS, 3 },
        { "study_error.dat", 3, 10, t[2], CTN_PLOT_LINESPOINTS, 4 },
        { "study_error.dat", 4, 8, "support stress, level = catenary", CTN_PLOT_DASHED, 2 },
        { "study_claims.dat", 1, 2, s->claims_title, CTN_PLOT_POINTS, 7 } };
    char extra[96];
    double top = 0;
    for (size_t i = 0; i < s->n; i++)
        if (s->row[i].present & 1u) top = fmax(top, s->row[i].v[CTN_FORM_FEA].stress_max * mpa(s));
    for (size_t i = 0; i < s->nclaims; i++) top = fmax(top, s->claims[2 * i]);
    snprintf(extra, sizeof extra, "set xrange [0:%.6g]\nset yrange [0.01:*]", 1.1 * top);
    ctn_plot_figure fig = { "study_error", title, xl, ylabel, 0, 1, "bottom right", extra, s->nclaims ? 5 : 4, ser };
    return ctn_plot_write_script(ctx, dir, &fig);
}

int ctn_study_write_figures(ctn_ctx *ctx, const ctn_study *s, const char *dir,
                            const char *names[4])
{
    if (!s || !dir) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_study_write_figures: bad arguments");
    static const ctn_form forms[4] = { CTN_FORM_FEA, CTN_FORM_CATENARY, CTN_FORM_ECATENARY, CTN_FORM_EFUNICULAR };
    const char *u = s->span.mpa > 0 ? "MPa" : "model units";
    char ymax[128], ymin[128], ysag[128];
    snprintf(ymax, sizeof ymax, "maximum stress, at the support [%s]", u);
    snprintf(ymin, sizeof ymin, "minimum stress, at the vertex [%s]", u);
    snprintf(ysag, sizeof ysag, "mid-span sag [%s]", s->span.length_unit);
    int rc = ctn_plot_mkdir(ctx, dir);
    for (int i = 0; i < 4 && !rc; i++) rc = write_form(ctx, s, dir, forms[i], 0);
    for (int i = 0; i < 2 && !rc; i++) rc = write_form(ctx, s, dir, forms[i], 1);
    if (!rc && s->mesh) rc = write_mesh(ctx, s, dir);
    if (!rc) rc = write_errors(ctx, s, dir);
    if (!rc) rc = length_figure(ctx, s, dir, "study_stress_max", 4, ymax, "Maximum stress (support) against cable length", "top right");
    if (!rc) rc = length_figure(ctx, s, dir, "study_stress_min", 5, ymin, "Minimum stress (vertex) against cable length", "top right");
    if (!rc) rc = length_figure(ctx, s, dir, "study_sag", 3, ysag, "Mid-span sag against cable length", "top left");
    if (!rc) rc = error_figure(ctx, s, dir);
    if (!rc && names)
        names[0] = "study_stress_max", names[1] = "study_stress_min", names[2] = "study_sag", names[3] = "study_error";
    return rc;
}
