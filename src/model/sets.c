/* Named sets of nodes or elements (`set`, docs/format.md): targets of loads, lineloads,
 * temperatures, wind and ice wherever a group or an element id is. */
#include "model/model.h"

#include <stdio.h>
#include <string.h>

int ctn_model_find_set(const ctn_model *m, const char *name)
{
    for (size_t i = 0; i < m->sets.n; i++)
        if (!strcmp(m->sets.v[i].name, name)) return (int)i;
    return -1;
}

int ctn_model_target_has(const ctn_model *m, int kind, int index, size_t e)
{
    switch (kind) {
    case CTN_TARGET_ELEMENT: return (int)e == index;
    case CTN_TARGET_GROUP: return m->elements.v[e].group == index;
    case CTN_TARGET_SET: {
        const ctn_set *s = &m->sets.v[index];
        return e < s->size && s->member[e];
    }
    default: return 1;
    }
}

int ctn_model_add_set(ctn_model *m, const char *name, int nodes, const unsigned char *member, size_t n)
{
    if (!m || !name || (n && !member)) return CTN_ERR_INVALID;
    if (ctn_model_find_set(m, name) >= 0 || ctn_model_find_group(m, name) >= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "set '%.63s': the name is already a set or a group", name);
    if (strlen(name) >= CTN_NAME_MAX) return ctn_model_error(m, CTN_ERR_MODEL, "set '%.63s': name too long", name);
    size_t count = 0;
    for (size_t i = 0; i < n; i++) count += member[i] != 0;
    if (!count) return ctn_model_error(m, CTN_ERR_MODEL, "set '%s': empty (it selects no %s)", name, nodes ? "node" : "element");
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->sets, 1);
    unsigned char *copy = rc ? NULL : ctn_malloc(m->ctx, n, 1);
    if (!copy) return rc ? rc : CTN_ERR_NOMEM;
    memcpy(copy, member, n);
    ctn_set *s = &m->sets.v[m->sets.n++];
    snprintf(s->name, sizeof s->name, "%s", name);
    s->nodes = nodes;
    s->member = copy;
    s->size = n;
    s->count = count;
    s->line = m->line;
    return CTN_OK;
}

void ctn_model_free_sets(ctn_model *m)
{
    for (size_t i = 0; i < m->sets.n; i++) ctn_free(m->sets.v[i].member);
    ctn_free(m->sets.v);
}

int ctn_model_find_cable(ctn_model *m, const char *what, int a, int b, int *reversed)
{
    int found = -1, ia = 0, ib = 0;
    if (ctn_model_node_lookup(m, a, &ia) || ctn_model_node_lookup(m, b, &ib)) return -1;
    for (size_t i = 0; i < m->cables.n; i++) {
        const ctn_cable *c = &m->cables.v[i];
        int fwd = c->node[0] == ia && c->node[1] == ib, back = c->node[0] == ib && c->node[1] == ia;
        if (!fwd && !back) continue;
        if (found >= 0) {
            ctn_model_error(m, CTN_ERR_MODEL, "%s: more than one cable joins nodes %d and %d (lines %d and %d)", what, a,
                            b, m->cables.v[found].line, c->line);
            return -1;
        }
        found = (int)i;
        *reversed = !fwd;
    }
    if (found < 0) ctn_model_error(m, CTN_ERR_MODEL, "%s: no cable joins nodes %d and %d", what, a, b);
    return found;
}
