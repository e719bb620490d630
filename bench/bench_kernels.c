/* bench_kernels - catena's hand-written CHOLMOD kernels against the library's own calls
 * (issue 22, item 6), on one model's tangent, the two ways alternated in one process.
 *
 * For a model file: the tangent at the reference state plus the shift that makes it
 * definite (as bench_block). Then R rounds; in each, every way in turn (a fresh solver
 * each time, through ctn_linsolve_create_opts with the CTN_LA_PLAIN_* bits of
 * linalg/linsolve.h):
 *   own       catena's path: the candidates AMD and METIS counted on the node graph
 *             (cholmod_order.c, cholmod_quotient.c), the analysis of the one kept from
 *             the node graph (cholmod_symbolic.c), the solves on two threads where the
 *             thread policy allows (cholmod_psolve.c, its 4-column sweeps psolve_k4*.c);
 *   symbolic  the same ordering, analysed by cholmod_l_analyze_p on the DOF pattern;
 *   order     cholmod_l_analyze's own choice of ordering (nmethods) on the DOF pattern;
 *   solve     catena's analysis, every solve by cholmod_l_solve2;
 *   lib       all three library calls.
 * For each way: the analysis (ctn_linsolve_create: ordering + symbolic analysis) wall
 * and CPU seconds, the first numeric factorization (it allocates the factor), a second
 * one, one single solve and one 4-column block solve (medians of 3 within the round),
 * the ordering, the factor's non-zeros and flops, and the largest difference of the
 * solutions from the first way's. Medians over the rounds are printed at the end.
 * The context allows two threads (as the catena command: no limit); --threads 1 asks
 * for one (then no way uses cholmod_psolve.c). --analysis: the analysis only.
 *
 *   bench_kernels MODEL.cable [--repeat R] [--threads T] [--analysis] [WAY...]   (default: own lib)
 */
#include "assemble/asm.h"
#include "linalg/linsolve.h"

#include "bench_common.h"
#include "bench_tangent.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_REPEAT 49
#define MAX_WAYS 5
#define K 4
enum { T_ANALYSIS, C_ANALYSIS, T_FACTOR1, T_FACTOR2, T_SOLVE1, T_SOLVE4, T_TOTAL, NT };
static const char *const tname[NT] = { "analysis", "anCPU", "factor1", "factor2", "solve1", "solve4", "total" };

static const struct { const char *name; unsigned plain; } ways[] = {
    { "own", 0 },
    { "symbolic", CTN_LA_PLAIN_SYMBOLIC },
    { "order", CTN_LA_PLAIN_ORDER },
    { "solve", CTN_LA_PLAIN_SOLVE },
    { "lib", CTN_LA_PLAIN_SYMBOLIC | CTN_LA_PLAIN_ORDER | CTN_LA_PLAIN_SOLVE },
};

static double median3(double a, double b, double c)
{
    double v[3] = { a, b, c };
    return median(v, 3);
}

typedef struct run {
    double t[NT];
    double lnz, fl, diff;
    ctn_la_ordering ord;
} run;

/* One way: create, factor twice, solve; X1 (n) and X4 (n x K) the solutions. */
static int analysis_only;

static int one(ctn_ctx *ctx, const ctn_pattern *pat, const double *Kx, double shift, unsigned plain, int threads,
               const double *B, double *X1, double *X4, run *r)
{
    ctn_la_options o = { sizeof o, CTN_LA_ORDER_AUTO, threads, plain };
    ctn_linsolve *ls = NULL;
    ctn_factor_info info;
    double t0 = now(), c0 = cpu_now();
    int rc = ctn_linsolve_create_opts(ctx, "cholmod", pat, &o, &ls);
    r->t[T_ANALYSIS] = now() - t0;
    r->t[C_ANALYSIS] = cpu_now() - c0;
    if (analysis_only) {
        memset(X1, 0, pat->n * sizeof *X1);
        memset(X4, 0, pat->n * K * sizeof *X4);
        r->t[T_TOTAL] = r->t[T_ANALYSIS];
        if (!rc) {
            r->lnz = (double)ctn_linsolve_factor_nnz(ls);
            r->fl = ctn_linsolve_flops(ls);
            r->ord = ctn_linsolve_ordering(ls);
        }
        ctn_linsolve_destroy(&ls);
        return rc;
    }
    double t1 = now();
    if (!rc) rc = ctn_linsolve_factor(ls, Kx, shift, &info);
    double t2 = now();
    if (!rc) rc = ctn_linsolve_factor(ls, Kx, shift, &info);
    double t3 = now();
    if (!rc && !info.ok) rc = ctn_error(ctx, CTN_ERR_LINALG, "not positive definite with the shift");
    r->t[T_FACTOR1] = t2 - t1;
    r->t[T_FACTOR2] = t3 - t2;
    double s1[3] = { 0 }, s4[3] = { 0 };
    for (int i = 0; i < 3 && !rc; i++) {
        double a = now();
        rc = ctn_linsolve_solve(ls, B, X1);
        double b = now();
        if (!rc) rc = ctn_linsolve_solve_block(ls, B, X4, K);
        s1[i] = b - a;
        s4[i] = now() - b;
    }
    r->t[T_SOLVE1] = median3(s1[0], s1[1], s1[2]);
    r->t[T_SOLVE4] = median3(s4[0], s4[1], s4[2]);
    r->t[T_TOTAL] = r->t[T_ANALYSIS] + r->t[T_FACTOR1] + r->t[T_FACTOR2] + r->t[T_SOLVE1] + r->t[T_SOLVE4];
    if (!rc) {
        r->lnz = (double)ctn_linsolve_factor_nnz(ls);
        r->fl = ctn_linsolve_flops(ls);
        r->ord = ctn_linsolve_ordering(ls);
    }
    ctn_linsolve_destroy(&ls);
    return rc;
}

/* The shift that makes K + shift I definite (doubled from 1e-8 of the largest diagonal). */
static int find_shift(ctn_ctx *ctx, const ctn_asm *a, const double *Kx, double *shift)
{
    ctn_pattern pat = { a->ndof, a->colptr, a->rowind };
    ctn_linsolve *ls = NULL;
    double dmax = 0;
    for (size_t q = 0; q < a->ndof; q++) dmax = fmax(dmax, fabs(Kx[a->colptr[q + 1] - 1]));
    int rc = ctn_linsolve_create(ctx, "cholmod", &pat, CTN_LA_ORDER_AUTO, &ls);
    for (*shift = 0; !rc; *shift = *shift > 0 ? 4 * *shift : 1e-8 * dmax) {
        ctn_factor_info info;
        if ((rc = ctn_linsolve_factor(ls, Kx, *shift, &info)) || info.ok) break;
        if (*shift > dmax) rc = ctn_error(ctx, CTN_ERR_LINALG, "no shift makes the tangent definite");
    }
    ctn_linsolve_destroy(&ls);
    return rc;
}

int main(int argc, char **argv)
{
    int reps = 3, threads = 0, sel[MAX_WAYS], nsel = 0;
    const char *path = NULL;
    for (int i = 1; i < argc; i++) {
        int w = -1;
        for (int j = 0; j < MAX_WAYS; j++)
            if (!strcmp(argv[i], ways[j].name)) w = j;
        if (!strcmp(argv[i], "--repeat") && i + 1 < argc && !parse_count(argv[i + 1], 1, MAX_REPEAT, &reps)) i++;
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc && !parse_count(argv[i + 1], 1, 2, &threads)) i++;
        else if (!strcmp(argv[i], "--analysis")) analysis_only = 1;
        else if (w >= 0 && nsel < MAX_WAYS) sel[nsel++] = w;
        else if (!path && argv[i][0] != '-') path = argv[i];
        else path = NULL, i = argc;
    }
    if (!path) {
        fprintf(stderr, "usage: bench_kernels MODEL.cable [--repeat R] [--threads T] [own|symbolic|order|solve|lib...]\n");
        return 1;
    }
    if (!nsel) sel[nsel++] = 0, sel[nsel++] = 4;
    bench_keep_heap();
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_asm *a = NULL;
    double *Kx = NULL, *B = NULL, *X[MAX_WAYS][2] = { { NULL } }, shift = 0;
    int rc = ctn_ctx_create(&ctx);
    if (!rc) ctn_ctx_set_threads(ctx, 0);           /* as the catena command: no limit */
    if (!rc) rc = bench_tangent(ctx, path, &m, &a, &Kx);
    size_t n = a ? a->ndof : 0;
    if (!rc && !analysis_only) rc = find_shift(ctx, a, Kx, &shift);
    if (!rc && !(B = malloc(n * K * sizeof *B))) rc = CTN_ERR_NOMEM;
    for (int w = 0; w < nsel && !rc; w++)
        if (!(X[w][0] = malloc(n * sizeof(double))) || !(X[w][1] = malloc(n * K * sizeof(double)))) rc = CTN_ERR_NOMEM;
    if (rc) {
        fprintf(stderr, "bench_kernels: %s\n", ctn_ctx_message(ctx));
        return 2;
    }
    srand(1);
    for (size_t i = 0; i < n * K; i++) B[i] = (double)rand() / RAND_MAX - 0.5;
    ctn_pattern pat = { n, a->colptr, a->rowind };
    static run runs[MAX_REPEAT][MAX_WAYS];
    printf("# %s: %zu DOFs, %zu non-zeros in the upper pattern; threads=%d; load average %.2f; %d rounds\n", path, n,
           (size_t)a->colptr[n], threads, load_average(), reps);
    printf("%-3s %-9s %-8s %9s %9s %9s %9s %9s %9s %9s %12s %11s %9s\n", "r", "way", "ordering", tname[0], tname[1],
           tname[2], tname[3], tname[4], tname[5], tname[6], "lnz", "flops", "diff");
    for (int r = 0; r < reps && !rc; r++)
        for (int w = 0; w < nsel && !rc; w++) {
            run *u = &runs[r][w];
            rc = one(ctx, &pat, Kx, shift, ways[sel[w]].plain, threads, B, X[w][0], X[w][1], u);
            if (rc) break;
            double d = 0, s = 0;
            for (size_t i = 0; i < n; i++) s = fmax(s, fabs(X[0][0][i]));
            s = s > 0 ? s : 1;
            for (size_t i = 0; i < n; i++) d = fmax(d, fabs(X[w][0][i] - X[0][0][i]));
            for (size_t i = 0; i < n * K; i++) d = fmax(d, fabs(X[w][1][i] - X[0][1][i]));
            u->diff = d / s;
            printf("%-3d %-9s %-8s %9.4f %9.4f %9.4f %9.4f %9.4f %9.4f %9.4f %12.0f %11.4g %9.1e\n", r + 1, ways[sel[w]].name,
                   ctn_la_ordering_name(u->ord), u->t[0], u->t[1], u->t[2], u->t[3], u->t[4], u->t[5], u->t[6], u->lnz,
                   u->fl, u->diff);
            fflush(stdout);
        }
    if (rc) {
        fprintf(stderr, "bench_kernels: %s\n", ctn_ctx_message(ctx));
        return 3;
    }
    printf("# medians over %d rounds (seconds)\n", reps);
    for (int w = 0; w < nsel; w++) {
        printf("%-3s %-9s %-8s", "med", ways[sel[w]].name, ctn_la_ordering_name(runs[0][w].ord));
        for (int t = 0; t < NT; t++) {
            double v[MAX_REPEAT];
            for (int r = 0; r < reps; r++) v[r] = runs[r][w].t[t];
            printf(" %9.4f", median(v, reps));
        }
        printf("\n");
    }
    for (int w = 0; w < nsel; w++) {
        free(X[w][0]);
        free(X[w][1]);
    }
    free(B);
    free(Kx);
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return 0;
}
