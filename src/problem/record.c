/* What a strategy keeps: iteration histories and the state of each step. */
#include "problem/problem.h"

#include <math.h>
#include <string.h>

int ctn_problem_record(ctn_problem *p, ctn_solution *s, double rnorm, double dnorm)
{
    return ctn_problem_record_ex(p, s, rnorm, dnorm, 0, 0.0);
}

int ctn_problem_record_ex(ctn_problem *p, ctn_solution *s, double rnorm, double dnorm, int rejected,
                          double shift)
{
    int rc = ctn_interrupted(p->ctx);
    if (!rc) rc = ctn_solution_push_residual(s, rnorm);
    if (!rc) rc = ctn_solution_push_increment(s, rejected ? 0.0 : dnorm);
    if (rc) return rc;
    s->sum.iterations++;
    s->sum.residual = rnorm;
    s->sum.increment = rejected ? 0.0 : dnorm;
    if (p->opt.monitor) {
        ctn_iterate it = { s->sum.iterations, rnorm, dnorm, rejected, shift };
        p->opt.monitor(p->opt.monitor_data, &it);
    }
    return CTN_OK;
}

/* Element states into a step (the one element loop's visitor). */
static void state_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    ctn_element_state *out = (ctn_element_state *)data + el->e;
    (void)a;
    out->length = el->st->l;
    out->strain = el->st->strain;
    out->force = el->st->N;
    out->stress = el->st->stress;
    out->slack = el->st->slack;
}

/* Reactions and element states at d (fext at the step's reached t) into step k. */
int ctn_problem_fill_step(ctn_problem *p, ctn_solution *s, size_t k, const double *d)
{
    ctn_step_state *st = &s->steps[k];
    const int *eq = p->a->map.eq;
    ctn_dofmap_to3(&p->a->map, d, st->d);
    if (st->rot) ctn_dofmap_rot_to3(&p->a->map, d, st->rot);
    if (ctn_asm_eval(p->a, d, 0, p->fint, NULL, NULL, NULL)) return CTN_OK;   /* collapsed: zeros stay */
    const double *fh = p->fl ? ctn_follow_forces(p, d) : NULL;
    for (size_t i = 0; i < p->ns; i++)
        p->react[i] = eq[i] < 0 ? p->fint[i] - p->fext[i] - (fh ? fh[i] : 0.0) : 0.0;
    ctn_dofmap_to3(&p->a->map, p->react, st->react);
    if (st->rot) ctn_dofmap_rot_to3(&p->a->map, p->react, st->moment);
    ctn_asm_loop(p->a, d, CTN_EVAL_STRESS, 0, state_visit, st->elem, NULL);
    return CTN_OK;
}
