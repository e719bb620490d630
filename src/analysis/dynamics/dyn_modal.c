/* Modal damping (`damping modal=Z1,Z2,...`): C_m = M Phi diag(2 zeta_i omega_i) Phi^T M
 * over the r lowest modes about the start state (mass-normalized, Phi^T M Phi = I), so
 * that mode i decays at zeta_i and the others are not damped by it. Never formed: it is
 * the low-rank U E U^T, U = M Phi (ndof x r), E = diag(2 zeta_i omega_i). Its products
 * add U (E (U^T x)); the effective tangent A + c2 U E U^T is solved by the Sherman-
 * Morrison-Woodbury identity on A's factorization:
 *   x = A^-1 b - Y S^-1 (c2 E U^T A^-1 b),  Y = A^-1 U (r solves per factorization),
 *   S = I + c2 E U^T Y (r x r, by Gaussian elimination with partial pivoting).
 * docs/theory.md "Dynamics". */
#include "analysis/dynamics/dynamics.h"

#include <math.h>
#include <string.h>

/* The modes about d0 by the modal analysis, on a solution of one step at d0. */
static int start_modes(ctn_dyn *dy, ctn_solution **tmp)
{
    ctn_problem *p = dy->p;
    ctn_modal_options mo;
    size_t k;
    ctn_modal_options_default(&mo);
    mo.count = dy->o->modal_count;
    mo.mass = dy->lumped ? CTN_MASS_LUMPED : CTN_MASS_CONSISTENT;
    mo.line = dy->o->line;
    int rc = ctn_solution_create(p->ctx, p->m->nodes.n, p->m->elements.n, tmp);
    if (!rc) (*tmp)->rot = p->a->map.rot > 0;          /* the start's rotations too */
    if (!rc) rc = ctn_solution_add_step(*tmp, "start", &k);
    if (!rc) rc = ctn_problem_fill_step(p, *tmp, k, dy->d0);
    if (rc) return rc;
    (*tmp)->sum.reason = CTN_CONVERGED;
    return ctn_problem_modes(p, *tmp, &mo);
}

/* U = M phi, the rotary inertia's R0 J R0^T rows included (the analysis's own mass: the
 * modal analysis's may share a beam's rotary inertia between its nodes), and phi, U
 * scaled to phi^T M phi = 1. */
static void normalize(const ctn_dyn *dy, double *phi, double *U)
{
    const ctn_problem *p = dy->p;
    ctn_dyn_mass(dy, phi, U);
    ctn_dyn_rot_mass_mult(dy, dy->d0, phi, U);
    double m = ctn_layout_dot(&p->eq, phi, U), s = m > 0 ? 1 / sqrt(m) : 1.0;
    for (size_t q = 0; q < p->ndof; q++) {
        phi[q] *= s;
        U[q] *= s;
    }
}

int ctn_dyn_modal_setup(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    const ctn_dynamics_options *o = dy->o;
    size_t n = p->ndof, r = (size_t)o->modal_count;
    if (!r) return CTN_OK;
    ctn_solution *tmp = NULL;
    double *st = NULL;
    int rc = start_modes(dy, &tmp);
    dy->mr = r;
    if (!rc) {
        dy->mPhi = ctn_calloc(p->ctx, n * r, sizeof(double));
        dy->mU = ctn_calloc(p->ctx, n * r, sizeof(double));
        dy->mY = ctn_calloc(p->ctx, n * r, sizeof(double));
        dy->mE = ctn_calloc(p->ctx, r, sizeof(double));
        dy->mS = ctn_calloc(p->ctx, r * r, sizeof(double));
        dy->mpiv = ctn_calloc(p->ctx, r, sizeof(size_t));
        dy->mG = ctn_calloc(p->ctx, r, sizeof(double));
        dy->mg = ctn_calloc(p->ctx, n, sizeof(double));
        st = ctn_calloc(p->ctx, p->ns, sizeof(double));
        if (!dy->mPhi || !dy->mU || !dy->mY || !dy->mE || !dy->mS || !dy->mpiv || !dy->mG || !dy->mg || !st)
            rc = CTN_ERR_NOMEM;
    }
    for (size_t i = 0; !rc && i < r; i++) {
        ctn_mode md;
        if ((rc = ctn_solution_mode(tmp, i, &md))) break;
        ctn_dofmap_from3(&p->a->map, md.shape, st);
        if (tmp->modes->rshapes) ctn_dofmap_rot_from3(&p->a->map, tmp->modes->rshapes + 3 * p->m->nodes.n * i, st);
        for (size_t s = 0; s < p->ns; s++)
            if (p->a->map.eq[s] >= 0) dy->mPhi[i * n + (size_t)p->a->map.eq[s]] = st[s];
        normalize(dy, dy->mPhi + i * n, dy->mU + i * n);
        double zeta = o->modal_zeta[o->modal_nzeta == 1 ? 0 : i];
        dy->mE[i] = 2 * zeta * md.angular_frequency;
        dy->mG[i] = md.angular_frequency > 0 ? 2 * zeta / md.angular_frequency : 0.0;
    }
    ctn_free(st);
    ctn_solution_destroy(&tmp);
    return rc;
}

/* z (r) = U^T x. */
static void project(const ctn_dyn *dy, const double *x, double *z)
{
    const ctn_problem *p = dy->p;
    for (size_t i = 0; i < dy->mr; i++) z[i] = ctn_layout_dot(&p->eq, dy->mU + i * p->ndof, x);
}

void ctn_dyn_modal_damp(const ctn_dyn *dy, const double *x, double *y)
{
    size_t n = dy->p->ndof;
    double z[CTN_DYN_MODAL_MAX];
    project(dy, x, z);
    for (size_t i = 0; i < dy->mr; i++) {
        double c = dy->mE[i] * z[i];
        for (size_t q = 0; q < n; q++) y[q] += c * dy->mU[i * n + q];
    }
}

/* z (r) += Omega^-2 Phi^T g, so that E z becomes E U^T v + diag(2 zeta / omega) Phi^T g. */
static void support_modes(const ctn_dyn *dy, const double *g, double *z)
{
    const ctn_problem *p = dy->p;
    for (size_t i = 0; g && i < dy->mr; i++)
        if (dy->mE[i] > 0) z[i] += dy->mG[i] / dy->mE[i] * ctn_layout_dot(&p->eq, dy->mPhi + i * p->ndof, g);
}

void ctn_dyn_modal_support(const ctn_dyn *dy, const double *g, double *y)
{
    size_t n = dy->p->ndof;
    for (size_t i = 0; i < dy->mr; i++) {
        double c = dy->mG[i] * ctn_layout_dot(&dy->p->eq, dy->mPhi + i * n, g);
        for (size_t q = 0; q < n; q++) y[q] += c * dy->mU[i * n + q];
    }
}

void ctn_dyn_modal_velocity(const ctn_dyn *dy, const double *v, const double *g, double *w)
{
    size_t n = dy->p->ndof;
    double z[CTN_DYN_MODAL_MAX];
    project(dy, v, z);
    support_modes(dy, g, z);
    memset(w, 0, n * sizeof(double));
    for (size_t i = 0; i < dy->mr; i++)
        for (size_t q = 0; q < n; q++) w[q] += dy->mE[i] * z[i] * dy->mPhi[i * n + q];
}

/* LU of the r x r S (row-major) with partial pivoting in place; piv (r). 0: singular. */
static int lu(double *S, size_t r, size_t *piv)
{
    for (size_t k = 0; k < r; k++) {
        size_t m = k;
        for (size_t i = k + 1; i < r; i++)
            if (fabs(S[i * r + k]) > fabs(S[m * r + k])) m = i;
        if (!(fabs(S[m * r + k]) > 0)) return 0;
        piv[k] = m;
        for (size_t j = 0; j < r && m != k; j++) {
            double t = S[k * r + j];
            S[k * r + j] = S[m * r + j];
            S[m * r + j] = t;
        }
        for (size_t i = k + 1; i < r; i++) {
            double f = S[i * r + k] /= S[k * r + k];
            for (size_t j = k + 1; j < r; j++) S[i * r + j] -= f * S[k * r + j];
        }
    }
    return 1;
}

static void lu_solve(const double *S, size_t r, const size_t *piv, double *b)
{
    for (size_t k = 0; k < r; k++) {
        double t = b[k];
        b[k] = b[piv[k]];
        b[piv[k]] = t;
        for (size_t j = 0; j < k; j++) b[k] -= S[k * r + j] * b[j];
    }
    for (size_t k = r; k-- > 0;) {
        for (size_t j = k + 1; j < r; j++) b[k] -= S[k * r + j] * b[j];
        b[k] /= S[k * r + k];
    }
}

int ctn_dyn_modal_factor(ctn_dyn *dy, double c2, int *ok)
{
    ctn_problem *p = dy->p;
    size_t n = p->ndof, r = dy->mr;
    double *S = dy->mS, z[CTN_DYN_MODAL_MAX];
    if (!r) return CTN_OK;
    int rc = ctn_linsolve_solve_block(p->ls, dy->mU, dy->mY, r);      /* Y = A^-1 U */
    if (rc) return rc;
    for (size_t j = 0; j < r; j++) {                                   /* S = I + c2 E U^T Y */
        project(dy, dy->mY + j * n, z);
        for (size_t i = 0; i < r; i++) S[i * r + j] = (i == j) + c2 * dy->mE[i] * z[i];
    }
    dy->mc2 = c2;
    *ok = lu(S, r, dy->mpiv);
    return CTN_OK;
}

void ctn_dyn_modal_correct(const ctn_dyn *dy, double *x)
{
    size_t n = dy->p->ndof, r = dy->mr;
    double z[CTN_DYN_MODAL_MAX];
    if (!r) return;
    project(dy, x, z);                                                  /* x = A^-1 b */
    for (size_t i = 0; i < r; i++) z[i] *= dy->mc2 * dy->mE[i];
    lu_solve(dy->mS, r, dy->mpiv, z);
    for (size_t i = 0; i < r; i++)
        for (size_t q = 0; q < n; q++) x[q] -= z[i] * dy->mY[i * n + q];
}
