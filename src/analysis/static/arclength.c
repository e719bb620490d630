/* Crisfield's cylindrical arc-length method for one load pattern F (the loads of the
 * first step): find (d, lambda) with f_int(d) = lambda F on the path, steps of constant
 * displacement length |Delta u| = ds. The tangent may be indefinite past a limit point,
 * so the engine factorizes LDL' here.
 *   predictor:  K du_t = F,  Delta lambda = +-ds/|du_t| (sign: along the previous step)
 *   corrector:  K du_r = r,  K du_t = F,  Delta u' = Delta u + du_r + dl du_t with
 *               |Delta u'| = ds: a dl^2 + b dl + c = 0, the root closer to Delta u. */
#include "problem/problem.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct arc {
    ctn_problem *e;
    ctn_solution *s;
    double *d, *d0;            /* current state, state at the step start (3 nn) */
    double *du, *ut, *ur, *F;  /* ndof: Delta u, du_t, du_r, load pattern */
    double *du_prev;           /* ndof: Delta u of the previous converged step */
    double lambda, ds, fref;
} arc;

static int solve_rhs(arc *a, const double *rhs, double *x, int *ok)
{
    long col;
    int rc = ctn_problem_factor(a->e, 0.0, ok, &col);
    if (rc || !*ok) return rc;
    return ctn_problem_linsolve(a->e, rhs, x);
}

/* d = d0 + du on free DOFs; residual at lambda; *valid = 0 if an element collapsed. */
static int place(arc *a, double lambda, double *rn, int *valid)
{
    ctn_problem *e = a->e;
    memcpy(a->d, a->d0, e->ns * sizeof(double));
    ctn_problem_update(e, a->d, 1.0, a->du);
    for (size_t i = 0; i < e->ns; i++) e->fext[i] = lambda * e->f1[i];
    return ctn_problem_residual(e, a->d, 1, rn, NULL, valid);
}

/* Root of the constraint closest in direction to the current Delta u. */
static int constraint_root(arc *a, double *dl)
{
    size_t n = a->e->ndof;
    const ctn_layout *eq = &a->e->eq;
    double A = ctn_layout_dot(eq, a->ut, a->ut), B = 0, C = 0, best = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        double v = a->du[i] + a->ur[i];
        B += 2 * a->ut[i] * v;
        C += v * v;
    }
    B = ctn_layout_sum(eq, B);
    C = ctn_layout_sum(eq, C) - a->ds * a->ds;
    double disc = B * B - 4 * A * C;
    if (!(disc >= 0) || !(A > 0)) return 0;
    double q = -0.5 * (B + copysign(sqrt(disc), B)), roots[2] = { q / A, q != 0 ? C / q : 0 };
    for (int k = 0; k < 2; k++) {                 /* maximize Delta u . Delta u' */
        double dot = 0;
        for (size_t i = 0; i < n; i++) dot += a->du[i] * (a->du[i] + a->ur[i] + roots[k] * a->ut[i]);
        if (dot > best) { best = dot; *dl = roots[k]; }
    }
    return 1;
}

/* One arc step from d0; *ok = 1 when converged (d, lambda updated). */
static int arc_step(arc *a, int first, int *ok)
{
    ctn_problem *e = a->e;
    size_t n = e->ndof;
    double rn, lam;
    memset(a->du, 0, n * sizeof(double));
    int valid, rc = place(a, a->lambda, &rn, &valid);   /* K at d0 */
    *ok = 0;
    if (rc || !valid || (rc = solve_rhs(a, a->F, a->ut, ok)) || !*ok) return rc;
    double sign = first ? 1.0 : (ctn_layout_dot(&a->e->eq, a->du_prev, a->ut) >= 0 ? 1.0 : -1.0);
    double dl = sign * a->ds / ctn_layout_norm(&a->e->eq, a->ut);
    for (size_t i = 0; i < n; i++) a->du[i] = dl * a->ut[i];
    lam = a->lambda + dl;
    *ok = 0;
    for (int it = 1; it <= e->opt.maxit; it++) {
        if ((rc = place(a, lam, &rn, &valid)) || !valid) return rc;
        if ((rc = ctn_problem_record(e, a->s, rn, it == 1 ? a->ds : fabs(dl)))) return rc;
        if (rn <= e->opt.tol * a->fref && it > 1) { *ok = 1; break; }
        int def;
        if ((rc = solve_rhs(a, e->r, a->ur, &def)) || !def) return rc;
        if ((rc = ctn_problem_linsolve(e, a->F, a->ut))) return rc;
        if (!constraint_root(a, &dl)) return CTN_OK;
        for (size_t i = 0; i < n; i++) a->du[i] += a->ur[i] + dl * a->ut[i];
        lam += dl;
    }
    if (*ok) {
        a->lambda = lam;
        memcpy(a->du_prev, a->du, n * sizeof(double));
    }
    return CTN_OK;
}

static int record_state(arc *a, size_t count)
{
    char name[32];
    size_t k;
    snprintf(name, sizeof name, "arc %zu", count);
    int rc = ctn_solution_add_step(a->s, name, &k);
    if (rc) return rc;
    ctn_step_state *st = &a->s->steps[k];
    st->reason = CTN_CONVERGED;
    st->t = a->lambda;
    for (size_t i = 0; i < a->e->ns; i++) a->e->fext[i] = a->lambda * a->e->f1[i];
    return ctn_problem_fill_step(a->e, a->s, k, a->d);
}

/* Node of state entry i. */
static size_t node_of(const ctn_dofmap *map, size_t i)
{
    size_t n = 0;
    while (n + 1 < map->nn && ctn_dofmap_node(map, n + 1) <= i) n++;
    return n;
}

static int check_model(const ctn_problem *e)
{
    const ctn_dofmap *map = &e->a->map;
    if (e->fl)
        return ctn_error(e->ctx, CTN_ERR_MODEL, "%s: arc-length traces a dead load pattern: give hload "
                         "projection=reference, or use another method", e->m->file);
    if (ctn_model_step_count(e->m) > 1)
        return ctn_error(e->ctx, CTN_ERR_MODEL, "%s: arc-length traces one load pattern; the model has %zu steps", e->m->file, ctn_model_step_count(e->m));
    for (size_t i = 0; i < e->ns; i++)
        if (e->p1[i] != 0)
            return ctn_error(e->ctx, CTN_ERR_MODEL, "%s: arc-length does not take prescribed displacements (node %d)", e->m->file, e->m->nodes.v[node_of(map, i)].id);
    return CTN_OK;
}

static int alloc_arc(arc *a)
{
    size_t n = a->e->ndof;
    double **v[] = { &a->du, &a->ut, &a->ur, &a->F, &a->du_prev };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++)
        if (!(*v[i] = ctn_calloc(a->e->ctx, n, sizeof(double)))) return CTN_ERR_NOMEM;
    a->d0 = ctn_calloc(a->e->ctx, a->e->ns, sizeof(double));
    return a->d0 ? CTN_OK : CTN_ERR_NOMEM;
}

static void free_arc(arc *a)
{
    double *v[] = { a->du, a->ut, a->ur, a->F, a->du_prev, a->d0 };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
}

/* Arc radius: given, or lambda_max/steps of the first linear step. */
static int initial_radius(arc *a)
{
    if (a->e->opt.arclength > 0) {
        a->ds = a->e->opt.arclength;
        return CTN_OK;
    }
    double rn;
    int ok = 0, valid, rc = place(a, 0.0, &rn, &valid);
    if (!rc && valid) rc = solve_rhs(a, a->F, a->ut, &ok);
    if (rc) return rc;
    if (!ok) {                                  /* an outcome, not a model error */
        a->s->sum.reason = CTN_DIVERGED_INDEFINITE;
        return CTN_OK;
    }
    a->ds = fabs(a->e->opt.lambda_max) * ctn_layout_norm(&a->e->eq, a->ut) / a->e->opt.steps;
    return CTN_OK;
}

/* Past the target: a load-controlled Newton correction at exactly lambda_max from the
 * last arc point (LDL' tangent); if it converges it replaces that point. */
static int land(arc *a, size_t count)
{
    ctn_problem *e = a->e;
    double target = e->opt.lambda_max, rn;
    memcpy(a->d0, a->d, e->ns * sizeof(double));
    memset(a->du, 0, e->ndof * sizeof(double));
    int valid, rc = place(a, target, &rn, &valid);
    for (int it = 1; !rc && valid && it <= e->opt.maxit; it++) {
        int ok;
        if ((rc = solve_rhs(a, e->r, a->ur, &ok)) || !ok) break;
        for (size_t i = 0; i < e->ndof; i++) a->du[i] += a->ur[i];
        if ((rc = place(a, target, &rn, &valid)) || !valid) break;
        if ((rc = ctn_problem_record(e, a->s, rn, ctn_layout_norm(&e->eq, a->ur)))) return rc;
        if (rn <= e->opt.tol * a->fref) {
            ctn_solution_drop_step(a->s);        /* the landing replaces that point */
            a->lambda = target;
            return record_state(a, count);
        }
    }
    memcpy(a->d, a->d0, e->ns * sizeof(double));     /* keep the last arc point */
    return rc;
}

static int trace(arc *a)
{
    ctn_problem *e = a->e;
    ctn_solve_summary *sum = &a->s->sum;
    size_t count = 0;
    int cuts = 0, rc = CTN_OK;
    sum->reason = CTN_DIVERGED_MAXIT;
    while (count < (size_t)e->opt.arcsteps) {
        int ok;
        memcpy(a->d0, a->d, e->ns * sizeof(double));
        if ((rc = arc_step(a, count == 0, &ok))) break;
        if (!ok) {
            memcpy(a->d, a->d0, e->ns * sizeof(double));
            if (cuts++ >= e->opt.maxcuts) { sum->reason = CTN_DIVERGED_ARCLENGTH; break; }
            sum->cuts++;
            a->ds *= 0.5;
            continue;
        }
        if ((rc = record_state(a, ++count))) break;
        if (a->lambda / e->opt.lambda_max >= 1) {
            sum->reason = CTN_CONVERGED;
            if (a->lambda != e->opt.lambda_max) rc = land(a, count);
            break;
        }
    }
    sum->load_factor = a->lambda;
    if (!rc && count == 0) rc = record_state(a, 0);   /* keep the starting state */
    if (!rc) sum->step = a->s->nsteps - 1;
    return rc;
}

int ctn_arclength_run(ctn_problem *e, ctn_solution *s, double *d)
{
    arc a;
    memset(&a, 0, sizeof a);
    a.e = e;
    a.s = s;
    a.d = d;
    ctn_problem_step_loads(e, 0);
    memset(e->f0, 0, e->ns * sizeof(double));
    int rc = check_model(e);
    if (!rc) rc = alloc_arc(&a);
    if (!rc) {
        for (size_t i = 0; i < e->ns; i++)
            if (e->a->map.eq[i] >= 0) a.F[e->a->map.eq[i]] = e->f1[i];
        a.fref = ctn_layout_norm(&e->eq, a.F);
        if (!(a.fref > 0)) rc = ctn_error(e->ctx, CTN_ERR_MODEL, "%s: arc-length needs a load on free DOFs", e->m->file);
    }
    if (!rc) rc = initial_radius(&a);
    if (!rc && s->sum.reason == CTN_DIVERGED_INDEFINITE) {  /* singular start: keep it */
        if (!(rc = record_state(&a, 0))) s->steps[s->nsteps - 1].reason = CTN_DIVERGED_INDEFINITE;
    } else if (!rc) {
        rc = trace(&a);
    }
    free_arc(&a);
    return rc;
}
