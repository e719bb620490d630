/* The time histories a dynamics analysis records: nodes' displacements and elements'
 * axial forces, in the order asked (catena/model.h). */
#include "model/model.h"

static int add_record(ctn_model *m, int node, unsigned dofs, int element, int reaction)
{
    for (size_t i = 0; i < m->records.n; i++) {
        const ctn_record *r = &m->records.v[i];
        unsigned mine = dofs ? dofs : CTN_FIX_ALL, theirs = r->dofs ? r->dofs : CTN_FIX_ALL;
        if ((node >= 0 && r->node == node && (theirs & mine) && r->reaction == reaction) ||
            (element >= 0 && r->element == element))
            return ctn_model_error(m, CTN_ERR_MODEL, "record: %s %d is recorded twice (first on line %d)",
                                   node >= 0 ? (reaction ? "the reaction of node" : "node") : "element",
                                   node >= 0 ? m->nodes.v[node].id : m->elements.v[element].id, r->line);
    }
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->records, 1);
    if (rc) return rc;
    ctn_record *r = &m->records.v[m->records.n++];
    r->node = node;
    r->dofs = dofs;
    r->element = element;
    r->line = m->line;
    r->reaction = reaction;
    return CTN_OK;
}

int ctn_model_record_node(ctn_model *m, int id, unsigned dofs)
{
    int i;
    if (!m) return CTN_ERR_INVALID;
    if (dofs & ~(unsigned)CTN_FIX_ALL6) return ctn_model_error(m, CTN_ERR_MODEL, "record: node %d: unknown directions", id);
    int rc = ctn_model_node_lookup(m, id, &i);
    return rc ? rc : add_record(m, i, dofs ? dofs : CTN_FIX_ALL, -1, 0);
}

int ctn_model_record_element(ctn_model *m, int id)
{
    if (!m) return CTN_ERR_INVALID;
    int e = ctn_idmap_get(&m->element_ids, id);
    if (e < 0) return ctn_model_error(m, CTN_ERR_MODEL, "record: undefined element %d", id);
    return add_record(m, -1, 0, e, 0);
}

int ctn_model_record_reaction(ctn_model *m, int id, unsigned dofs)
{
    int i;
    if (!m) return CTN_ERR_INVALID;
    if (dofs & ~(unsigned)CTN_FIX_ALL6) return ctn_model_error(m, CTN_ERR_MODEL, "record: node %d: unknown directions", id);
    int rc = ctn_model_node_lookup(m, id, &i);
    return rc ? rc : add_record(m, i, dofs, -1, 1);   /* 0: its fixed directions */
}

size_t ctn_model_record_count(const ctn_model *m) { return m ? m->records.n : 0; }
