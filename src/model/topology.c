/* Model topology and loads: nodes, concentrated and horizontal loads. */
#include "model/model.h"

#include <math.h>
#include <string.h>

static int finite3(const double v[3]) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

int ctn_model_add_node(ctn_model *m, int id, const double X[3], unsigned fix)
{
    if (!m || !X) return CTN_ERR_INVALID;
    if (id <= 0) return ctn_model_error(m, CTN_ERR_MODEL, "node id must be a positive integer (got %d)", id);
    int old = ctn_idmap_get(&m->node_ids, id);
    if (old >= 0 && m->nodes.v[old].line > 0)       /* a cable's interior node: its line */
        return ctn_model_error(m, CTN_ERR_MODEL, "duplicate node id %d (defined on line %d)", id, m->nodes.v[old].line);
    if (old >= 0) return ctn_model_error(m, CTN_ERR_MODEL, "duplicate node id %d", id);
    if (!finite3(X)) return ctn_model_error(m, CTN_ERR_MODEL, "node %d: coordinates must be finite", id);
    if (fix & ~(unsigned)CTN_FIX_ALL6) return ctn_model_error(m, CTN_ERR_MODEL, "node %d: bad fix flags", id);
    if (m->nodes.n >= (size_t)0x7fffffff / 3)
        return ctn_model_error(m, CTN_ERR_MODEL, "too many nodes");
    long lim = ctn_ctx_model_limit(m->ctx);
    if (lim && m->nodes.n >= (size_t)lim)
        return ctn_model_error(m, CTN_ERR_MODEL, "model too large: more than %ld nodes (the caller's limit)", lim);
    if (m->steps.n) return ctn_model_error(m, CTN_ERR_MODEL, "nodes must be defined before the first step");
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->nodes, 1);
    if (!rc) rc = ctn_idmap_put(m->ctx, &m->node_ids, id, (int)m->nodes.n);
    if (rc) return rc;
    ctn_node *p = &m->nodes.v[m->nodes.n++];
    p->id = id;
    memcpy(p->X, X, sizeof p->X);
    memset(p->guess, 0, sizeof p->guess);
    p->fix = fix;
    p->line = m->line;
    p->mass = 0.0;
    p->ndof = 3;
    if (id > m->max_node_id) m->max_node_id = id;
    return CTN_OK;
}

/* Node index of id or an "undefined node" error. */
int ctn_model_node_lookup(const ctn_model *m, int id, int *index)
{
    *index = ctn_idmap_get(&m->node_ids, id);
    if (*index < 0) return ctn_model_error(m, CTN_ERR_MODEL, "undefined node %d", id);
    return CTN_OK;
}

/* A force (or, into mloads, a moment) F at node id, of the current step. */
static int add_nodal(ctn_model *m, int node, const double F[3], int moment)
{
    if (!m || !F) return CTN_ERR_INVALID;
    int a, rc;
    if ((rc = ctn_model_node_lookup(m, node, &a))) return rc;
    if (!finite3(F)) return ctn_model_error(m, CTN_ERR_MODEL, "%s on node %d must be finite", moment ? "moment" : "load", node);
    if ((rc = moment ? CTN_ARRAY_RESERVE(m->ctx, m->mloads, 1) : CTN_ARRAY_RESERVE(m->ctx, m->ploads, 1))) return rc;
    ctn_pload *p = moment ? &m->mloads.v[m->mloads.n++] : &m->ploads.v[m->ploads.n++];
    p->node = a;
    memcpy(p->F, F, sizeof p->F);
    p->step = ctn_model_load_tag(m);
    p->line = m->line;
    return CTN_OK;
}

int ctn_model_add_load(ctn_model *m, int node, const double F[3]) { return add_nodal(m, node, F, 0); }
int ctn_model_add_moment(ctn_model *m, int node, const double M[3]) { return add_nodal(m, node, M, 1); }

/* Prescribed increments u of the fixed DOFs named by dofs (bits 0..2, after shifting
 * rotation flags down by 3 when rot) of node id. */
static int add_prescribed(ctn_model *m, int node, unsigned dofs, const double u[3], int rot)
{
    static const char *const name[2][3] = { { "x", "y", "z" }, { "rx", "ry", "rz" } };
    if (!m || !u) return CTN_ERR_INVALID;
    int a, rc;
    if ((rc = ctn_model_node_lookup(m, node, &a))) return rc;
    if (!finite3(u)) return ctn_model_error(m, CTN_ERR_MODEL, "%s of node %d must be finite", rot ? "rotation" : "displacement", node);
    unsigned fix = m->nodes.v[a].fix >> (rot ? 3 : 0);
    for (int k = 0; k < 3; k++)
        if ((dofs >> k & 1u) && !(fix >> k & 1u))
            return ctn_model_error(m, CTN_ERR_MODEL, "node %d: %s is not fixed; only fixed DOFs take a prescribed %s", node,
                                   name[rot][k], rot ? "rotation" : "displacement");
    if ((rc = CTN_ARRAY_RESERVE(m->ctx, m->pdisps, 1))) return rc;
    ctn_pdisp *p = &m->pdisps.v[m->pdisps.n++];
    p->node = a;
    for (int k = 0; k < 3; k++) p->u[k] = dofs >> k & 1u ? u[k] : 0.0;
    p->step = ctn_model_load_tag(m);
    p->rot = rot;
    return CTN_OK;
}

int ctn_model_add_displacement(ctn_model *m, int node, unsigned dofs, const double u[3])
{
    return add_prescribed(m, node, dofs & CTN_FIX_ALL, u, 0);
}

int ctn_model_add_rotation(ctn_model *m, int node, unsigned dofs, const double r[3])
{
    return add_prescribed(m, node, (dofs & CTN_FIX_ROT) >> 3, r, 1);
}

int ctn_model_add_hload(ctn_model *m, double q, int first, int last)
{
    return ctn_model_add_hload_projected(m, q, first, last, CTN_PROJECT_DEFORMED);
}

int ctn_model_add_hload_projected(ctn_model *m, double q, int first, int last, ctn_projection proj)
{
    if (!m) return CTN_ERR_INVALID;
    if (proj != CTN_PROJECT_DEFORMED && proj != CTN_PROJECT_REFERENCE)
        return ctn_model_error(m, CTN_ERR_MODEL, "hload: unknown projection");
    if (!isfinite(q)) return ctn_model_error(m, CTN_ERR_MODEL, "horizontal load q must be finite");
    if (first > last) return ctn_model_error(m, CTN_ERR_MODEL, "element range %d-%d is empty", first, last);
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->hloads, 1);
    if (rc) return rc;
    ctn_hload *h = &m->hloads.v[m->hloads.n++];
    h->q = q;
    h->reference = proj == CTN_PROJECT_REFERENCE;
    h->first = first;
    h->last = last;
    h->group = -1;
    h->line = m->line;
    h->step = ctn_model_load_tag(m);
    return CTN_OK;
}

int ctn_model_add_hload_group(ctn_model *m, double q, const char *group, ctn_projection proj)
{
    if (!m || !group) return CTN_ERR_INVALID;
    int g = ctn_model_find_group(m, group);
    if (g < 0) return ctn_model_error(m, CTN_ERR_MODEL, "hload: undefined group '%.63s'", group);
    int rc = ctn_model_add_hload_projected(m, q, 1, 1, proj);
    if (!rc) m->hloads.v[m->hloads.n - 1].group = g;
    return rc;
}
