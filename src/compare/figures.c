/* Figures of one comparison: deformed configuration and stress along the cable. */
#include "compare/cmp.h"
#include "catena/plot.h"

#include <stdio.h>
#include <string.h>

#define MAX_CURVES 4

/* The forms drawn against the FEA: those of the span's load case. */
static size_t drawn_forms(const ctn_compare *c, ctn_form *f)
{
    unsigned L = c->span.loads;
    ctn_form want[3];
    size_t k = 0, n = 0;
    if (L & CTN_SPAN_POINT) want[k++] = CTN_FORM_FUNICULAR, want[k++] = CTN_FORM_EFUNICULAR;
    else if (!(L & CTN_SPAN_WEIGHT)) want[k++] = CTN_FORM_PARABOLA, want[k++] = CTN_FORM_EPARABOLA;
    else {
        want[k++] = CTN_FORM_CATENARY;
        want[k++] = CTN_FORM_ECATENARY;
        if (L & CTN_SPAN_HLOAD) want[k++] = CTN_FORM_PARABOLA;
    }
    f[n++] = CTN_FORM_FEA;
    for (size_t i = 0; i < k; i++)
        if (ctn_compare_has(c, want[i])) f[n++] = want[i];
    return n;
}

/* Write compare_<curve>_<key>.dat; the stress column in MPa when the model has units. */
static int write_curve(ctn_ctx *ctx, const ctn_compare *c, const char *dir, ctn_form f, ctn_curve k,
                       char *file, size_t len)
{
    size_t m = ctn_compare_curve_size(c, f, k);
    double *xy = ctn_malloc(ctx, 2 * m, sizeof *xy), scale = c->span.mpa > 0 ? c->span.mpa : 1;
    if (!xy) return CTN_ERR_NOMEM;
    int rc = ctn_compare_curve(c, f, k, xy);
    if (rc) rc = ctn_cmp_error(ctx, c->file, rc, "cannot sample the %s", ctn_form_name(f));
    for (size_t i = 0; !rc && k == CTN_CURVE_STRESS && i < m; i++) xy[2 * i + 1] *= scale;
    snprintf(file, len, "compare_%s_%s.dat", k == CTN_CURVE_SHAPE ? "shape" : "stress", ctn_form_key(f));
    char head[160];
    snprintf(head, sizeof head, "catena compare: %s, %s\nx [%s]  %s", ctn_form_name(f),
             k == CTN_CURVE_SHAPE ? "deformed configuration" : "stress T/A along the cable",
             c->span.length_unit, k == CTN_CURVE_SHAPE ? "y (up)" : (c->span.mpa > 0 ? "stress [MPa]" : "stress"));
    if (!rc) rc = ctn_plot_write_data(ctx, dir, file, head, 2, m, xy);
    ctn_free(xy);
    return rc;
}

static void labels(const ctn_span *s, ctn_curve k, char *xl, char *yl, size_t len)
{
    const char *u = s->length_unit;
    snprintf(xl, len, *u ? "horizontal position x [%s]" : "horizontal position x", u);
    if (k == CTN_CURVE_SHAPE) snprintf(yl, len, *u ? "height y [%s]" : "height y", u);
    else snprintf(yl, len, s->mpa > 0 ? "stress T/A [MPa]" : "stress T/A");
}

static int figure(ctn_ctx *ctx, const ctn_compare *c, const char *dir, ctn_curve k, const char *name)
{
    ctn_form f[MAX_CURVES];
    size_t n = drawn_forms(c, f);
    char files[MAX_CURVES][64], xl[64], yl[64], title[128];
    ctn_plot_series ser[MAX_CURVES];
    int rc = CTN_OK;
    for (size_t i = 0; i < n && !rc; i++) {
        rc = write_curve(ctx, c, dir, f[i], k, files[i], sizeof files[i]);
        ser[i] = (ctn_plot_series){ files[i], 1, 2, ctn_form_name(f[i]),
                                    i == 0 ? CTN_PLOT_LINESPOINTS : i == 1 ? CTN_PLOT_LINES : CTN_PLOT_DASHED,
                                    (int)i + 1 };
    }
    labels(&c->span, k, xl, yl, sizeof xl);
    snprintf(title, sizeof title, "%s: FEA (%zu elements) and closed forms, L_0 = %.6g %s",
             k == CTN_CURVE_SHAPE ? "Deformed configuration" : "Stress along the cable", c->span.n,
             c->span.L0, c->span.length_unit);
    ctn_plot_figure fig = { name, title, xl, yl, 0, 0, "top center",
                            "set autoscale xfix\nset offsets 0, 0, graph 0.35, graph 0.05", n, ser };
    if (!rc) rc = ctn_plot_write_script(ctx, dir, &fig);
    return rc;
}

int ctn_compare_write_figures(ctn_ctx *ctx, const ctn_compare *c, const char *dir,
                              const char *names[2])
{
    if (!c || !dir) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_compare_write_figures: bad arguments");
    if (!ctn_compare_has(c, CTN_FORM_FEA)) return ctn_error(ctx, CTN_ERR_INVALID, "no FEA values to draw");
    int rc = ctn_plot_mkdir(ctx, dir);
    if (!rc) rc = figure(ctx, c, dir, CTN_CURVE_SHAPE, "compare_shape");
    if (!rc) rc = figure(ctx, c, dir, CTN_CURVE_STRESS, "compare_stress");
    if (!rc && names) names[0] = "compare_shape", names[1] = "compare_stress";
    return rc;
}
