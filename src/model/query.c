/* Read-only queries of a model. */
#include "element/element.h"

#include <string.h>

size_t ctn_model_node_count(const ctn_model *m) { return m ? m->nodes.n : 0; }
size_t ctn_model_element_count(const ctn_model *m) { return m ? m->elements.n : 0; }
size_t ctn_model_cable_count(const ctn_model *m) { return m ? m->cables.n : 0; }

int ctn_model_node(const ctn_model *m, size_t i, ctn_node_info *out)
{
    if (!m || !out || i >= m->nodes.n) return CTN_ERR_INVALID;
    const ctn_node *p = &m->nodes.v[i];
    out->id = p->id;
    memcpy(out->X, p->X, sizeof out->X);
    memcpy(out->guess, p->guess, sizeof out->guess);
    out->fix = p->fix;
    return CTN_OK;
}

int ctn_model_node_dofs(const ctn_model *m, size_t i)
{
    return m && i < m->nodes.n ? m->nodes.v[i].ndof : 0;
}

int ctn_model_has_rotations(const ctn_model *m) { return m && m->rot_nodes > 0; }

int ctn_model_element(const ctn_model *m, size_t i, ctn_element_info *out)
{
    if (!m || !out || i >= m->elements.n) return CTN_ERR_INVALID;
    const ctn_element *e = &m->elements.v[i];
    memset(out, 0, sizeof *out);
    out->id = e->id;
    out->type = ctn_element_family(e->type)->name;
    out->nnodes = e->nnodes;
    out->nodes = ctn_elem_nodes(m, i);
    out->node[0] = out->nodes[0];
    out->node[1] = out->nodes[e->nnodes - 1];
    out->l0 = e->l0;
    out->k = ctn_element_family(e->type)->params ? e->par[0] : 0;   /* the springs' k */
    out->group = e->group >= 0 ? m->groups.v[e->group].name : NULL;
    if (e->section < 0) return CTN_OK;
    const ctn_section *s = &m->sections.v[e->section];
    const ctn_material *mat = &m->materials.v[s->material];
    out->has_section = 1;
    out->A = s->A;
    out->E = mat->E;
    out->w = s->w;
    out->strain = mat->strain;
    out->tension_only = mat->tension_only || (ctn_element_family(e->type)->flags & CTN_ELEM_TENSION_ONLY);
    out->alpha = mat->alpha;
    out->capacity = s->mbl > 0 ? s->mbl / s->safety : 0;
    return CTN_OK;
}

static void cable_info(const ctn_cable *c, ctn_cable_info *out)
{
    out->node[0] = c->node[0];
    out->node[1] = c->node[1];
    out->first = c->first;
    out->count = c->count;
    out->length = c->length;
    out->target = (ctn_cable_target)c->target;
    out->target_value = c->target_value;
    out->target_achieved = c->resolved ? c->target_achieved : 0;
    out->target_iterations = c->target_iterations;
}

int ctn_model_cable(const ctn_model *m, size_t i, ctn_cable_info *out)
{
    if (!m || !out || i >= m->cables.n) return CTN_ERR_INVALID;
    cable_info(&m->cables.v[i], out);
    return CTN_OK;
}

int ctn_model_element_target(const ctn_model *m, size_t i, ctn_cable_info *out)
{
    if (!m || !out || i >= m->elements.n) return CTN_ERR_INVALID;
    size_t lo = 0, hi = m->etargets.n;                 /* sorted by element index */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (m->etargets.v[mid].first < i) lo = mid + 1;
        else hi = mid;
    }
    memset(out, 0, sizeof *out);
    if (lo < m->etargets.n && m->etargets.v[lo].first == i) cable_info(&m->etargets.v[lo], out);
    return CTN_OK;
}

int ctn_model_node_index(const ctn_model *m, int id, size_t *index)
{
    if (!m || !index) return CTN_ERR_INVALID;
    int i = ctn_idmap_get(&m->node_ids, id);
    if (i < 0) return CTN_ERR_INVALID;
    *index = (size_t)i;
    return CTN_OK;
}

void ctn_model_gravity(const ctn_model *m, double g[3])
{
    for (int k = 0; k < 3; k++) g[k] = m ? m->gravity[k] : 0.0;
}

const char *ctn_model_force_unit(const ctn_model *m) { return m ? m->force_unit : ""; }
const char *ctn_model_length_unit(const ctn_model *m) { return m ? m->length_unit : ""; }
double ctn_model_mpa_factor(const ctn_model *m) { return m ? m->mpa : 0.0; }
const char *ctn_model_file(const ctn_model *m) { return m ? m->file : ""; }
