/* Load cases and combinations: each solved non-linearly from its installed state (the
 * converged end of a model step), not cumulatively. A case runs exactly what a further
 * load step after its installed state would run: the same state, the same start loads
 * (the step's totals, by the same sums) and the same end loads (those totals and the
 * case's own records, in the model's order), so a case reproduces that step bit for bit
 * (tests/test_cases.c). Each result is a solution of one step, kept in the main one. */
#include "problem/problem.h"

#include <string.h>

/* d (state) = the state at the end of step k of s. */
static void installed_state(const ctn_problem *p, const ctn_solution *s, size_t k, double *d)
{
    const ctn_step_state *st = &s->steps[k];
    memset(d, 0, p->ns * sizeof(double));
    ctn_dofmap_from3(&p->a->map, st->d, d);
    if (p->a->map.rot && st->rot) ctn_dofmap_rot_from3(&p->a->map, st->rot, d);
}

/* Case (or combination) i into a new solution of one step. */
static int solve_case(ctn_problem *p, const ctn_solution *s, size_t i, double *d, double *dstep, int *tags,
                      double *factors, ctn_solution **out)
{
    const ctn_model *m = p->m;
    const char *name = NULL;
    int from = 0, comb = 0;
    ctn_loadsel sel;
    ctn_model_case_info(m, i, &name, &from, &comb);
    ctn_model_case_sel(m, i, &sel, tags, factors);
    if ((size_t)from >= s->nsteps || s->steps[from].reason != CTN_CONVERGED)
        return ctn_error(p->ctx, CTN_ERR_INVALID, "case '%s': its installed state (step %d) was not solved", name, from + 1);
    ctn_solution *cs = NULL;
    size_t idx = 0;
    int rc = ctn_solution_create(p->ctx, m->nodes.n, m->elements.n, &cs);
    if (rc) return rc;
    cs->rot = s->rot;
    cs->of_case = i + 1;
    cs->threads = s->threads;
    if ((rc = ctn_solution_add_step(cs, name, &idx))) goto done;
    ctn_problem_step_loads(p, (size_t)from);        /* the installed state's totals */
    memcpy(p->f0, p->f1, p->ns * sizeof(double));
    memcpy(p->p0, p->p1, p->ns * sizeof(double));
    ctn_problem_sel_loads(p, &sel);                 /* and the case's */
    installed_state(p, s, (size_t)from, d);
    int sub = comb ? 0 : m->cases.v[i].substeps;
    if (p->strategy->preshape && (sub > 0 ? sub : p->opt.steps) == 1) {   /* as a further step */
        ctn_loadsel base = ctn_loadsel_step((size_t)from);               /* would start */
        int placed = 0;
        if ((rc = ctn_preshape_step(p, &base, &sel, d, &placed))) goto done;
    }
    p->sum = &cs->sum;
    rc = ctn_problem_run_step(p, cs, idx, sub, d, dstep);
    cs->sum.step = 0;
    cs->sum.reason = cs->steps[idx].reason;
    cs->sum.load_factor = cs->steps[idx].t;
    cs->sum.stable = -1;                            /* not checked */
done:
    if (rc) ctn_solution_destroy(&cs);
    *out = cs;
    return rc;
}

int ctn_problem_cases(ctn_problem *p, ctn_solution *s)
{
    const ctn_model *m = p->m;
    size_t n = ctn_model_case_count(m), nt = m->cases.n ? m->cases.n : 1;
    if (!n) return CTN_OK;
    if (p->strategy->run != ctn_strategy_auto.run)
        return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, m->cases.v[0].line,
                            "load cases are solved by load steps: method=arclength follows a single load pattern "
                            "(use method=auto or method=newton)");
    double *d = ctn_calloc(p->ctx, p->ns, sizeof(double)), *dstep = ctn_calloc(p->ctx, p->ns, sizeof(double));
    double *factors = ctn_calloc(p->ctx, nt, sizeof(double));
    int *tags = ctn_calloc(p->ctx, nt, sizeof(int));
    s->cases = ctn_calloc(p->ctx, n, sizeof *s->cases);
    int rc = d && dstep && factors && tags && s->cases ? CTN_OK : CTN_ERR_NOMEM;
    ctn_solve_summary *keep = p->sum;
    for (size_t i = 0; i < n && !rc; i++) {
        rc = solve_case(p, s, i, d, dstep, tags, factors, &s->cases[i]);
        if (!rc) s->ncases = i + 1;
    }
    p->sum = keep;
    ctn_free(d);
    ctn_free(dstep);
    ctn_free(factors);
    ctn_free(tags);
    return rc;
}
