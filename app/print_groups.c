/* The summary's lines for groups and capacity, and the warning when a member is over it. */
#include "app.h"

void ctn_print_groups(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    size_t k = ctn_solution_step_count(s) - 1, e = 0;
    for (size_t g = 0; g < ctn_model_group_count(m); g++) {
        ctn_group_result r;
        if (ctn_solution_group(m, s, k, g, &r)) continue;
        fprintf(out, "group %-12s %zu elements, force %.6g to %.6g %s, max strain %.4g, length %.8g %s, weight %.6g %s",
                r.name, r.elements, r.min_force, r.max_force, ctn_model_force_unit(m), r.max_strain, r.length,
                ctn_model_length_unit(m), r.weight, ctn_model_force_unit(m));
        if (r.has_capacity) fprintf(out, ", max utilisation %.4f (element %d)", r.max_utilisation, r.worst_element);
        if (r.slack) fprintf(out, ", %zu slack", r.slack);
        fputc('\n', out);
    }
    double u = 0;
    ctn_element_info info;
    if (!ctn_solution_worst_utilisation(m, s, k, &e, &u) && !ctn_model_element(m, e, &info))
        fprintf(out, "capacity: max utilisation %.4f at element %d (force / (mbl / safety))%s\n", u, info.id,
                u > 1 ? ": OVER CAPACITY" : "");
    ctn_beam_result b = { .size = sizeof b };
    if (!ctn_solution_worst_beam(m, s, k, &e, &b) && !ctn_model_element(m, e, &info))
        fprintf(out, "beams: max utilisation %.4f at element %d (|N|/A + |My|/Wy + |Mz|/Wz = %.6g over fy %.6g)%s\n",
                b.utilisation, info.id, b.stress, b.fy, b.utilisation > 1 ? ": OVER CAPACITY" : "");
}

/* The warning when a beam's combined stress is over its material's fy. */
static void beam_warning(FILE *out, const char *model, const ctn_model *m, const ctn_solution *s, size_t k)
{
    size_t e = 0, over = 0;
    ctn_beam_result b = { .size = sizeof b };
    ctn_element_info info;
    if (ctn_solution_worst_beam(m, s, k, &e, &b) || !(b.utilisation > 1) || ctn_model_element(m, e, &info)) return;
    for (size_t i = 0; i < ctn_model_element_count(m); i++) {
        ctn_beam_result r = { .size = sizeof r };
        if (!ctn_solution_beam(m, s, k, i, &r) && r.fy > 0 && r.utilisation > 1) over++;
    }
    fprintf(out, "catena: %s: warning: %zu beam element(s) over their yield stress; the worst, element %d, at "
                 "utilisation %.4f (combined stress %.6g, fy %.6g)\n", model, over, info.id, b.utilisation, b.stress, b.fy);
}

void ctn_print_capacity_warning(FILE *out, const char *model, const ctn_model *m, const ctn_solution *s)
{
    size_t e = 0, over = 0, k = ctn_solution_step_count(s) - 1;
    double u = 0;
    ctn_element_info info;
    beam_warning(out, model, m, s, k);
    if (ctn_solution_worst_utilisation(m, s, k, &e, &u) || !(u > 1) || ctn_model_element(m, e, &info)) return;
    for (size_t i = 0; i < ctn_model_element_count(m); i++) {
        ctn_element_info ei;
        ctn_element_state st;
        if (!ctn_model_element(m, i, &ei) && !ctn_solution_step_element(s, k, i, &st) && ctn_utilisation(&ei, &st) > 1) over++;
    }
    fprintf(out, "catena: %s: warning: %zu element(s) over capacity; the worst, element %d, at utilisation %.4f "
                 "(force %.6g, capacity mbl / safety %.6g)\n", model, over, info.id, u, u * info.capacity, info.capacity);
}
