/* Static analysis: the load-step driver and the entry points. Each load step goes from
 * the previous step's state to its own loads in increments of t; a failed increment is
 * halved (cut back) up to maxcuts times; the state of each step is kept. Arc-length has
 * its own driver (arclength.c). */
#include "analysis/analysis.h"
#include "analysis/buckling/buckling.h"
#include "problem/dynamics_options.h"
#include "problem/la_options.h"
#include "start/fdensity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

int ctn_problem_run_step(ctn_problem *p, ctn_solution *s, size_t k, int sub, double *d, double *dstep)
{
    ctn_step_state *st = &s->steps[k];
    double dt0 = 1.0 / (sub > 0 ? sub : p->opt.steps), t = 0, dt = dt0;
    int cuts = 0, it0 = s->sum.iterations, rc = CTN_OK;
    ctn_reason why = CTN_CONVERGED;
    while (t < 1) {
        double tn = t + dt > 1 - 1e-12 ? 1 : t + dt;
        memcpy(dstep, d, p->ns * sizeof(double));
        ctn_problem_set_t(p, tn, d);
        if ((rc = ctn_newton_correct(p, s, d, &why))) break;
        if (why == CTN_CONVERGED) {
            t = tn;
            dt = fmin(dt0, 2 * dt);
            continue;
        }
        memcpy(d, dstep, p->ns * sizeof(double));
        if (cuts >= p->opt.maxcuts || why == CTN_DIVERGED_ROUNDOFF) break;   /* smaller loads
                                                          cannot lift them above round-off */
        cuts++;
        s->sum.cuts++;
        dt *= 0.5;
    }
    ctn_problem_set_t(p, t, d);
    st->t = t;
    st->reason = why;
    st->iterations = s->sum.iterations - it0;
    return rc ? rc : ctn_problem_fill_step(p, s, k, d);
}

/* |f_ext| on the free DOFs at the end of the step being solved (f1). */
static double step_load(const void *ud, size_t i)
{
    const ctn_problem *p = ud;
    return p->a->map.eq[i] >= 0 ? p->f1[i] : 0;
}

static double step_load_norm(const ctn_problem *p)
{
    double s = 0;
    for (size_t i = 0; i < p->ns; i++)
        if (p->a->map.eq[i] >= 0) s += p->f1[i] * p->f1[i];
    return ctn_layout_norm_ss(&p->st, ctn_layout_sum(&p->st, s), step_load, p);
}

/* The load-step strategies (auto, newton). */
static int run_steps(ctn_problem *p, ctn_solution *s, double *d)
{
    double *dstep = ctn_calloc(p->ctx, p->ns, sizeof(double));
    int rc = dstep ? CTN_OK : CTN_ERR_NOMEM;
    memset(p->f1, 0, p->ns * sizeof(double));
    memset(p->p1, 0, p->ns * sizeof(double));
    if (p->dT1) memset(p->dT1, 0, p->a->ne * sizeof(double));
    ctn_follow_reset(p);
    size_t nsteps = ctn_model_step_count(p->m);
    if (p->max_steps && p->max_steps < nsteps) nsteps = p->max_steps;
    for (size_t k = 0; !rc && k < nsteps; k++) {
        size_t idx;
        if ((rc = ctn_solution_add_step(s, ctn_model_step_name(p->m, k), &idx))) break;
        memcpy(p->f0, p->f1, p->ns * sizeof(double));
        memcpy(p->p0, p->p1, p->ns * sizeof(double));
        ctn_problem_step_loads(p, k);
        double target = step_load_norm(p);
        int sub = ctn_model_step_substeps(p->m, k);
        if (k > 0 && p->strategy->preshape && (sub > 0 ? sub : p->opt.steps) == 1) {   /* a chain heated */
            ctn_loadsel from = ctn_loadsel_step(k - 1), to = ctn_loadsel_step(k);   /* slack, a wind */
            int placed = 0;                                                          /* that turns */
            if ((rc = ctn_preshape_step(p, &from, &to, d, &placed))) break;
        }
        if ((rc = ctn_problem_run_step(p, s, idx, sub, d, dstep))) break;
        s->sum.step = k;
        s->sum.fext_norm = s->steps[idx].reason == CTN_CONVERGED || !(target > 0) ? ctn_problem_fref(p) : target;
        s->sum.reason = s->steps[idx].reason;
        s->sum.load_factor = s->steps[idx].t;
        if (s->sum.reason != CTN_CONVERGED) break;
    }
    ctn_free(dstep);
    return rc;
}

typedef struct start_check {
    const ctn_problem *p;
    size_t bad;            /* first element with a non-finite force, or SIZE_MAX */
    double N;
} start_check;

static void start_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    start_check *c = data;
    (void)a;
    if (c->bad == (size_t)-1 && !(isfinite(el->st->N) && isfinite(el->st->energy))) {
        c->bad = el->e;
        c->N = el->st->N;
    }
}

/* The start state must have finite element forces: otherwise the model is beyond double
 * precision (e.g. a stretch l/l0 of 1e200), an input error naming the element. */
static int check_start(ctn_problem *p, const double *d)
{
    start_check c = { p, (size_t)-1, 0 };
    size_t collapsed = 0;
    const ctn_model *m = p->m;
    for (size_t i = 0; i < m->nodes.n; i++) {
        const ctn_node *nd = &m->nodes.v[i];
        for (int k = 0; k < 3; k++)
            if (!isfinite(nd->X[k] + nd->guess[k]))
                return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, nd->line, "node %d: its start position is beyond "
                                    "double precision (a start stretched by loads over a stiffness EA near 0: check "
                                    "E, A, the loads and the units)", nd->id);
    }
    if (ctn_asm_loop(p->a, d, 0, 0, start_visit, &c, &collapsed)) {
        const ctn_element *el = &m->elements.v[collapsed];
        return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, el->line, "element %d has a chord of zero length (or "
                            "beyond double precision) in the start state%s", el->id,
                            ctn_element_family(el->type)->eval == ctn_catenary2_ops.eval ? " (or its catenary's forces overflow)" : "");
    }
    if (c.bad == (size_t)-1) return CTN_OK;
    const ctn_element *el = &m->elements.v[c.bad];
    return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, el->line,
                        "element %d: its force in the start state is not finite (N = %g, stiffness scale %g)",
                        el->id, c.N, ctn_asm_block_of(p->a, c.bad)->ops->stiffness(ctn_asm_props(p->a, c.bad)));
}

/* The start: the model's starting displacements on free DOFs, zero on fixed ones. */
static void start_state(ctn_problem *p, double *d)
{
    for (size_t i = 0; i < p->m->nodes.n; i++)
        for (int k = 0; k < 3; k++) p->v3[3 * i + (size_t)k] = p->m->nodes.v[i].guess[k];
    ctn_dofmap_from3(&p->a->map, p->v3, d);
    for (size_t i = 0; i < p->ns; i++)
        if (p->a->map.eq[i] < 0) d[i] = 0.0;
    if (p->dT) {                                     /* the reference temperature */
        memset(p->dT, 0, p->a->ne * sizeof(double));
        ctn_asm_set_temperatures(p->a, p->dT);
    }
}

/* The stability of the converged state. The last Newton iteration factored the tangent a
 * correction away from it: if that was LL' of K itself and it succeeded, the state is
 * stable at no cost (the tangents differ by the round-off of the last correction). Else
 * a tangent definite by its structure (members in tension tying every free DOF to a
 * support) needs no factorization, unless a modal analysis follows and reuses the
 * check's factor; otherwise the problem factors it. */
static int check_stability(ctn_problem *p, ctn_solution *s)
{
    s->sum.stable = 1;
    if (p->last_definite || p->ndof == 0) {
        memset(&s->stability, 0, sizeof s->stability);
        s->stability.stable = 1;
        s->stability.dir = -1;
        return CTN_OK;
    }
    if (p->opt.modal.count == 0) {                  /* a modal analysis wants K_T's factor */
        int ok = 0, rc = ctn_problem_stable_by_tension(p, s, &ok);
        if (rc) return rc;
        if (ok) {
            memset(&s->stability, 0, sizeof s->stability);
            s->stability.stable = s->stability.by_tension = 1;
            s->stability.dir = -1;
            return CTN_OK;
        }
    }
    ctn_solve_summary *keep = p->sum;
    int rc = ctn_problem_stability(p, s, &s->stability);
    p->sum = keep;
    s->sum.stable = rc ? -1 : s->stability.stable;
    if (rc == CTN_ERR_NOMEM) return rc;
    if (rc) ctn_ctx_clear(p->ctx);                  /* could not tell: left unchecked */
    return CTN_OK;
}

/* The static analysis with the problem's options. */
static int static_solve(ctn_problem *p, ctn_solution **out)
{
    *out = NULL;
    ctn_solution *s = NULL;
    double *d = NULL;
    int rc = ctn_solution_create(p->ctx, p->m->nodes.n, p->m->elements.n, &s);
    if (rc) return rc;
    s->rot = p->a->map.rot > 0;
    p->sum = &s->sum;
    s->threads = p->opt.threads;
    s->sum.t_setup = p->t_setup;
    p->mode = 0;
    p->mech_node = p->mech_dir = -1;
    if (!(d = ctn_calloc(p->ctx, p->ns, sizeof(double)))) rc = CTN_ERR_NOMEM;
    int rest = ctn_dynamics_asked(&p->opt.dynamics) && p->opt.dynamics.from_rest && !p->max_steps;
    if (!rc && rest) rc = ctn_dynamics_run(p, s, &p->opt.dynamics);   /* no static analysis */
    if (!rc) {
        start_state(p, d);
        if (rest) goto summary;
        if (p->strategy->preshape) rc = ctn_preshape(p, d, &s->sum.preshaped);
        if (!rc && p->strategy->preshape && !s->sum.preshaped) rc = ctn_fdensity_start(p, d, &s->sum.fdensity);
        if (!rc) rc = check_start(p, d);
        if (!rc) rc = p->strategy->run(p, s, d);
        if (!rc && s->sum.reason != CTN_CONVERGED && p->mech_node >= 0) {   /* junction.c's finding */
            s->sum.reason = CTN_DIVERGED_MECHANISM;
            s->sum.fail_node = p->m->nodes.v[p->mech_node].id;
            s->sum.fail_dir = p->mech_dir;
            if (s->nsteps) s->steps[s->nsteps - 1].reason = CTN_DIVERGED_MECHANISM;
        }
        if (!rc && s->sum.reason == CTN_CONVERGED) rc = check_stability(p, s);
        if (s->sum.reason == CTN_CONVERGED) s->sum.fail_element = 0;
        if (!rc && s->sum.reason == CTN_CONVERGED && p->opt.modal.count > 0) rc = ctn_problem_modes(p, s, &p->opt.modal);
        if (!rc && s->sum.reason == CTN_CONVERGED && p->opt.buckling.count > 0)
            rc = ctn_problem_buckling(p, s, &p->opt.buckling);
        if (!rc && s->sum.reason == CTN_CONVERGED && !p->max_steps && ctn_model_case_count(p->m)) rc = ctn_problem_cases(p, s);
        if (!rc && s->sum.reason == CTN_CONVERGED && !p->max_steps && ctn_dynamics_asked(&p->opt.dynamics))
            rc = ctn_dynamics_run(p, s, &p->opt.dynamics);
    summary:
        if (!s->sum.fext_norm) s->sum.fext_norm = ctn_problem_fref(p);
        s->sum.ordering = p->ls ? ctn_ordering_of_la(ctn_linsolve_ordering(p->ls)) : CTN_ORDER_NATURAL;
        s->sum.ndof = p->ndof;
        s->sum.nnz_factor = p->ls ? ctn_linsolve_factor_nnz(p->ls) : 0;
        s->sum.flops_factor = p->ls ? ctn_linsolve_flops(p->ls) : 0;
        s->sum.solve_threads = p->ls ? ctn_linsolve_solve_threads(p->ls) : 1;
        ctn_blas_name(s->sum.blas, sizeof s->sum.blas);
        s->ranks = ctn_comm_size(ctn_ctx_comm(p->ctx));
        s->by_columns = p->dist;
        snprintf(s->linsolver, sizeof s->linsolver, "%s", p->ls ? ctn_linsolve_label(p->ls) : p->ls_name ? p->ls_name : "");
    }
    ctn_free(d);
    p->sum = NULL;
    if (rc) ctn_solution_destroy(&s);
    *out = s;
    return rc;
}

int ctn_static_run(ctn_problem *p, const ctn_solve_options *o, ctn_solution **out)
{
    ctn_solve_options keep = p->opt;
    const ctn_strategy_ops *keep_strategy = p->strategy;
    p->opt = *o;
    p->strategy = ctn_strategy_of(o->method);
    if (p->opt.maxcuts < 0) p->opt.maxcuts = p->strategy->maxcuts;
    int rc = static_solve(p, out);
    p->opt = keep;
    p->strategy = keep_strategy;
    return rc;
}

int ctn_problem_solve(ctn_problem *p, ctn_solution **out)
{
    if (!p || !out) return p ? ctn_error(p->ctx, CTN_ERR_INVALID, "ctn_problem_solve: out is NULL") : CTN_ERR_INVALID;
    ctn_analysis *a = NULL;
    int rc = ctn_analysis_create(p, "static", NULL, &a);
    *out = NULL;
    if (!rc) rc = ctn_analysis_run(a, out);
    ctn_analysis_destroy(&a);
    return rc;
}

/* The analysis object: the problem's options by default; other options may change what
 * a run does (tolerances, iterations, steps, cut-backs, arc-length, the monitor, the
 * modes after it), not what the problem set up for them. */
static void static_defaults(const ctn_problem *p, void *opt) { *(ctn_solve_options *)opt = p->opt; }

static int static_check(ctn_problem *p, const void *opt)
{
    const ctn_solve_options *o = opt, *q = &p->opt;
    int rc = ctn_solve_options_check(p->ctx, o);
    if (rc) return rc;
    const char *ls = o->linear_solver ? o->linear_solver : ctn_strategy_of(o->method)->linear_solver;
    const char *pls = q->linear_solver ? q->linear_solver : p->strategy->linear_solver;
    const char *key = o->method != q->method                            ? "method"
                      : strcmp(ls, pls)                                 ? "linear_solver"
                      : o->ordering != q->ordering                      ? "ordering"
                      : o->threads != q->threads                        ? "threads"
                      : o->reuse != q->reuse                            ? "reuse"
                      : o->linesearch != q->linesearch                  ? "linesearch"
                                                                        : NULL;
    return key ? ctn_error(p->ctx, CTN_ERR_INVALID, "static analysis: its %s differs from the problem's, which was set "
                           "up for it: create the problem with these options", key)
               : CTN_OK;
}

static int static_analysis(ctn_problem *p, const void *opt, ctn_solution **s)
{
    return ctn_static_run(p, opt, s);
}

const ctn_analysis_ops ctn_analysis_static = {
    "static", sizeof(ctn_solve_options), 0, static_defaults, static_check, static_analysis,
};

int ctn_solve(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt,
              ctn_solution **out)
{
    if (!m || !out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_solve: model or out is NULL");
    *out = NULL;
    ctn_problem *p = NULL;
    int rc = ctn_problem_create(ctx, m, opt, &p);
    if (!rc) rc = ctn_problem_solve(p, out);
    ctn_problem_destroy(&p);
    return rc;
}

const ctn_strategy_ops ctn_strategy_auto = { "auto", "cholmod", 1, 1, 10, run_steps };
const ctn_strategy_ops ctn_strategy_newton = { "newton", "cholmod", 0, 0, 0, run_steps };
const ctn_strategy_ops ctn_strategy_arclength = { "arclength", "cholmod-ldl", 0, 0, 10, ctn_arclength_run };

const ctn_strategy_ops *ctn_strategy_of(ctn_method method)
{
    switch (method) {
    case CTN_METHOD_AUTO: return &ctn_strategy_auto;
    case CTN_METHOD_NEWTON: return &ctn_strategy_newton;
    case CTN_METHOD_ARCLENGTH: return &ctn_strategy_arclength;
    default: return NULL;
    }
}
