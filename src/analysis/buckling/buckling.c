/* Linear buckling about a converged state (docs/theory.md, "Linear buckling"): K_T at
 * the state d of the last step, u' = K_T^-1 f (f that step's total loads), K' = dK_T/
 * dlambda by a central difference of the tangent at d +- h u', and the dense symmetric-
 * definite pencil -K' phi = theta K_T phi (LAPACK dsygv): lambda = 1 + 1/theta, the
 * lowest positive ones kept. Family-agnostic: only the assembled tangent is used, so
 * every element family (bars, cables, springs, beams) buckles without code of its own. */
#include "analysis/analysis.h"
#include "analysis/buckling/buckling.h"
#include "linalg/lapack.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The step along u': h max|u'| is this fraction of the model's size (the bounding-box
 * diagonal), small enough for the O(h^2) error of the difference (1e-10 relative) and
 * large enough for its round-off (eps / 1e-5, 1e-11 relative). */
#define CTN_BUCKLING_STEP 1e-5

/* An error of the buckling analysis at its `buckling` line (or without a place). */
static int buckling_error(const ctn_problem *p, const ctn_buckling_options *o, int code, const char *msg)
{
    if (o->line > 0) return ctn_error_at(p->ctx, code, p->m->file, o->line, "%s", msg);
    return ctn_error(p->ctx, code, "%s", msg);
}

typedef struct bk_work {
    ctn_problem *p;
    const ctn_buckling_options *opt;
    size_t n;                 /* free DOFs */
    double *d, *dh;           /* state: the converged state, a perturbed one */
    double *fs;               /* state: the step's loads */
    double *f, *u;            /* ndof: the loads on the free DOFs, u' = K_T^-1 f */
    double *K0, *K1;          /* nnz: K_T at d, K' */
    double *A, *B;            /* n x n dense: -K' (then U^-T (-K') U^-1 and its reduction
                                 to tridiagonal form), K_T (then U, K_T = U^T U) */
    double *theta;            /* n: the pencil's eigenvalues, ascending */
    double *td, *te, *tau;    /* n: the tridiagonal form (diagonal, off-diagonal) and the
                                 reflectors' factors */
    double *d2, *e2;          /* n: their copies, which dsterf overwrites */
    double *work;             /* dstebz's 4 n, dstein's 5 n, dsytrd's and dormtr's 64 n */
    int *iwork, lwork;        /* 7 n */
    double *w0, *w1;          /* ndof scratch */
} bk_work;

static void bk_free(bk_work *w)
{
    double *v[] = { w->d, w->dh, w->fs, w->f, w->u, w->K0, w->K1, w->A, w->B, w->theta, w->w0, w->w1,
                    w->td, w->te, w->tau, w->d2, w->e2, w->work };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
    ctn_free(w->iwork);
}

static int bk_alloc(bk_work *w)
{
    ctn_problem *p = w->p;
    size_t n = w->n ? w->n : 1, nz = p->a->nnz ? p->a->nnz : 1;
    w->d = ctn_calloc(p->ctx, p->ns, sizeof(double));
    w->dh = ctn_calloc(p->ctx, p->ns, sizeof(double));
    w->fs = ctn_calloc(p->ctx, p->ns, sizeof(double));
    w->f = ctn_calloc(p->ctx, n, sizeof(double));
    w->u = ctn_calloc(p->ctx, n, sizeof(double));
    /* zeroed: the assembly assigns an entry from its first element and adds the others,
     * and leaves an entry of the pattern that no element reaches as it was */
    w->K0 = ctn_calloc(p->ctx, nz, sizeof(double));
    w->K1 = ctn_calloc(p->ctx, nz, sizeof(double));
    w->A = ctn_calloc(p->ctx, n * n, sizeof(double));
    w->B = ctn_calloc(p->ctx, n * n, sizeof(double));
    w->theta = ctn_malloc(p->ctx, n, sizeof(double));
    w->w0 = ctn_malloc(p->ctx, n, sizeof(double));
    w->w1 = ctn_malloc(p->ctx, n, sizeof(double));
    double **t[] = { &w->td, &w->te, &w->tau, &w->d2, &w->e2 };
    for (size_t i = 0; i < sizeof t / sizeof *t; i++) *t[i] = ctn_calloc(p->ctx, n, sizeof(double));
    w->lwork = 64 * (int)n;
    w->work = ctn_malloc(p->ctx, (size_t)w->lwork, sizeof(double));
    w->iwork = ctn_malloc(p->ctx, 10 * n, sizeof(int));
    return w->d && w->dh && w->fs && w->f && w->u && w->K0 && w->K1 && w->A && w->B && w->theta && w->w0 &&
                   w->w1 && w->td && w->te && w->tau && w->d2 && w->e2 && w->work && w->iwork
               ? CTN_OK
               : CTN_ERR_NOMEM;
}

/* Dense (both triangles, column-major) from the pattern's upper triangle, scaled by c. */
static void to_dense(const ctn_problem *p, const double *Kx, double c, double *D)
{
    size_t n = p->ndof;
    memset(D, 0, n * n * sizeof(double));
    for (size_t j = 0; j < n; j++)
        for (int k = p->a->colptr[j]; k < p->a->colptr[j + 1]; k++) {
            size_t i = (size_t)p->a->rowind[k];
            D[i + j * n] = D[j + i * n] = c * Kx[k];
        }
}

/* The loads of the solution's last step on the free DOFs (f) and their norm. All loads
 * of the step count, an hload by its value on the reference projection. */
static double step_loads(bk_work *w, const ctn_solution *s)
{
    ctn_problem *p = w->p;
    size_t nm = ctn_model_step_count(p->m), k = s->nsteps < nm ? s->nsteps - 1 : nm - 1;
    ctn_model_step_loads(p->m, k, p->v3, NULL);
    ctn_dofmap_from3(&p->a->map, p->v3, w->fs);
    if (p->a->map.rot) {
        ctn_model_step_moments(p->m, k, p->v3, NULL);
        ctn_dofmap_rot_from3(&p->a->map, p->v3, w->fs);
    }
    for (size_t i = 0; i < p->ns; i++)
        if (p->a->map.eq[i] >= 0) w->f[p->a->map.eq[i]] = w->fs[i];
    return ctn_layout_norm(&p->eq, w->f);
}

/* Factor K_T (dense Cholesky in B): not positive definite is an error naming the
 * direction that fails; then u' = K_T^-1 f. */
static int path_tangent(bk_work *w)
{
    ctn_problem *p = w->p;
    int n = (int)w->n, one = 1, info = 0;
    to_dense(p, w->K0, 1.0, w->B);
    dpotrf_("U", &n, w->B, &n, &info, 1);
    if (info > 0) {
        char msg[320];
        size_t q = (size_t)info - 1;
        snprintf(msg, sizeof msg, "buckling: the loaded state is not stable (the tangent stiffness is not positive "
                 "definite, first at node %d, direction %s): linear buckling is about a stable state; "
                 "solve to a smaller load", p->m->nodes.v[p->a->map.dof_node[q]].id,
                 ctn_dof_name(p->a->map.dof_dir[q]));
        return buckling_error(p, w->opt, CTN_ERR_MODEL, msg);
    }
    memcpy(w->u, w->f, w->n * sizeof(double));
    dpotrs_("U", &n, &one, w->B, &n, w->u, &n, &info, 1);
    return info ? ctn_error(p->ctx, CTN_ERR_LINALG, "buckling: LAPACK dpotrs failed (info %d)", info) : CTN_OK;
}

/* The tangent's values at d (+) h u' into Kx. */
static int tangent_along(bk_work *w, double h, double *Kx)
{
    ctn_problem *p = w->p;
    memcpy(w->dh, w->d, p->ns * sizeof(double));
    ctn_problem_update(p, w->dh, h, w->u);
    if (ctn_asm_eval(p->a, w->dh, 0, p->fint, Kx, NULL, NULL))
        return buckling_error(p, w->opt, CTN_ERR_MODEL, "buckling: an element collapses along the load path's "
                              "tangent u' = K_T^-1 f (no finite difference of the tangent)");
    return CTN_OK;
}

/* K' = (K_T(d + h u') - K_T(d - h u')) / 2h; *h the step used. */
static int tangent_rate(bk_work *w, ctn_buckling_summary *sum)
{
    ctn_problem *p = w->p;
    double umax = 0;
    for (size_t q = 0; q < w->n; q++) umax = fmax(umax, fabs(w->u[q]));
    umax = ctn_layout_max(&p->eq, umax);
    double scale = p->lref > 0 ? p->lref : 1.0, h = CTN_BUCKLING_STEP * scale / umax;
    if (!(umax > 0) || !isfinite(h))
        return buckling_error(p, w->opt, CTN_ERR_MODEL, "buckling: the step's loads do not move the structure "
                              "(K_T^-1 f is zero or not finite)");
    sum->h = h;
    int rc = tangent_along(w, h, w->K1);
    if (!rc) rc = tangent_along(w, -h, p->Kx);
    if (rc) return rc;
    for (size_t k = 0; k < p->a->nnz; k++) w->K1[k] = (w->K1[k] - p->Kx[k]) / (2 * h);
    return CTN_OK;
}

/* theta ascending: -K' phi = theta K_T phi with K_T = U^T U (U in B, path_tangent's):
 * the standard problem U^-T (-K') U^-1 z = theta z (dsygst), reduced to tridiagonal form
 * (dsytrd; the reflectors stay in A), its eigenvalues (dsterf). Only the eigenvectors
 * asked for are computed later (vectors()): the tridiagonal reduction is the cost,
 * 4/3 n^3, where dsygv's full eigenvector set costs several times more. */
static int pencil(bk_work *w)
{
    int n = (int)w->n, itype = 1, info = 0;
    to_dense(w->p, w->K1, -1.0, w->A);
    dsygst_(&itype, "U", &n, w->A, &n, w->B, &n, &info, 1);
    if (!info) dsytrd_("U", &n, w->A, &n, w->td, w->te, w->tau, w->work, &w->lwork, &info, 1);
    if (info) return ctn_error(w->p->ctx, CTN_ERR_LINALG, "buckling: LAPACK's reduction failed (info %d)", info);
    memcpy(w->theta, w->td, w->n * sizeof(double));
    memcpy(w->e2, w->te, w->n * sizeof(double));
    dsterf_(&n, w->theta, w->e2, &info);
    return info ? ctn_error(w->p->ctx, CTN_ERR_LINALG, "buckling: LAPACK dsterf failed (info %d)", info) : CTN_OK;
}

/* The eigenvectors of the pencil for the count eigenvalues theta[col[k]] into Z (n x
 * count): each of the tridiagonal form by bisection and inverse iteration (dstebz,
 * dstein), then z <- Q z (dormtr), phi = U^-1 z. */
static int vectors(bk_work *w, const int *col, int count, double *Z)
{
    int n = (int)w->n, info = 0, m = 0, nsplit = 0, one = 1, ifail = 0;
    int *iblock = w->iwork, *isplit = w->iwork + n, *iw = w->iwork + 2 * n;     /* n, n, 5 n */
    double vl = 0, vu = 0, abstol = 0, th;
    for (int k = 0; k < count && !info; k++) {
        int idx = col[k] + 1;
        dstebz_("I", "B", &n, &vl, &vu, &idx, &idx, &abstol, w->td, w->te, &m, &nsplit, &th, iblock, isplit,
                w->work, iw, &info, 1, 1);
        if (!info && m != 1) info = -100;
        if (!info) dstein_(&n, w->td, w->te, &one, &th, iblock, isplit, Z + (size_t)n * (size_t)k, &n, w->work, iw,
                           &ifail, &info);
    }
    if (!info) dormtr_("L", "U", "N", &n, &count, w->A, &n, w->tau, Z, &n, w->work, &w->lwork, &info, 1, 1, 1);
    if (info) return ctn_error(w->p->ctx, CTN_ERR_LINALG, "buckling: LAPACK's eigenvectors failed (info %d)", info);
    double alpha = 1.0;
    dtrsm_("L", "U", "N", "N", &n, &count, &alpha, w->B, &n, Z, &n, 1, 1, 1, 1);
    return CTN_OK;
}

typedef struct bk_pick {
    double lambda;
    int col;
} bk_pick;

static int by_lambda(const void *a, const void *b)
{
    double x = ((const bk_pick *)a)->lambda, y = ((const bk_pick *)b)->lambda;
    return (x > y) - (x < y);
}

/* The positive factors lambda = 1 + 1/theta, ascending, into pick; their count. A theta
 * within the round-off of the largest is no buckling (lambda beyond resolution). */
static size_t factors(const bk_work *w, bk_pick *pick)
{
    double tmax = 0;
    size_t np = 0;
    for (size_t i = 0; i < w->n; i++) tmax = fmax(tmax, fabs(w->theta[i]));
    for (size_t i = 0; i < w->n; i++) {
        double th = w->theta[i], lam = 1.0 + 1.0 / th;
        if (!(fabs(th) > 64 * DBL_EPSILON * tmax) || !isfinite(lam) || !(lam > 0)) continue;
        pick[np].lambda = lam;
        pick[np++].col = (int)i;
    }
    qsort(pick, np, sizeof *pick, by_lambda);
    return np;
}

/* One mode: the residual of K(lambda) phi, the shape (3 per node, largest |component|
 * 1 and positive), the node that moves most. */
static void describe(bk_work *w, double lam, double *phi, ctn_buckling_mode *out, double *shape)
{
    ctn_problem *p = w->p;
    size_t n = w->n, nn = p->m->nodes.n;
    ctn_problem_symv(p, w->K0, phi, w->w0);
    ctn_problem_symv(p, w->K1, phi, w->w1);
    double a = ctn_layout_norm(&p->eq, w->w0), b = fabs(lam - 1) * ctn_layout_norm(&p->eq, w->w1);
    for (size_t q = 0; q < n; q++) w->w0[q] += (lam - 1) * w->w1[q];
    out->factor = lam;
    out->residual = a + b > 0 ? ctn_layout_norm(&p->eq, w->w0) / (a + b) : 0;
    memset(w->dh, 0, p->ns * sizeof(double));
    ctn_problem_axpy(p, w->dh, 1.0, phi);
    ctn_dofmap_to3(&p->a->map, w->dh, shape);
    size_t imax = 0, inode = 0;
    double amax = 0, nmax = -1;
    for (size_t i = 0; i < 3 * nn; i++)
        if (fabs(shape[i]) > amax) { amax = fabs(shape[i]); imax = i; }
    for (size_t i = 0; i < nn; i++) {
        const double *v = shape + 3 * i;
        double s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (s > nmax) { nmax = s; inode = i; }
    }
    if (amax > 0) {
        double c = (shape[imax] < 0 ? -1.0 : 1.0) / amax;
        for (size_t i = 0; i < 3 * nn; i++) shape[i] *= c;
    } else {                                 /* rotations only: the node of the largest */
        size_t qmax = 0;
        for (size_t q = 1; q < n; q++)
            if (fabs(phi[q]) > fabs(phi[qmax])) qmax = q;
        inode = (size_t)p->a->map.dof_node[qmax];
    }
    out->node = p->m->nodes.v[inode].id;
}

int ctn_buckling_check(ctn_problem *p, const ctn_buckling_options *o)
{
    char msg[256];
    if (p->ndof > CTN_BUCKLING_MAX_DOFS) {
        snprintf(msg, sizeof msg, "buckling: the model has %zu free DOFs, more than the %d the dense buckling "
                 "analysis takes (CTN_BUCKLING_MAX_DOFS)", p->ndof, CTN_BUCKLING_MAX_DOFS);
        return buckling_error(p, o, CTN_ERR_MODEL, msg);
    }
    if ((size_t)o->count > p->ndof) {
        snprintf(msg, sizeof msg, "buckling: count=%d is more than the %zu free DOFs", o->count, p->ndof);
        return buckling_error(p, o, CTN_ERR_MODEL, msg);
    }
    return CTN_OK;
}

static int bk_solve(bk_work *w, const ctn_solution *s, ctn_buckling_summary *sum)
{
    ctn_problem *p = w->p;
    int rc = ctn_problem_tangent_at(p, s, w->d, "buckling");
    if (rc) return rc;
    memcpy(w->K0, p->Kx, p->a->nnz * sizeof(double));
    sum->load_norm = step_loads(w, s);
    if (!(sum->load_norm > 0))
        return buckling_error(p, w->opt, CTN_ERR_MODEL, "buckling: the last step has no loads on free DOFs: "
                              "there is no load to find a factor of");
    rc = path_tangent(w);
    if (!rc) rc = tangent_rate(w, sum);
    if (!rc) rc = pencil(w);
    return rc;
}

int ctn_problem_buckling(ctn_problem *p, ctn_solution *s, const ctn_buckling_options *options)
{
    if (!p || !s || !options) return p ? ctn_error(p->ctx, CTN_ERR_INVALID, "ctn_problem_buckling: bad arguments") : CTN_ERR_INVALID;
    ctn_buckling_options opt;
    int rc = ctn_buckling_options_take(p->ctx, &opt, options);
    if (rc) return rc;
    if (opt.count < 1) return ctn_error(p->ctx, CTN_ERR_INVALID, "buckling: count must be >= 1 (got %d)", opt.count);
    if (s->sum.reason != CTN_CONVERGED || !s->nsteps)
        return ctn_error(p->ctx, CTN_ERR_INVALID, "buckling: the solution did not converge");
    if ((rc = ctn_buckling_check(p, &opt))) return rc;
    double t0 = ctn_clock();
    bk_work w;
    memset(&w, 0, sizeof w);
    w.p = p;
    w.opt = &opt;
    w.n = p->ndof;
    ctn_problem_settle(p);
    ctn_buckling_summary sum;
    memset(&sum, 0, sizeof sum);
    sum.asked = opt.count;
    sum.ndof = (int)w.n;
    bk_pick *pick = NULL;
    ctn_buckles *res = NULL;
    int *col = NULL;
    double *Z = NULL;
    rc = bk_alloc(&w);
    if (!rc && !(pick = ctn_malloc(p->ctx, w.n ? w.n : 1, sizeof *pick))) rc = CTN_ERR_NOMEM;
    if (!rc) rc = bk_solve(&w, s, &sum);
    size_t np = rc ? 0 : factors(&w, pick), count = np < (size_t)opt.count ? np : (size_t)opt.count;
    if (!rc && !(res = ctn_buckles_create(p->ctx, count, p->m->nodes.n))) rc = CTN_ERR_NOMEM;
    if (!rc && count) {
        col = ctn_malloc(p->ctx, count, sizeof *col);
        Z = ctn_malloc(p->ctx, w.n * count, sizeof *Z);
        if (!col || !Z) rc = CTN_ERR_NOMEM;
        for (size_t k = 0; !rc && k < count; k++) col[k] = pick[k].col;
        if (!rc) rc = vectors(&w, col, (int)count, Z);
    }
    for (size_t k = 0; !rc && k < count; k++)
        describe(&w, pick[k].lambda, Z + w.n * k, &res->mode[k], res->shapes + 3 * p->m->nodes.n * k);
    if (!rc && opt.check && count)           /* the non-linear check, from the first mode */
        rc = ctn_buckling_nonlinear(p, s, w.d, w.fs, w.K0, Z, pick[0].lambda, opt.line, &sum);
    if (w.d && !rc) {                        /* the tangent at the solution again */
        ctn_asm_eval(p->a, w.d, 0, p->fint, p->Kx, NULL, NULL);
    }
    if (!rc) {
        sum.count = (int)count;
        sum.t_total = ctn_clock() - t0;
        res->sum = sum;
        ctn_buckles_destroy(&s->buckling);
        s->buckling = res;
    }
    if (rc) ctn_buckles_destroy(&res);
    ctn_free(pick);
    ctn_free(col);
    ctn_free(Z);
    bk_free(&w);
    return rc;
}

/* The analysis object: the buckling factors about the solution's last step, stored in it. */
static void bk_defaults(const ctn_problem *p, void *opt)
{
    (void)p;
    ctn_buckling_options_default(opt);
}

static int bk_options_check(ctn_problem *p, const void *opt)
{
    const ctn_buckling_options *o = opt;
    if (o->count < 1) return ctn_error(p->ctx, CTN_ERR_INVALID, "buckling analysis: count must be >= 1 (got %d)", o->count);
    return CTN_OK;
}

static int bk_run(ctn_problem *p, const void *opt, ctn_solution **s) { return ctn_problem_buckling(p, *s, opt); }

const ctn_analysis_ops ctn_analysis_buckling = {
    "buckling", sizeof(ctn_buckling_options), 1, bk_defaults, bk_options_check, bk_run,
};
