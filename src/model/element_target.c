/* Catenary elements set by a target (ctn_element_spec.target: H=, sag=, tension=): the
 * checks, the first unstressed length (the taut parabola's, as for a cable:
 * cable_target.c) and the record the outer root find works on (src/solve/target.c): the
 * record of a one-element cable. */
#include "element/element.h"
#include "model/cable_target.h"

#include <stdio.h>
#include <string.h>

int ctn_element_target_first(const ctn_model *m, const ctn_element_spec *s, ctn_element *e, double chord)
{
    if (s->target == CTN_TARGET_NONE) return CTN_OK;
    const ctn_element_ops *ops = ctn_element_family(e->type);
    char what[48];
    snprintf(what, sizeof what, "%s %d", ops->name, s->id);
    if (ops != &ctn_catenary2_ops)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: only catenary elements (and cables) take a target H=, sag=, tension=", what);
    if (s->l0 != CTN_L0_DEFAULT)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: a target (H=, sag=, tension=) sets the length: give no length with it", what);
    if (s->q > 0 || s->force > 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: q= and force= are for form finding: give them without a target", what);
    const int *nd = m->conn.v + e->conn;             /* staged by make_record */
    ctn_cable_spec cs = { .n = 1, .shape = CTN_SHAPE_STRAIGHT, .prestress = s->prestress, .target = s->target,
                          .target_value = s->target_value };
    int rc = ctn_cable_target_check(m, what, &cs, s->section, m->nodes.v[nd[0]].X, m->nodes.v[nd[1]].X, chord, &e->l0);
    if (!rc && s->target == CTN_TARGET_SAG && !(m->sections.v[e->section].w > 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: sag= needs a weight (section %s has w = 0: a weightless catenary is "
                               "straight)", what, m->sections.v[e->section].name);
    return rc;
}

void ctn_element_target_record(ctn_model *m, const ctn_element_spec *s, size_t e)
{
    ctn_cable *c = &m->etargets.v[m->etargets.n++];
    const int *nd = ctn_elem_nodes(m, e);
    memset(c, 0, sizeof *c);
    c->node[0] = nd[0];
    c->node[1] = nd[m->elements.v[e].nnodes - 1];
    c->first = e;
    c->count = 1;
    c->length = m->elements.v[e].l0;
    c->shape = CTN_SHAPE_STRAIGHT;
    c->target = (int)s->target;
    c->target_value = s->target_value;
    c->line = m->elements.v[e].line;
}
