/* One step of the implicit generalized-alpha family (Chung-Hulbert; HHT and Newmark as
 * its special cases), forces averaged between t_n and t_n+1:
 *   R = (1 - af) r(d1) + af r0 - M ((1 - am) a1 + am a0) - C ((1 - af) v1 + af v0) = 0,
 * r = f_ext - f_int, a1 and v1 Newmark's in d1:
 *   a1 = (d1 - d0 - h v0 - h^2 (1/2 - beta) a0) / (beta h^2),
 *   v1 = v0 + h ((1 - gamma) a0 + gamma a1).
 * Newton on d1: (K_T + c1 M + c2 C) dd = R / (1 - af), c1 = (1 - am) / ((1 - af) beta
 * h^2), c2 = gamma / (beta h) (modal damping's low-rank part of C by Woodbury's identity,
 * dyn_modal.c). docs/theory.md "Dynamics". */
#include "analysis/dynamics/dynamics.h"
#include "linalg/pcg.h"

#include <math.h>
#include <string.h>

int ctn_dyn_residual(ctn_dyn *dy, const double *d, int with_K, double *r, int *valid)
{
    ctn_problem *p = dy->p;
    double rn = 0, pi = 0, work = 0;
    int rc = ctn_problem_residual(p, d, with_K, &rn, &pi, valid);
    if (rc || !*valid) return rc;
    const int *eq = p->a->map.eq;
    const double *fh = p->fl ? ctn_follow_loads(p->fl) : NULL;   /* pi took them too */
    for (size_t i = 0; i < p->ns; i++)
        if (eq[i] >= 0) work += fh ? (p->fext[i] + fh[i]) * d[i] : p->fext[i] * d[i];
    dy->U1 = pi + ctn_layout_sum(&p->st, work);         /* pi = U - f_ext . d */
    memcpy(r, p->r, p->ndof * sizeof(double));
    return CTN_OK;
}

void ctn_dyn_mass(const ctn_dyn *dy, const double *x, double *y)
{
    ctn_pattern pat = { dy->p->ndof, dy->mcol, dy->mrow };
    ctn_sym_matvec(&pat, dy->mval, x, y);
}

void ctn_dyn_damp(const ctn_dyn *dy, const double *x, double *y)
{
    if (dy->Cx) ctn_problem_symv(dy->p, dy->Cx, x, y);
    else memset(y, 0, dy->p->ndof * sizeof(double));
    if (dy->mr) ctn_dyn_modal_damp(dy, x, y);
}

/* a1, v1 from d1 (Newmark). */
static void kinematics(ctn_dyn *dy, double h)
{
    const ctn_problem *p = dy->p;
    const int *eq = p->a->map.eq;
    double b = dy->beta, g = dy->gamma;
    for (size_t i = 0; i < p->ns; i++) {
        int q = eq[i];
        if (q < 0 || p->a->map.dof_dir[q] >= 3) continue;   /* rotations: dyn_rot.c */
        double a = (dy->d1[i] - dy->d0[i] - h * dy->v0[q] - h * h * (0.5 - b) * dy->a0[q]) / (b * h * h);
        dy->a1[q] = a;
        dy->v1[q] = dy->v0[q] + h * ((1 - g) * dy->a0[q] + g * a);
    }
    ctn_dyn_rot_kinematics(dy, h);
}

/* R (dy->R) from r1 = f_ext - f_int(d1); the force scale |f_ext| + |f_int| + |M a1| of
 * the convergence test in *ref. */
static void step_residual(ctn_dyn *dy, const double *r1, double *ref)
{
    const ctn_problem *p = dy->p;
    size_t n = p->ndof;
    double am = dy->am, af = dy->af, *w = dy->w, *y = dy->R;
    for (size_t q = 0; q < n; q++) w[q] = (1 - am) * dy->a1[q] + am * dy->a0[q];
    ctn_dyn_mass(dy, w, y);                           /* y = M a(n+1-am) */
    double ma = ctn_layout_norm(&p->eq, y);
    for (size_t q = 0; q < n; q++) y[q] = (1 - af) * r1[q] + af * dy->r0[q] - y[q];
    if (dy->rot) ma = sqrt(ma * ma + ctn_dyn_rot_residual(dy, y));   /* rotary inertia */
    if (ctn_dyn_damped(dy) && !dy->rot) {
        for (size_t q = 0; q < n; q++) w[q] = (1 - af) * dy->v1[q] + af * dy->v0[q];
        ctn_dyn_damp(dy, w, dy->w2);
        for (size_t q = 0; q < n; q++) y[q] -= dy->w2[q];
    } else if (ctn_dyn_damped(dy)) {                  /* on each end's spatial velocities */
        ctn_dyn_damp_at(dy, dy->d1, dy->v1, w, dy->w2);
        for (size_t q = 0; q < n; q++) y[q] -= (1 - af) * dy->w2[q];
        ctn_dyn_damp_at(dy, dy->d0, dy->v0, w, dy->w2);
        for (size_t q = 0; q < n; q++) y[q] -= af * dy->w2[q];
    }
    for (size_t q = 0; dy->fsup && q < n; q++) y[q] -= dy->fsup[q];   /* moving supports */
    double fe = 0, fi = 0;
    const int *eq = p->a->map.eq;
    for (size_t i = 0; i < p->ns; i++)
        if (eq[i] >= 0) {
            fe += p->fext[i] * p->fext[i];
            fi += p->fint[i] * p->fint[i];
        }
    *ref = sqrt(ctn_layout_sum(&p->st, fe)) + sqrt(ctn_layout_sum(&p->st, fi)) + ma;
}

/* The effective tangent K_T + c1 M + c2 C into p->Kx, factored; *ok = 0 if it is not
 * positive definite. */
static int factor_effective(ctn_dyn *dy, double h, int *ok)
{
    ctn_problem *p = dy->p;
    double c1 = (1 - dy->am) / ((1 - dy->af) * dy->beta * h * h), c2 = dy->gamma / (dy->beta * h);
    size_t mnz = (size_t)dy->mcol[p->ndof];
    for (size_t k = 0; k < mnz; k++) p->Kx[dy->mslot[k]] += c1 * dy->mval[k];   /* M's nonzeros only */
    for (size_t k = 0; dy->Cx && k < p->a->nnz; k++) p->Kx[k] += c2 * dy->Cx[k];
    ctn_dyn_rot_tangent(dy, c1 + c2 * dy->o->damping_alpha);   /* rotary inertia, alpha R J W */
    ctn_dyn_wind_tangent(dy, c2);
    long col = -1;
    int rc = ctn_problem_factor(p, 0.0, ok, &col);
    dy->sum.factorizations++;
    if (!rc && *ok) rc = ctn_dyn_modal_factor(dy, c2, ok);
    if (!rc && *ok) ctn_dyn_exact_blocks(dy, h);
    return rc;
}

/* The predictor: the displacements of t_n (a step of any size starts from a state the
 * elements know; the constant-acceleration predictor may carry a long step across a
 * support, onto another branch of a member's law). */
static void predict(ctn_dyn *dy)
{
    const ctn_problem *p = dy->p;
    for (size_t i = 0; i < p->ns; i++)
        if (p->a->map.eq[i] >= 0) dy->d1[i] = dy->d0[i];   /* fixed DOFs: at t_n+1 already */
}

/* Newton corrections below this fraction of |d| + L_ref make the next residual a
 * round-off one (quadratic convergence): it is then evaluated without the tangent,
 * which is assembled only if that residual fails the test after all. */
#define CTN_DYN_LIKELY 1e-5

int ctn_dyn_implicit_step(ctn_dyn *dy, double h, int *ok)
{
    ctn_problem *p = dy->p;
    const ctn_dynamics_options *o = dy->o;
    double *r1 = dy->r1;
    int small = 0, with_K = 1, rc = CTN_OK;
    *ok = 0;
    predict(dy);
    for (int it = 0;; it++) {
        int valid = 0, posdef = 0;
        double ref = 0;
        kinematics(dy, h);
        if ((rc = ctn_dyn_residual(dy, dy->d1, with_K, r1, &valid)) || !valid) return rc;
        ctn_dyn_wind(dy, dy->d1, dy->v1, dy->t1, r1);
        step_residual(dy, r1, &ref);
        double rn = ctn_layout_norm(&p->eq, dy->R);
        if (!isfinite(rn)) return CTN_OK;
        if (small || rn <= o->tol * ref) {
            *ok = 1;
            return CTN_OK;
        }
        if (it >= o->maxit) return CTN_OK;
        if (!with_K) {                                /* not converged after all: K too */
            with_K = 1;
            continue;
        }
        if ((rc = factor_effective(dy, h, &posdef)) || !posdef) return rc;
        for (size_t q = 0; q < p->ndof; q++) dy->R[q] /= 1 - dy->af;
        if ((rc = ctn_dyn_exact_solve(dy, dy->R, dy->w))) return rc;
        ctn_problem_update(p, dy->d1, 1.0, dy->w);
        dy->sum.iterations++;
        double dn = ctn_layout_norm(&p->eq, dy->w), dd = ctn_layout_norm(&p->st, dy->d1) + p->lref;
        small = dn <= o->dtol * dd;
        with_K = !(dn <= CTN_DYN_LIKELY * dd);
        if ((rc = ctn_interrupted(p->ctx))) return rc;
    }
}
