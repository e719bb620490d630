/* The log-log figure of the mesh convergence study. */
#include "compare/cmp.h"
#include "catena/plot.h"

#include <math.h>
#include <stdio.h>

/* Converged rows with every error above zero: n, err_sag, err_T, err_H, n^-2 guide. */
static int write_table(ctn_ctx *ctx, const ctn_convergence *c, const char *dir)
{
    size_t n = ctn_convergence_count(c), k = 0;
    double *d = ctn_malloc(ctx, 5 * (n ? n : 1), sizeof *d), guide = 0;
    if (!d) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < n; i++) {
        const ctn_convergence_row *r = ctn_convergence_row_at(c, i);
        if (r->reason != CTN_CONVERGED || !(r->err_sag > 0 && r->err_T > 0 && r->err_H > 0)) continue;
        double nn = (double)r->n;
        if (!k) guide = 0.25 * fmin(r->err_T, fmin(r->err_sag, r->err_H)) * nn * nn;   /* below every curve */
        double row[5] = { nn, r->err_sag, r->err_T, r->err_H, guide / (nn * nn) };
        for (int j = 0; j < 5; j++) d[5 * k + (size_t)j] = row[j];
        k++;
    }
    int rc = ctn_plot_write_data(ctx, dir, "convergence.dat",
        "catena convergence: FEA (engineering strain) against the elastic catenary, relative errors\n"
        "elements  mid-span sag  support tension  horizontal force  guide: slope -2", 5, k, d);
    ctn_free(d);
    return rc;
}

int ctn_convergence_write_figures(ctn_ctx *ctx, const ctn_convergence *c, const char *dir)
{
    if (!c || !dir) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_convergence_write_figures: bad arguments");
    const ctn_span *s = ctn_convergence_span(c);
    char title[128];
    snprintf(title, sizeof title, "Mesh convergence to the elastic catenary (L_0 = %.6g %s, span %.6g %s)", s->L0,
             s->length_unit, s->l, s->length_unit);
    ctn_plot_series ser[4] = {
        { "convergence.dat", 1, 2, "mid-span sag", CTN_PLOT_LINESPOINTS, 1 },
        { "convergence.dat", 1, 3, "support tension", CTN_PLOT_LINESPOINTS, 2 },
        { "convergence.dat", 1, 4, "horizontal force", CTN_PLOT_LINESPOINTS, 3 },
        { "convergence.dat", 1, 5, "slope -2 (second order)", CTN_PLOT_DASHED, 7 } };
    ctn_plot_figure fig = { "convergence", title, "number of elements n",
                            "relative difference from the elastic catenary", 1, 1, "top right",
                            NULL, 4, ser };
    int rc = ctn_plot_mkdir(ctx, dir);
    if (!rc) rc = write_table(ctx, c, dir);
    if (!rc) rc = ctn_plot_write_script(ctx, dir, &fig);
    return rc;
}
