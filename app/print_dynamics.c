/* The dynamics analysis in the solve command's summary: the method, the steps, the
 * energy balance at the end, the last row of the recorded histories; on stderr, where
 * a time step failed. */
#include "app.h"

void ctn_print_dynamics(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    (void)m;
    ctn_dynamics_summary d;
    size_t rows, cols;
    if (ctn_solution_dynamics_summary(s, &d)) return;
    const double *h = ctn_solution_history(s, &rows, &cols), *e = ctn_solution_energy(s, NULL);
    fprintf(out, "dynamics (%s, dt %g s, %s mass): %zu steps to t = %g s (%d substeps, %d halvings of dt), "
                 "%d iterations, %d factorizations, time %.3f s\n",
            ctn_dyn_method_name(d.method), d.dt, d.mass == CTN_MASS_LUMPED ? "lumped" : "consistent", d.steps,
            d.t_reached, d.substeps, d.cuts, d.iterations, d.factorizations, d.t_total);
    if (d.method == CTN_DYN_GENALPHA || d.method == CTN_DYN_HHT)
        fprintf(out, "  rho_inf %g: alpha_m %.6g, alpha_f %.6g, gamma %.6g, beta %.6g\n", d.rho_inf, d.alpha_m, d.alpha_f,
                d.gamma, d.beta);
    if (d.method == CTN_DYN_CENTRAL) fprintf(out, "  stable step of the mesh %.6g s\n", d.dt_stable);
    if (d.damping_alpha > 0 || d.damping_beta > 0)
        fprintf(out, "  Rayleigh damping: alpha %.6g 1/s, beta %.6g s\n", d.damping_alpha, d.damping_beta);
    if (d.modal_count) fprintf(out, "  modal damping: the %d lowest modes about the start\n", d.modal_count);
    if (d.relative_wind) fprintf(out, "  wind drag on the relative velocity: %d elements\n", d.relative_wind);
    if (d.output_every > 1 || d.frames) {
        fprintf(out, "  output: %zu rows (every %d steps, and the last)", rows, d.output_every);
        if (d.frames) fprintf(out, ", %zu frames for the VTU series", d.frames);
        fputc('\n', out);
    }
    if (rows) {
        const double *en = e + 4 * (rows - 1);
        fprintf(out, "  energy at t = %g: kinetic %.6g, strain %.6g, work of loads %.6g, damping %.6g; balance error "
                     "%.2e (largest over the steps, relative)\n", h[(rows - 1) * (cols + 1)], en[0], en[1], en[2], en[3],
                d.energy_error);
    }
    for (size_t c = 0; rows && c < cols; c++)
        fprintf(out, "  %-14s %.10g at t = %g\n", ctn_solution_history_name(s, c), h[(rows - 1) * (cols + 1) + c + 1],
                h[(rows - 1) * (cols + 1)]);
}

void ctn_print_dynamics_failure(FILE *out, const char *model, const ctn_solution *s)
{
    ctn_dynamics_summary d;
    if (ctn_solution_dynamics_summary(s, &d) || d.reason == CTN_CONVERGED) return;
    fprintf(out, "catena: %s: dynamics: the time step from t = %.10g s did not converge with dt halved %d times "
                 "(to %g s); the histories stop at t = %.10g s\n", model, d.t_fail, d.cuts, d.dt / (double)(1u << (d.cuts > 30 ? 30 : d.cuts)),
            d.t_reached);
}
