/* The figure of a study on catenary elements (CTN_STUDY_CATENARY) with the span's mesh
 * beside them: how far the FE mesh and the elastic catenary's closed form are from the
 * element, against the excess length. */
#include "compare/study.h"
#include "catena/plot.h"

#include <math.h>
#include <stdio.h>

#define DCOL 8

/* Rows with the element and the mesh: L0, L0 - chord, then |X - element| / element for
 * X = the mesh (sag, support stress, H) and the elastic catenary (the same three). */
static int write_data(ctn_ctx *ctx, const ctn_study *s, const char *dir)
{
    const unsigned both = 1u << CTN_FORM_FEA | 1u << CTN_FORM_ECATENARY;
    double *d = ctn_malloc(ctx, DCOL * (s->n ? s->n : 1), sizeof *d), C = hypot(s->span.l, s->span.h);
    size_t k = 0;
    if (!d) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < s->n; i++) {
        const ctn_study_row *r = &s->row[i];
        if (!r->has_mesh || (r->present & both) != both) continue;
        const ctn_compare_values *f = &r->v[CTN_FORM_FEA], *m = &r->mesh, *e = &r->v[CTN_FORM_ECATENARY];
        double row[DCOL] = { r->L0, r->L0 - C, fabs(ctn_compare_rel(m->sag, f->sag)),
                             fabs(ctn_compare_rel(m->stress_max, f->stress_max)), fabs(ctn_compare_rel(m->H, f->H)),
                             fabs(ctn_compare_rel(e->sag, f->sag)), fabs(ctn_compare_rel(e->stress_max, f->stress_max)),
                             fabs(ctn_compare_rel(e->H, f->H)) };
        for (int j = 0; j < DCOL; j++) d[DCOL * k + (size_t)j] = row[j];
        k++;
    }
    char head[320];
    snprintf(head, sizeof head, "catena study: the FE mesh (%zu cable elements) and the elastic catenary against the "
             "catenary element, |X - element| / element\nL0  L0-chord  mesh: sag  support stress  H  elastic catenary: "
             "sag  support stress  H", s->span.n);
    int rc = ctn_plot_write_data(ctx, dir, "study_element.dat", head, DCOL, k, d);
    ctn_free(d);
    return rc;
}

int ctn_study_write_element_figure(ctn_ctx *ctx, const ctn_study *s, const char *dir, const char **name)
{
    if (!s || !dir) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_study_write_element_figure: bad arguments");
    if (name) *name = NULL;
    if (!s->mesh) return CTN_OK;                       /* no mesh beside the elements */
    char xl[128], mesh[3][64];
    snprintf(xl, sizeof xl, "excess length L_0 - chord [%s] (chord %.6g %s)", s->span.length_unit,
             hypot(s->span.l, s->span.h), s->span.length_unit);
    static const char *const what[3] = { "sag", "support stress", "H" };
    for (int i = 0; i < 3; i++) snprintf(mesh[i], sizeof mesh[i], "FE mesh (%zu elements): %s", s->span.n, what[i]);
    ctn_plot_series ser[6] = {
        { "study_element.dat", 2, 3, mesh[0], CTN_PLOT_LINESPOINTS, 4 },
        { "study_element.dat", 2, 4, mesh[1], CTN_PLOT_LINESPOINTS, 1 },
        { "study_element.dat", 2, 5, mesh[2], CTN_PLOT_LINESPOINTS, 3 },
        { "study_element.dat", 2, 6, "elastic catenary: sag", CTN_PLOT_POINTS, 4 },
        { "study_element.dat", 2, 7, "elastic catenary: support stress", CTN_PLOT_POINTS, 1 },
        { "study_element.dat", 2, 8, "elastic catenary: H", CTN_PLOT_POINTS, 3 } };
    ctn_plot_figure fig = { "study_element", "The FE mesh and the closed form against one catenary element per length",
                            xl, "|X - element| / element", 1, 1, "center right", "set autoscale xfix\nset yrange [1e-17:1]",
                            6, ser };
    int rc = ctn_plot_mkdir(ctx, dir);
    if (!rc) rc = write_data(ctx, s, dir);
    if (!rc) rc = ctn_plot_write_script(ctx, dir, &fig);
    if (!rc && name) *name = "study_element";
    return rc;
}
