/* Linear algebra at scale (issue 10):
 * - conjugate gradients preconditioned by the Cholesky factor of a nearby matrix solve
 *   a system to round-off, checked against CHOLMOD's direct solve and the residual;
 * - reuse of the last factorization once Newton converges quadratically: the same
 *   equilibrium as factoring every iteration (both checked by their residual), fewer
 *   factorizations, and pure Newton still factors once per iteration;
 * - orderings: natural, AMD and METIS give the same equilibrium; `auto` keeps the one
 *   with the fewest flops (natural within 10 %) and says which; a chain keeps natural;
 * - threads and the BLAS are reported. */
#include "catena.h"
#include "check.h"
#include "linalg/backends/cholmod/chol.h"
#include "linalg/linsolve.h"
#include "linalg/pcg.h"

#include <stdlib.h>

/* A K x K hypar net (bench/hypar_net.py --issue10) as model text. */
static char *net_text(int k, const char *solve_line)
{
    size_t cap = 256 + (size_t)(k + 1) * (size_t)(k + 1) * 200, len = 0;
    char *t = malloc(cap);
    if (!t) return NULL;
    double h = 100.0 / k;
    len += (size_t)snprintf(t + len, cap - len, "units kN m\nmaterial strand E=1.6e8\nsection s material=strand A=1.5e-4\n");
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++) {
            double x = -50 + i * h, y = -50 + j * h;
            int fix = i == 0 || i == k || j == 0 || j == k;
            len += (size_t)snprintf(t + len, cap - len, "node %d %.17g %.17g %.17g%s\n", i * (k + 1) + j + 1, x, y,
                                    10 * (x * x - y * y) / 2500.0, fix ? " fix=xyz" : "");
        }
    int e = 1;
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++)
            for (int dir = 0; dir < 2; dir++) {
                int di = dir == 0, dj = dir == 1;
                if (i + di > k || j + dj > k) continue;
                if (((i == 0 || i == k) && di == 0) || ((j == 0 || j == k) && dj == 0)) continue;
                len += (size_t)snprintf(t + len, cap - len, "element %d %d %d section=s eps0=2e-3\n", e++,
                                        i * (k + 1) + j + 1, (i + di) * (k + 1) + j + dj + 1);
            }
    for (int i = 1; i < k; i++)
        for (int j = 1; j < k; j++)
            len += (size_t)snprintf(t + len, cap - len, "load %d 0 0 %.17g\n", i * (k + 1) + j + 1, -0.2 * h * h);
    snprintf(t + len, cap - len, "%s\n", solve_line);
    return t;
}

typedef struct run {
    ctn_solve_summary sum;
    double *d;              /* displacements, 3 per node (owned) */
    size_t n3;
} run;

static int solve_text(const char *text, run *r)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    memset(r, 0, sizeof *r);
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "net.cable", text, strlen(text), &m, &opt);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (s) {
        ctn_solution_summary(s, &r->sum);
        r->n3 = 3 * ctn_model_node_count(m);
        r->d = malloc(r->n3 * sizeof(double));
        if (r->d) memcpy(r->d, ctn_solution_displacements(s), r->n3 * sizeof(double));
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return rc == CTN_OK && r->d;
}

/* max |a - b| / max |a| */
static double rel_diff(const run *a, const run *b)
{
    double dm = 0, am = 0;
    for (size_t i = 0; i < a->n3; i++) {
        dm = fmax(dm, fabs(a->d[i] - b->d[i]));
        am = fmax(am, fabs(a->d[i]));
    }
    return am > 0 ? dm / am : dm;
}

static int converged(const run *r, double tol)
{
    return r->sum.reason == CTN_CONVERGED && r->sum.residual <= tol * r->sum.fext_norm;
}

typedef struct op {
    const ctn_pattern *p;
    const double *A;
    ctn_linsolve *M;
} op;

static int op_apply(void *data, const double *x, double *y)
{
    const op *o = data;
    ctn_sym_matvec(o->p, o->A, x, y);
    return CTN_OK;
}

static int op_precond(void *data, const double *x, double *y)
{
    const op *o = data;
    return ctn_linsolve_solve(o->M, x, y);
}

/* A tridiagonal SPD matrix A (upper triangle by columns), solved by CG preconditioned by
 * the factor of a neighbour B = A + 0.3 I: the direct solution of A, to round-off. */
static void test_pcg(void)
{
    enum { N = 40 };
    int colptr[N + 1], rowind[2 * N], nz = 0;
    double A[2 * N], B[2 * N], b[N], x[N], y[N], xd[N], work[4 * N];
    for (int j = 0; j < N; j++) {
        colptr[j] = nz;
        if (j > 0) { rowind[nz] = j - 1; A[nz] = B[nz] = -1.0; nz++; }
        rowind[nz] = j; A[nz] = 2.0 + 0.01 * j; B[nz] = A[nz] + 0.3; nz++;
        b[j] = sin(0.3 * j) + 1;
    }
    colptr[N] = nz;
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_pattern pat = { N, colptr, rowind };
    ctn_linsolve *exact = NULL, *near = NULL;
    ctn_factor_info info;
    CHECK(ctn_linsolve_create(ctx, "cholmod", &pat, CTN_LA_ORDER_AUTO, &exact) == CTN_OK);
    CHECK(ctn_linsolve_create(ctx, "cholmod", &pat, CTN_LA_ORDER_AUTO, &near) == CTN_OK);
    if (exact && near) {
        CHECK(ctn_linsolve_factor(exact, A, 0, &info) == CTN_OK && info.ok);
        CHECK(ctn_linsolve_factor(near, B, 0, &info) == CTN_OK && info.ok);
        CHECK(ctn_linsolve_solve(exact, b, xd) == CTN_OK);
        ctn_sym_matvec(&pat, A, xd, y);                   /* the product on the pattern */
        double r = 0, bn = 0, e = 0, xn = 0;
        for (int i = 0; i < N; i++) { r += (y[i] - b[i]) * (y[i] - b[i]); bn += b[i] * b[i]; }
        CHECK_MSG(sqrt(r) <= 1e-13 * sqrt(bn), "A x_direct - b: %g", sqrt(r));
        double y0[N], y1[N], y2[N];                        /* two at once: the same bits */
        ctn_sym_matvec(&pat, A, b, y2);
        ctn_sym_matvec2(&pat, A, xd, b, y0, y1);
        CHECK(!memcmp(y0, y, sizeof y) && !memcmp(y1, y2, sizeof y2));
        op o = { &pat, A, near };
        ctn_pcg g = { .apply = op_apply, .precond = op_precond, .data = &o };
        ctn_pcg_init(&g, N, work);
        double res;
        int its, posdef;
        CHECK(ctn_pcg_solve(&g, b, x, 1e-13 * sqrt(bn), 50, &res, &its, &posdef) == CTN_OK);
        for (int i = 0; i < N; i++) { e += (x[i] - xd[i]) * (x[i] - xd[i]); xn += xd[i] * xd[i]; }
        CHECK_MSG(posdef && res <= 1e-13 * sqrt(bn) && its < 20, "res %g after %d", res, its);
        CHECK_MSG(sqrt(e) <= 1e-12 * sqrt(xn), "|x_cg - x_direct| / |x| = %g", sqrt(e / xn));
        for (int i = 0; i < nz; i++) B[i] = -A[i];        /* negative definite: stopped */
        CHECK(ctn_pcg_solve(&g, b, x, 0, 50, &res, &its, &posdef) == CTN_OK);
        o.A = B;
        CHECK(ctn_pcg_solve(&g, b, x, 0, 50, &res, &its, &posdef) == CTN_OK && !posdef);
    }
    ctn_linsolve_destroy(&exact);
    ctn_linsolve_destroy(&near);
    ctn_ctx_destroy(&ctx);
}

/* The net with and without reuse, and by pure Newton. */
static void test_reuse(void)
{
    static const char *lines[] = { "solve tol=1e-10", "solve tol=1e-10 reuse=off", "solve tol=1e-10 method=newton" };
    run r[3];
    int ok = 1;
    for (int i = 0; i < 3; i++) {
        char *t = net_text(30, lines[i]);
        ok &= t && solve_text(t, &r[i]);
        free(t);
    }
    if (ok) {
        for (int i = 0; i < 3; i++) CHECK_MSG(converged(&r[i], 1e-10), "%s: %s", lines[i], ctn_reason_name(r[i].sum.reason));
        CHECK_MSG(r[0].sum.reused > 0 && r[0].sum.factorizations < r[1].sum.factorizations,
                  "reuse: %d factorizations (%d reused) against %d", r[0].sum.factorizations, r[0].sum.reused,
                  r[1].sum.factorizations);
        CHECK(r[0].sum.iterations == r[1].sum.iterations);           /* Newton's steps, to round-off */
        CHECK(r[1].sum.reused == 0 && r[1].sum.factorizations == r[1].sum.iterations);
        CHECK(r[2].sum.reused == 0 && r[2].sum.factorizations == r[2].sum.iterations);
        CHECK_MSG(rel_diff(&r[1], &r[0]) < 1e-9 && rel_diff(&r[1], &r[2]) < 1e-9, "%g %g", rel_diff(&r[1], &r[0]),
                  rel_diff(&r[1], &r[2]));
        CHECK(r[0].sum.stable == 1);      /* checked by a factorization of its own tangent */
    }
    for (int i = 0; i < 3; i++) free(r[i].d);
}

/* Every ordering: the same equilibrium; auto keeps the fewest flops. */
static void test_orderings(void)
{
    static const char *lines[] = { "solve ordering=natural", "solve ordering=amd", "solve ordering=metis", "solve" };
    static const ctn_ordering want[] = { CTN_ORDER_NATURAL, CTN_ORDER_AMD, CTN_ORDER_METIS };
    run r[4];
    int ok = 1;
    for (int i = 0; i < 4; i++) {
        char *t = net_text(30, lines[i]);
        ok &= t && solve_text(t, &r[i]);
        free(t);
    }
    if (ok) {
        double best = INFINITY;
        for (int i = 0; i < 3; i++) {
            CHECK(converged(&r[i], 1e-10) && r[i].sum.ordering == want[i] && r[i].sum.flops_factor > 0);
            CHECK_MSG(rel_diff(&r[0], &r[i]) < 1e-9, "%s: %g", lines[i], rel_diff(&r[0], &r[i]));
            best = fmin(best, r[i].sum.flops_factor);
        }
        CHECK(r[3].sum.ordering != CTN_ORDER_AUTO && r[3].sum.flops_factor <= 1.1 * best);
        CHECK(r[1].sum.flops_factor < r[0].sum.flops_factor);     /* a net fills in natural order */
        CHECK(r[3].sum.threads >= 1 && r[3].sum.blas[0] && strcmp(r[3].sum.blas, "none"));
        CHECK(!strcmp(ctn_ordering_name(CTN_ORDER_METIS), "metis") && !strcmp(ctn_ordering_name((ctn_ordering)9), "?"));
    }
    for (int i = 0; i < 4; i++) free(r[i].d);
    run c;                                                       /* a chain: no fill */
    const char *chain = "material steel E=2e8\nsection s material=steel A=3e-4 w=0.1\ngravity 0 -1 0\n"
                        "node 1 0 0 0 fix=xyz\nnode 2 100 0 0 fix=xyz\n"
                        "cable 1 2 section=s n=500 length=110\nsolve threads=1\n";
    if (solve_text(chain, &c)) {
        CHECK(c.sum.reason == CTN_CONVERGED && c.sum.ordering == CTN_ORDER_NATURAL && c.sum.threads == 1);
        CHECK(c.sum.nnz_factor == 6 * 499 + 9 * 498);            /* triu(K): no fill */
    }
    free(c.d);
}

/* The quotient graph: supervariables of a pattern given by its upper columns (rows
 * listed), against the grouping worked out by hand. */
static size_t supervariables(int n, const int *const *cols, ctn_chol_quot *q, chol *c)
{
    size_t nz = 0;
    for (int j = 0; j < n; j++)
        for (const int *r = cols[j]; *r >= 0; r++) nz++;
    c->A = cholmod_l_allocate_sparse((size_t)n, (size_t)n, nz, 1, 1, 1, CHOLMOD_PATTERN, &c->cm);
    if (!c->A) return 0;
    SuiteSparse_long *Ap = c->A->p, *Ai = c->A->i;
    nz = 0;
    for (int j = 0; j < n; j++) {
        Ap[j] = (SuiteSparse_long)nz;
        for (const int *r = cols[j]; *r >= 0; r++) Ai[nz++] = *r;
    }
    Ap[n] = (SuiteSparse_long)nz;
    size_t ns = ctn_chol_quotient(c, q) == CTN_OK ? q->ns : 0;
    cholmod_l_free_sparse(&c->A, &c->cm);
    return ns;
}

static void test_quotient(void)
{
    chol c;
    ctn_chol_quot q;
    memset(&c, 0, sizeof c);
    CHECK(ctn_ctx_create(&c.ctx) == CTN_OK);
    cholmod_l_start(&c.cm);
    /* Three nodes in a chain with 3, 2 and 3 free DOFs (columns 0-2, 3-4, 5-7): column 3
     * is column 2 and its diagonal, but column 5 sees DOF 3 and not DOF 2. */
    static const int c0[] = { 0, -1 }, c1[] = { 0, 1, -1 }, c2[] = { 0, 1, 2, -1 }, c3[] = { 0, 1, 2, 3, -1 },
                     c4[] = { 0, 1, 2, 3, 4, -1 }, c5[] = { 3, 4, 5, -1 }, c6[] = { 3, 4, 5, 6, -1 },
                     c7[] = { 3, 4, 5, 6, 7, -1 };
    static const int *const chain[] = { c0, c1, c2, c3, c4, c5, c6, c7 };
    CHECK(supervariables(8, chain, &q, &c) == 3);
    if (q.first) CHECK(q.first[1] == 3 && q.first[2] == 5 && q.first[3] == 8);
    if (q.G) {                                   /* the quotient: a path 0 - 1 - 2 */
        const SuiteSparse_long *Gp = q.G->p, *Gi = q.G->i;
        CHECK(Gp[3] == 5 && Gi[0] == 0 && Gi[1] == 0 && Gi[2] == 1 && Gi[3] == 1 && Gi[4] == 2);
        SuiteSparse_long sperm[3] = { 2, 0, 1 }, perm[8];
        ctn_chol_quotient_expand(&q, sperm, perm);
        CHECK(perm[0] == 5 && perm[2] == 7 && perm[3] == 0 && perm[5] == 2 && perm[6] == 3 && perm[7] == 4);
    }
    ctn_chol_quotient_free(&c, &q);
    /* Column 1 is column 0 and its diagonal, but column 3 sees row 0 alone: no merge. */
    static const int d0[] = { 0, -1 }, d1[] = { 0, 1, -1 }, d2[] = { 1, 2, -1 }, d3[] = { 0, 3, -1 };
    static const int *const apart[] = { d0, d1, d2, d3 };
    CHECK(supervariables(4, apart, &q, &c) == 4 && !q.G);
    ctn_chol_quotient_free(&c, &q);
    cholmod_l_finish(&c.cm);
    ctn_ctx_destroy(&c.ctx);
}

/* A net past the size where AMD is analysed on a second thread beside METIS: `auto`
 * keeps the cheaper of the two, as each analysed alone finds them; the same equilibrium
 * as with AMD alone. */
static void test_parallel_orderings(void)
{
    static const char *lines[] = { "solve ordering=amd tol=1e-10", "solve ordering=metis tol=1e-10", "solve tol=1e-10" };
    run r[3];
    int ok = 1;
    for (int i = 0; i < 3; i++) {
        char *t = net_text(90, lines[i]);
        ok &= t && solve_text(t, &r[i]);
        free(t);
    }
    if (ok) {
        CHECK(r[2].sum.ndof >= 20000);
        double best = fmin(r[0].sum.flops_factor, r[1].sum.flops_factor);
        CHECK_MSG(r[2].sum.flops_factor == best, "auto %g, amd %g, metis %g", r[2].sum.flops_factor,
                  r[0].sum.flops_factor, r[1].sum.flops_factor);
        CHECK(r[2].sum.ordering == (r[0].sum.flops_factor <= r[1].sum.flops_factor ? CTN_ORDER_AMD : CTN_ORDER_METIS));
        CHECK_MSG(converged(&r[2], 1e-10) && rel_diff(&r[0], &r[2]) < 1e-9, "%g", rel_diff(&r[0], &r[2]));
    }
    for (int i = 0; i < 3; i++) free(r[i].d);
}

int main(void)
{
    test_quotient();
    test_parallel_orderings();
    test_pcg();
    test_reuse();
    test_orderings();
    CHECK_DONE();
}
