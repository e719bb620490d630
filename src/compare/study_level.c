/* Error of the catenary against the FEA at a given stress level (taut branch). */
#include "compare/study.h"

#include <math.h>
#include <string.h>

#define BOTH ((1u << CTN_FORM_FEA) | (1u << CTN_FORM_CATENARY))

size_t ctn_study_taut_end(const ctn_study *s)
{
    size_t end = 0;
    double best = INFINITY;
    for (size_t i = 0; i < s->n; i++)
        if ((s->row[i].present & BOTH) == BOTH && s->row[i].v[CTN_FORM_FEA].stress_max < best) {
            best = s->row[i].v[CTN_FORM_FEA].stress_max;
            end = i;
        }
    return end;
}

static double level_of(const ctn_study_row *r, ctn_level_axis axis)
{
    return r->v[axis == CTN_LEVEL_FEA ? CTN_FORM_FEA : CTN_FORM_CATENARY].stress_max;
}

/* Errors and stresses of one row: L0, stress_fea, stress_cat, err_max, err_min, err_sag. */
static void row_point(const ctn_study_row *r, double p[6])
{
    const ctn_compare_values *f = &r->v[CTN_FORM_FEA], *c = &r->v[CTN_FORM_CATENARY];
    p[0] = r->L0;
    p[1] = f->stress_max;
    p[2] = c->stress_max;
    p[3] = ctn_compare_rel(c->stress_max, f->stress_max);
    p[4] = ctn_compare_rel(c->stress_min, f->stress_min);
    p[5] = ctn_compare_rel(c->sag, f->sag);
}

int ctn_study_level_at(const ctn_study *s, ctn_level_axis axis, double stress,
                       ctn_study_level *out)
{
    if (!out) return CTN_ERR_INVALID;
    memset(out, 0, sizeof *out);
    if (!s || !(stress > 0) || (axis != CTN_LEVEL_FEA && axis != CTN_LEVEL_CATENARY)) return CTN_ERR_INVALID;
    out->stress = stress;
    size_t end = ctn_study_taut_end(s);
    for (size_t i = 0; i + 1 <= end; i++) {
        const ctn_study_row *a = &s->row[i], *b = &s->row[i + 1];
        if ((a->present & BOTH) != BOTH || (b->present & BOTH) != BOTH) continue;
        double ya = level_of(a, axis), yb = level_of(b, axis);
        if (!(ya >= stress && stress >= yb) || ya == yb) continue;
        double t = (ya - stress) / (ya - yb), pa[6], pb[6], p[6];
        row_point(a, pa);
        row_point(b, pb);
        for (int k = 0; k < 6; k++) p[k] = pa[k] + t * (pb[k] - pa[k]);
        *out = (ctn_study_level){ stress, 1, p[0], p[1], p[2], p[3], p[4], p[5] };
        return CTN_OK;
    }
    return CTN_OK;
}
