/* The modal analysis in the solve command's summary: one line per mode. */
#include "app.h"

#include <string.h>

/* The consistent mass unit, force s^2 / length, by name ("" without units). */
static const char *mass_unit(const ctn_model *m)
{
    static const char *const f[3] = { "N", "kN", "MN" }, *const names[2][3] = {
        { "kg", "t", "kt" },                          /* per m: N s^2/m = kg */
        { "t", "kt", "Mt" } };                        /* per mm: N s^2/mm = t */
    const char *L = ctn_model_length_unit(m), *F = ctn_model_force_unit(m);
    int lm = !strcmp(L, "mm"), us = !strcmp(F, "lbf") ? 0 : !strcmp(F, "kip") ? 1 : -1;
    if (us >= 0 && !strcmp(L, "ft")) return us ? "kslug" : "slug";      /* lbf s^2/ft = slug */
    if (us >= 0 && !strcmp(L, "in")) return us ? "kip s^2/in" : "lbf s^2/in";
    for (int i = 0; i < 3; i++)
        if (!strcmp(ctn_model_force_unit(m), f[i])) return names[lm][i];
    return "";
}

static void mode_line(FILE *out, size_t k, const ctn_mode *md)
{
    fprintf(out, "%6zu %-9s %14.8g %12.6g %14.8g %12.4g %12.4g %12.4g %8d\n", k + 1,
            md->kind == CTN_MODE_VIBRATION ? "" : ctn_mode_kind_name(md->kind),
            md->frequency, md->period, md->angular_frequency, md->effective_mass[0], md->effective_mass[1],
            md->effective_mass[2], md->node);
    if (md->kind != CTN_MODE_ZERO) return;
    fprintf(out, "       a mechanism or rigid-body motion: %d node(s) move:", md->nnodes);
    for (int i = 0; i < md->nnodes && i < CTN_MODE_MAX_NODES; i++) fprintf(out, " %d", md->nodes[i]);
    fprintf(out, "%s\n", md->nnodes > CTN_MODE_MAX_NODES ? " ..." : "");
}

void ctn_print_modes(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    ctn_modal_summary ms;
    if (ctn_solution_modal_summary(s, &ms)) return;
    const char *mu = mass_unit(m);
    fprintf(out, "modes (%s mass, %d %s): %d factorization(s), %d solves, %d Lanczos restarts, "
                 "max |K phi - w^2 M phi| / |K phi| %.1e\n",
            ms.mass == CTN_MASS_LUMPED ? "lumped" : "consistent", ms.count,
            ms.shift > 0 ? "nearest the shift" : "lowest", ms.factorizations, ms.solves, ms.lanczos_restarts,
            ms.max_residual);
    if (ms.reused_factor) fprintf(out, "shift-invert: sigma = 0 on the stability check's factor of K_T (no factorization)\n");
    if (ms.solver == CTN_EIGEN_ARPACK && ms.block_solves > 0)
        fprintf(out, "eigen-solver: arpack, after the block solver did not converge in %d block solves\n", ms.block_solves);
    else if (ms.solver == CTN_EIGEN_ARPACK) fprintf(out, "eigen-solver: arpack (one vector per solve)\n");
    else if (ms.solver == CTN_EIGEN_SLEPC) fprintf(out, "eigen-solver: SLEPc Krylov-Schur, shift-invert on MUMPS\n");
    else fprintf(out, "eigen-solver: block Lanczos, blocks of %d, %d block solves\n", ms.block_size, ms.block_solves);
    fprintf(out, "modal time: %.3f s (tangent and mass %.3f s, factorization %.3f s, solves %.3f s), CPU %.3f s "
                 "(solves %.3f s)\n", ms.t_total, ms.t_assemble, ms.t_factor, ms.t_solve, ms.t_cpu, ms.t_solve_cpu);
    fprintf(out, "moving mass [%s]: x %.6g, y %.6g, z %.6g\n", *mu ? mu : "model units", ms.total_mass[0],
            ms.total_mass[1], ms.total_mass[2]);
    fprintf(out, "  mode %-9s %14s %12s %14s %12s %12s %12s %8s\n", "", "frequency [Hz]", "period [s]", "omega [rad/s]",
            "eff. mass x", "eff. mass y", "eff. mass z", "node");
    for (size_t k = 0; k < ctn_solution_mode_count(s); k++) {
        ctn_mode md;
        ctn_solution_mode(s, k, &md);
        mode_line(out, k, &md);
    }
}
