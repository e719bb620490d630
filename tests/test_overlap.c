/* The assembly overlapped with the factorization (solve/overlap.c, linalg/cholmod_feed.c):
 * - on a chain of 36 000 DOFs, at a state off the equilibrium: the internal forces, the
 *   tangent, the energy, the factorization's outcome and the solution are those of
 *   ctn_asm_eval then ctn_linsolve_factor, to the bit;
 * - with shifts that make the matrix indefinite: the same failing pivot's column; a
 *   factorization after a failed one is whole again;
 * - a collapsed element: reported as the same element, the factorization's thread ends;
 * - a factorization started and then not wanted (before, during and after its
 *   assembly) stops, and the next one is whole;
 * - only a simplicial factor in the natural ordering, already factorized, is followed
 *   (not an AMD one, not before the first factorization); small models are not;
 * - pure Newton solves the chain to the same bits with the overlap (default threads)
 *   and without it (threads=1), in the same iterations, one factorization each (the
 *   converged state's, started beside its assembly, is dropped). */
#include "problem/problem.h"
#include "catena.h"
#include "chain_model.h"
#include "check.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define ELEMENTS 12000              /* 35 997 DOFs: above CTN_OVERLAP_MIN_DOF */

typedef struct rig {
    ctn_model *m;
    ctn_asm *a;
    ctn_linsolve *seq, *ovl;        /* the plain path's solver and the overlap's */
    double *d, *f1, *f2, *K1, *K2, *x1, *x2;
} rig;

/* The chain, a state near its equilibrium (perturbed), two solvers factorized once. */
static int rig_open(ctn_ctx *ctx, rig *r)
{
    memset(r, 0, sizeof *r);
    ctn_solution *s = NULL;
    if (!(r->m = chain_model(ctx, ELEMENTS)) || ctn_solve(ctx, r->m, NULL, &s) || ctn_asm_create(ctx, r->m, &r->a))
        return 0;
    ctn_pattern pat = { r->a->ndof, r->a->colptr, r->a->rowind };
    size_t ns = r->a->map.nstate, nnz = r->a->nnz;
    r->d = calloc(ns, sizeof(double));
    r->f1 = calloc(ns, sizeof(double));
    r->f2 = calloc(ns, sizeof(double));
    r->K1 = calloc(nnz, sizeof(double));
    r->K2 = calloc(nnz, sizeof(double));
    r->x1 = calloc(r->a->ndof, sizeof(double));
    r->x2 = calloc(r->a->ndof, sizeof(double));
    int ok = r->d && r->f1 && r->f2 && r->K1 && r->K2 && r->x1 && r->x2 &&
             !ctn_linsolve_create(ctx, "cholmod", &pat, CTN_ORDER_NATURAL, &r->seq) &&
             !ctn_linsolve_create(ctx, "cholmod", &pat, CTN_ORDER_NATURAL, &r->ovl);
    if (ok) {
        ctn_dofmap_from3(&r->a->map, ctn_solution_displacements(s), r->d);
        for (size_t i = 0; i < ns; i++)
            if (r->a->map.eq[i] >= 0) r->d[i] += 1e-7 * ((double)(i % 7) - 3);
        CHECK(!ctn_linsolve_feedable(r->ovl));       /* nothing factorized yet */
        ctn_factor_info info;
        ok = !ctn_asm_eval(r->a, r->d, 0, r->f1, r->K1, NULL, NULL) &&
             !ctn_linsolve_factor(r->seq, r->K1, 0.0, &info) && !ctn_linsolve_factor(r->ovl, r->K1, 0.0, &info);
        CHECK(ok && info.ok && ctn_linsolve_feedable(r->ovl));
    }
    ctn_solution_destroy(&s);
    return ok;
}

static void rig_close(rig *r)
{
    ctn_linsolve_destroy(&r->seq);
    ctn_linsolve_destroy(&r->ovl);
    ctn_asm_destroy(&r->a);
    ctn_model_destroy(&r->m);
    free(r->d); free(r->f1); free(r->f2); free(r->K1); free(r->K2); free(r->x1); free(r->x2);
}

/* Both paths at d with the shift: the same results to the bit. The failing pivot's
 * column, -1 if none. */
static long compare(rig *r, double shift, const char *what)
{
    ctn_factor_info i1, i2;
    double U1 = 0, U2 = 0;
    size_t ns = r->a->map.nstate, nnz = r->a->nnz, n = r->a->ndof, b1 = 0, b2 = 0;
    int c2 = 1;
    memset(r->f2, 0, ns * sizeof(double));
    memset(r->K2, 0, nnz * sizeof(double));
    int c1 = ctn_asm_eval(r->a, r->d, 0, r->f1, r->K1, &U1, &b1);
    int rc1 = ctn_linsolve_factor(r->seq, r->K1, shift, &i1);
    int rc2 = ctn_overlap_eval_factor(r->a, r->ovl, r->d, 0, r->f2, r->K2, shift, &U2, &b2, &c2, &i2);
    CHECK_MSG(!rc1 && !rc2 && !c1 && !c2, "%s", what);
    CHECK_MSG(!memcmp(r->f1, r->f2, ns * sizeof(double)) && !memcmp(r->K1, r->K2, nnz * sizeof(double)), "%s", what);
    CHECK_MSG(U1 == U2, "%s: energy %.17g against %.17g", what, U2, U1);
    CHECK_MSG(i1.ok == i2.ok && i1.fail_col == i2.fail_col, "%s: ok %d / %d, pivot %ld / %ld", what, i2.ok, i1.ok,
              i2.fail_col, i1.fail_col);
    if (!i1.ok || !i2.ok) return i1.fail_col;
    for (size_t i = 0; i < n; i++) r->x1[i] = r->x2[i] = 1.0 + (double)(i % 5);
    CHECK(!ctn_linsolve_solve(r->seq, r->x1, r->x1) && !ctn_linsolve_solve(r->ovl, r->x2, r->x2));
    CHECK_MSG(!memcmp(r->x1, r->x2, n * sizeof(double)), "%s: the solutions differ", what);
    return -1;
}

static void test_same_bits(ctn_ctx *ctx)
{
    rig r;
    if (!rig_open(ctx, &r)) {
        CHECK(!"the chain's rig");
        rig_close(&r);
        return;
    }
    CHECK(ctn_overlap_possible(r.a, r.ovl) == (sysconf(_SC_NPROCESSORS_ONLN) >= 2));
    compare(&r, 0.0, "no shift");
    double dmax = 0, dmin = HUGE_VAL;
    for (size_t c = 0; c < r.a->ndof; c++) {
        double kd = r.K1[r.a->colptr[c + 1] - 1];
        dmax = fmax(dmax, kd);
        dmin = fmin(dmin, kd);
    }
    compare(&r, -2 * dmax, "shifted below every pivot: the first fails");
    compare(&r, -0.5 * (dmin + dmax), "shifted into the pivots");
    long deepest = -1;                                /* the pivots fall along the chain: */
    for (double f = 1e-3; f > 1e-8; f *= 0.1) {       /* smaller shifts fail further on */
        long col = compare(&r, -f * dmin, "a small shift");
        if (col > deepest) deepest = col;
    }
    CHECK_MSG(deepest > 20000, "the deepest failing pivot: %ld", deepest);   /* past a few blocks of rows */
    compare(&r, 0.0, "after failures, no shift");

    ctn_overlap o;                                    /* started, then not wanted */
    for (int k = 0; k < 3; k++) {
        CHECK(ctn_overlap_start(&o, r.a, r.ovl, r.K2, 0.0));
        if (k > 0) CHECK(!ctn_overlap_assemble(&o, r.a, r.d, 0, r.f2, r.K2, NULL, NULL));
        if (k == 2) ctn_feed_publish(&o.feed, r.a->ndof / 2);
        ctn_overlap_abandon(&o);
        CHECK(!o.running);
    }
    compare(&r, 0.0, "after abandoned factorizations");

    size_t q = r.a->nn / 3, b1 = 0;                   /* a node onto its neighbour */
    for (int j = 0; j < 3; j++) r.d[3 * q + (size_t)j] += r.m->nodes.v[q + 1].X[j] - r.m->nodes.v[q].X[j] +
                                                          r.d[3 * (q + 1) + (size_t)j] - r.d[3 * q + (size_t)j];
    size_t b2 = 0;
    int c2 = 0;
    ctn_factor_info info;
    CHECK(ctn_asm_eval(r.a, r.d, 0, r.f1, r.K1, NULL, &b1) == 1);
    CHECK(!ctn_overlap_eval_factor(r.a, r.ovl, r.d, 0, r.f2, r.K2, 0.0, NULL, &b2, &c2, &info) && c2 && b2 == b1);
    rig_close(&r);
}

/* An AMD-ordered factor, and a small model: not followed. */
static void test_not_followed(ctn_ctx *ctx)
{
    ctn_model *m = chain_model(ctx, ELEMENTS);
    ctn_asm *a = NULL;
    ctn_linsolve *ls = NULL;
    CHECK(m && !ctn_asm_create(ctx, m, &a));
    double *K = a ? calloc(a->nnz, sizeof(double)) : NULL, *f = a ? calloc(a->map.nstate, sizeof(double)) : NULL,
           *d = a ? calloc(a->map.nstate, sizeof(double)) : NULL;
    if (K && f && d) {
        ctn_pattern pat = { a->ndof, a->colptr, a->rowind };
        ctn_factor_info info;
        CHECK(!ctn_linsolve_create(ctx, "cholmod", &pat, CTN_ORDER_AMD, &ls));
        CHECK(!ctn_asm_eval(a, d, 0, f, K, NULL, NULL) && !ctn_linsolve_factor(ls, K, 0.0, &info));
        CHECK(!ctn_linsolve_feedable(ls) && !ctn_overlap_possible(a, ls));
    }
    free(K); free(f); free(d);
    ctn_linsolve_destroy(&ls);
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
}

/* Pure Newton with the overlap (default) and without (threads=1): the same bits. */
static void test_solve(ctn_ctx *ctx)
{
    ctn_model *m = chain_model(ctx, ELEMENTS);
    ctn_solution *s[2] = { NULL, NULL };
    ctn_solve_summary sum[2];
    for (int k = 0; k < 2 && m; k++) {
        ctn_solve_options opt;
        ctn_solve_options_default(&opt);
        opt.method = CTN_METHOD_NEWTON;
        opt.threads = k ? 1 : 0;
        CHECK(!ctn_solve(ctx, m, &opt, &s[k]));
        if (s[k]) ctn_solution_summary(s[k], &sum[k]);
    }
    if (s[0] && s[1]) {
        size_t n = 3 * m->nodes.n;
        CHECK(!memcmp(ctn_solution_displacements(s[0]), ctn_solution_displacements(s[1]), n * sizeof(double)));
        CHECK(sum[0].reason == CTN_CONVERGED && sum[1].reason == CTN_CONVERGED);
        CHECK(sum[0].iterations == sum[1].iterations);
        for (int k = 0; k < 2; k++)                   /* the paper's: one per iteration */
            CHECK_MSG(sum[k].factorizations == sum[k].iterations, "%d factorizations in %d iterations",
                      sum[k].factorizations, sum[k].iterations);
        CHECK(sum[0].stable == 1 && sum[1].stable == 1);
    }
    ctn_solution_destroy(&s[0]);
    ctn_solution_destroy(&s[1]);
    ctn_model_destroy(&m);
}

/* The problem's path: the residual with K starts the factorization (once a first one has
 * allocated the factor), ctn_problem_factor waits for it, a residual without it or a
 * settle drops it; threads=1 never starts one. */
static void test_problem(ctn_ctx *ctx)
{
    ctn_model *m = chain_model(ctx, ELEMENTS);
    int two = sysconf(_SC_NPROCESSORS_ONLN) >= 2;
    for (int threads = 0; threads < 2 && m; threads++) {
        ctn_solve_options opt;
        ctn_solve_options_default(&opt);
        opt.method = CTN_METHOD_NEWTON;
        opt.threads = threads;
        ctn_problem *p = NULL;
        ctn_solution *s = NULL;
        CHECK(!ctn_problem_create(ctx, m, &opt, &p) && !ctn_solution_create(ctx, m->nodes.n, m->elements.n, &s));
        if (!p || !s) break;
        CHECK(p->overlap == !threads);
        double *d = calloc(p->ns, sizeof(double)), rn = 0;
        int valid = 0, ok = 0;
        long col = -1;
        p->sum = &s->sum;
        ctn_problem_set_t(p, 1.0, d);
        CHECK(!ctn_problem_residual(p, d, 1, &rn, NULL, &valid) && valid && !p->ovl.running);   /* first */
        CHECK(!ctn_problem_factor(p, 0.0, &ok, &col));
        CHECK(!ctn_problem_residual(p, d, 1, &rn, NULL, &valid) && valid && p->ovl.running == (two && !threads));
        int before = s->sum.factorizations;
        CHECK(!ctn_problem_factor(p, 0.0, &ok, &col) && !p->ovl.running && s->sum.factorizations == before + 1);
        CHECK(!ctn_problem_residual(p, d, 1, &rn, NULL, &valid) && valid);
        CHECK(!ctn_problem_residual(p, d, 0, &rn, NULL, &valid) && valid && !p->ovl.running);   /* dropped */
        CHECK(!ctn_problem_residual(p, d, 1, &rn, NULL, &valid) && valid);
        ctn_problem_settle(p);
        CHECK(!p->ovl.running && !p->spd_factor && s->sum.factorizations == before + 1);
        CHECK(!ctn_problem_residual(p, d, 1, &rn, NULL, &valid) && valid);
        free(d);
        p->sum = NULL;
        ctn_problem_destroy(&p);                      /* drops the one still running */
        ctn_solution_destroy(&s);
    }
    ctn_model_destroy(&m);
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    if (ctn_ctx_create(&ctx)) return 1;
    ctn_ctx_set_threads(ctx, 2);                         /* the helper allowed */
    test_same_bits(ctx);
    test_not_followed(ctx);
    test_solve(ctx);
    test_problem(ctx);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
