/* Results by group and the capacity check (utilisation = force / (mbl / safety); a beam's
 * with fy, its combined stress / fy). */
#include "model/model.h"
#include "problem/solution.h"

#include <math.h>
#include <string.h>

double ctn_utilisation(const ctn_element_info *e, const ctn_element_state *st)
{
    return e && st && e->capacity > 0 ? st->force / e->capacity : 0.0;
}

static void add_member(ctn_group_result *r, const ctn_model *m, const ctn_element_info *e,
                       const ctn_element_state *st, const ctn_beam_result *beam)
{
    double g = sqrt(m->gravity[0] * m->gravity[0] + m->gravity[1] * m->gravity[1] + m->gravity[2] * m->gravity[2]);
    if (!r->elements++) {
        r->max_force = r->min_force = st->force;
        r->max_strain = st->strain;
        r->max_stress = -INFINITY;
    }
    r->max_force = fmax(r->max_force, st->force);
    r->min_force = fmin(r->min_force, st->force);
    r->max_strain = fmax(r->max_strain, st->strain);
    if (e->has_section) r->max_stress = fmax(r->max_stress, st->stress);
    if (e->capacity > 0 && (!r->has_capacity || ctn_utilisation(e, st) > r->max_utilisation)) {
        r->has_capacity = 1;
        r->max_utilisation = ctn_utilisation(e, st);
        r->worst_element = e->id;
    }
    if (beam && beam->fy > 0 && (!r->has_capacity || beam->utilisation > r->max_utilisation)) {
        r->has_capacity = 1;
        r->max_utilisation = beam->utilisation;
        r->worst_element = e->id;
    }
    r->slack += (size_t)(e->tension_only && st->slack);
    r->length += e->l0;
    r->stressed_length += st->length;
    r->weight += e->w * e->l0 * g;
}

int ctn_solution_group(const ctn_model *m, const ctn_solution *s, size_t k, size_t g, ctn_group_result *out)
{
    if (!m || !s || !out || g >= m->groups.n) return CTN_ERR_INVALID;
    memset(out, 0, sizeof *out);
    out->name = m->groups.v[g].name;
    for (size_t i = 0; i < m->elements.n; i++) {
        ctn_element_info e;
        ctn_element_state st;
        if (m->elements.v[i].group != (int)g) continue;
        if (ctn_model_element(m, i, &e) || ctn_solution_step_element(s, k, i, &st)) return CTN_ERR_INVALID;
        ctn_catenary_result c = { .size = sizeof c };
        if (!ctn_solution_catenary(m, s, k, i, &c)) st.length = c.length;   /* the curve, not the chord */
        ctn_beam_result b = { .size = sizeof b };
        add_member(out, m, &e, &st, ctn_solution_beam(m, s, k, i, &b) ? NULL : &b);
    }
    if (!(out->max_stress > -INFINITY)) out->max_stress = 0;
    return CTN_OK;
}

int ctn_solution_worst_utilisation(const ctn_model *m, const ctn_solution *s, size_t k, size_t *e, double *u)
{
    if (!m || !s || !e || !u) return CTN_ERR_INVALID;
    int found = 0;
    for (size_t i = 0; i < m->elements.n; i++) {
        ctn_element_info info;
        ctn_element_state st;
        if (ctn_model_element(m, i, &info) || !(info.capacity > 0) || ctn_solution_step_element(s, k, i, &st)) continue;
        double ui = ctn_utilisation(&info, &st);
        if (!found || ui > *u) {
            *u = ui;
            *e = i;
            found = 1;
        }
    }
    return found ? CTN_OK : CTN_ERR_INVALID;
}
