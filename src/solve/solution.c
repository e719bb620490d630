/* The solution object: allocation and accessors. */
#include "solve/solution.h"

int ctn_solution_alloc(ctn_ctx *ctx, size_t nn, size_t ne, int maxit, ctn_solution **out)
{
    ctn_solution *s = ctn_calloc(ctx, 1, sizeof(ctn_solution));
    *out = NULL;
    if (!s) return CTN_ERR_NOMEM;
    s->nn = nn;
    s->ne = ne;
    s->d = ctn_calloc(ctx, 3 * nn, sizeof(double));
    s->react = ctn_calloc(ctx, 3 * nn, sizeof(double));
    s->elem = ctn_calloc(ctx, ne, sizeof(ctn_element_state));
    s->rhist = ctn_calloc(ctx, (size_t)maxit + 1, sizeof(double));
    s->dhist = ctn_calloc(ctx, (size_t)maxit + 1, sizeof(double));
    if (!s->d || !s->react || !s->elem || !s->rhist || !s->dhist) {
        ctn_solution_destroy(&s);
        return CTN_ERR_NOMEM;
    }
    s->sum.fail_dir = -1;
    *out = s;
    return CTN_OK;
}

void ctn_solution_destroy(ctn_solution **s)
{
    if (!s || !*s) return;
    ctn_free((*s)->d);
    ctn_free((*s)->react);
    ctn_free((*s)->elem);
    ctn_free((*s)->rhist);
    ctn_free((*s)->dhist);
    ctn_free(*s);
    *s = NULL;
}

void ctn_solution_summary(const ctn_solution *s, ctn_solve_summary *out)
{
    if (s && out) *out = s->sum;
}

const double *ctn_solution_residual_history(const ctn_solution *s, size_t *n)
{
    if (n) *n = s ? s->nhist + 1 : 0;
    return s ? s->rhist : NULL;
}

const double *ctn_solution_increment_history(const ctn_solution *s, size_t *n)
{
    if (n) *n = s ? s->nhist : 0;
    return s ? s->dhist : NULL;
}

const double *ctn_solution_displacements(const ctn_solution *s) { return s ? s->d : NULL; }
const double *ctn_solution_reactions(const ctn_solution *s) { return s ? s->react : NULL; }

int ctn_solution_element(const ctn_solution *s, size_t i, ctn_element_state *out)
{
    if (!s || !out || i >= s->ne) return CTN_ERR_INVALID;
    *out = s->elem[i];
    return CTN_OK;
}
