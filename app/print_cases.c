/* Load cases and combinations in the solve command's summary: a line each, and the
 * envelope's extremes. */
#include "app.h"

#include <math.h>

/* Largest and smallest element force of a one-step solution. */
static void extremes(const ctn_model *m, const ctn_solution *cs, double *hi, double *lo, int *ihi)
{
    *hi = -INFINITY, *lo = INFINITY, *ihi = 0;
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_state es;
        ctn_element_info ei;
        if (ctn_solution_step_element(cs, 0, e, &es) || ctn_model_element(m, e, &ei)) continue;
        if (es.force > *hi) *hi = es.force, *ihi = ei.id;
        *lo = fmin(*lo, es.force);
    }
}

void ctn_print_cases(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    size_t n = ctn_solution_case_count(s);
    if (!n) return;
    double gmax = -INFINITY, gmin = INFINITY;
    const char *nmax = "", *nmin = "";
    fprintf(out, "case                    from          iterations  max tension  (element)  min force  result\n");
    for (size_t i = 0; i < n; i++) {
        const ctn_solution *cs = ctn_solution_case(s, i);
        const char *name = "";
        int from = 0, comb = 0, id = 0;
        double hi, lo;
        ctn_step_result st;
        if (ctn_model_case_info(m, i, &name, &from, &comb) || ctn_solution_step(cs, 0, &st)) continue;
        extremes(m, cs, &hi, &lo, &id);
        fprintf(out, "%-11.11s %-11.11s %-13.13s %10d  %11.6g  %9d  %9.6g  %s\n", comb ? "combination" : "case", name,
                *ctn_model_step_name(m, (size_t)from) ? ctn_model_step_name(m, (size_t)from) : "(the step)",
                st.iterations, hi, id, lo, ctn_reason_name(st.reason));
        if (st.reason != CTN_CONVERGED) continue;
        if (hi > gmax) gmax = hi, nmax = name;
        if (lo < gmin) gmin = lo, nmin = name;
    }
    if (isfinite(gmax)) fprintf(out, "envelope: max force %.10g (%s), min force %.10g (%s)\n", gmax, nmax, gmin, nmin);
    for (size_t i = 0; i < n; i++) {
        ctn_step_result st;
        int comb = 0;
        if (ctn_model_case_info(m, i, NULL, NULL, &comb) || ctn_solution_step(ctn_solution_case(s, i), 0, &st) ||
            st.reason == CTN_CONVERGED)
            continue;
        fprintf(out, "not converged: %s '%s': %s at load factor %.6g (its last converged state is written)\n",
                comb ? "combination" : "case", st.name, ctn_reason_name(st.reason), st.load_factor);
    }
}

int ctn_cases_converged(const ctn_solution *s, const char **failed)
{
    for (size_t i = 0; i < ctn_solution_case_count(s); i++) {
        ctn_step_result st;
        if (ctn_solution_step(ctn_solution_case(s, i), 0, &st) || st.reason == CTN_CONVERGED) continue;
        *failed = st.name;
        return 0;
    }
    return 1;
}

/* The largest |d - base| over the nodes (base NULL: from the reference geometry) and
 * its node's id. */
static double largest(const ctn_model *m, const double *d, const double *base, int *id)
{
    double big = 0;
    size_t at = 0;
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        double u[3];
        for (int k = 0; k < 3; k++) u[k] = d[3 * i + (size_t)k] - (base ? base[3 * i + (size_t)k] : 0);
        double n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        if (n > big) big = n, at = i;
    }
    ctn_node_info p;
    *id = ctn_model_node(m, at, &p) ? 0 : p.id;
    return big;
}

void ctn_print_displacements(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    size_t ns = ctn_solution_step_count(s), nc = ctn_solution_case_count(s);
    if (!ctn_model_node_count(m)) return;
    fprintf(out, "displacement           name          largest |u|       node  measured from\n");
    for (size_t k = 0; k < ns; k++) {
        ctn_step_result st;
        int id = 0;
        if (ctn_solution_step(s, k, &st)) continue;
        double u = largest(m, st.d, NULL, &id);
        fprintf(out, "%-22s %-13.13s %-17.10g %5d  the reference geometry\n", "step", *st.name ? st.name : "(the step)",
                u, id);
    }
    for (size_t i = 0; i < nc; i++) {
        ctn_step_result st, base;
        const char *name = "";
        int from = 0, comb = 0, id = 0;
        if (ctn_model_case_info(m, i, &name, &from, &comb) || ctn_solution_step(ctn_solution_case(s, i), 0, &st) ||
            ctn_solution_step(s, (size_t)from, &base))
            continue;
        double u = largest(m, st.d, base.d, &id);
        const char *fn = ctn_model_step_name(m, (size_t)from);
        fprintf(out, "%-22s %-13.13s %-17.10g %5d  the installed state, step %s\n", comb ? "combination" : "case", name, u,
                id, *fn ? fn : "(the step)");
    }
}
