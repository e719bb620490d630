/* Helpers of the modal study: solving, classifying cable modes, Irvine's formulas,
 * figures. */
#include "modal_study.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

int study_solve(study_run *r, const char *text)
{
    ctn_solve_options opt;
    ctn_solve_summary sum;
    memset(r, 0, sizeof *r);
    if (ctn_ctx_create(&r->ctx)) return CTN_ERR_NOMEM;
    int rc = ctn_read_string(r->ctx, "study.cable", text, strlen(text), &r->m, &opt);
    if (!rc) rc = ctn_solve(r->ctx, r->m, &opt, &r->s);
    if (!rc) ctn_solution_summary(r->s, &sum);
    if (!rc && (sum.reason != CTN_CONVERGED || !ctn_solution_mode_count(r->s))) rc = CTN_ERR_NOCONV;
    if (rc) fprintf(stderr, "modal_study: %s\n", *ctn_ctx_message(r->ctx) ? ctn_ctx_message(r->ctx) : "not converged");
    return rc;
}

void study_free(study_run *r)
{
    ctn_solution_destroy(&r->s);
    ctn_model_destroy(&r->m);
    ctn_ctx_destroy(&r->ctx);
}

double study_freq(const study_run *r, size_t k)
{
    ctn_mode md;
    return ctn_solution_mode(r->s, k, &md) ? NAN : md.frequency;
}

int study_classify(const study_run *r, size_t k)
{
    ctn_mode md;
    if (ctn_solution_mode(r->s, k, &md)) return 2;
    size_t nn = ctn_model_node_count(r->m);
    double inplane = 0, outplane = 0, sym = 0, anti = 0;
    for (size_t i = 2; i < nn; i++) {
        const double *u = md.shape + 3 * i, *v = md.shape + 3 * (nn + 1 - i);   /* the mirror node */
        inplane += u[0] * u[0] + u[1] * u[1];
        outplane += u[2] * u[2];
        sym += (u[1] - v[1]) * (u[1] - v[1]);
        anti += (u[1] + v[1]) * (u[1] + v[1]);
    }
    if (outplane > inplane) return 0;
    return sym < anti ? 1 : -1;
}

void study_first_kinds(const study_run *r, double f0, double *sym, double *anti, double *out)
{
    *sym = *anti = *out = 0;
    for (size_t k = 0; k < ctn_solution_mode_count(r->s); k++) {
        int c = study_classify(r, k);
        double wbar = study_freq(r, k) / f0;
        if (c == 1 && !*sym) *sym = wbar;
        if (c == -1 && !*anti) *anti = wbar;
        if (c == 0 && !*out) *out = wbar;
    }
}

double irvine_symmetric(double l2)
{
    double lo = PI / 2 + 1e-12, hi = 3 * PI / 2 - 1e-12;
    for (int it = 0; it < 200; it++) {                  /* bisection on sin x - cos x (x - 4x^3/l2) */
        double x = 0.5 * (lo + hi), gx = sin(x) - cos(x) * (x - 4 * x * x * x / l2);
        double glo = sin(lo) - cos(lo) * (lo - 4 * lo * lo * lo / l2);
        if ((gx > 0) == (glo > 0)) lo = x;
        else hi = x;
    }
    return lo + hi;                                     /* w = 2 x */
}

void irvine_parameters(const study_run *r, double L, double w, double EA, double *l2, double *f0)
{
    double H = fabs(ctn_solution_reactions(r->s)[0]), d = 0;
    ctn_solution_cable_sag(r->m, r->s, 0, &d);
    double Le = L * (1 + 8 * (d / L) * (d / L));        /* Irvine's L_e of a level span */
    *l2 = pow(w * L / H, 2) * L / (H * Le / EA);
    *f0 = sqrt(H / (w / 9.80665)) / L / (2 * PI);
}

int study_data(ctn_ctx *ctx, const char *dir, const char *file, const char *header, size_t ncol,
               size_t nrow, const double *d)
{
    int rc = ctn_plot_write_data(ctx, dir, file, header, ncol, nrow, d);
    if (rc) fprintf(stderr, "modal_study: %s\n", ctn_ctx_message(ctx));
    return rc;
}

int study_figure(ctn_ctx *ctx, const char *dir, const ctn_plot_figure *f)
{
    int rendered = 0, rc = ctn_plot_write_script(ctx, dir, f);
    if (!rc) rc = ctn_plot_render(ctx, dir, f->name, &rendered);
    if (rc) fprintf(stderr, "modal_study: %s\n", ctn_ctx_message(ctx));
    else printf("figure: %s/%s.%s\n", dir, f->name, rendered ? "svg" : "gp (gnuplot not found)");
    return rc;
}
