/* The non-linear check beside linear buckling (`buckling ... check=1`): from the solved
 * state d0 (load factor 1 on the last step's loads f), the load path of the structure
 * with an imperfection in the first buckling mode phi: the loads lambda (f + g), g =
 * a0 K_T phi / (lambda_1 - 1) (a0 = 1e-3 of the model's size for phi's largest
 * translation 1, its sign the one whose load adds to the step's: the worse for a limit
 * point, either for a bifurcation): the load of an initial crookedness a0 phi, lambda a0 (-K') phi, with
 * K' = -K_T / (lambda_1 - 1) along phi, so the amplitude grows as a0 lambda /
 * (lambda_1 - lambda) as a crooked column's does), in CTN_BK_INCREMENTS increments
 * of lambda from 1 towards the linear factor lambda_1, lambda_1 - lambda falling by
 * CTN_BK_RATIO each (so the amplitude grows by about 1.25 an increment: 20 of them end
 * at lambda_1 - 0.0115 (lambda_1 - 1)), each solved by the static analysis's own
 * increment (with its cut-backs). Then:
 * - a limit: an increment that fails, jumps (increment()), or ends at a state whose
 *   tangent is not positive definite (the LL' factorization fails; an indefinite linear
 *   solver cannot tell) ends the path: the largest stable load factor, bisected to 1e-3 of the
 *   increment (an arch snapping through: below the linear factor, the point);
 * - else (the path stays stable to the last increment: a bifurcation whose post-buckling path is stable, an
 *   Euler column): Southwell's factor. The path's amplitude in the mode grows as
 *   a = lambda c / (1 - lambda / lambda_c), so a / lambda = c + a / lambda_c: the
 *   least-squares slope of a / lambda against a over the path is 1 / lambda_c.
 * A linear factor at or below 1 (a tension-stiffened structure) has no path to check:
 * nl_kind 0. The model's loads that follow the geometry are not scaled: refused. */
#include "analysis/analysis.h"
#include "analysis/buckling/buckling.h"

#include <math.h>
#include <string.h>

#define CTN_BK_INCREMENTS 20
#define CTN_BK_RATIO 0.8           /* lambda_1 - lambda falls by this each increment */
#define CTN_BK_IMPERFECTION 1e-3   /* a0 over the model's size */
#define CTN_BK_BISECTIONS 10
#define CTN_BK_JUMP 8

typedef struct bk_path {
    ctn_problem *p;
    ctn_solution *ns;         /* scratch: the path's increments */
    const double *fs;         /* state: the step's loads f */
    double *g;                /* state: the imperfection's load g */
    double *d, *dprev, *dstep;/* state */
    double *f0, *f1;          /* state: the problem's, saved */
    const double *d0, *phi;   /* the solved state, the mode (ndof) */
    double a, rate;           /* the path's amplitude in the mode, |da| / dlambda of the
                                 last increment (0: none yet) */
} bk_path;

/* f0, f1 of the increment lambda a -> b. */
static void loads(bk_path *b, double la, double lb)
{
    ctn_problem *p = b->p;
    for (size_t i = 0; i < p->ns; i++) {
        p->f0[i] = la * (b->fs[i] + b->g[i]);
        p->f1[i] = lb * (b->fs[i] + b->g[i]);
    }
}

/* 1 in *ok when the tangent at state d is positive definite (the LL' factorization
 * succeeds; always with an indefinite linear solver, which cannot tell). */
static int definite(bk_path *b, const double *d, int *ok)
{
    ctn_problem *p = b->p;
    int posdef = 1, valid, rc = CTN_OK;
    long col;
    double rn;
    *ok = 1;
    if (!p->ls || ctn_linsolve_type(p->ls)->indefinite) return CTN_OK;
    if (!(rc = ctn_problem_residual(p, d, 1, &rn, NULL, &valid)) && valid) rc = ctn_problem_factor(p, 0.0, &posdef, &col);
    *ok = !rc && valid && posdef;
    return rc;
}

/* The amplitude of state d - d0 in the mode phi (ndof): phi . (d - d0) / phi . phi. */
static double amplitude(const ctn_problem *p, const double *d, const double *d0, const double *phi)
{
    double a = 0, n = 0;
    for (size_t i = 0; i < p->ns; i++) {
        int q = p->a->map.eq[i];
        if (q < 0) continue;
        a += phi[q] * (d[i] - d0[i]);
        n += phi[q] * phi[q];
    }
    return n > 0 ? a / n : 0;
}

/* Solve the increment la -> lb from b->d: 1 in *ok when it converged to a stable state
 * on the same branch (b->d, b->a and b->rate then at it; else b->d is back where it
 * was). Same branch: the amplitude's rate |da| / dlambda at most CTN_BK_JUMP times the
 * last increment's, so a jump over a limit (an arch that the load-controlled solver
 * snaps through to its inverted, stable form) is a failure of the path; along a stable
 * path the rate grows by about 1.6 an increment (1 / (lambda_1 - lambda)^2). */
static int increment(bk_path *b, double la, double lb, int *ok)
{
    ctn_problem *p = b->p;
    loads(b, la, lb);
    memcpy(b->dprev, b->d, p->ns * sizeof(double));
    int rc = ctn_problem_run_step(p, b->ns, 0, 1, b->d, b->dstep);
    *ok = !rc && b->ns->steps[0].reason == CTN_CONVERGED;
    double a = *ok ? amplitude(p, b->d, b->d0, b->phi) : 0, rate = fabs(a - b->a) / (lb - la);
    if (*ok && b->rate > 0 && rate > CTN_BK_JUMP * b->rate) *ok = 0;
    if (*ok && !rc) rc = definite(b, b->d, ok);
    if (rc || !*ok) {
        memcpy(b->d, b->dprev, p->ns * sizeof(double));
        return rc;
    }
    b->a = a;
    b->rate = rate;
    return rc;
}

/* The path, its kind and factor into sum. */
static int walk(bk_path *b, double lam1, ctn_buckling_summary *sum)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, la = 1, lb = 1;
    int rc = CTN_OK, ok = 1, m = 0;
    for (int k = 1; k <= CTN_BK_INCREMENTS && ok; k++) {
        lb = lam1 - (lam1 - 1) * pow(CTN_BK_RATIO, k);
        if ((rc = increment(b, la, lb, &ok))) return rc;
        sum->nl_increments++;
        if (!ok) break;
        double a = b->a, y = a / lb;
        sx += a; sy += y; sxx += a * a; sxy += a * y; m++;
        la = lb;
    }
    if (ok) {                                  /* stable to the top: Southwell */
        double den = m * sxx - sx * sx, slope = den != 0 ? (m * sxy - sx * sy) / den : 0;
        sum->nl_kind = 2;
        sum->nl_factor = slope > 0 ? 1 / slope : 0;
        return CTN_OK;
    }
    double lo = la, hi = lb;
    for (int h = 0; h < CTN_BK_BISECTIONS; h++) {   /* the limit between lo and hi */
        double mid = 0.5 * (lo + hi);
        if ((rc = increment(b, lo, mid, &ok))) return rc;
        sum->nl_increments++;
        if (ok) lo = mid;
        else hi = mid;
    }
    sum->nl_kind = 1;
    sum->nl_factor = lo;
    return CTN_OK;
}

int ctn_buckling_nonlinear(ctn_problem *p, const ctn_solution *s, const double *d0, const double *fs, const double *K0,
                           const double *phi, double lam1, int line, ctn_buckling_summary *sum)
{
    if (!(lam1 > 1)) return CTN_OK;
    if (p->fl)
        return ctn_error_at(p->ctx, CTN_ERR_MODEL, p->m->file, line, "buckling: check=1 scales the step's loads, and "
                            "the model has loads that follow the geometry (wind, hload projection=deformed), which "
                            "it does not scale: drop check=1 or make them dead loads");
    bk_path b = { p, NULL, fs, NULL, NULL, NULL, NULL, NULL, NULL, d0, phi, 0, 0 };
    double *v[6];
    for (int i = 0; i < 6; i++) v[i] = ctn_calloc(p->ctx, p->ns ? p->ns : 1, sizeof(double));
    double *kphi = ctn_calloc(p->ctx, p->ndof ? p->ndof : 1, sizeof(double));
    int rc = v[0] && v[1] && v[2] && v[3] && v[4] && v[5] && kphi ? CTN_OK : CTN_ERR_NOMEM;
    size_t k0;
    if (!rc) rc = ctn_solution_create(p->ctx, p->m->nodes.n, p->m->elements.n, &b.ns);
    if (!rc) {
        b.ns->rot = s->rot;
        rc = ctn_solution_add_step(b.ns, "check", &k0);
    }
    if (rc) goto done;
    b.g = v[0]; b.d = v[1]; b.dprev = v[2]; b.dstep = v[3]; b.f0 = v[4]; b.f1 = v[5];
    double umax = 0;                           /* phi's largest translation */
    for (size_t q = 0; q < p->ndof; q++)
        if (p->a->map.dof_dir[q] < 3) umax = fmax(umax, fabs(phi[q]));
    double a0 = CTN_BK_IMPERFECTION * p->lref / (umax > 0 ? umax : 1);
    ctn_problem_symv(p, K0, phi, kphi);
    double along = 0;                          /* the sign that adds to the loads */
    for (size_t i = 0; i < p->ns; i++) {
        int q = p->a->map.eq[i];
        along += q >= 0 ? kphi[q] * fs[i] : 0;
    }
    if (along < 0) a0 = -a0;
    for (size_t i = 0; i < p->ns; i++) {
        int q = p->a->map.eq[i];
        b.g[i] = q >= 0 ? a0 * kphi[q] / (lam1 - 1) : 0;
    }
    sum->nl_imperfection = fabs(a0) * (umax > 0 ? umax : 1);
    memcpy(b.f0, p->f0, p->ns * sizeof(double));
    memcpy(b.f1, p->f1, p->ns * sizeof(double));
    memcpy(b.d, d0, p->ns * sizeof(double));
    if (p->dT0 && p->dT1) memcpy(p->dT0, p->dT1, p->a->ne * sizeof(double));   /* held */
    memcpy(p->p0, p->p1, p->ns * sizeof(double));
    ctn_solve_summary *keep = p->sum;
    p->sum = &b.ns->sum;
    rc = walk(&b, lam1, sum);
    p->sum = keep;
    memcpy(p->f0, b.f0, p->ns * sizeof(double));
    memcpy(p->f1, b.f1, p->ns * sizeof(double));
    ctn_problem_set_t(p, 1.0, v[1]);
done:
    ctn_solution_destroy(&b.ns);
    for (int i = 0; i < 6; i++) ctn_free(v[i]);
    ctn_free(kphi);
    return rc;
}
