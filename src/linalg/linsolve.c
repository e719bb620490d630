/* Linear solver objects: the registry and the calls that dispatch to a backend. */
#include "linalg/linsolve.h"

#include <string.h>

struct ctn_linsolve {
    const ctn_linsolve_ops *ops;
    void *impl;
    ctn_ctx *ctx;
};

static const ctn_linsolve_ops *const solvers[] = { &ctn_cholmod_ll_ops, &ctn_cholmod_ldl_ops };

const ctn_linsolve_ops *ctn_linsolve_find(const char *name)
{
    for (size_t i = 0; name && i < sizeof solvers / sizeof *solvers; i++)
        if (!strcmp(solvers[i]->name, name)) return solvers[i];
    return NULL;
}

int ctn_linsolve_create(ctn_ctx *ctx, const char *name, const ctn_pattern *p, ctn_ordering ord,
                        ctn_linsolve **out)
{
    *out = NULL;
    const ctn_linsolve_ops *ops = ctn_linsolve_find(name);
    if (!ops) return ctn_error(ctx, CTN_ERR_INVALID, "unknown linear solver '%s'", name ? name : "");
    ctn_linsolve *s = ctn_calloc(ctx, 1, sizeof *s);
    if (!s) return CTN_ERR_NOMEM;
    s->ops = ops;
    s->ctx = ctx;
    int rc = ops->create(ctx, p, ord, &s->impl);
    if (rc) {
        ctn_free(s);
        return rc;
    }
    *out = s;
    return CTN_OK;
}

void ctn_linsolve_destroy(ctn_linsolve **s)
{
    if (!s || !*s) return;
    (*s)->ops->destroy((*s)->impl);
    ctn_free(*s);
    *s = NULL;
}

const ctn_linsolve_ops *ctn_linsolve_type(const ctn_linsolve *s) { return s->ops; }

int ctn_linsolve_factor(ctn_linsolve *s, const double *Kx, double shift, ctn_factor_info *info)
{
    return s->ops->factor(s->impl, Kx, shift, info);
}

int ctn_linsolve_solve(ctn_linsolve *s, const double *b, double *x)
{
    return s->ops->solve(s->impl, b, x);
}

int ctn_linsolve_inertia(ctn_linsolve *s, double tol, long *negative, long *zero, long *first)
{
    if (!s->ops->inertia) return ctn_error(s->ctx, CTN_ERR_INVALID, "linear solver '%s' gives no inertia", s->ops->name);
    return s->ops->inertia(s->impl, tol, negative, zero, first);
}

ctn_ordering ctn_linsolve_ordering(const ctn_linsolve *s) { return s->ops->ordering(s->impl); }

size_t ctn_linsolve_factor_nnz(const ctn_linsolve *s) { return s->ops->factor_nnz(s->impl); }
