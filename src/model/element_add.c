/* Elements of any registered family: the spec, the generic checks, and the record. */
#include "element/element.h"
#include "model/cable_target.h"

#include <math.h>
#include <string.h>

void ctn_element_spec_init(ctn_element_spec *s)
{
    if (!s) return;
    memset(s, 0, sizeof *s);
    s->size = sizeof *s;
    s->l0 = CTN_L0_DEFAULT;
}

/* |b - a| without overflow of the squares. */
static double distance(const double a[3], const double b[3])
{
    return hypot(hypot(b[0] - a[0], b[1] - a[1]), b[2] - a[2]);
}

static int check_room(const ctn_model *m)
{
    if (m->steps.n) return ctn_model_error(m, CTN_ERR_MODEL, "elements must be defined before the first step");
    if (m->elements.n >= (size_t)0x7fffffff)
        return ctn_model_error(m, CTN_ERR_MODEL, "too many elements");
    long lim = ctn_ctx_model_limit(m->ctx);
    if (lim && m->elements.n >= (size_t)lim)
        return ctn_model_error(m, CTN_ERR_MODEL, "model too large: more than %ld elements (the caller's limit)", lim);
    return CTN_OK;
}

/* Node indices of the spec into idx; consecutive nodes distinct and apart. */
static int resolve_nodes(const ctn_model *m, const ctn_element_spec *s, const ctn_element_ops *ops,
                         int *idx, double *chord)
{
    int want = ops->nnodes;
    if ((want && s->nnodes != want) || s->nnodes < 2 || s->nnodes > CTN_ELEM_MAX_NODES || !s->nodes)
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d: a %s element takes %d nodes (got %d)", s->id, ops->name,
                               want ? want : 2, s->nnodes);
    *chord = 0;
    for (int k = 0; k < s->nnodes; k++) {
        int rc = ctn_model_node_lookup(m, s->nodes[k], &idx[k]);
        if (rc) return rc;
        if (k == 0) continue;
        if (idx[k] == idx[k - 1])
            return ctn_model_error(m, CTN_ERR_MODEL, "element %d connects node %d to itself", s->id, s->nodes[k]);
        double d = distance(m->nodes.v[idx[k - 1]].X, m->nodes.v[idx[k]].X);
        if (!(d > 0))
            return ctn_model_error(m, CTN_ERR_MODEL, "element %d has zero length (nodes %d and %d coincide)", s->id,
                                   s->nodes[k - 1], s->nodes[k]);
        *chord += d;
    }
    return CTN_OK;
}

/* Form-finding keys: a force density q or a target force, positive, not both. */
static int density(const ctn_model *m, const ctn_element_spec *s)
{
    if (!isfinite(s->q) || s->q < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d: q must be positive and finite (got %g)", s->id, s->q);
    if (!isfinite(s->force) || s->force < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d: force must be positive and finite (got %g)", s->id, s->force);
    if (s->q > 0 && s->force > 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d: give q= or force=, not both", s->id);
    return CTN_OK;
}

/* The record of spec s (defaults resolved), checked by its family. */
static int make_record(ctn_model *m, const ctn_element_spec *s, int type, ctn_element *e, int *idx)
{
    const ctn_element_ops *ops = ctn_element_family(type);
    double chord = 0;
    int rc = resolve_nodes(m, s, ops, idx, &chord);
    if (!rc) rc = ctn_array_reserve(m->ctx, (void **)&m->conn.v, &m->conn.cap, m->conn.n + (size_t)s->nnodes, sizeof(int));
    if (rc) return rc;
    memcpy(m->conn.v + m->conn.n, idx, (size_t)s->nnodes * sizeof(int));   /* staged, not yet counted: */
    memset(e, 0, sizeof *e);
    e->conn = m->conn.n;                              /* the checks may read the nodes */
    e->id = s->id;
    e->type = type;
    e->nnodes = s->nnodes;
    e->section = -1;
    e->group = -1;
    if (!(ops->flags & CTN_ELEM_SECTION) && s->section)
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d: a %s element takes no section", s->id, ops->name);
    if (ops->flags & CTN_ELEM_SECTION) {
        e->section = s->section ? ctn_model_find_section(m, s->section) : -1;
        if (e->section < 0)
            return ctn_model_error(m, CTN_ERR_MODEL, "element %d: undefined section '%s'", s->id, s->section ? s->section : "");
    }
    e->l0 = s->l0 == CTN_L0_DEFAULT ? chord : s->l0;
    if (ops->params) ops->params(s, e->par);
    e->line = m->line;
    if ((rc = density(m, s))) return rc;
    if (s->prestress != CTN_PRESTRESS_NONE) {
        if (s->prestress < CTN_PRESTRESS_FORCE || s->prestress > CTN_PRESTRESS_STRAIN)
            return ctn_model_error(m, CTN_ERR_MODEL, "element %d: unknown prestress", s->id);
        if (s->l0 != CTN_L0_DEFAULT)
            return ctn_model_error(m, CTN_ERR_MODEL, "element %d: give at most one of l0=, N0=, s0=, eps0=", s->id);
        if (!ops->prestress_l0)
            return ctn_model_error(m, CTN_ERR_MODEL, "element %d: a %s element takes no prestress", s->id, ops->name);
        rc = ops->check(m, e);                      /* section, k: before they are used */
        if (!rc) rc = ops->prestress_l0(m, e, (int)s->prestress, s->prestress_value, chord, &e->l0);
        if (rc) return rc;
    }
    if (s->target != CTN_TARGET_NONE && (rc = ctn_element_target_first(m, s, e, chord))) return rc;
    return ops->check(m, e);
}

int ctn_model_add_element_spec(ctn_model *m, const ctn_element_spec *spec)
{
    if (!m || !spec || spec->size < sizeof(size_t)) return CTN_ERR_INVALID;
    ctn_element_spec s;
    ctn_element_spec_init(&s);
    ctn_spec_copy(&s, sizeof s, spec);
    int type = ctn_element_family_find(s.type ? s.type : "cable"), idx[CTN_ELEM_MAX_NODES], rc;
    if (type < 0) return ctn_model_error(m, CTN_ERR_MODEL, "unknown element type '%s'", s.type);
    if (s.id <= 0) return ctn_model_error(m, CTN_ERR_MODEL, "element id must be a positive integer (got %d)", s.id);
    int old = ctn_idmap_get(&m->element_ids, s.id);
    if (old >= 0 && m->elements.v[old].line > 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "duplicate element id %d (defined on line %d)", s.id,
                               m->elements.v[old].line);
    if (old >= 0) return ctn_model_error(m, CTN_ERR_MODEL, "duplicate element id %d", s.id);
    ctn_element e;
    if ((rc = make_record(m, &s, type, &e, idx)) || (rc = check_room(m))) return rc;
    if (s.group && (rc = ctn_model_group_get(m, s.group, &e.group))) return rc;
    if ((rc = CTN_ARRAY_RESERVE(m->ctx, m->elements, 1))) return rc;
    if (s.target != CTN_TARGET_NONE && (rc = CTN_ARRAY_RESERVE(m->ctx, m->etargets, 1))) return rc;
    int ff = s.q > 0 || s.force > 0;
    if (ff && (rc = CTN_ARRAY_RESERVE(m->ctx, m->densities, 1))) return rc;
    if ((rc = ctn_array_reserve(m->ctx, (void **)&m->conn.v, &m->conn.cap, m->conn.n + (size_t)e.nnodes, sizeof(int))))
        return rc;
    if ((rc = ctn_idmap_put(m->ctx, &m->element_ids, s.id, (int)m->elements.n))) return rc;
    e.conn = m->conn.n;
    memcpy(m->conn.v + m->conn.n, idx, (size_t)e.nnodes * sizeof(int));
    m->conn.n += (size_t)e.nnodes;
    m->elements.v[m->elements.n++] = e;
    for (int k = 0; k < e.nnodes; k++) {             /* a family of rotations: 6 DOFs */
        ctn_node *p = &m->nodes.v[idx[k]];
        if (p->ndof >= ctn_element_family(type)->ndof_node) continue;
        p->ndof = ctn_element_family(type)->ndof_node;
        m->rot_nodes++;
    }
    if (s.target != CTN_TARGET_NONE) ctn_element_target_record(m, &s, m->elements.n - 1);
    if (ff) ctn_model_put_density(m, m->elements.n - 1, s.q, s.force);   /* the last: room reserved */
    if (s.id > m->max_element_id) m->max_element_id = s.id;
    return CTN_OK;
}

int ctn_model_add_element(ctn_model *m, int id, int n1, int n2, const char *section,
                          double l0)
{
    ctn_element_spec s;
    int nodes[2] = { n1, n2 };
    ctn_element_spec_init(&s);
    s.id = id;
    s.nnodes = 2;
    s.nodes = nodes;
    s.section = section ? section : "";
    s.l0 = l0;
    return ctn_model_add_element_spec(m, &s);
}
