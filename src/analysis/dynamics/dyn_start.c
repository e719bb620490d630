/* The start of a dynamics analysis: the method's parameters, the held loads and the
 * start state, the loads and support motions at a time, the mass (on its own pattern)
 * and damping matrices, the initial acceleration, the stable step of the explicit method
 * and the first row. */
#include "analysis/dynamics/dynamics.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

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

/* The method's am, af, gamma, beta. */
void ctn_dyn_method_params(ctn_dyn *dy)
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
void ctn_dyn_start_loads(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    memset(p->f1, 0, p->ns * sizeof(double));
    memset(p->p1, 0, p->ns * sizeof(double));
    ctn_problem_step_loads(p, ctn_model_step_count(p->m) - 1);
    memcpy(p->f0, p->f1, p->ns * sizeof(double));
    memcpy(p->p0, p->p1, p->ns * sizeof(double));
    if (p->dT) memcpy(p->dT0, p->dT1, p->a->ne * sizeof(double));
    if (dy->s->nsteps) {
        const ctn_step_state *st = &dy->s->steps[dy->s->nsteps - 1];
        ctn_dofmap_from3(&p->a->map, st->d, dy->d0);
        if (p->a->map.rot && st->rot) ctn_dofmap_rot_from3(&p->a->map, st->rot, dy->d0);   /* psi */
    }
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

/* a0 = M^-1 (f_ext - f_int(d0) - C v0 - M_fs a_s - C_fs v_s): M factored by the problem's linear solver, or
 * over the lumped diagonal where M is singular (DOFs without mass: a0 = 0 there). */
int ctn_dyn_acceleration(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    ctn_factor_info info = { 0, -1 };
    if (dy->rot) ctn_dyn_rot_mass_add(dy, 1.0);        /* rotary inertia at d0, spatial */
    int rc = dy->lumped && !dy->rot ? CTN_OK : ctn_linsolve_factor(p->ls, dy->Mx, 0.0, &info);
    if (dy->rot) ctn_dyn_rot_mass_add(dy, -1.0);
    p->spd_factor = p->last_definite = 0;
    p->factored_at = NULL;
    ctn_dyn_damp(dy, dy->v0, dy->w2);
    for (size_t q = 0; q < p->ndof; q++) dy->w2[q] = dy->r0[q] - dy->w2[q] - (dy->fsup ? dy->fsup[q] : 0.0);
    if (!rc && info.ok) rc = ctn_linsolve_solve(p->ls, dy->w2, dy->a0);
    else
        for (size_t q = 0; q < p->ndof; q++) dy->a0[q] = dy->diag[q] > 0 ? dy->w2[q] / dy->diag[q] : 0.0;
    ctn_dyn_rot_start(dy, dy->a0);
    return rc;
}

/* The start: r0 and K_0 at d0, M (and C = a M + b K_0), a0, the energies, the stable step
 * of the explicit method, the first row. */
int ctn_dyn_start(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    const ctn_dynamics_options *o = dy->o;
    int valid = 0, lumped = dy->lumped;
    double tot[3];
    size_t bad;
    char msg[256];
    int rc = ctn_dyn_wind_setup(dy);
    if (!rc) rc = ctn_dyn_residual(dy, dy->d0, 1, dy->r0, &valid);
    if (!rc && valid && dy->nwind) {
        ctn_dyn_wind(dy, dy->d0, dy->v0, 0.0, dy->r0);
        memcpy(dy->wf0, dy->wf, p->ns * sizeof(double));
    }
    if (!rc && valid && p->fl) memcpy(dy->fh0, ctn_follow_loads(p->fl), p->ns * sizeof(double));
    if (!rc && !valid) {
        snprintf(msg, sizeof msg, "dynamics: element %d cannot be evaluated in the start state (a chord of zero length)",
                 p->sum->fail_element);
        return ctn_dyn_error(p, o, msg);
    }
    if (!rc) rc = ctn_asm_mass(p->ctx, p->a, lumped, dy->Mx);
    if (!rc) rc = ctn_dyn_rot_setup(dy);
    if (!rc) rc = mass_pattern(dy);
    if (rc) return rc;
    ctn_asm_mass_diag(p->a, dy->diag, tot, &bad);
    ctn_dyn_rot_stable_diag(dy);
    for (size_t k = 0; dy->Cx && k < p->a->nnz; k++) dy->Cx[k] = o->damping_alpha * dy->Mx[k] + o->damping_beta * p->Kx[k];
    if ((rc = ctn_dyn_modal_setup(dy)) || (rc = ctn_dyn_exact_setup(dy))) return rc;
    dy->sum.mass = lumped ? CTN_MASS_LUMPED : CTN_MASS_CONSISTENT;
    dy->U = dy->U1;
    dy->e0 = dy->U;
    dy->escale = fabs(dy->U);
    if (o->method == CTN_DYN_CENTRAL) {
        if ((rc = ctn_dyn_stable_step(dy))) return rc;
        if (o->dt > dy->sum.dt_stable) {
            snprintf(msg, sizeof msg, "dynamics: dt=%g is above the stable step of method=central, %.6g s (2 / omega_max "
                     "of the mesh at the start state): give dt <= %.6g", o->dt, dy->sum.dt_stable, dy->sum.dt_stable);
            return ctn_dyn_error(p, o, msg);
        }
    }
    if ((rc = ctn_dyn_output_begin(dy))) return rc;
    ctn_dyn_support_force(dy, 0.0, 0.0, 1.0, 1.0);
    if ((rc = ctn_dyn_acceleration(dy))) return rc;
    return ctn_dyn_record_begin(dy);
}
