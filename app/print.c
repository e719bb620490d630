/* Human-readable output of the solve command. */
#include "app.h"

#include <math.h>

void ctn_print_iteration(void *data, int it, double rnorm, double dnorm)
{
    ctn_iter_log *lg = data;
    fprintf(lg->out, "               %3d  %-16.6e  %-10.3e", it, rnorm, dnorm);
    if (lg->r[0] > 0 && lg->r[1] > 0 && rnorm > 0 && lg->r[0] != lg->r[1])
        fprintf(lg->out, "  %.2f", log(rnorm / lg->r[0]) / log(lg->r[0] / lg->r[1]));
    fputc('\n', lg->out);
    lg->r[1] = lg->r[0];
    lg->r[0] = rnorm;
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

static void print_reactions(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    const double *r = ctn_solution_reactions(s);
    double sum[3] = { 0, 0, 0 };
    const char *fu = ctn_model_force_unit(m);
    fprintf(out, "reactions%s%s%s      node            fx            fy            fz\n", *fu ? " [" : "", fu, *fu ? "]" : "");
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info n;
        ctn_model_node(m, i, &n);
        if (!n.fix) continue;
        fprintf(out, "                %8d  %12.6g  %12.6g  %12.6g\n", n.id, r[3 * i], r[3 * i + 1], r[3 * i + 2]);
        for (int k = 0; k < 3; k++) sum[k] += r[3 * i + k];
    }
    fprintf(out, "                     sum  %12.6g  %12.6g  %12.6g\n", sum[0], sum[1], sum[2]);
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
        fprintf(out, "start: %d slack chain(s) placed on the arc of their unstressed length\n", sum->preshaped);
    if (sum->relaxed)
        fprintf(out, "start: %d increment(s) began with compression cut off (relaxation)\n", sum->relaxed);
    if (sum->cuts) fprintf(out, "load increments cut back %d time(s)\n", sum->cuts);
    if (sum->floor)
        fprintf(out, "note: converged with the residual at its round-off floor (|dd| at the resolution "
                     "of the coordinates), above tol |f_ext|\n");
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
            sum.ordering == CTN_ORDER_NATURAL ? "natural" : "AMD");
    fprintf(out, "time: setup %.3f s, assembly %.3f s, factorization %.3f s, solves %.3f s "
                 "(factor non-zeros %zu)\n", sum.t_setup, sum.t_assemble, sum.t_factor, sum.t_solve,
            sum.nnz_factor);
    if (sum.reason == CTN_DIVERGED_INDEFINITE)
        fprintf(out, "the tangent has a non-positive pivot at node %d, direction %c: a compressed "
                     "or unrestrained degree of freedom\n", sum.fail_node, "xyz"[sum.fail_dir]);
    print_notes(out, m, &sum);
    print_steps(out, m, s);
    size_t imax, imin;
    force_range(m, s, &imax, &imin);
    print_element_line(out, "max", m, s, imax);
    print_element_line(out, "min", m, s, imin);
    print_slack(out, m, s);
    print_cables(out, m, s);
    print_reactions(out, m, s);
}
