/* The dynamics analysis in the result JSON: "dynamics" with the method and its
 * parameters, the counts, "t" (every row's time), "histories" (an array of numbers per
 * recorded column, by its name "ID.ux", "ID.force") and "energy" (kinetic, strain, work,
 * damping per row). docs/format.md, "Dynamics". */
#include "io/json_dynamics.h"

#include "catena/analysis.h"

#include <math.h>

/* Column c (0: t) of the rows x w table v, as an array. */
static void column(ctn_jw *j, const char *key, const double *v, size_t rows, size_t w, size_t c)
{
    ctn_jw_array(j, key);
    for (size_t r = 0; r < rows; r++) ctn_jw_number(j, NULL, v[r * w + c]);
    ctn_jw_end(j);
}

static void put_parameters(ctn_jw *j, const ctn_dynamics_summary *d)
{
    ctn_jw_string(j, "method", ctn_dyn_method_name(d->method));
    ctn_jw_number(j, "dt", d->dt);
    ctn_jw_number(j, "t_end", d->t_end);
    ctn_jw_number(j, "steps", (double)d->steps);
    ctn_jw_bool(j, "converged", d->reason == CTN_CONVERGED);
    ctn_jw_number(j, "t_reached", d->t_reached);
    if (d->reason != CTN_CONVERGED) ctn_jw_number(j, "t_fail", d->t_fail);
    if (d->method == CTN_DYN_GENALPHA || d->method == CTN_DYN_HHT) ctn_jw_number(j, "rho_inf", d->rho_inf);
    ctn_jw_number(j, "alpha_m", d->alpha_m);
    ctn_jw_number(j, "alpha_f", d->alpha_f);
    ctn_jw_number(j, "gamma", d->gamma);
    ctn_jw_number(j, "beta", d->beta);
    ctn_jw_string(j, "mass", d->mass == CTN_MASS_LUMPED ? "lumped" : "consistent");
    ctn_jw_number(j, "damping_alpha", d->damping_alpha);
    ctn_jw_number(j, "damping_beta", d->damping_beta);
    if (d->method == CTN_DYN_CENTRAL) ctn_jw_number(j, "dt_stable", d->dt_stable);
    ctn_jw_number(j, "iterations", d->iterations);
    ctn_jw_number(j, "factorizations", d->factorizations);
    ctn_jw_number(j, "cuts", d->cuts);
    ctn_jw_number(j, "substeps", d->substeps);
    ctn_jw_number(j, "energy_error", d->energy_error);
    if (d->output_every > 1) ctn_jw_number(j, "output_every", d->output_every);
    if (d->frames) ctn_jw_number(j, "frames", (double)d->frames);
    if (d->modal_count) ctn_jw_number(j, "modal_damping_modes", d->modal_count);
    if (d->relative_wind) ctn_jw_number(j, "relative_wind_elements", d->relative_wind);
}

void ctn_json_put_dynamics(ctn_jw *j, const ctn_solution *s)
{
    ctn_dynamics_summary d;
    size_t rows, cols;
    if (ctn_solution_dynamics_summary(s, &d)) return;
    const double *h = ctn_solution_history(s, &rows, &cols), *e = ctn_solution_energy(s, NULL);
    ctn_jw_object(j, "dynamics");
    put_parameters(j, &d);
    column(j, "t", h, rows, cols + 1, 0);
    ctn_jw_object(j, "histories");
    for (size_t c = 0; c < cols; c++) column(j, ctn_solution_history_name(s, c), h, rows, cols + 1, c + 1);
    ctn_jw_end(j);
    ctn_jw_object(j, "energy");
    static const char *const names[4] = { "kinetic", "strain", "work", "damping" };
    for (size_t c = 0; c < 4; c++) column(j, names[c], e, rows, 4, c);
    ctn_jw_end(j);
    ctn_jw_end(j);
}

int ctn_dynamics_finite(const ctn_solution *s)
{
    ctn_dynamics_summary d;
    size_t rows, cols;
    if (ctn_solution_dynamics_summary(s, &d)) return 1;
    const double *h = ctn_solution_history(s, &rows, &cols), *e = ctn_solution_energy(s, NULL);
    for (size_t i = 0; i < rows * (cols + 1); i++)
        if (!isfinite(h[i])) return 0;
    for (size_t i = 0; i < rows * 4; i++)
        if (!isfinite(e[i])) return 0;
    for (size_t k = 0; k < ctn_solution_frame_count(s); k++) {
        ctn_dyn_frame f;
        ctn_solution_frame(s, k, &f);
        size_t nn = f.nodes, ne = f.elements;
        for (size_t i = 0; i < 3 * nn; i++)
            if (!isfinite(f.d[i]) || !isfinite(f.v[i]) || !isfinite(f.react[i])) return 0;
        for (size_t i = 0; i < ne; i++)
            if (!isfinite(f.force[i])) return 0;
    }
    return isfinite(d.energy_error) && isfinite(d.dt_stable);
}
