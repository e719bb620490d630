/* The problem: setup once per model, residual and potential at a load parameter t,
 * factorization with an optional shift, solves. */
#include "analysis/buckling/buckling.h"
#include "analysis/modal/modal.h"
#include "problem/dynamics_options.h"
#include "problem/la_options.h"

#include <math.h>
#include <string.h>

/* Diagonal of the bounding box of the reference nodes. */
static double model_size(const ctn_model *m)
{
    double lo[3], hi[3], s = 0;
    for (int k = 0; k < 3; k++) lo[k] = hi[k] = m->nodes.v[0].X[k];
    for (size_t i = 1; i < m->nodes.n; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], m->nodes.v[i].X[k]);
            hi[k] = fmax(hi[k], m->nodes.v[i].X[k]);
        }
    for (int k = 0; k < 3; k++) s += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    return sqrt(s);
}

/* The in_chain mask (problem.h). */
static unsigned char *chain_members(const ctn_problem *p)
{
    const ctn_model *m = p->m;
    unsigned char *mask = ctn_calloc(p->ctx, m->elements.n ? m->elements.n : 1, 1);
    int *deg = ctn_calloc(p->ctx, m->nodes.n ? m->nodes.n : 1, sizeof(int));
    if (mask && deg) {
        for (size_t k = 0; k < m->conn.n; k++) deg[m->conn.v[k]]++;
        for (size_t e = 0; e < m->elements.n; e++) {
            const int *nd = ctn_elem_nodes(m, e);
            int n = m->elements.v[e].nnodes;
            for (int k = 0; k < n && !mask[e]; k++)
                mask[e] = n == 2 && deg[nd[k]] == 2 && m->nodes.v[nd[k]].fix == 0;
        }
    }
    ctn_free(deg);
    if (!deg) {
        ctn_free(mask);
        return NULL;
    }
    return mask;
}

static int alloc_vectors(ctn_problem *p)
{
    ctn_ctx *ctx = p->ctx;
    double **vs[] = { &p->fint, &p->fext, &p->f0, &p->f1, &p->p0, &p->p1, &p->dsave, &p->react };
    ctn_dvec *vn[] = { &p->vr, &p->vdd, &p->vw };
    double **an[] = { &p->r, &p->dd, &p->w };
    for (size_t i = 0; i < sizeof vs / sizeof *vs; i++)
        if (!(*vs[i] = ctn_calloc(ctx, p->ns, sizeof(double)))) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < sizeof vn / sizeof *vn; i++) {
        if (ctn_dvec_create(ctx, &p->eq, vn[i])) return CTN_ERR_NOMEM;
        *an[i] = vn[i]->v;
    }
    if (!(p->v3 = ctn_calloc(ctx, 3 * p->a->nn, sizeof(double)))) return CTN_ERR_NOMEM;
    if (!(p->in_chain = chain_members(p))) return CTN_ERR_NOMEM;
    if (p->a->map.rot_update == ctn_rot_update_compose && !(p->wd = ctn_calloc(ctx, p->ns, sizeof(double))))
        return CTN_ERR_NOMEM;
    double **vt[] = { &p->dT0, &p->dT1, &p->dT };
    for (size_t i = 0; i < 3 && p->m->tloads.n; i++)
        if (!(*vt[i] = ctn_calloc(ctx, p->a->ne, sizeof(double)))) return CTN_ERR_NOMEM;
    return CTN_OK;
}

static int setup(ctn_problem *p)
{
    /* threads=1 asked for: one thread everywhere (an application solving side by side) */
    int rc = ctn_asm_create_ex(p->ctx, p->m, p->opt.threads == 1 ? CTN_ASM_ONE_THREAD : 0, &p->a);
    if (rc) return rc;
    p->ns = p->a->map.nstate;
    p->ndof = p->a->ndof;
    /* every process holds every entry (one process, or the replicated model of an MPI
       job, docs/parallel.md): all owned, reductions local, the serial communicator's */
    ctn_layout_serial(&p->eq, p->ndof, NULL);
    ctn_layout_serial(&p->st, p->ns, NULL);
    if ((rc = alloc_vectors(p))) return rc;
    p->lref = model_size(p->m);
    p->kscale = p->a->kscale;
    if ((rc = ctn_follow_create(p))) return rc;
    /* Fixed moments on spun nodes (spin.c): a rolled-up cantilever's equilibrium is
     * stable with the symmetric part of its tangent indefinite, where LL' fails at any
     * small shift and the globalized corrector can never take Newton's step (not
     * converged in 850 iterations): LDL' then, as arc-length's. */
    const char *given = p->opt.linear_solver ? p->opt.linear_solver : p->strategy->linear_solver;
    if (!p->opt.linear_solver && !strcmp(given, "cholmod") && ctn_spin_wanted(p)) given = "cholmod-ldl";
    const char *name = ctn_linsolve_default(p->ctx, given);
    p->ls_name = name;
    if ((rc = ctn_problem_dist_setup(p, name))) return rc;
    if (p->ndof == 0) return CTN_OK;        /* statically determinate: nothing to factor */
    if ((rc = ctn_problem_solver_create(p, name, ctn_la_ordering_of(p->opt.ordering), &p->ls))) return rc;
    if ((rc = ctn_spin_create(p))) return rc;
    int reuse = p->strategy->globalized && p->opt.reuse && !p->fl && !p->sp && !ctn_linsolve_type(p->ls)->indefinite;
    if (reuse && !(p->cg = ctn_calloc(p->ctx, 4 * p->ndof, sizeof(double)))) return CTN_ERR_NOMEM;
    /* Pure Newton factorizes every tangent it assembles (but the converged state's) */
    p->overlap = p->opt.method == CTN_METHOD_NEWTON && !p->opt.linesearch && !p->fl && !p->sp && p->opt.threads != 1 &&
                 !ctn_linsolve_type(p->ls)->indefinite && !p->dist;
    return CTN_OK;
}

/* A modal analysis asked for in the options is checked before any solve: its count
 * and the model's mass (errors at the `modes` line). */
static int modal_precheck(ctn_problem *p)
{
    if (p->opt.modal.count < 1) return CTN_OK;
    double tot[3], *diag = ctn_malloc(p->ctx, p->ndof ? p->ndof : 1, sizeof(double));
    if (!diag) return CTN_ERR_NOMEM;
    int rc = ctn_modal_check(p, &p->opt.modal, diag, tot);
    ctn_free(diag);
    return rc;
}

/* A dynamics analysis asked for in the options is checked before any solve (errors at
 * the `dynamics` line): from rest, no static analysis runs, so none of its own either. */
static int dynamics_precheck(ctn_problem *p)
{
    const ctn_dynamics_options *o = &p->opt.dynamics;
    if (!ctn_dynamics_asked(o)) return CTN_OK;
    if (o->from_rest && (p->opt.modal.count > 0 || p->opt.buckling.count > 0))
        return ctn_error_at(p->ctx, CTN_ERR_MODEL, p->m->file, o->line, "dynamics: from rest (no `step` line before "
                            "it) no static analysis runs, so `%s` has no state to run about: put a `step` line before "
                            "`dynamics`", p->opt.modal.count > 0 ? "modes" : "buckling");
    return ctn_dynamics_check(p, o);
}

int ctn_problem_create(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt,
                       ctn_problem **out)
{
    int rc = m ? ctn_model_targets_found(ctx, m) : CTN_OK;
    if (rc) return rc;
    return ctn_problem_create_any(ctx, m, opt, out);
}

int ctn_problem_create_any(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt, ctn_problem **out)
{
    if (!out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_problem_create: out is NULL");
    *out = NULL;
    if (!m) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_problem_create: model is NULL");
    ctn_solve_options o;
    int rc = ctn_solve_options_take(ctx, &o, opt);
    if (!rc) rc = ctn_solve_options_check(ctx, &o);
    if (!rc) rc = ctn_model_validate(m);
    if (rc) return rc;
    if (m->tloads.n && o.method == CTN_METHOD_ARCLENGTH)
        return ctn_error_at(ctx, CTN_ERR_MODEL, m->file, m->tloads.v[0].line,
                            "temperature changes are applied in load steps: method=arclength follows a single load "
                            "pattern (use method=auto or method=newton)");
    if (m->cases.n && o.method == CTN_METHOD_ARCLENGTH)
        return ctn_error_at(ctx, CTN_ERR_MODEL, m->file, m->cases.v[0].line,
                            "load cases are solved by load steps: method=arclength follows a single load pattern "
                            "(use method=auto or method=newton)");
    double t0 = ctn_clock();
    ctn_problem *p = ctn_calloc(ctx, 1, sizeof *p);
    if (!p) return CTN_ERR_NOMEM;
    p->ctx = ctx;
    p->m = m;
    p->opt = o;
    p->strategy = ctn_strategy_of(o.method);
    if (p->opt.steps < 1) p->opt.steps = 1;
    if (p->opt.maxcuts < 0) p->opt.maxcuts = p->strategy->maxcuts;
    if ((rc = setup(p)) || (rc = modal_precheck(p)) ||
        (p->opt.buckling.count > 0 && (rc = ctn_buckling_check(p, &p->opt.buckling))) ||
        (rc = dynamics_precheck(p))) {
        ctn_problem_destroy(&p);
        return rc;
    }
    p->t_setup = ctn_clock() - t0;
    *out = p;
    return CTN_OK;
}

void ctn_problem_destroy(ctn_problem **pp)
{
    if (!pp || !*pp) return;
    ctn_problem *p = *pp;
    ctn_problem_settle(p);
    ctn_asm_destroy(&p->a);
    ctn_linsolve_destroy(&p->ls);
    ctn_follow_destroy(&p->fl);
    ctn_spin_destroy(&p->sp);
    double *v[] = { p->fint, p->fext, p->f0, p->f1, p->p0, p->p1, p->dsave, p->react, p->r, p->dd, p->w, p->v3, p->Kx,
                    p->dT0, p->dT1, p->dT, p->cg, p->wd };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
    ctn_free(p->in_chain);
    ctn_free(p->lcolptr);
    ctn_free(p->lrowind);
    ctn_free(p);
    *pp = NULL;
}

void ctn_problem_set_t(ctn_problem *p, double t, double *d)
{
    ctn_follow_set_t(p, t);
    const int *eq = p->a->map.eq;
    for (size_t i = 0; i < p->ns; i++) {
        p->fext[i] = p->f0[i] + t * (p->f1[i] - p->f0[i]);
        if (eq[i] < 0) d[i] = p->p0[i] + t * (p->p1[i] - p->p0[i]);
    }
    if (!p->dT) return;
    for (size_t e = 0; e < p->a->ne; e++) p->dT[e] = p->dT0[e] + t * (p->dT1[e] - p->dT0[e]);
    ctn_asm_set_temperatures(p->a, p->dT);
}

void ctn_problem_step_loads(ctn_problem *p, size_t k)
{
    ctn_loadsel sel = ctn_loadsel_step(k);
    ctn_problem_sel_loads(p, &sel);
}

void ctn_problem_sel_loads(ctn_problem *p, const ctn_loadsel *sel)
{
    ctn_model_sel_loads(p->m, sel, 1, p->v3, NULL);
    ctn_dofmap_from3(&p->a->map, p->v3, p->f1);
    ctn_model_sel_loads(p->m, sel, 1, NULL, p->v3);
    ctn_follow_sel(p, sel);
    ctn_dofmap_from3(&p->a->map, p->v3, p->p1);
    if (p->a->map.rot) {                          /* moments and prescribed rotations */
        ctn_model_sel_moments(p->m, sel, p->v3, NULL);
        ctn_dofmap_rot_from3(&p->a->map, p->v3, p->f1);
        ctn_model_sel_moments(p->m, sel, NULL, p->v3);
        ctn_dofmap_rot_from3(&p->a->map, p->v3, p->p1);
    }
    if (!p->dT) return;
    memcpy(p->dT0, p->dT1, p->a->ne * sizeof(double));
    ctn_model_sel_temperatures(p->m, sel, p->dT1);
}

int ctn_problem_residual(ctn_problem *p, const double *d, int with_K, double *rnorm, double *pi,
                         int *valid)
{
    double t0 = ctn_clock(), U = 0, work = 0;
    const int *eq = p->a->map.eq;
    size_t bad = 0;
    ctn_problem_settle(p);
    if (with_K && p->overlap && ctn_overlap_possible(p->a, p->ls) && ctn_overlap_start(&p->ovl, p->a, p->ls, p->Kx, 0.0))
        *valid = !ctn_overlap_assemble(&p->ovl, p->a, d, p->mode, p->fint, p->Kx, pi ? &U : NULL, &bad);
    else if (p->dist) *valid = !ctn_problem_dist_eval(p, d, p->mode, with_K ? p->Kx : NULL, &U, &bad);
    else *valid = !ctn_asm_eval(p->a, d, p->mode, p->fint, with_K ? p->Kx : NULL, pi ? &U : NULL, &bad);
    if (!*valid) p->sum->fail_element = p->m->elements.v[bad].id;     /* reported if not converged */
    if (*valid) {
        const double *fh = p->fl ? ctn_follow_forces(p, d) : NULL;
        double rr = 0;
        for (size_t i = 0; i < p->ns; i++) {
            int q = eq[i];
            if (q < 0) continue;
            double fe = fh ? p->fext[i] + fh[i] : p->fext[i], ri = fe - p->fint[i];
            p->r[q] = ri;
            rr += ri * ri;
            if (pi) work += fe * d[i];
        }
        *rnorm = sqrt(ctn_layout_sum(&p->st, rr));
        if (pi) *pi = ctn_layout_sum(&p->st, U - work);
        *valid = isfinite(*rnorm) && (!pi || isfinite(*pi));
    }
    if (!*valid) ctn_problem_settle(p);
    p->sum->t_assemble += ctn_clock() - t0;
    return CTN_OK;
}

/* f_ext on a free DOF (with the follower loads), or 0. */
static double free_load(const void *ud, size_t i)
{
    const ctn_problem *p = ud;
    const double *fh = p->fl ? ctn_follow_loads(p->fl) : NULL;
    return p->a->map.eq[i] < 0 ? 0 : fh ? p->fext[i] + fh[i] : p->fext[i];
}

/* f_int on a supported DOF, or 0. */
static double support_force(const void *ud, size_t i)
{
    const ctn_problem *p = ud;
    return p->a->map.eq[i] < 0 ? p->fint[i] : 0;
}

double ctn_problem_fref(const ctn_problem *p)
{
    double ff = 0, fr = 0;
    const int *eq = p->a->map.eq;
    const double *fh = p->fl ? ctn_follow_loads(p->fl) : NULL;
    for (size_t i = 0; i < p->ns; i++) {
        double fe = fh ? p->fext[i] + fh[i] : p->fext[i];
        if (eq[i] >= 0) ff += fe * fe;
        else fr += p->fint[i] * p->fint[i];
    }
    ff = ctn_layout_sum(&p->st, ff);
    fr = ctn_layout_sum(&p->st, fr);
    if (ff > 0) return ctn_layout_norm_ss(&p->st, ff, free_load, p);
    return fr > 0 ? ctn_layout_norm_ss(&p->st, fr, support_force, p) : 1.0;
}

void ctn_problem_settle(ctn_problem *p)
{
    if (!p->ovl.running) return;
    ctn_overlap_abandon(&p->ovl);
    p->spd_factor = 0;
    p->factored_at = NULL;
}

int ctn_problem_factor(ctn_problem *p, double shift, int *posdef, long *fail_col)
{
    double t0 = ctn_clock();
    ctn_factor_info info = { 1, -1 };
    if (shift != 0) ctn_problem_settle(p);
    int beside = p->ovl.running;                  /* started beside the last assembly */
    int rc = beside ? ctn_overlap_finish(&p->ovl, &info)
                    : p->ls ? ctn_linsolve_factor(p->ls, p->Kx, shift, &info) : CTN_OK;
    p->sum->t_factor += beside ? p->ovl.t_fac : ctn_clock() - t0;
    p->sum->t_factor_cpu += p->ls ? ctn_linsolve_cpu(p->ls) : 0;
    p->sum->threads = p->ls ? ctn_linsolve_threads(p->ls) : 1;
    p->sum->factorizations++;
    *posdef = info.ok;
    *fail_col = info.fail_col;
    p->shift = shift;
    p->last_definite = info.ok && shift == 0 && (!p->ls || !ctn_linsolve_type(p->ls)->indefinite);
    p->spd_factor = p->last_definite;
    p->factored_at = NULL;
    return rc;
}

int ctn_problem_linsolve(ctn_problem *p, const double *b, double *x)
{
    ctn_problem_settle(p);
    double t0 = ctn_clock();
    int rc = !p->ls ? CTN_OK : p->sp ? ctn_spin_solve(p, b, x) : p->fl ? ctn_follow_solve(p, b, x)
                                    : ctn_linsolve_solve(p->ls, b, x);
    p->sum->t_solve += ctn_clock() - t0;
    p->sum->solves++;
    return rc;
}

double ctn_problem_max_diag(const ctn_problem *p)
{
    double m = 0;
    if (p->dist) m = ctn_problem_dist_max_diag(p);
    else
        for (size_t c = 0; c < p->ndof; c++) m = fmax(m, p->Kx[p->a->colptr[c + 1] - 1]);
    return m > 0 ? m : p->kscale;
}

void ctn_problem_axpy(const ctn_problem *p, double *d, double alpha, const double *v)
{
    ctn_dofmap_axpy(&p->a->map, d, alpha, v);
}

void ctn_problem_update(const ctn_problem *p, double *d, double alpha, const double *v)
{
    ctn_dofmap_update(&p->a->map, d, alpha, v);
}
