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

/* A model error at the `dynamics` line (or without a place, from the API). */
static int dyn_error(const ctn_problem *p, const ctn_dynamics_options *o, const char *msg)
{
    if (o->line > 0) return ctn_error_at(p->ctx, CTN_ERR_MODEL, p->m->file, o->line, "%s", msg);
    return ctn_error(p->ctx, CTN_ERR_MODEL, "%s", msg);
}

/* A node with a free translation and no mass in it, and a section of its elements
 * without mass, for the messages: "node N (section 'S' has no mass)". */
static void massless_node(const ctn_problem *p, const double *diag, char *what, size_t size)
{
    const ctn_model *m = p->m;
    snprintf(what, size, "no free node");
    for (size_t i = 0; i < m->nodes.n; i++)
        for (int k = 0; k < 3; k++) {
            int q = p->a->map.eq[ctn_dofmap_node(&p->a->map, i) + (size_t)k];
            if (q < 0 || diag[q] > 0) continue;
            const char *sec = NULL;
            for (size_t e = 0; e < m->elements.n && !sec; e++) {
                const ctn_element *el = &m->elements.v[e];
                for (int j = 0; j < el->nnodes && !sec; j++)
                    if ((size_t)ctn_elem_nodes(m, e)[j] == i && el->section >= 0 && !(ctn_model_section_mass(m, el->section) > 0))
                        sec = m->sections.v[el->section].name;
            }
            if (sec) snprintf(what, size, "node %d has no mass in u%c (no node mass=, and section '%s' has no mass= "
                              "nor w= with units)", m->nodes.v[i].id, "xyz"[k], sec);
            else snprintf(what, size, "node %d has no mass in u%c (no node mass=, and no element with a mass "
                          "reaches it)", m->nodes.v[i].id, "xyz"[k]);
            return;
        }
}

/* The mass: every section's mass told (units), some free DOF with mass, and every free
 * DOF with mass for the explicit method. */
static int check_mass(ctn_problem *p, const ctn_dynamics_options *o, double *diag)
{
    char msg[400], what[256];
    size_t bad = 0, nmass = 0;
    double tot[3];
    if (ctn_asm_mass_diag(p->a, diag, tot, &bad)) {
        const ctn_model *m = p->m;
        const ctn_section *sec = &m->sections.v[m->elements.v[bad].section];
        return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, sec->line, "section '%s': its weight w=%g gives no mass in a "
                            "model without units: give mass= (or units) for the dynamics", sec->name, sec->w);
    }
    for (size_t q = 0; q < p->ndof; q++) nmass += diag[q] > 0;
    massless_node(p, diag, what, sizeof what);
    if (nmass == 0) {
        snprintf(msg, sizeof msg, "dynamics: no free DOF carries mass: %s", what);
        return dyn_error(p, o, msg);
    }
    if (o->method == CTN_DYN_CENTRAL && nmass < p->ndof) {
        snprintf(msg, sizeof msg, "dynamics: method=central needs mass at every free DOF: %s", what);
        return dyn_error(p, o, msg);
    }
    return CTN_OK;
}

int ctn_dynamics_check(ctn_problem *p, const ctn_dynamics_options *o)
{
    const ctn_model *m = p->m;
    if (p->a->map.rot > 0) return dyn_error(p, o, "dynamics: models with rotations (beam, rspring) are not supported yet");
    if (p->fl) return dyn_error(p, o, "dynamics: loads that follow the geometry (hload projection=deformed, wind) are "
                                      "not supported yet");
    if (o->line > 0 && (size_t)o->steps_before != m->steps.n)
        return dyn_error(p, o, "dynamics: give it after the last `step` line (it starts from that step's equilibrium)");
    if (p->ndof == 0) return dyn_error(p, o, "dynamics: the model has no free DOF");
    double *diag = ctn_malloc(p->ctx, p->ndof, sizeof(double));
    if (!diag) return CTN_ERR_NOMEM;
    int rc = check_mass(p, o, diag);
    ctn_free(diag);
    return rc;
}

/* M's nonzeros apart from K's pattern (as the modal analysis keeps them): a consistent
 * mass couples a DOF only to the same direction at an element's other node, a lumped one
 * nothing. */
static int mass_pattern(ctn_dyn *dy)
{
    const ctn_asm *a = dy->p->a;
    size_t n = dy->p->ndof, mnz = 0;
    for (size_t k = 0; k < a->nnz; k++) mnz += dy->Mx[k] != 0;
    dy->mcol = ctn_malloc(dy->p->ctx, n + 1, sizeof(int));
    dy->mrow = ctn_malloc(dy->p->ctx, mnz ? mnz : 1, sizeof(int));
    dy->mval = ctn_malloc(dy->p->ctx, mnz ? mnz : 1, sizeof(double));
    dy->mslot = ctn_malloc(dy->p->ctx, mnz ? mnz : 1, sizeof(int));
    if (!dy->mcol || !dy->mrow || !dy->mval || !dy->mslot) return CTN_ERR_NOMEM;
    int at = 0;
    for (size_t j = 0; j < n; j++) {
        dy->mcol[j] = at;
        for (int k = a->colptr[j]; k < a->colptr[j + 1]; k++)
            if (dy->Mx[k] != 0) {
                dy->mrow[at] = a->rowind[k];
                dy->mslot[at] = k;
                dy->mval[at++] = dy->Mx[k];
            }
    }
    dy->mcol[n] = at;
    return CTN_OK;
}

static void dyn_free(ctn_dyn *dy)
{
    ctn_free(dy->severed);
    ctn_free(dy->mcol);
    ctn_free(dy->mrow);
    ctn_free(dy->mval);
    ctn_free(dy->mslot);
    double *v[] = { dy->Mx, dy->Cx, dy->diag, dy->d0, dy->d1, dy->v0, dy->a0, dy->v1, dy->a1, dy->r0, dy->r1,
                    dy->R, dy->w, dy->w2, dy->ework, dy->fe0 };
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
    if (!dy->d0 || !dy->d1 || !dy->fe0 || !dy->Mx || !dy->ework) return CTN_ERR_NOMEM;
    size_t nr = p->m->removals.n;
    if (nr && !(dy->severed = ctn_calloc(p->ctx, nr, 1))) return CTN_ERR_NOMEM;
    if ((dy->o->damping_alpha > 0 || dy->o->damping_beta > 0) && !(dy->Cx = ctn_calloc(p->ctx, nz, sizeof(double))))
        return CTN_ERR_NOMEM;
    return CTN_OK;
}

/* The method's am, af, gamma, beta. */
static void method_params(ctn_dyn *dy)
{
    const ctn_dynamics_options *o = dy->o;
    double r = o->rho_inf;
    dy->am = dy->af = 0;
    dy->gamma = 0.5;
    dy->beta = 0.25;
    if (o->method == CTN_DYN_GENALPHA) {
        dy->am = (2 * r - 1) / (r + 1);
        dy->af = r / (r + 1);
    } else if (o->method == CTN_DYN_HHT) {
        dy->af = isnan(o->alpha) ? (1 - r) / (1 + r) : -o->alpha;
    } else if (o->method == CTN_DYN_NEWMARK) {
        dy->gamma = o->gamma;
        dy->beta = o->beta;
    }
    if (o->method == CTN_DYN_GENALPHA || o->method == CTN_DYN_HHT) {
        dy->gamma = 0.5 - dy->am + dy->af;
        dy->beta = 0.25 * (1 - dy->am + dy->af) * (1 - dy->am + dy->af);
    }
    if (o->method == CTN_DYN_CENTRAL) dy->beta = 0;
    dy->sum.alpha_m = dy->am;
    dy->sum.alpha_f = dy->af;
    dy->sum.gamma = dy->gamma;
    dy->sum.beta = dy->beta;
}

/* The loads of the model's last step, held (f0 = f1), and the start state d0: s's last
 * step, or the start geometry (zero). */
static void start_loads(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    memset(p->f1, 0, p->ns * sizeof(double));
    memset(p->p1, 0, p->ns * sizeof(double));
    ctn_problem_step_loads(p, ctn_model_step_count(p->m) - 1);
    memcpy(p->f0, p->f1, p->ns * sizeof(double));
    memcpy(p->p0, p->p1, p->ns * sizeof(double));
    if (p->dT) memcpy(p->dT0, p->dT1, p->a->ne * sizeof(double));
    if (dy->s->nsteps) ctn_dofmap_from3(&p->a->map, dy->s->steps[dy->s->nsteps - 1].d, dy->d0);
    ctn_problem_set_t(p, 1.0, dy->d0);
    ctn_dyn_set_time(dy, 0.0, dy->d0);
    memcpy(dy->fe0, p->fext, p->ns * sizeof(double));
}

void ctn_dyn_set_time(ctn_dyn *dy, double t, double *d)
{
    ctn_problem *p = dy->p;
    const ctn_model *m = p->m;
    for (size_t i = 0; i < p->ns; i++)
        if (p->a->map.eq[i] < 0) d[i] = p->p1[i];
    if (!m->dloads.n) return;
    memcpy(p->fext, p->f1, p->ns * sizeof(double));
    for (size_t j = 0; j < m->dloads.n; j++) {
        const ctn_dload *dl = &m->dloads.v[j];
        double f = ctn_model_fn_value(m, dl->fn, t);
        size_t at = ctn_dofmap_node(&p->a->map, (size_t)dl->node);
        for (int k = 0; k < 3; k++) {
            if (!dl->dofs) p->fext[at + (size_t)k] += f * dl->F[k];
            else if (dl->dofs >> k & 1) d[at + (size_t)k] += f * dl->F[k];
        }
    }
}

/* a0 = M^-1 (f_ext - f_int(d0) - C v0): M factored by the problem's linear solver, or
 * over the lumped diagonal where M is singular (DOFs without mass: a0 = 0 there). */
static int start_acceleration(ctn_dyn *dy, int lumped)
{
    ctn_problem *p = dy->p;
    ctn_factor_info info = { 0, -1 };
    int rc = lumped ? CTN_OK : ctn_linsolve_factor(p->ls, dy->Mx, 0.0, &info);
    p->spd_factor = p->last_definite = 0;
    p->factored_at = NULL;
    ctn_dyn_damp(dy, dy->v0, dy->w2);
    for (size_t q = 0; q < p->ndof; q++) dy->w2[q] = dy->r0[q] - dy->w2[q];
    if (!rc && info.ok) return ctn_linsolve_solve(p->ls, dy->w2, dy->a0);
    for (size_t q = 0; q < p->ndof; q++) dy->a0[q] = dy->diag[q] > 0 ? dy->w2[q] / dy->diag[q] : 0.0;
    return rc;
}

/* The removals due at t (their time at most t): each element severed, then the state at
 * t balanced again (r0, a0; the strain energy the elements held counts as dissipated). */
static int apply_removals(ctn_dyn *dy, double t)
{
    ctn_problem *p = dy->p;
    const ctn_model *m = p->m;
    int changed = 0, valid = 0, rc = CTN_OK;
    for (size_t i = 0; i < m->removals.n && !rc; i++) {
        if (dy->severed[i] || m->removals.v[i].t > t + 1e-9 * dy->o->dt) continue;
        rc = ctn_asm_sever_element(p->a, (size_t)m->removals.v[i].element);
        dy->severed[i] = changed = 1;
    }
    if (rc || !changed) return rc;
    ctn_dyn_set_time(dy, t, dy->d0);
    if ((rc = ctn_dyn_residual(dy, dy->d0, 0, dy->r0, &valid))) return rc;
    dy->D += dy->U - dy->U1;
    dy->U = dy->U1;
    return start_acceleration(dy, dy->lumped);
}

/* The earliest removal after t, or INFINITY. */
static double next_removal(const ctn_dyn *dy, double t)
{
    double next = INFINITY;
    for (size_t i = 0; i < dy->p->m->removals.n; i++)
        if (!dy->severed[i] && dy->p->m->removals.v[i].t > t) next = fmin(next, dy->p->m->removals.v[i].t);
    return next;
}

/* The severed elements restored (the problem outlives the analysis). */
static void restore_removals(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    for (size_t i = 0; dy->severed && i < p->m->removals.n; i++)
        if (dy->severed[i]) ctn_asm_setup_element(p->a, (size_t)p->m->removals.v[i].element);
    if (dy->severed && p->dT) ctn_asm_set_temperatures(p->a, p->dT);
}

/* The start: r0 and K_0 at d0, M (and C = a M + b K_0), a0, the energies, the stable step
 * of the explicit method, the first row. */
static int start(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    const ctn_dynamics_options *o = dy->o;
    int valid = 0, lumped = o->method == CTN_DYN_CENTRAL || o->mass == CTN_MASS_LUMPED;
    double tot[3];
    size_t bad;
    char msg[256];
    int rc = ctn_dyn_residual(dy, dy->d0, 1, dy->r0, &valid);
    if (!rc && !valid) {
        snprintf(msg, sizeof msg, "dynamics: element %d cannot be evaluated in the start state (a chord of zero length)",
                 p->sum->fail_element);
        return dyn_error(p, o, msg);
    }
    if (!rc) rc = ctn_asm_mass(p->ctx, p->a, lumped, dy->Mx);
    if (!rc) rc = mass_pattern(dy);
    if (rc) return rc;
    ctn_asm_mass_diag(p->a, dy->diag, tot, &bad);
    for (size_t k = 0; dy->Cx && k < p->a->nnz; k++) dy->Cx[k] = o->damping_alpha * dy->Mx[k] + o->damping_beta * p->Kx[k];
    dy->sum.mass = lumped ? CTN_MASS_LUMPED : CTN_MASS_CONSISTENT;
    dy->U = dy->U1;
    dy->e0 = dy->U;
    dy->escale = fabs(dy->U);
    if (o->method == CTN_DYN_CENTRAL) {
        if ((rc = ctn_dyn_stable_step(dy))) return rc;
        if (o->dt > dy->sum.dt_stable) {
            snprintf(msg, sizeof msg, "dynamics: dt=%g is above the stable step of method=central, %.6g s (2 / omega_max "
                     "of the mesh at the start state): give dt <= %.6g", o->dt, dy->sum.dt_stable, dy->sum.dt_stable);
            return dyn_error(p, o, msg);
        }
    }
    if ((rc = start_acceleration(dy, lumped))) return rc;
    return ctn_dyn_record_begin(dy);
}

void ctn_dyn_accept(ctn_dyn *dy, double h, const double *r1)
{
    ctn_problem *p = dy->p;
    const int *eq = p->a->map.eq;
    size_t n = p->ndof;
    double work = 0;
    for (size_t i = 0; i < p->ns; i++)                   /* the trapezoidal rule (exact for */
        if (eq[i] >= 0) work += 0.5 * (dy->fe0[i] + p->fext[i]) * (dy->d1[i] - dy->d0[i]);   /* loads held) */
    dy->W += ctn_layout_sum(&p->st, work);
    memcpy(dy->fe0, p->fext, p->ns * sizeof(double));
    if (dy->Cx) {
        ctn_dyn_damp(dy, dy->v0, dy->w2);
        double c0 = ctn_layout_dot(&p->eq, dy->v0, dy->w2);
        ctn_dyn_damp(dy, dy->v1, dy->w2);
        dy->D += 0.5 * h * (c0 + ctn_layout_dot(&p->eq, dy->v1, dy->w2));
    }
    ctn_dyn_mass(dy, dy->v1, dy->w2);
    dy->ek = 0.5 * ctn_layout_dot(&p->eq, dy->v1, dy->w2);
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
    ctn_dyn_set_time(dy, t + h, dy->d1);
    return dy->o->method == CTN_DYN_CENTRAL ? ctn_dyn_central_step(dy, h, ok) : ctn_dyn_implicit_step(dy, h, ok);
}

/* From t = 0 to t_end: each multiple of dt reached in steps of dt, halved on failure. */
static int march(ctn_dyn *dy)
{
    const ctn_dynamics_options *o = dy->o;
    size_t N = (size_t)ceil(o->t_end / o->dt - 1e-9);
    double t = 0, h = o->dt;
    int level = 0, rc = CTN_OK;
    for (size_t k = 1; k <= N; k++) {
        double target = k == N ? o->t_end : (double)k * o->dt;
        while (t < target - 1e-9 * o->dt) {
            if (dy->severed && (rc = apply_removals(dy, t))) return rc;
            double hs = fmin(h, target - t), tr = dy->severed ? next_removal(dy, t) : INFINITY;
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
                return CTN_OK;
            }
            h *= 0.5;
            level++;
            dy->sum.cuts++;
        }
        t = target;
        if ((rc = ctn_dyn_record_row(dy, t))) return rc;
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
    s->dyn->sum = dy->sum;
    return CTN_OK;
}

int ctn_dynamics_run(ctn_problem *p, ctn_solution *s, const ctn_dynamics_options *o)
{
    double t0 = ctn_clock();
    ctn_solve_summary *keep = p->sum;
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
    p->sum = &s->sum;
    p->mode = 0;
    ctn_problem_settle(p);
    p->overlap = 0;                                  /* K_T is not what is factored */
    int rc = ctn_dynamics_check(p, o);
    if (!rc) rc = dyn_alloc(&dy);
    if (!rc) {
        method_params(&dy);
        start_loads(&dy);
        rc = start(&dy);
    }
    if (!rc) rc = march(&dy);
    if (!rc) rc = finish(&dy, t0);
    restore_removals(&dy);
    p->overlap = overlap;
    p->sum = keep;
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
    if (!rc) rc = ctn_dynamics_run(p, n, &o);
    if (rc) ctn_solution_destroy(&n);
    *s = n;
    return rc;
}

const ctn_analysis_ops ctn_analysis_dynamics = {
    "dynamics", sizeof(ctn_dynamics_options), 0, dyn_defaults, dyn_check, dyn_analysis,
};
