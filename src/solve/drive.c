/* ctn_solve: the load-step driver. Each load step goes from the previous step's state
 * to its own loads in increments of t; a failed increment is halved (cut back) up to
 * maxcuts times; the state of each step is kept. Arc-length has its own driver. */
#include "solve/engine.h"

#include <math.h>
#include <string.h>

/* One load step in increments, with cut-back. dstep: 3 nn scratch. */
static int run_step(ctn_engine *e, ctn_solution *s, size_t k, double *d, double *dstep)
{
    ctn_step_state *st = &s->steps[k];
    int sub = ctn_model_step_substeps(e->m, k);
    double dt0 = 1.0 / (sub > 0 ? sub : e->opt.steps), t = 0, dt = dt0;
    int cuts = 0, it0 = s->sum.iterations, rc = CTN_OK;
    ctn_reason why = CTN_CONVERGED;
    while (t < 1) {
        double tn = t + dt > 1 - 1e-12 ? 1 : t + dt;
        memcpy(dstep, d, e->n3 * sizeof(double));
        ctn_engine_set_t(e, tn, d);
        if ((rc = ctn_newton_correct(e, s, d, &why))) break;
        if (why == CTN_CONVERGED) {
            t = tn;
            dt = fmin(dt0, 2 * dt);
            continue;
        }
        memcpy(d, dstep, e->n3 * sizeof(double));
        if (cuts >= e->opt.maxcuts) break;
        cuts++;
        s->sum.cuts++;
        dt *= 0.5;
    }
    ctn_engine_set_t(e, t, d);
    st->t = t;
    st->reason = why;
    st->iterations = s->sum.iterations - it0;
    ctn_engine_fill_step(e, s, k, d);
    return rc;
}

static int run_steps(ctn_engine *e, ctn_solution *s, double *d, double *dstep)
{
    for (size_t k = 0; k < ctn_model_step_count(e->m); k++) {
        size_t idx;
        int rc = ctn_solution_add_step(s, ctn_model_step_name(e->m, k), &idx);
        if (rc) return rc;
        memcpy(e->f0, e->f1, e->n3 * sizeof(double));
        memcpy(e->p0, e->p1, e->n3 * sizeof(double));
        ctn_model_step_loads(e->m, k, e->f1, e->p1);
        if ((rc = run_step(e, s, idx, d, dstep))) return rc;
        s->sum.step = k;
        s->sum.reason = s->steps[idx].reason;
        s->sum.load_factor = s->steps[idx].t;
        if (s->sum.reason != CTN_CONVERGED) break;
    }
    return CTN_OK;
}

/* The start state must have finite element forces: otherwise the model is beyond double
 * precision (e.g. a stretch l/l0 of 1e200), an input error naming the element. */
static int check_start(ctn_engine *e, const double *d)
{
    for (size_t i = 0; i < e->a->ne; i++) {
        double X[CTN_EDOF], u[CTN_EDOF], f[CTN_EDOF];
        ctn_elem_state st;
        ctn_asm_gather(e->a, i, d, X, u);
        int bad = e->a->ops->eval(&e->a->props[i], X, u, f, NULL, &st);
        if (!bad && isfinite(st.N) && isfinite(st.energy)) continue;
        const ctn_element *el = &e->m->elements.v[i];
        if (bad) return ctn_error_at(e->ctx, CTN_ERR_MODEL, e->m->file, el->line, "element %d has zero length in the start state", el->id);
        return ctn_error_at(e->ctx, CTN_ERR_MODEL, e->m->file, el->line,
                            "element %d: its force in the start state is not finite (stretch l/l0 = %g, E A = %g)",
                            el->id, st.l / e->a->props[i].l0, e->a->props[i].EA);
    }
    return CTN_OK;
}

static void resolve_options(const ctn_model *m, const ctn_solve_options *opt, ctn_solve_options *o)
{
    if (opt) *o = *opt;
    else ctn_model_solve_options(m, o);
    if (o->steps < 1) o->steps = 1;
    if (o->maxcuts < 0) o->maxcuts = o->method == CTN_METHOD_NEWTON ? 0 : 10;
}

int ctn_solve(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt,
              ctn_solution **out)
{
    if (!m || !out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_solve: model or out is NULL");
    *out = NULL;
    int rc = ctn_model_validate(m);
    if (rc) return rc;
    ctn_solve_options o;
    resolve_options(m, opt, &o);
    ctn_solution *s = NULL;
    ctn_engine e;
    double *d = NULL, *dstep = NULL, t0 = ctn_now();
    if ((rc = ctn_solution_create(ctx, m->nodes.n, m->elements.n, &s))) return rc;
    rc = ctn_engine_setup(&e, ctx, m, &o, &s->sum);
    s->sum.t_setup = ctn_now() - t0;
    if (!rc && (!(d = ctn_calloc(ctx, e.n3, sizeof(double))) || !(dstep = ctn_calloc(ctx, e.n3, sizeof(double)))))
        rc = CTN_ERR_NOMEM;
    if (!rc) {
        for (size_t i = 0; i < e.n3; i++)
            d[i] = e.a->eq[i] >= 0 ? m->nodes.v[i / 3].guess[i % 3] : 0.0;
        if (o.method == CTN_METHOD_AUTO) rc = ctn_preshape(&e, d, &s->sum.preshaped);
        if (!rc) rc = check_start(&e, d);
        if (!rc) rc = o.method == CTN_METHOD_ARCLENGTH ? ctn_arclength_run(&e, s, d) : run_steps(&e, s, d, dstep);
        s->sum.fext_norm = ctn_engine_fref(&e);
        s->sum.ordering = ctn_chol_ordering(e.ch);
        s->sum.ndof = e.ndof;
        s->sum.nnz_factor = ctn_chol_factor_nnz(e.ch);
    }
    ctn_free(d);
    ctn_free(dstep);
    ctn_engine_teardown(&e);
    if (rc) ctn_solution_destroy(&s);
    *out = s;
    return rc;
}
