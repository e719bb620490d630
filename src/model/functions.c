/* Functions of time and the forces and support motions that follow them in a dynamics
 * analysis (catena/model.h). */
#include "element/element.h"
#include "model/model.h"

#include <math.h>
#include <string.h>

static int find_fn(const ctn_model *m, const char *name)
{
    for (size_t i = 0; name && i < m->fns.n; i++)
        if (!strcmp(m->fns.v[i].name, name)) return (int)i;
    return -1;
}

/* The parameters' checks: finite; a ramp's t1 after its t0; a table's t increasing. */
static int check_fn(ctn_model *m, const char *name, ctn_fn_kind kind, const double par[4], const double *t,
                    const double *v, size_t n)
{
    for (int k = 0; k < 4; k++)
        if (!isfinite(par[k])) return ctn_model_error(m, CTN_ERR_MODEL, "function %s: its parameters must be finite", name);
    if (kind == CTN_FN_RAMP && !(par[1] > par[0]))
        return ctn_model_error(m, CTN_ERR_MODEL, "function %s: ramp t1=%g must be after t0=%g", name, par[1], par[0]);
    if (kind == CTN_FN_HARMONIC && !(par[1] >= 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "function %s: freq must be >= 0 (found %g)", name, par[1]);
    if (kind != CTN_FN_TABLE) return CTN_OK;
    if (n < 2 || !t || !v) return ctn_model_error(m, CTN_ERR_MODEL, "function %s: a table needs two points or more", name);
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(t[i]) || !isfinite(v[i])) return ctn_model_error(m, CTN_ERR_MODEL, "function %s: table point %zu is not finite", name, i + 1);
        if (i && !(t[i] > t[i - 1]))
            return ctn_model_error(m, CTN_ERR_MODEL, "function %s: table times must increase (point %zu: t=%g after t=%g)",
                                   name, i + 1, t[i], t[i - 1]);
    }
    return CTN_OK;
}

int ctn_model_add_function(ctn_model *m, const char *name, ctn_fn_kind kind, const double par[4], const double *t,
                           const double *v, size_t n)
{
    if (!m || !name || !par || kind < CTN_FN_RAMP || kind > CTN_FN_TABLE) return CTN_ERR_INVALID;
    if (!*name || strlen(name) >= CTN_NAME_MAX) return ctn_model_error(m, CTN_ERR_MODEL, "function: bad name '%.40s'", name);
    int j = find_fn(m, name);
    if (j >= 0) return ctn_model_error(m, CTN_ERR_MODEL, "function %s defined twice (first on line %d)", name, m->fns.v[j].line);
    int rc = check_fn(m, name, kind, par, t, v, n);
    if (!rc) rc = CTN_ARRAY_RESERVE(m->ctx, m->fns, 1);
    if (rc) return rc;
    ctn_fn f;
    memset(&f, 0, sizeof f);
    strcpy(f.name, name);
    f.kind = kind;
    memcpy(f.par, par, sizeof f.par);
    f.line = m->line;
    if (kind == CTN_FN_TABLE) {
        f.t = ctn_malloc(m->ctx, n, sizeof(double));
        f.v = ctn_malloc(m->ctx, n, sizeof(double));
        if (!f.t || !f.v) {
            ctn_free(f.t);
            ctn_free(f.v);
            return CTN_ERR_NOMEM;
        }
        memcpy(f.t, t, n * sizeof(double));
        memcpy(f.v, v, n * sizeof(double));
        f.n = n;
    }
    m->fns.v[m->fns.n++] = f;
    return CTN_OK;
}

double ctn_model_fn_value(const ctn_model *m, int i, double t)
{
    const ctn_fn *f = &m->fns.v[i];
    switch (f->kind) {
    case CTN_FN_RAMP: return t <= f->par[0] ? 0.0 : t >= f->par[1] ? 1.0 : (t - f->par[0]) / (f->par[1] - f->par[0]);
    case CTN_FN_STEP: return t < f->par[0] ? 0.0 : 1.0;
    case CTN_FN_HARMONIC: return f->par[3] + f->par[0] * sin(6.28318530717958647692 * f->par[1] * t + f->par[2]);
    default: break;
    }
    if (t <= f->t[0]) return f->v[0];
    if (t >= f->t[f->n - 1]) return f->v[f->n - 1];
    size_t lo = 0, hi = f->n - 1;                    /* t[lo] <= t < t[hi] */
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (f->t[mid] <= t) lo = mid;
        else hi = mid;
    }
    return f->v[lo] + (f->v[hi] - f->v[lo]) * (t - f->t[lo]) / (f->t[hi] - f->t[lo]);
}

static int add_dload(ctn_model *m, int id, unsigned dofs, const double F[3], const char *fn)
{
    int node, rc;
    if (!m || !F) return CTN_ERR_INVALID;
    if ((rc = ctn_model_node_lookup(m, id, &node))) return rc;
    int j = find_fn(m, fn);
    if (j < 0) return ctn_model_error(m, CTN_ERR_MODEL, "undefined function '%.40s' (define it with `function` first)", fn ? fn : "");
    for (int k = 0; k < 3; k++)
        if (!isfinite(F[k])) return ctn_model_error(m, CTN_ERR_MODEL, "%s on node %d must be finite", dofs ? "motion" : "load", id);
    if (dofs & ~m->nodes.v[node].fix & CTN_FIX_ALL)
        return ctn_model_error(m, CTN_ERR_MODEL, "displace: node %d: a motion fn= moves fixed DOFs only (fix= them)", id);
    if ((rc = CTN_ARRAY_RESERVE(m->ctx, m->dloads, 1))) return rc;
    ctn_dload *d = &m->dloads.v[m->dloads.n++];
    d->node = node;
    d->dofs = dofs;
    memcpy(d->F, F, sizeof d->F);
    d->fn = j;
    d->line = m->line;
    return CTN_OK;
}

int ctn_model_add_load_fn(ctn_model *m, int id, const double F[3], const char *fn) { return add_dload(m, id, 0, F, fn); }

int ctn_model_add_removal(ctn_model *m, int id, double t)
{
    if (!m) return CTN_ERR_INVALID;
    int e = ctn_idmap_get(&m->element_ids, id);
    if (e < 0) return ctn_model_error(m, CTN_ERR_MODEL, "remove: undefined element %d", id);
    const ctn_element_ops *ops = ctn_element_family(m->elements.v[e].type);
    if (!ops->sever)
        return ctn_model_error(m, CTN_ERR_MODEL, "remove: element %d is a %s: only cable elements and springs can be "
                               "removed in time", id, ops->name);
    if (!(isfinite(t) && t >= 0)) return ctn_model_error(m, CTN_ERR_MODEL, "remove: t must be >= 0 and finite (found %g)", t);
    for (size_t i = 0; i < m->removals.n; i++)
        if (m->removals.v[i].element == e)
            return ctn_model_error(m, CTN_ERR_MODEL, "remove: element %d is removed twice (first on line %d)", id,
                                   m->removals.v[i].line);
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->removals, 1);
    if (rc) return rc;
    ctn_removal *r = &m->removals.v[m->removals.n++];
    r->element = e;
    r->t = t;
    r->line = m->line;
    return CTN_OK;
}

int ctn_model_add_motion_fn(ctn_model *m, int id, unsigned dofs, const double u[3], const char *fn)
{
    if (!dofs || (dofs & ~(unsigned)CTN_FIX_ALL)) return CTN_ERR_INVALID;
    return add_dload(m, id, dofs, u, fn);
}
