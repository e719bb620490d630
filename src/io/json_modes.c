/* The modal analysis in the result JSON: "modal" (the analysis as a whole) and "modes"
 * (docs/format.md, "Results"). Only the public accessors; numbers as the JSON writer
 * prints them. */
#include "io/json_modes.h"

#include <math.h>

static void xyz_object(ctn_jw *j, const char *key, const double v[3])
{
    ctn_jw_object(j, key);
    ctn_jw_number(j, "x", v[0]);
    ctn_jw_number(j, "y", v[1]);
    ctn_jw_number(j, "z", v[2]);
    ctn_jw_end(j);
}

static void put_modal(ctn_jw *j, const ctn_modal_summary *ms)
{
    ctn_jw_object(j, "modal");
    ctn_jw_number(j, "count", ms->count);
    ctn_jw_string(j, "mass", ms->mass == CTN_MASS_LUMPED ? "lumped" : "consistent");
    ctn_jw_number(j, "shift", ms->shift);
    ctn_jw_number(j, "sigma", ms->sigma);
    xyz_object(j, "total_mass", ms->total_mass);
    ctn_jw_number(j, "zero_modes", ms->zero_modes);
    ctn_jw_number(j, "unstable_modes", ms->unstable_modes);
    ctn_jw_number(j, "lanczos_restarts", ms->lanczos_restarts);
    ctn_jw_number(j, "factorizations", ms->factorizations);
    ctn_jw_number(j, "solves", ms->solves);
    ctn_jw_number(j, "max_residual", ms->max_residual);
    ctn_jw_string(j, "solver", ms->solver == CTN_EIGEN_ARPACK ? "arpack" : ms->solver == CTN_EIGEN_SLEPC ? "slepc" : "block");
    ctn_jw_number(j, "block_size", ms->block_size);
    ctn_jw_number(j, "block_solves", ms->block_solves);
    ctn_jw_number(j, "max_floor", ms->max_floor);
    ctn_jw_bool(j, "reused_factor", ms->reused_factor);
    ctn_jw_end(j);
}

void ctn_json_put_shape(ctn_jw *j, const ctn_model *m, const double *shape)
{
    ctn_jw_array(j, "shape");
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info n;
        ctn_model_node(m, i, &n);
        ctn_jw_object(j, NULL);
        ctn_jw_number(j, "node", n.id);
        ctn_jw_number(j, "ux", shape[3 * i]);
        ctn_jw_number(j, "uy", shape[3 * i + 1]);
        ctn_jw_number(j, "uz", shape[3 * i + 2]);
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
}

static void put_mode(ctn_jw *j, const ctn_model *m, size_t k, const ctn_mode *md)
{
    ctn_jw_object(j, NULL);
    ctn_jw_number(j, "mode", (double)(k + 1));
    ctn_jw_string(j, "kind", ctn_mode_kind_name(md->kind));
    ctn_jw_number(j, "frequency", md->frequency);
    ctn_jw_number(j, "period", md->period);
    ctn_jw_number(j, "angular_frequency", md->angular_frequency);
    ctn_jw_number(j, "eigenvalue", md->eigenvalue);
    xyz_object(j, "participation", md->participation);
    xyz_object(j, "effective_mass", md->effective_mass);
    ctn_jw_number(j, "node", md->node);
    if (md->kind == CTN_MODE_ZERO) {
        ctn_jw_number(j, "moving_nodes", md->nnodes);
        ctn_jw_array(j, "nodes");
        for (int i = 0; i < md->nnodes && i < CTN_MODE_MAX_NODES; i++) ctn_jw_number(j, NULL, md->nodes[i]);
        ctn_jw_end(j);
    }
    ctn_json_put_shape(j, m, md->shape);
    ctn_jw_end(j);
}

void ctn_json_put_modes(ctn_jw *j, const ctn_model *m, const ctn_solution *s)
{
    ctn_modal_summary ms;
    if (ctn_solution_modal_summary(s, &ms)) return;
    put_modal(j, &ms);
    ctn_jw_array(j, "modes");
    for (size_t k = 0; k < ctn_solution_mode_count(s); k++) {
        ctn_mode md;
        ctn_solution_mode(s, k, &md);
        put_mode(j, m, k, &md);
    }
    ctn_jw_end(j);
}

int ctn_modes_finite(const ctn_model *m, const ctn_solution *s)
{
    size_t nn = ctn_model_node_count(m);
    for (size_t k = 0; k < ctn_solution_mode_count(s); k++) {
        ctn_mode md;
        ctn_solution_mode(s, k, &md);
        double v[10] = { md.frequency, md.period, md.angular_frequency, md.eigenvalue, md.participation[0],
                         md.participation[1], md.participation[2], md.effective_mass[0], md.effective_mass[1],
                         md.effective_mass[2] };
        for (int i = 0; i < 10; i++)
            if (!isfinite(v[i])) return 0;
        for (size_t i = 0; i < 3 * nn; i++)
            if (!isfinite(md.shape[i])) return 0;
    }
    ctn_modal_summary ms;
    return ctn_solution_modal_summary(s, &ms) || (isfinite(ms.sigma) && isfinite(ms.max_residual) &&
           isfinite(ms.total_mass[0] + ms.total_mass[1] + ms.total_mass[2]));
}
