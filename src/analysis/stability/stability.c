/* Stability of an equilibrium: the inertia of the tangent at a solution's state.
 * A Cholesky attempt (LL') says whether the tangent is positive definite; if not, an
 * LDL' factorization on the same pattern counts the negative and zero pivots (by
 * Sylvester's law of inertia, the negative and zero eigenvalues), with zero meaning
 * within 1e-12 of the largest diagonal entry. */
#include "analysis/analysis.h"

#include "linalg/pcg.h"

#include <math.h>
#include <string.h>

int ctn_problem_tangent_at(ctn_problem *p, const ctn_solution *s, double *d, const char *who)
{
    const double *d3 = ctn_solution_displacements(s);
    if (!d3 || s->nn != p->m->nodes.n) return ctn_error(p->ctx, CTN_ERR_INVALID, "%s: the solution is not of this problem's model", who);
    const double *rot = ctn_solution_rotations(s);
    if (!rot != !p->a->map.rot) return ctn_error(p->ctx, CTN_ERR_INVALID, "%s: the solution is not of this problem's model", who);
    ctn_dofmap_from3(&p->a->map, d3, d);
    if (rot) ctn_dofmap_rot_from3(&p->a->map, rot, d);
    ctn_problem_settle(p);                         /* K is rewritten */
    if (ctn_problem_eval_tangent(p, d))
        return ctn_error(p->ctx, CTN_ERR_INVALID, "%s: an element has zero length in that state", who);
    return CTN_OK;
}

static void locate(const ctn_problem *p, long col, ctn_stability *out)
{
    if (col < 0) return;
    out->node = p->m->nodes.v[p->a->map.dof_node[col]].id;
    out->dir = p->a->map.dof_dir[col];
}

/* A solver that names no pivot (MUMPS, which pivots) found a zero one: CHOLMOD's LDL'
 * without pivoting names its column, as in one process (every process holds the whole
 * tangent: docs/parallel.md). */
static int locate_zero(ctn_problem *p, ctn_stability *out)
{
    ctn_linsolve *ldl = NULL;
    ctn_pattern pat;
    ctn_factor_info info;
    long neg = 0, zero = 0, first = -1;
    double *Kx = NULL;
    int rc = ctn_problem_whole_K(p, &pat, &Kx);
    if (!rc) rc = ctn_linsolve_create_threads(p->ctx, "cholmod-ldl", &pat, CTN_LA_ORDER_AUTO, p->opt.threads, &ldl);
    if (!rc) rc = ctn_linsolve_factor(ldl, Kx, 0.0, &info);
    if (Kx) ctn_problem_whole_K_done(p, &pat, Kx);
    if (!rc && info.ok) rc = ctn_linsolve_inertia(ldl, 1e-12 * ctn_problem_max_diag(p), &neg, &zero, &first);
    locate(p, !rc && info.ok ? first : info.fail_col, out);
    ctn_linsolve_destroy(&ldl);
    return rc;
}

/* The eigenvalue of K of least magnitude, by inverse iteration on its LDL' factor (the
 * Rayleigh quotient of the 30th iterate), in *lam. */
static int least_eigenvalue(ctn_problem *p, ctn_linsolve *ldl, double *lam)
{
    double *x = p->r, *y = p->w;                    /* ndof scratch, free after a solve */
    *lam = 0;
    for (size_t i = 0; i < p->ndof; i++) x[i] = 1.0 + 1e-3 * (double)(i % 7);
    for (int it = 0; it < 30; it++) {
        int rc = ctn_linsolve_solve(ldl, x, x);
        if (rc) return rc;
        double n = ctn_layout_norm(&p->eq, x);
        if (!(n > 0) || !isfinite(n)) return CTN_OK;
        for (size_t i = 0; i < p->ndof; i++) x[i] /= n;
    }
    ctn_problem_symv(p, p->Kx, x, y);
    *lam = ctn_layout_dot(&p->eq, x, y);
    return CTN_OK;
}

/* The weakest mode: the eigenvector of least magnitude (least_eigenvalue's iterate, left
 * in p->r). When that eigenvalue is negative, its largest component names the node and
 * direction that fall; otherwise the first negative pivot stays the report. */
static int weakest_mode(ctn_problem *p, ctn_linsolve *ldl, ctn_stability *out)
{
    double lam;
    int rc = least_eigenvalue(p, ldl, &lam);
    if (rc || !(lam < 0)) return rc;
    const double *x = p->r;
    size_t imax = 0;
    for (size_t i = 1; i < p->ndof; i++)
        if (fabs(x[i]) > fabs(x[imax])) imax = i;
    locate(p, (long)imax, out);
    return CTN_OK;
}

/* Fixed moments on spun nodes (problem/spin.c): the whole tangent is K + E S E^T, S the
 * blocks -[g]x / 2 at those nodes (not symmetric), and K, its symmetric part, may be
 * indefinite on a stable path (the cantilever rolled up by a fixed end moment: 2
 * negative eigenvalues of K from half the roll-up on, on a path whose equilibrium is
 * unique, so whose whole tangent is never singular). By Bauer and Fike (K symmetric),
 * every eigenvalue of the whole tangent lies within |S| = max |g| / 2 of one of K's:
 * where K's eigenvalue of least magnitude exceeds that, K's count of negative
 * eigenvalues is the whole tangent's count of eigenvalues of negative real part, and
 * stands. Else the skew part can move eigenvalues across the imaginary axis, and the
 * static (divergence) check is the sign of the whole tangent's determinant through K's
 * LDL' (ctn_spin_det_sign): negative (an odd number of negative real eigenvalues:
 * unstable, negative 1) or positive (an even number, taken as none: stable; two real
 * eigenvalues that cross zero together are not seen); zero is semidefinite. A flutter
 * instability (a complex pair crossing) is seen by no static check. */
static int spin_sign(ctn_problem *p, ctn_linsolve *ldl, ctn_stability *out)
{
    double lam, skew = 0.5 * ctn_spin_moment_max(p);
    int sign = 0, rc = least_eigenvalue(p, ldl, &lam);
    if (rc || fabs(lam) > skew) return rc;
    if ((rc = ctn_spin_det_sign(p, ldl, out->negative, &sign))) return rc;
    out->semidefinite = sign == 0;
    out->negative = sign < 0;
    if (sign > 0) {
        out->node = 0;
        out->dir = -1;
    }
    return CTN_OK;
}

/* Not definite: count the inertia with LDL'. */
static int inertia(ctn_problem *p, ctn_stability *out)
{
    ctn_linsolve *ldl = NULL;
    ctn_factor_info info;
    long zero = 0, first = -1;
    int rc = ctn_problem_solver_create(p, ctn_linsolve_default(p->ctx, "cholmod-inertia"), CTN_LA_ORDER_AUTO, &ldl);
    if (!rc) rc = ctn_linsolve_factor(ldl, p->Kx, 0.0, &info);
    if (!rc && info.ok) {
        rc = ctn_linsolve_inertia(ldl, 1e-12 * ctn_problem_max_diag(p), &out->negative, &zero, &first);
        out->semidefinite = !rc && out->negative == 0 && zero > 0;
        locate(p, first, out);
        if (!rc && out->semidefinite && first < 0) rc = locate_zero(p, out);
        if (!rc && out->negative > 0) rc = weakest_mode(p, ldl, out);
        if (!rc && p->sp) rc = spin_sign(p, ldl, out);
    } else if (!rc) {
        out->semidefinite = 1;                      /* an exactly zero pivot */
        locate(p, info.fail_col, out);
    }
    ctn_linsolve_destroy(&ldl);
    return rc;
}

int ctn_problem_stability(ctn_problem *p, const ctn_solution *s, ctn_stability *out)
{
    if (!p || !s || !out) return p ? ctn_error(p->ctx, CTN_ERR_INVALID, "ctn_problem_stability: bad arguments") : CTN_ERR_INVALID;
    memset(out, 0, sizeof *out);
    out->dir = -1;
    if (p->ndof == 0) {                            /* nothing can move */
        out->stable = 1;
        return CTN_OK;
    }
    ctn_solve_summary scratch, *outer = p->sum;   /* a solve's check counts in its summary */
    memset(&scratch, 0, sizeof scratch);
    double *d = ctn_calloc(p->ctx, p->ns, sizeof(double));
    if (!d) return CTN_ERR_NOMEM;
    p->sum = &scratch;
    int ok = 0, rc = ctn_problem_tangent_at(p, s, d, "ctn_problem_stability");
    long col = -1;
    if (!rc) rc = ctn_problem_factor(p, 0.0, &ok, &col);
    int definite_only = !ctn_linsolve_type(p->ls)->indefinite;   /* LL': ok = definite */
    if (!rc && ok && definite_only) {
        out->stable = 1;
        p->factored_at = s;                        /* K_T at s itself: modes may reuse it */
    }
    else if (!rc) {
        locate(p, col, out);
        rc = inertia(p, out);
        out->stable = !rc && !out->semidefinite && out->negative == 0 && out->node == 0;
    }
    p->sum = outer;
    if (outer) {
        outer->factorizations += scratch.factorizations;
        outer->t_factor += scratch.t_factor;
        outer->t_factor_cpu += scratch.t_factor_cpu;
    }
    ctn_free(d);
    return rc;
}

/* The analysis object: the inertia at the solution's last step, stored in it. */
static void stability_defaults(const ctn_problem *p, void *opt)
{
    (void)p;
    ctn_stability_options_default(opt);
}

static int stability_check(ctn_problem *p, const void *opt)
{
    (void)p;
    (void)opt;
    return CTN_OK;
}

static int stability_run(ctn_problem *p, const void *opt, ctn_solution **s)
{
    (void)opt;
    ctn_stability st;
    int rc = ctn_problem_stability(p, *s, &st);
    if (rc) return rc;
    (*s)->stability = st;
    (*s)->sum.stable = st.stable;
    return CTN_OK;
}

const ctn_analysis_ops ctn_analysis_stability = {
    "stability", sizeof(ctn_stability_options), 1, stability_defaults, stability_check, stability_run,
};
