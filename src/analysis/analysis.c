/* Analyses as objects: the registry and the public entry points (catena/analysis.h). */
#include "analysis/analysis.h"

#include "core/versioned.h"

#include <stdio.h>
#include <string.h>

static const ctn_analysis_ops *const registry[] = {
    &ctn_analysis_static, &ctn_analysis_stability, &ctn_analysis_modal, &ctn_analysis_buckling,
    &ctn_analysis_dynamics,
};
#define NKINDS (sizeof registry / sizeof registry[0])

struct ctn_analysis {
    ctn_problem *p;
    const ctn_analysis_ops *ops;
    void *opt;                 /* ops->options_size bytes, the caller's keys over defaults */
};

size_t ctn_analysis_count(void) { return NKINDS; }

const char *ctn_analysis_type(size_t i) { return i < NKINDS ? registry[i]->name : NULL; }

const ctn_analysis_ops *ctn_analysis_find(const char *name)
{
    for (size_t i = 0; name && i < NKINDS; i++)
        if (!strcmp(registry[i]->name, name)) return registry[i];
    return NULL;
}

int ctn_analysis_create(ctn_problem *p, const char *name, const void *options, ctn_analysis **out)
{
    if (!p || !out) return p ? ctn_error(p->ctx, CTN_ERR_INVALID, "ctn_analysis_create: problem or out is NULL") : CTN_ERR_INVALID;
    *out = NULL;
    const ctn_analysis_ops *ops = ctn_analysis_find(name);
    if (!ops) {
        char known[128] = "";
        for (size_t i = 0; i < NKINDS; i++)
            snprintf(known + strlen(known), sizeof known - strlen(known), "%s%s", i ? ", " : "", registry[i]->name);
        return ctn_error(p->ctx, CTN_ERR_INVALID, "unknown analysis '%.40s' (known: %s)", name ? name : "(null)", known);
    }
    ctn_analysis *a = ctn_calloc(p->ctx, 1, sizeof *a);
    void *opt = a ? ctn_calloc(p->ctx, 1, ops->options_size) : NULL;
    if (!opt) {
        ctn_free(a);
        return CTN_ERR_NOMEM;
    }
    ops->defaults(p, opt);
    char what[64];
    snprintf(what, sizeof what, "%s analysis options", ops->name);
    int rc = options ? ctn_versioned_take(p->ctx, opt, ops->options_size, options, what) : CTN_OK;
    if (!rc) rc = ops->check(p, opt);
    if (rc) {
        ctn_free(opt);
        ctn_free(a);
        return rc;
    }
    a->p = p;
    a->ops = ops;
    a->opt = opt;
    *out = a;
    return CTN_OK;
}

int ctn_analysis_run(ctn_analysis *a, ctn_solution **s)
{
    if (!a || !s) return a ? ctn_error(a->p->ctx, CTN_ERR_INVALID, "ctn_analysis_run: solution is NULL") : CTN_ERR_INVALID;
    if (a->ops->needs_solution) {
        if (!*s) return ctn_error(a->p->ctx, CTN_ERR_INVALID, "%s analysis: it runs about a solution (*s is NULL)", a->ops->name);
        if ((*s)->sum.reason != CTN_CONVERGED || !(*s)->nsteps)
            return ctn_error(a->p->ctx, CTN_ERR_INVALID, "%s analysis: the solution did not converge", a->ops->name);
    }
    return a->ops->run(a->p, a->opt, s);
}

const char *ctn_analysis_name(const ctn_analysis *a) { return a ? a->ops->name : NULL; }

void ctn_analysis_destroy(ctn_analysis **a)
{
    if (!a || !*a) return;
    ctn_free((*a)->opt);
    ctn_free(*a);
    *a = NULL;
}
