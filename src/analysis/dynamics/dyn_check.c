/* The dynamics analysis's checks of the model (before any solve, at the `dynamics`
 * line): the line after the last step, mass (every free DOF's for the explicit method,
 * naming a node and a section without it). */
#include "analysis/dynamics/dynamics.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A model error at the `dynamics` line (or without a place, from the API). */
int ctn_dyn_error(const ctn_problem *p, const ctn_dynamics_options *o, const char *msg)
{
    if (o->line > 0) return ctn_error_at(p->ctx, CTN_ERR_MODEL, p->m->file, o->line, "%s", msg);
    return ctn_error(p->ctx, CTN_ERR_MODEL, "%s", msg);
}

/* A node with a free translation and no mass in it, and a section of its elements
 * without mass, for the messages: "node N (section 'S' has no mass)". */
static void massless_node(const ctn_problem *p, const double *diag, char *what, size_t size)
{
    const ctn_model *m = p->m;
    snprintf(what, size, "no free node");
    for (size_t i = 0; i < m->nodes.n; i++)
        for (int k = 0; k < ctn_dofmap_count(&p->a->map, i); k++) {
            int q = p->a->map.eq[ctn_dofmap_node(&p->a->map, i) + (size_t)k];
            if (q < 0 || diag[q] > 0) continue;
            if (k >= 3) {
                snprintf(what, size, "node %d has no rotary inertia in r%c (no beam with a section mass reaches it)",
                         m->nodes.v[i].id, "xyz"[k - 3]);
                return;
            }
            const char *sec = NULL;
            for (size_t e = 0; e < m->elements.n && !sec; e++) {
                const ctn_element *el = &m->elements.v[e];
                for (int j = 0; j < el->nnodes && !sec; j++)
                    if ((size_t)ctn_elem_nodes(m, e)[j] == i && el->section >= 0 && !(ctn_model_section_mass(m, el->section) > 0))
                        sec = m->sections.v[el->section].name;
            }
            if (sec) snprintf(what, size, "node %d has no mass in u%c (no node mass=, and section '%s' has no mass= "
                              "nor w= with units)", m->nodes.v[i].id, "xyz"[k], sec);
            else snprintf(what, size, "node %d has no mass in u%c (no node mass=, and no element with a mass "
                          "reaches it)", m->nodes.v[i].id, "xyz"[k]);
            return;
        }
}

/* The mass: every section's mass told (units), some free DOF with mass, and every free
 * DOF with mass for the explicit method. */
static int check_mass(ctn_problem *p, const ctn_dynamics_options *o, double *diag)
{
    char msg[400], what[256];
    size_t bad = 0, nmass = 0;
    double tot[3];
    if (ctn_asm_mass_diag(p->a, diag, tot, &bad)) {
        const ctn_model *m = p->m;
        const ctn_section *sec = &m->sections.v[m->elements.v[bad].section];
        return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, sec->line, "section '%s': its weight w=%g gives no mass in a "
                            "model without units: give mass= (or units) for the dynamics", sec->name, sec->w);
    }
    for (size_t q = 0; q < p->ndof; q++) nmass += diag[q] > 0;
    massless_node(p, diag, what, sizeof what);
    if (nmass == 0) {
        snprintf(msg, sizeof msg, "dynamics: no free DOF carries mass: %s", what);
        return ctn_dyn_error(p, o, msg);
    }
    if (o->method == CTN_DYN_CENTRAL && nmass < p->ndof) {
        snprintf(msg, sizeof msg, "dynamics: method=central needs mass at every free DOF: %s", what);
        return ctn_dyn_error(p, o, msg);
    }
    return CTN_OK;
}

/* A reaction is recorded only where the node is fixed, a rotation only on a node that has
 * rotations. */
static int check_reaction_records(const ctn_problem *p)
{
    static const char *const dir[6] = { "ux", "uy", "uz", "rx", "ry", "rz" };
    const ctn_model *m = p->m;
    for (size_t i = 0; i < m->records.n; i++) {
        const ctn_record *r = &m->records.v[i];
        if (r->element >= 0) continue;
        unsigned want = ctn_dyn_record_dofs(m, r), free_dofs = r->reaction ? want & ~m->nodes.v[r->node].fix : 0;
        int id = m->nodes.v[r->node].id, k = 0;
        if (ctn_model_node_dofs(m, (size_t)r->node) != 6 && (want & CTN_FIX_ROT))
            return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, r->line, "record: node %d has no rotations (no beam or "
                                "rspring reaches it): dof= takes ux, uy, uz there", id);
        if (r->reaction && !want)
            return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, r->line, "record: node %d has no support (fix=): it "
                                "has no reaction to record", id);
        while (free_dofs && !(free_dofs >> k & 1)) k++;
        if (free_dofs)
            return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, r->line, "record: node %d is not fixed in %s: it has no "
                                "reaction there (give dof= of its fixed directions, or fix= them)", id, dir[k]);
    }
    return CTN_OK;
}

int ctn_dynamics_check(ctn_problem *p, const ctn_dynamics_options *o)
{
    const ctn_model *m = p->m;
    int rc = check_reaction_records(p);
    if (rc) return rc;
    if ((rc = ctn_dyn_wind_check(p, o))) return rc;
    if (o->line > 0 && (size_t)o->steps_before != m->steps.n)
        return ctn_dyn_error(p, o, "dynamics: give it after the last `step` line (it starts from that step's equilibrium)");
    if (p->ndof == 0) return ctn_dyn_error(p, o, "dynamics: the model has no free DOF");
    double *diag = ctn_malloc(p->ctx, p->ndof, sizeof(double));
    if (!diag) return CTN_ERR_NOMEM;
    rc = check_mass(p, o, diag);
    ctn_free(diag);
    return rc;
}
