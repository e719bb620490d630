/* Human-readable output of the solve command. */
#include "app.h"

#include <math.h>
#include <string.h>

void ctn_print_iteration(void *data, const ctn_iterate *it)
{
    ctn_iter_log *lg = data;
    fprintf(lg->out, "               %3d  %-16.6e  %-10.3e", it->iteration, it->residual, it->increment);
    if (it->rejected) {                             /* the state stays: no order */
        fprintf(lg->out, "  rejected (shift %.3g)\n", it->shift);
        return;
    }
    if (lg->r[0] > 0 && lg->r[1] > 0 && it->residual > 0 && lg->r[0] != lg->r[1])
        fprintf(lg->out, "  %.2f", log(it->residual / lg->r[0]) / log(lg->r[0] / lg->r[1]));
    fputc('\n', lg->out);
    lg->r[1] = lg->r[0];
    lg->r[0] = it->residual;
}

/* Largest and smallest element force; indices in *imax, *imin. */
static void force_range(const ctn_model *m, const ctn_solution *s, size_t *imax, size_t *imin)
{
    ctn_element_state st, best, worst;
    *imax = *imin = 0;
    ctn_solution_element(s, 0, &best);
    worst = best;
    for (size_t e = 1; e < ctn_model_element_count(m); e++) {
        ctn_solution_element(s, e, &st);
        if (st.force > best.force) { best = st; *imax = e; }
        if (st.force < worst.force) { worst = st; *imin = e; }
    }
}

static void print_element_line(FILE *out, const char *label, const ctn_model *m,
                               const ctn_solution *s, size_t e)
{
    ctn_element_info info;
    ctn_element_state st;
    ctn_model_element(m, e, &info);
    ctn_solution_element(s, e, &st);
    double mpa = ctn_model_mpa_factor(m);
    if (!info.has_section) {                        /* a spring: a force, no stress */
        fprintf(out, "%s tension %12.6g %-3s (%s %d)\n", label, st.force, ctn_model_force_unit(m), info.type, info.id);
        return;
    }
    fprintf(out, "%s tension %12.6g %-3s stress %12.6g %s (element %d)\n", label, st.force,
            ctn_model_force_unit(m), mpa > 0 ? st.stress * mpa : st.stress,
            mpa > 0 ? "MPa" : "(model units)", info.id);
}

static void print_cables(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    for (size_t i = 0; i < ctn_model_cable_count(m); i++) {
        ctn_cable_info c;
        ctn_node_info a, b;
        double sag, dmax;
        ctn_model_cable(m, i, &c);
        ctn_model_node(m, (size_t)c.node[0], &a);
        ctn_model_node(m, (size_t)c.node[1], &b);
        fprintf(out, "cable %d-%d: %zu elements, unstressed length %.10g %s", a.id, b.id,
                c.count, c.length, ctn_model_length_unit(m));
        if (!ctn_solution_cable_sag(m, s, i, &sag))
            fprintf(out, ", mid-span sag %.10g %s", sag, ctn_model_length_unit(m));
        if (!ctn_solution_cable_max_sag_from_chord(m, s, i, &dmax))
            fprintf(out, ", max sag from chord %.10g %s", dmax, ctn_model_length_unit(m));
        fputc('\n', out);
    }
}

/* Tension-only elements that carry no force. */
static void print_slack(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    size_t count = 0;
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_state st;
        ctn_element_info info;
        ctn_solution_element(s, e, &st);
        if (!st.slack) continue;
        ctn_model_element(m, e, &info);
        if (count < 20) fprintf(out, "%s%d", count ? " " : "slack elements: ", info.id);
        count++;
    }
    if (count > 20) fprintf(out, " ... (%zu in all)", count);
    if (count) fputc('\n', out);
}

static void print_steps(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    size_t n = ctn_solution_step_count(s);
    if (n < 2) return;
    fprintf(out, "step                    load factor  iterations  max tension  result\n");
    for (size_t k = 0; k < n; k++) {
        ctn_step_result st;
        double nmax = -INFINITY;
        ctn_solution_step(s, k, &st);
        for (size_t e = 0; e < ctn_model_element_count(m); e++) {
            ctn_element_state es;
            ctn_solution_step_element(s, k, e, &es);
            nmax = fmax(nmax, es.force);
        }
        fprintf(out, "%-22.22s  %11.6g  %10d  %11.6g  %s\n", st.name, st.load_factor,
                st.iterations, nmax, ctn_reason_name(st.reason));
    }
}

/* How the run went, beyond the reason: start, cut-backs, floor, where it stopped. */
static void print_notes(FILE *out, const ctn_model *m, const ctn_solve_summary *sum)
{
    if (sum->preshaped)
        fprintf(out, "start: %d slack chain(s) or junction(s) pre-shaped (on the arc of their unstressed length, hanging along their loads, or on the catenaries of a junction's cables)\n", sum->preshaped);
    if (sum->fdensity)
        fprintf(out, "start: the net's free nodes moved towards the shape of its start forces held as force densities\n");
    if (sum->relaxed)
        fprintf(out, "start: %d increment(s) began with compression cut off (relaxation)\n", sum->relaxed);
    if (sum->cuts) fprintf(out, "load increments cut back %d time(s)\n", sum->cuts);
    if (sum->floor) {
        const char *name = ctn_model_step_name(m, sum->floor_step);
        fprintf(out, "note: step %zu%s%s%s converged with the residual at its round-off floor "
                     "(|dd| at the resolution of the coordinates, |r| within the computed floor %.3e, "
                     "above tol |f_ext|)\n", sum->floor_step + 1, *name ? " (" : "", name, *name ? ")" : "",
                sum->residual_floor);
    }
    if (sum->reason == CTN_DIVERGED_ROUNDOFF)
        fprintf(out, "the residual cannot fall below its round-off floor %.3e (%.3g of the forces meeting "
                     "at the nodes, %.3g |f_ext|): the stiffness is too large for these loads to be "
                     "resolved in double precision\n", sum->residual_floor,
                sum->force_scale > 0 ? sum->residual_floor / sum->force_scale : INFINITY,
                sum->residual_floor / sum->fext_norm);
    if (sum->reason != CTN_CONVERGED) {
        const char *name = ctn_model_step_name(m, sum->step);
        fprintf(out, "last converged state: load factor %.6g of step %zu%s%s%s (written as the result)\n",
                sum->load_factor, sum->step + 1, *name ? " (" : "", name, *name ? ")" : "");
    }
}

void ctn_print_summary(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    fprintf(out, "%s after %d iterations: |r| = %.3e (|f_ext| = %.6g), %zu free DOFs, ordering %s\n",
            ctn_reason_name(sum.reason), sum.iterations, sum.residual, sum.fext_norm, sum.ndof,
            ctn_ordering_name(sum.ordering));
    fprintf(out, "time: setup %.3f s, assembly %.3f s, factorization %.3f s (%d; CPU %.3f s, %d thread%s), "
                 "solves %.3f s (%d%s)\n", sum.t_setup, sum.t_assemble, sum.t_factor, sum.factorizations,
            sum.t_factor_cpu, sum.threads, sum.threads == 1 ? "" : "s", sum.t_solve, sum.solves,
            sum.solve_threads > 1 ? "; 2 threads" : "");
    fprintf(out, "factor: %zu non-zeros, %.3g flops; BLAS %s\n", sum.nnz_factor, sum.flops_factor, sum.blas);
    if (sum.reason == CTN_DIVERGED_INDEFINITE)
        fprintf(out, "the tangent has a non-positive pivot at node %d, direction %s: a compressed "
                     "or unrestrained degree of freedom\n", sum.fail_node, ctn_dof_name(sum.fail_dir));
    if (sum.reason == CTN_DIVERGED_MECHANISM)
        fprintf(out, "the loads move node %d without bound along %s: nothing restrains that motion, so the model "
                     "has no equilibrium (check the supports' fix= and the members at that node)\n",
                sum.fail_node, ctn_dof_name(sum.fail_dir));
    print_notes(out, m, &sum);
    print_steps(out, m, s);
    ctn_print_cases(out, m, s);
    ctn_print_displacements(out, m, s);
    size_t imax, imin;
    force_range(m, s, &imax, &imin);
    print_element_line(out, "max", m, s, imax);
    print_element_line(out, "min", m, s, imin);
    print_slack(out, m, s);
    print_cables(out, m, s);
    ctn_print_groups(out, m, s);
    ctn_print_modes(out, m, s);
    ctn_print_buckling(out, m, s);
    ctn_print_dynamics(out, m, s);
}

void ctn_print_stability(FILE *out, const char *model, const ctn_solution *s)
{
    ctn_stability st;
    if (ctn_solution_stability(s, &st) || st.stable) return;
    char where[64] = "";
    if (st.node) snprintf(where, sizeof where, " at node %d, direction %s", st.node, ctn_dof_name(st.dir));
    if (st.semidefinite)
        fprintf(out, "catena: %s: warning: the equilibrium is not stable: the tangent stiffness is singular "
                     "(semi-definite)%s: a node held only by slack members, or a mechanism\n", model, where);
    else
        fprintf(out, "catena: %s: warning: unstable equilibrium: the tangent stiffness has %ld negative "
                     "eigenvalue(s); the weakest mode moves%s\n", model, st.negative, where);
}

/* The strain of largest magnitude (signed) of the members with a material that carry it
 * (a slack tension-only member's negative strain is the chord's slackness, not a
 * strain of its material), and its element index. */
static double max_strain(const ctn_model *m, const ctn_solution *s, size_t *at)
{
    double best = 0;
    *at = 0;
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_info info;
        ctn_element_state st;
        if (ctn_model_element(m, e, &info) || !info.has_section || ctn_solution_element(s, e, &st) || st.slack)
            continue;
        if (fabs(st.strain) > fabs(best)) {
            best = st.strain;
            *at = e;
        }
    }
    return best;
}

/* Largest coordinate of the deformed model, in metres when the model has units. */
static double max_extent(const ctn_model *m, const ctn_solution *s)
{
    const double *d = ctn_solution_displacements(s);
    const char *L = ctn_model_length_unit(m);
    double big = 0, scale = !strcmp(L, "mm") ? 1e-3 : !strcmp(L, "ft") ? 0.3048 : !strcmp(L, "in") ? 0.0254 : 1.0;
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info n;
        ctn_model_node(m, i, &n);
        for (int k = 0; k < 3; k++) big = fmax(big, fabs(n.X[k] + d[3 * i + (size_t)k]));
    }
    return big * scale;
}

void ctn_print_warnings(FILE *out, const char *model, const ctn_model *m, const ctn_solution *s)
{
    size_t at;
    double eps = max_strain(m, s, &at), big = max_extent(m, s);
    if (fabs(eps) > 0.1) {
        ctn_element_info info;
        ctn_model_element(m, at, &info);
        fprintf(out, "catena: %s: warning: element %d has a strain of %.3g (%s above 10 %%): far beyond an elastic "
                     "cable; check E, the loads and the units\n", model, info.id, eps,
                eps > 0 ? "an elongation" : "a shortening");
    }
    if (big > 1e7)
        fprintf(out, "catena: %s: warning: the deformed model reaches %.3g m from the origin (over 10,000 km); "
                     "check the lengths, the loads and the units\n", model, big);
    ctn_print_capacity_warning(out, model, m, s);
}
