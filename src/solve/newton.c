/* Pure Newton-Raphson (the paper's): K_T(d) dd = f_ext - f_int(d), d <- d + dd.
 * Symbolic work (DOF map, pattern, scatter map, ordering, analysis) happens once in
 * setup; the iteration loop allocates nothing. */
#include "assemble/asm.h"
#include "linalg/chol.h"
#include "solve/solution.h"

#include <math.h>
#include <string.h>
#include <time.h>

typedef struct newton {
    ctn_ctx *ctx;
    const ctn_model *m;
    ctn_solve_options opt;
    ctn_asm *a;
    ctn_chol *ch;
    double *fint, *fext;       /* 3 per node */
    double *r, *dd;            /* per equation */
    double fref, lref;         /* |f_ext| on free DOFs; model size */
} newton;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double norm2(const double *v, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) s += v[i] * v[i];
    return sqrt(s);
}

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

static int setup(newton *nw)
{
    ctn_ctx *ctx = nw->ctx;
    int rc = ctn_asm_create(ctx, nw->m, &nw->a);
    if (rc) return rc;
    size_t nn = nw->a->nn, ndof = nw->a->ndof;
    if (ndof == 0) return ctn_error(ctx, CTN_ERR_MODEL, "the model has no free degree of freedom");
    if ((rc = ctn_chol_create(ctx, ndof, nw->a->colptr, nw->a->rowind, nw->opt.ordering, &nw->ch)))
        return rc;
    nw->fint = ctn_malloc(ctx, 3 * nn, sizeof(double));
    nw->fext = ctn_malloc(ctx, 3 * nn, sizeof(double));
    nw->r = ctn_malloc(ctx, ndof, sizeof(double));
    nw->dd = ctn_malloc(ctx, ndof, sizeof(double));
    if (!nw->fint || !nw->fext || !nw->r || !nw->dd) return CTN_ERR_NOMEM;
    ctn_model_external_forces(nw->m, nw->fext);
    double s = 0;
    for (size_t i = 0; i < 3 * nn; i++)
        if (nw->a->eq[i] >= 0) s += nw->fext[i] * nw->fext[i];
    nw->fref = s > 0 ? sqrt(s) : 1.0;     /* unloaded: absolute residual test */
    nw->lref = model_size(nw->m);
    return CTN_OK;
}

static void teardown(newton *nw)
{
    ctn_asm_destroy(&nw->a);
    ctn_chol_destroy(&nw->ch);
    ctn_free(nw->fint);
    ctn_free(nw->fext);
    ctn_free(nw->r);
    ctn_free(nw->dd);
}

/* f_int and K at d, residual r = f_ext - f_int on free DOFs; its norm in *rnorm.
 * CTN_ERR_DOMAIN if an element collapsed. */
static int residual(newton *nw, const double *d, int with_K, double *rnorm, double *t)
{
    size_t bad;
    double t0 = now();
    int rc = ctn_asm_eval(nw->a, d, nw->fint, with_K ? ctn_chol_values(nw->ch) : NULL, &bad);
    if (rc) return rc;
    for (size_t i = 0; i < 3 * nw->a->nn; i++) {
        int q = nw->a->eq[i];
        if (q >= 0) nw->r[q] = nw->fext[i] - nw->fint[i];
    }
    *rnorm = norm2(nw->r, nw->a->ndof);
    *t += now() - t0;
    return isfinite(*rnorm) ? CTN_OK : CTN_ERR_DOMAIN;
}

/* d += sign * dd on free DOFs. */
static void update(newton *nw, double *d, double sign)
{
    for (size_t i = 0; i < 3 * nw->a->nn; i++) {
        int q = nw->a->eq[i];
        if (q >= 0) d[i] += sign * nw->dd[q];
    }
}

static int all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* One Newton step from d (K already assembled). Returns a status (backend failure);
 * *why gets 0 to go on, or the reason the iteration must stop. */
static int step(newton *nw, ctn_solution *s, double *d, double *rnorm, ctn_reason *why)
{
    long col;
    *why = 0;
    double t0 = now();
    int bad = ctn_chol_factorize(nw->ch, &col);
    s->sum.t_factor += now() - t0;
    if (bad) {
        if (col < 0) return ctn_ctx_code(nw->ctx);
        ctn_ctx_clear(nw->ctx);
        s->sum.fail_node = nw->m->nodes.v[nw->a->dof_node[col]].id;
        s->sum.fail_dir = nw->a->dof_dir[col];
        *why = CTN_DIVERGED_INDEFINITE;
        return CTN_OK;
    }
    t0 = now();
    int rc = ctn_chol_solve(nw->ch, nw->r, nw->dd);
    s->sum.t_solve += now() - t0;
    if (rc) return rc;
    if (!all_finite(nw->dd, nw->a->ndof)) {
        *why = CTN_DIVERGED_NANORINF;
        return CTN_OK;
    }
    update(nw, d, 1.0);
    if (residual(nw, d, 1, rnorm, &s->sum.t_assemble)) {
        update(nw, d, -1.0);                  /* keep the last finite state */
        *why = CTN_DIVERGED_NANORINF;
    }
    return CTN_OK;
}

static int iterate(newton *nw, ctn_solution *s)
{
    double *d = s->d, rnorm;
    for (size_t i = 0; i < 3 * nw->a->nn; i++)
        d[i] = nw->a->eq[i] >= 0 ? nw->m->nodes.v[i / 3].guess[i % 3] : 0.0;
    s->sum.reason = CTN_DIVERGED_MAXIT;
    if (residual(nw, d, 1, &rnorm, &s->sum.t_assemble)) {
        s->sum.reason = CTN_DIVERGED_NANORINF;
        return CTN_OK;
    }
    s->rhist[0] = s->sum.residual = rnorm;
    for (int it = 1; it <= nw->opt.maxit; it++) {
        ctn_reason why;
        int rc = step(nw, s, d, &rnorm, &why);
        if (rc) return rc;
        if (why) {
            s->sum.reason = why;
            break;
        }
        double dnorm = norm2(nw->dd, nw->a->ndof);
        s->nhist = (size_t)it;
        s->sum.iterations = it;
        s->rhist[it] = s->sum.residual = rnorm;
        s->dhist[it - 1] = s->sum.increment = dnorm;
        if (nw->opt.monitor) nw->opt.monitor(nw->opt.monitor_data, it, rnorm, dnorm);
        if (rnorm <= nw->opt.tol * nw->fref &&
            dnorm <= nw->opt.dtol * (norm2(d, 3 * nw->a->nn) + nw->lref)) {
            s->sum.reason = CTN_CONVERGED;
            break;
        }
    }
    return CTN_OK;
}

/* Element states and reactions at the final displacements. */
static void finish(newton *nw, ctn_solution *s)
{
    const ctn_model *m = nw->m;
    ctn_asm_eval(nw->a, s->d, nw->fint, NULL, NULL);
    for (size_t i = 0; i < 3 * nw->a->nn; i++)
        s->react[i] = nw->a->eq[i] < 0 ? nw->fint[i] - nw->fext[i] : 0.0;
    for (size_t e = 0; e < nw->a->ne; e++) {
        double X[CTN_EDOF], u[CTN_EDOF], f[CTN_EDOF];
        ctn_elem_state st = { 0, 0, 0, 0 };
        ctn_asm_gather(nw->a, e, s->d, X, u);
        nw->a->ops->eval(&nw->a->props[e], X, u, f, NULL, &st);
        s->elem[e].length = st.l;
        s->elem[e].strain = st.strain;
        s->elem[e].force = st.N;
        s->elem[e].stress = st.N / m->sections.v[m->elements.v[e].section].A;
        s->elem[e].slack = st.slack;
    }
    s->sum.fext_norm = nw->fref;
    s->sum.ordering = ctn_chol_ordering(nw->ch);
    s->sum.ndof = nw->a->ndof;
    s->sum.nnz_factor = ctn_chol_factor_nnz(nw->ch);
}

int ctn_solve(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt,
              ctn_solution **out)
{
    if (!m || !out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_solve: model or out is NULL");
    *out = NULL;
    int rc = ctn_model_validate(m);
    if (rc) return rc;
    newton nw;
    memset(&nw, 0, sizeof nw);
    nw.ctx = ctx;
    nw.m = m;
    if (opt) nw.opt = *opt;
    else ctn_model_solve_options(m, &nw.opt);
    ctn_solution *s = NULL;
    double t0 = now();
    if (!(rc = setup(&nw)) &&
        !(rc = ctn_solution_alloc(ctx, m->nodes.n, m->elements.n, nw.opt.maxit, &s)) &&
        (s->sum.t_setup = now() - t0, !(rc = iterate(&nw, s)))) {
        finish(&nw, s);
        *out = s;
        s = NULL;
    }
    ctn_solution_destroy(&s);
    teardown(&nw);
    return rc;
}
