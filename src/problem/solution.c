/* The solution object: per-step states, histories and accessors. The accessors without
 * a step refer to the last step. */
#include "model/model.h"
#include "problem/solution.h"

#include <stdio.h>

int ctn_solution_create(ctn_ctx *ctx, size_t nn, size_t ne, ctn_solution **out)
{
    *out = ctn_calloc(ctx, 1, sizeof(ctn_solution));
    if (!*out) return CTN_ERR_NOMEM;
    (*out)->ctx = ctx;
    (*out)->nn = nn;
    (*out)->ne = ne;
    (*out)->sum.fail_dir = -1;
    (*out)->sum.stable = -1;
    (*out)->stability.dir = -1;
    return CTN_OK;
}

int ctn_solution_add_step(ctn_solution *s, const char *name, size_t *k)
{
    int rc = ctn_array_reserve(s->ctx, (void **)&s->steps, &s->capsteps, s->nsteps + 1, sizeof *s->steps);
    if (rc) return rc;
    ctn_step_state *st = &s->steps[s->nsteps];
    snprintf(st->name, sizeof st->name, "%s", name ? name : "");
    st->reason = CTN_DIVERGED_MAXIT;
    st->t = 0;
    st->iterations = 0;
    st->d = ctn_calloc(s->ctx, 3 * s->nn, sizeof(double));
    st->react = ctn_calloc(s->ctx, 3 * s->nn, sizeof(double));
    st->elem = ctn_calloc(s->ctx, s->ne, sizeof(ctn_element_state));
    st->rot = s->rot ? ctn_calloc(s->ctx, 3 * s->nn, sizeof(double)) : NULL;
    st->moment = s->rot ? ctn_calloc(s->ctx, 3 * s->nn, sizeof(double)) : NULL;
    s->nsteps++;                               /* counted even if partial: freed by destroy */
    if (!st->d || !st->react || !st->elem || (s->rot && (!st->rot || !st->moment))) return CTN_ERR_NOMEM;
    *k = s->nsteps - 1;
    return CTN_OK;
}

int ctn_solution_push_residual(ctn_solution *s, double r)
{
    int rc = ctn_array_reserve(s->ctx, (void **)&s->rhist, &s->capr, s->nr + 1, sizeof(double));
    if (!rc) s->rhist[s->nr++] = r;
    return rc;
}

int ctn_solution_push_increment(ctn_solution *s, double d)
{
    int rc = ctn_array_reserve(s->ctx, (void **)&s->dhist, &s->capd, s->nd + 1, sizeof(double));
    if (!rc) s->dhist[s->nd++] = d;
    return rc;
}

static void free_step(ctn_step_state *st)
{
    ctn_free(st->d);
    ctn_free(st->react);
    ctn_free(st->elem);
    ctn_free(st->rot);
    ctn_free(st->moment);
}

void ctn_solution_destroy(ctn_solution **s)
{
    if (!s || !*s) return;
    for (size_t k = 0; k < (*s)->nsteps; k++) free_step(&(*s)->steps[k]);
    ctn_modes_destroy(&(*s)->modes);
    for (size_t k = 0; k < (*s)->ncases; k++) ctn_solution_destroy(&(*s)->cases[k]);
    ctn_free((*s)->cases);
    ctn_buckles_destroy(&(*s)->buckling);
    ctn_dyn_result_destroy(&(*s)->dyn);
    ctn_free((*s)->steps);
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
    if (n) *n = s ? s->nr : 0;
    return s ? s->rhist : NULL;
}

const double *ctn_solution_increment_history(const ctn_solution *s, size_t *n)
{
    if (n) *n = s ? s->nd : 0;
    return s ? s->dhist : NULL;
}

static const ctn_step_state *last(const ctn_solution *s)
{
    return s && s->nsteps ? &s->steps[s->nsteps - 1] : NULL;
}

const double *ctn_solution_displacements(const ctn_solution *s) { return last(s) ? last(s)->d : NULL; }
const double *ctn_solution_reactions(const ctn_solution *s) { return last(s) ? last(s)->react : NULL; }

const double *ctn_solution_rotations(const ctn_solution *s) { return last(s) ? last(s)->rot : NULL; }
const double *ctn_solution_reaction_moments(const ctn_solution *s) { return last(s) ? last(s)->moment : NULL; }
int ctn_solution_has_rotations(const ctn_solution *s) { return s && s->rot; }

int ctn_solution_step_rotations(const ctn_solution *s, size_t k, const double **rot, const double **moment)
{
    if (!s || k >= s->nsteps) return CTN_ERR_INVALID;
    if (rot) *rot = s->steps[k].rot;
    if (moment) *moment = s->steps[k].moment;
    return CTN_OK;
}

int ctn_solution_element(const ctn_solution *s, size_t i, ctn_element_state *out)
{
    return s ? ctn_solution_step_element(s, s->nsteps - 1, i, out) : CTN_ERR_INVALID;
}

size_t ctn_solution_step_count(const ctn_solution *s) { return s ? s->nsteps : 0; }

int ctn_solution_step(const ctn_solution *s, size_t k, ctn_step_result *out)
{
    if (!s || !out || k >= s->nsteps) return CTN_ERR_INVALID;
    const ctn_step_state *st = &s->steps[k];
    out->name = st->name;
    out->reason = st->reason;
    out->load_factor = st->t;
    out->iterations = st->iterations;
    out->d = st->d;
    out->react = st->react;
    return CTN_OK;
}

int ctn_solution_step_element(const ctn_solution *s, size_t k, size_t i, ctn_element_state *out)
{
    if (!s || !out || k >= s->nsteps || i >= s->ne) return CTN_ERR_INVALID;
    *out = s->steps[k].elem[i];
    return CTN_OK;
}

void ctn_solution_drop_step(ctn_solution *s)
{
    if (!s || !s->nsteps) return;
    free_step(&s->steps[--s->nsteps]);
}

int ctn_solution_stability(const ctn_solution *s, ctn_stability *out)
{
    if (!s || !out || s->sum.stable < 0) return CTN_ERR_INVALID;
    *out = s->stability;
    return CTN_OK;
}

size_t ctn_solution_case_count(const ctn_solution *s) { return s ? s->ncases : 0; }

const ctn_solution *ctn_solution_case(const ctn_solution *s, size_t i)
{
    return s && i < s->ncases ? s->cases[i] : NULL;
}

int ctn_solution_threads(const ctn_solution *s) { return s ? s->threads : 1; }
