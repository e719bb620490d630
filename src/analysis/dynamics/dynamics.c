/* Dynamics analysis: time integration from rest at the start geometry, or from the
 * equilibrium of a static solution's last step with its loads held, by the implicit
 * generalized-alpha family (dyn_implicit.c) or explicit central differences
 * (dyn_central.c); a failed step is retried with dt halved, up to maxcuts times, and dt
 * grows back after; a row of the histories at every multiple of dt (dyn_record.c).
 * docs/theory.md "Dynamics". */
#include "analysis/analysis.h"
#include "analysis/dynamics/dynamics.h"
#include "problem/dynamics_options.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void dyn_free(ctn_dyn *dy)
{
    ctn_free(dy->severed);
    ctn_free(dy->mcol);
    ctn_free(dy->mrow);
    ctn_free(dy->mval);
    ctn_free(dy->mslot);
    ctn_free(dy->sup_e);
    ctn_free(dy->sup_off);
    ctn_free(dy->sup_idx);
    ctn_free(dy->mpiv);
    ctn_free(dy->welem);
    ctn_dyn_rot_free(dy);
    double *v[] = { dy->Mx, dy->Cx, dy->diag, dy->d0, dy->d1, dy->v0, dy->a0, dy->v1, dy->a1, dy->r0, dy->r1,
                    dy->R, dy->w, dy->w2, dy->ework, dy->fe0, dy->react, dy->vs, dy->as, dy->sup_M, dy->sup_K, dy->fsup, dy->mPhi, dy->mU, dy->mY, dy->mE, dy->mS, dy->mG, dy->mg, dy->wk, dy->wvel, dy->wD, dy->wf,
                    dy->wf0, dy->wv, dy->fh0 };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
}

static int dyn_alloc(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    size_t n = p->ndof, nz = p->a->nnz ? p->a->nnz : 1;
    double **nv[] = { &dy->diag, &dy->v0, &dy->a0, &dy->v1, &dy->a1, &dy->r0, &dy->r1, &dy->R, &dy->w, &dy->w2 };
    for (size_t i = 0; i < sizeof nv / sizeof *nv; i++)
        if (!(*nv[i] = ctn_calloc(p->ctx, n, sizeof(double)))) return CTN_ERR_NOMEM;
    dy->d0 = ctn_calloc(p->ctx, p->ns, sizeof(double));
    dy->d1 = ctn_calloc(p->ctx, p->ns, sizeof(double));
    dy->fe0 = ctn_calloc(p->ctx, p->ns, sizeof(double));
    dy->Mx = ctn_calloc(p->ctx, nz, sizeof(double));
    dy->ework = ctn_calloc(p->ctx, 3 * (size_t)p->a->maxdof + 16, sizeof(double));
    if (p->fl && !(dy->fh0 = ctn_calloc(p->ctx, p->ns, sizeof(double)))) return CTN_ERR_NOMEM;
    if (!dy->d0 || !dy->d1 || !dy->fe0 || !dy->Mx || !dy->ework) return CTN_ERR_NOMEM;
    size_t nr = p->m->removals.n;
    if (nr && !(dy->severed = ctn_calloc(p->ctx, nr, 1))) return CTN_ERR_NOMEM;
    if ((dy->o->damping_alpha > 0 || dy->o->damping_beta > 0) && !(dy->Cx = ctn_calloc(p->ctx, nz, sizeof(double))))
        return CTN_ERR_NOMEM;
    return CTN_OK;
}

void ctn_dyn_accept(ctn_dyn *dy, double h, const double *r1)
{
    ctn_problem *p = dy->p;
    const int *eq = p->a->map.eq, *dir = p->a->map.dof_dir;
    size_t n = p->ndof;
    double work = ctn_dyn_rot_work(dy, dy->fe0, p->fext);   /* moments: on the spatial turn */
    for (size_t i = 0; i < p->ns; i++)                   /* the trapezoidal rule (exact for */
        if (eq[i] >= 0 && dir[eq[i]] < 3) work += 0.5 * (dy->fe0[i] + p->fext[i]) * (dy->d1[i] - dy->d0[i]);   /* loads held) */
    for (size_t i = 0; dy->nwind && i < p->ns; i++)     /* the drag's work, likewise */
        if (eq[i] >= 0) work += 0.5 * (dy->wf0[i] + dy->wf[i]) * (dy->d1[i] - dy->d0[i]);
    if (dy->nwind) memcpy(dy->wf0, dy->wf, p->ns * sizeof(double));
    if (p->fl) {                                         /* the follower loads', likewise */
        const double *fh = ctn_follow_loads(p->fl);
        for (size_t i = 0; i < p->ns; i++)
            if (eq[i] >= 0) work += 0.5 * (dy->fh0[i] + fh[i]) * (dy->d1[i] - dy->d0[i]);
        memcpy(dy->fh0, fh, p->ns * sizeof(double));
    }
    dy->W += ctn_layout_sum(&p->st, work);
    memcpy(dy->fe0, p->fext, p->ns * sizeof(double));
    if (ctn_dyn_damped(dy)) {                            /* the power w . C w (spatial w) */
        ctn_dyn_damp_at(dy, dy->d0, dy->v0, dy->w, dy->w2);
        double c0 = ctn_layout_dot(&p->eq, dy->w, dy->w2);
        ctn_dyn_damp_at(dy, dy->d1, dy->v1, dy->w, dy->w2);
        dy->D += 0.5 * h * (c0 + ctn_layout_dot(&p->eq, dy->w, dy->w2));
    }
    ctn_dyn_mass(dy, dy->v1, dy->w2);
    dy->ek = 0.5 * ctn_layout_dot(&p->eq, dy->v1, dy->w2) + ctn_dyn_rot_accept(dy);
    dy->U = dy->U1;
    memcpy(dy->d0, dy->d1, p->ns * sizeof(double));
    memcpy(dy->v0, dy->v1, n * sizeof(double));
    memcpy(dy->a0, dy->a1, n * sizeof(double));
    memcpy(dy->r0, r1, n * sizeof(double));
    dy->emax = fmax(dy->emax, fabs(dy->ek + dy->U - dy->W + dy->D - dy->e0));
    dy->escale = fmax(dy->escale, dy->ek + fabs(dy->U) + fabs(dy->W) + dy->D);
}

/* One step of h from t by the method; *ok = 0 when it failed. */
static int try_step(ctn_dyn *dy, double t, double h, int *ok)
{
    dy->t1 = t + h;
    ctn_dyn_set_time(dy, t + h, dy->d1);
    ctn_dyn_support_force(dy, t, t + h, 1 - dy->am, 1 - dy->af);   /* central: am = af = 0 */
    return dy->o->method == CTN_DYN_CENTRAL ? ctn_dyn_central_step(dy, h, ok) : ctn_dyn_implicit_step(dy, h, ok);
}

/* A failed run's last converged state as a row when the rows skip steps and it is not
 * the last row already (every step is a row otherwise). */
static int last_row(ctn_dyn *dy, double t)
{
    const ctn_dyn_result *res = dy->s->dyn;
    size_t w = 1 + res->ncol;
    if (dy->every == 1 || !res->nrow || res->rows[(res->nrow - 1) * w] == t) return CTN_OK;
    return ctn_dyn_record_row(dy, t);
}

/* From t = 0 to t_end: each multiple of dt reached in steps of dt, halved on failure; a
 * row at every output_every-th and the last. */
static int march(ctn_dyn *dy)
{
    const ctn_dynamics_options *o = dy->o;
    size_t N = (size_t)ceil(o->t_end / o->dt - 1e-9);
    double t = 0, h = o->dt;
    int level = 0, rc = CTN_OK;
    for (size_t k = 1; k <= N; k++) {
        double target = k == N ? o->t_end : (double)k * o->dt;
        while (t < target - 1e-9 * o->dt) {
            if (dy->severed && (rc = ctn_dyn_apply_removals(dy, t))) return rc;
            double hs = fmin(h, target - t), tr = dy->severed ? ctn_dyn_next_removal(dy, t) : INFINITY;
            if (tr < t + hs - 1e-9 * o->dt) hs = tr - t;            /* a step ends at a removal */
            int ok = 0;
            if ((rc = try_step(dy, t, hs, &ok))) return rc;
            if (ok) {
                ctn_dyn_accept(dy, hs, dy->r1);
                t += hs;
                dy->sum.substeps++;
                if (level > 0) {
                    h *= 2;
                    level--;
                }
                continue;
            }
            if (level >= o->maxcuts || o->method == CTN_DYN_CENTRAL) {
                dy->sum.reason = CTN_DIVERGED_MAXIT;
                dy->sum.t_fail = t;
                return last_row(dy, t);
            }
            h *= 0.5;
            level++;
            dy->sum.cuts++;
        }
        t = target;
        if ((k % (size_t)dy->every == 0 || k == N) && (rc = ctn_dyn_record_row(dy, t))) return rc;
        dy->sum.steps = k;
        dy->sum.t_reached = t;
        if ((k & 63) == 0) ctn_progress(dy->p->ctx, "dynamics", t, o->t_end);
    }
    dy->sum.reason = CTN_CONVERGED;
    return CTN_OK;
}

/* The state reached as the solution's step "dynamics", the summaries. */
static int finish(ctn_dyn *dy, double t0)
{
    ctn_solution *s = dy->s;
    size_t idx;
    int rc = ctn_solution_add_step(s, "dynamics", &idx);
    if (!rc) rc = ctn_problem_fill_step(dy->p, s, idx, dy->d0);
    if (rc) return rc;
    s->steps[idx].t = dy->sum.t_reached / dy->o->t_end;
    s->steps[idx].reason = dy->sum.reason;
    s->steps[idx].iterations = dy->sum.iterations;
    s->sum.reason = dy->sum.reason;
    s->sum.load_factor = 1.0;
    dy->sum.energy_error = dy->escale > 0 ? dy->emax / dy->escale : 0.0;
    dy->sum.t_total = ctn_clock() - t0;
    dy->sum.output_every = dy->every;
    dy->sum.modal_count = (int)dy->mr;
    dy->sum.frames = s->dyn->nframe;
    dy->sum.relative_wind = (int)dy->nwind;
    s->dyn->sum = dy->sum;
    return CTN_OK;
}

int ctn_dynamics_run(ctn_problem *p, ctn_solution *s, const ctn_dynamics_options *o)
{
    double t0 = ctn_clock();
    ctn_solve_summary *keep = p->sum;
    ctn_follow *fl = p->fl;                          /* hloads that follow the geometry; */
    int follow = fl && ctn_follow_hload_count(fl) > 0;   /* winds: the relative drag */
    int overlap = p->overlap;
    ctn_dyn dy;
    memset(&dy, 0, sizeof dy);
    dy.p = p;
    dy.s = s;
    dy.o = o;
    dy.sum.method = o->method;
    dy.sum.dt = o->dt;
    dy.sum.t_end = o->t_end;
    dy.sum.rho_inf = o->rho_inf;
    dy.sum.damping_alpha = o->damping_alpha;
    dy.sum.damping_beta = o->damping_beta;
    dy.sum.reason = CTN_DIVERGED_MAXIT;
    dy.lumped = o->method == CTN_DYN_CENTRAL || o->mass == CTN_MASS_LUMPED;
    dy.every = o->output_every > 0 ? o->output_every : 1;
    p->sum = &s->sum;
    p->mode = 0;
    ctn_problem_settle(p);
    p->overlap = 0;                                  /* K_T is not what is factored */
    int rc = ctn_dynamics_check(p, o);
    if (!follow) p->fl = NULL;
    if (!rc) rc = dyn_alloc(&dy);
    if (!rc) {
        ctn_dyn_method_params(&dy);
        ctn_dyn_start_loads(&dy);
        ctn_follow_drop_winds(p);
        rc = ctn_dyn_start(&dy);
    }
    if (!rc) rc = march(&dy);
    if (!rc) rc = finish(&dy, t0);
    ctn_dyn_restore_removals(&dy);
    p->overlap = overlap;
    p->sum = keep;
    p->fl = fl;
    dyn_free(&dy);
    return rc;
}

/* The analysis object: from rest when *s is NULL (a new solution), else from the
 * converged last step of *s. */
static void dyn_defaults(const ctn_problem *p, void *opt)
{
    (void)p;
    ctn_dynamics_options_default(opt);
}

static int dyn_check(ctn_problem *p, const void *opt)
{
    const ctn_dynamics_options *o = opt;
    char msg[256];
    if (ctn_dynamics_options_fault(o, msg, sizeof msg)) return ctn_error(p->ctx, CTN_ERR_INVALID, "%s", msg);
    if (!ctn_dynamics_asked(o)) return ctn_error(p->ctx, CTN_ERR_INVALID, "dynamics analysis: give dt and t_end");
    return CTN_OK;
}

static int dyn_analysis(ctn_problem *p, const void *opt, ctn_solution **s)
{
    ctn_dynamics_options o = *(const ctn_dynamics_options *)opt;
    if (*s && ((*s)->sum.reason != CTN_CONVERGED || !(*s)->nsteps))
        return ctn_error(p->ctx, CTN_ERR_INVALID, "dynamics analysis: the solution did not converge");
    o.line = 0;                                      /* the API's: no `step` line count */
    if (*s) return ctn_dynamics_run(p, *s, &o);
    ctn_solution *n = NULL;
    int rc = ctn_solution_create(p->ctx, p->m->nodes.n, p->m->elements.n, &n);
    if (!rc) n->rot = p->a->map.rot > 0;               /* the rotations and moments kept */
    if (!rc) rc = ctn_dynamics_run(p, n, &o);
    if (rc) ctn_solution_destroy(&n);
    *s = n;
    return rc;
}

const ctn_analysis_ops ctn_analysis_dynamics = {
    "dynamics", sizeof(ctn_dynamics_options), 0, dyn_defaults, dyn_check, dyn_analysis,
};
