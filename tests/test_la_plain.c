/* linalg's own options (ctn_la_options) and the CHOLMOD backends with the library's calls
 * in place of catena's kernels (CTN_LA_PLAIN_*, what bench/bench_kernels.c measures):
 * every way solves K x = b to a residual, computed with K itself, at the rounding floor;
 * the analysis by cholmod_l_analyze_p of the same ordering gives catena's node-graph
 * analysis's factor size and flops exactly; options given as NULL, size 0 or an older,
 * shorter struct mean the defaults; the ordering names. K: a g x g grid of nodes of 3
 * DOFs (the grid's Laplacian times an SPD 3 x 3 block, plus the identity), 50 700 DOFs
 * for g = 130, large enough for the solves on two threads (cholmod_psolve.c), and a
 * chain (a path of nodes), whose natural ordering has no fill. */
/* ctest-cost: 20 (about the seconds it takes under ASan: ctest -j starts it early) */
#include "check.h"
#include "linalg/linsolve.h"

#include <stddef.h>
#include <stdlib.h>

typedef struct mat {
    size_t n;
    int *colptr, *rowind;
    double *x;
} mat;

static const double B3[3][3] = { { 4, 1, 0.5 }, { 1, 3, 0.25 }, { 0.5, 0.25, 2 } };

/* Node u's neighbours below it (u - 1 along a row, u - g a row below); g = 0: a chain. */
static int lower_neighbours(int u, int g, int nodes, int nb[2])
{
    int k = 0;
    if (g == 0) {
        if (u > 0) nb[k++] = u - 1;
        return k;
    }
    if (u >= g) nb[k++] = u - g;
    if (u % g) nb[k++] = u - 1;
    (void)nodes;
    return k;
}

static int degree(int u, int g, int nodes)
{
    if (g == 0) return (u > 0) + (u + 1 < nodes);
    int r = u / g, q = u % g;
    return (r > 0) + (r + 1 < g) + (q > 0) + (q + 1 < g);
}

/* The upper triangle of K, columns in order, rows sorted. */
static int build(mat *m, int g, int nodes)
{
    m->n = 3 * (size_t)nodes;
    size_t cap = m->n * 9;
    m->colptr = malloc((m->n + 1) * sizeof *m->colptr);
    m->rowind = malloc(cap * sizeof *m->rowind);
    m->x = malloc(cap * sizeof *m->x);
    if (!m->colptr || !m->rowind || !m->x) return 0;
    size_t nz = 0;
    for (int u = 0; u < nodes; u++) {
        int nb[2], k = lower_neighbours(u, g, nodes, nb);
        if (k == 2 && nb[0] > nb[1]) {
            int t = nb[0];
            nb[0] = nb[1];
            nb[1] = t;
        }
        for (int a = 0; a < 3; a++) {
            m->colptr[3 * u + a] = (int)nz;
            for (int i = 0; i < k; i++)
                for (int b = 0; b < 3; b++) {
                    m->rowind[nz] = 3 * nb[i] + b;
                    m->x[nz++] = -B3[b][a];
                }
            for (int b = 0; b <= a; b++) {
                m->rowind[nz] = 3 * u + b;
                m->x[nz++] = degree(u, g, nodes) * B3[b][a] + (a == b);
            }
        }
    }
    m->colptr[m->n] = (int)nz;
    return 1;
}

static void freemat(mat *m)
{
    free(m->colptr);
    free(m->rowind);
    free(m->x);
}

/* ||K x - b||_inf / (||K||-ish ||x||_inf + ||b||_inf), K symmetric from its upper triangle. */
static double residual(const mat *m, const double *x, const double *b)
{
    double *r = malloc(m->n * sizeof *r), rmax = 0, xmax = 0, bmax = 0, kmax = 0;
    if (!r) return INFINITY;
    for (size_t i = 0; i < m->n; i++) r[i] = -b[i];
    for (size_t j = 0; j < m->n; j++)
        for (int p = m->colptr[j]; p < m->colptr[j + 1]; p++) {
            size_t i = (size_t)m->rowind[p];
            r[i] += m->x[p] * x[j];
            if (i != j) r[j] += m->x[p] * x[i];
            kmax = fmax(kmax, fabs(m->x[p]));
        }
    for (size_t i = 0; i < m->n; i++) {
        rmax = fmax(rmax, fabs(r[i]));
        xmax = fmax(xmax, fabs(x[i]));
        bmax = fmax(bmax, fabs(b[i]));
    }
    free(r);
    return rmax / (kmax * xmax + bmax);
}

/* Create with o, factor, one solve and one 4-column block solve: their residuals. */
static int run(ctn_ctx *ctx, const mat *m, const ctn_la_options *o, const double *B, double *X, double res[2],
               size_t *lnz, double *fl, ctn_la_ordering *ord, int *threads)
{
    ctn_pattern p = { m->n, m->colptr, m->rowind };
    ctn_linsolve *ls = NULL;
    ctn_factor_info info = { 0, -1 };
    int rc = ctn_linsolve_create_opts(ctx, "cholmod", &p, o, &ls);
    if (!rc) rc = ctn_linsolve_factor(ls, m->x, 0.0, &info);
    if (!rc && !info.ok) rc = -1;
    if (!rc) rc = ctn_linsolve_solve(ls, B, X);
    if (!rc) {
        *threads = ctn_linsolve_solve_threads(ls);
        res[0] = residual(m, X, B);
        rc = ctn_linsolve_solve_block(ls, B, X, 4);
    }
    res[1] = 0;
    for (int k = 0; !rc && k < 4; k++) res[1] = fmax(res[1], residual(m, X + k * m->n, B + k * m->n));
    if (!rc) {
        *lnz = ctn_linsolve_factor_nnz(ls);
        *fl = ctn_linsolve_flops(ls);
        *ord = ctn_linsolve_ordering(ls);
    }
    ctn_linsolve_destroy(&ls);
    return rc;
}

static void model(ctn_ctx *ctx, int g, int nodes, int expect_psolve)
{
    mat m = { 0, NULL, NULL, NULL };
    int built = build(&m, g, nodes);
    CHECK(built);
    double *B = malloc(4 * m.n * sizeof *B), *X = malloc(4 * m.n * sizeof *X);
    CHECK(B && X);
    if (!built || !B || !X) {
        freemat(&m);
        free(B);
        free(X);
        return;
    }
    unsigned long s = 7;
    for (size_t i = 0; i < 4 * m.n; i++) {
        s = s * 6364136223846793005UL + 1442695040888963407UL;
        B[i] = (double)(s >> 33) / 4294967296.0 - 0.25;
    }
    static const unsigned masks[] = { 0, CTN_LA_PLAIN_SYMBOLIC, CTN_LA_PLAIN_ORDER, CTN_LA_PLAIN_SOLVE,
                                      CTN_LA_PLAIN_SYMBOLIC | CTN_LA_PLAIN_ORDER | CTN_LA_PLAIN_SOLVE };
    static const ctn_la_ordering ords[] = { CTN_LA_ORDER_AUTO, CTN_LA_ORDER_AMD, CTN_LA_ORDER_METIS };
    for (size_t i = 0; i < sizeof ords / sizeof *ords; i++) {
        size_t lnz0 = 0;
        double fl0 = 0;
        for (size_t k = 0; k < sizeof masks / sizeof *masks; k++) {
            ctn_la_options o = { sizeof o, ords[i], 0, masks[k] };
            double res[2] = { INFINITY, INFINITY }, fl = 0;
            size_t lnz = 0;
            ctn_la_ordering got = CTN_LA_ORDER_AUTO;
            int threads = 0;
            int rc = run(ctx, &m, &o, B, X, res, &lnz, &fl, &got, &threads);
            CHECK_MSG(rc == 0, "g %d ordering %s plain %u: %s", g, ctn_la_ordering_name(ords[i]), masks[k],
                      ctn_ctx_message(ctx));
            CHECK_MSG(res[0] < 1e-14 && res[1] < 1e-14, "g %d ordering %s plain %u: residuals %.3g %.3g", g,
                      ctn_la_ordering_name(ords[i]), masks[k], res[0], res[1]);
            CHECK(got != CTN_LA_ORDER_AUTO);
            if (ords[i] != CTN_LA_ORDER_AUTO) CHECK(got == ords[i]);
            /* the solves on two threads unless CHOLMOD's are asked for */
            CHECK(threads == ((masks[k] & CTN_LA_PLAIN_SOLVE) || !expect_psolve ? 1 : 2));
            if (k == 0) lnz0 = lnz, fl0 = fl;
            /* CHOLMOD's analysis of the same ordering: the same factor as the node graph's */
            if (masks[k] == CTN_LA_PLAIN_SYMBOLIC || masks[k] == CTN_LA_PLAIN_SOLVE) {
                CHECK_MSG(lnz == lnz0, "g %d ordering %s plain %u: lnz %zu against %zu", g,
                          ctn_la_ordering_name(ords[i]), masks[k], lnz, lnz0);
                CHECK_CLOSE(fl, fl0, 1e-12, 0);
            }
            /* a chain: natural makes no fill, and AUTO keeps it */
            if (g == 0 && ords[i] == CTN_LA_ORDER_AUTO && !(masks[k] & CTN_LA_PLAIN_ORDER))
                CHECK(got == CTN_LA_ORDER_NATURAL && lnz == (size_t)m.colptr[m.n]);
        }
    }
    if (expect_psolve) {                         /* an older struct: no plain bits */
        ctn_la_options old = { offsetof(ctn_la_options, plain), CTN_LA_ORDER_AUTO, 0, CTN_LA_PLAIN_SOLVE };
        double res[2], fl;
        size_t lnz;
        ctn_la_ordering got;
        int threads = 0;
        CHECK(run(ctx, &m, &old, B, X, res, &lnz, &fl, &got, &threads) == 0 && threads == 2);
    }
    freemat(&m);
    free(B);
    free(X);
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    CHECK(ctn_ctx_create(&ctx) == CTN_OK);
    if (!ctx) return 1;
    ctn_ctx_set_threads(ctx, 0);                /* as the catena command: no limit */
    /* the ordering's names */
    CHECK(!strcmp(ctn_la_ordering_name(CTN_LA_ORDER_AUTO), "auto"));
    CHECK(!strcmp(ctn_la_ordering_name(CTN_LA_ORDER_NATURAL), "natural"));
    CHECK(!strcmp(ctn_la_ordering_name(CTN_LA_ORDER_AMD), "amd"));
    CHECK(!strcmp(ctn_la_ordering_name(CTN_LA_ORDER_METIS), "metis"));
    CHECK(!strcmp(ctn_la_ordering_name((ctn_la_ordering)9), "?"));
    /* options: NULL and size 0 are the defaults (ordering AUTO, no plain bits); an older,
     * shorter struct (up to threads) gives what it has, the defaults for the rest */
    {
        mat m = { 0, NULL, NULL, NULL };
        CHECK(build(&m, 20, 400));
        ctn_pattern p = { m.n, m.colptr, m.rowind };
        ctn_la_options zero = { 0, CTN_LA_ORDER_NATURAL, 1, CTN_LA_PLAIN_ORDER };
        ctn_la_options old = { offsetof(ctn_la_options, plain), CTN_LA_ORDER_NATURAL, 1, CTN_LA_PLAIN_ORDER };
        const ctn_la_options *given[] = { NULL, &zero, &old };
        ctn_la_ordering got[3] = { CTN_LA_ORDER_AUTO, CTN_LA_ORDER_AUTO, CTN_LA_ORDER_AUTO };
        for (int i = 0; i < 3; i++) {
            ctn_linsolve *ls = NULL;
            CHECK(ctn_linsolve_create_opts(ctx, "cholmod", &p, given[i], &ls) == CTN_OK);
            if (ls) got[i] = ctn_linsolve_ordering(ls);
            ctn_linsolve_destroy(&ls);
        }
        CHECK(got[0] == CTN_LA_ORDER_AMD || got[0] == CTN_LA_ORDER_METIS);   /* a grid: not natural */
        CHECK(got[1] == got[0]);
        CHECK(got[2] == CTN_LA_ORDER_NATURAL);
        ctn_linsolve *ls = NULL;
        CHECK(ctn_linsolve_create_opts(ctx, "nonesuch", &p, NULL, &ls) == CTN_ERR_INVALID && !ls);
        freemat(&m);
    }
    model(ctx, 130, 130 * 130, 1);              /* 50 700 DOFs: the two-thread solves */
    model(ctx, 20, 400, 0);
    model(ctx, 0, 2000, 0);                     /* a chain */
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
