/* bench_block - one solve with k right-hand sides against k solves with one (issue 12).
 *
 * For a model file: the tangent at the reference state plus a shift that makes it
 * definite (the cost of a solve depends on the factor's structure, not on its values),
 * factored once by catena's "cholmod" backend; then, for each k, the median of R
 * repetitions of one block solve of an n x k random block (ctn_linsolve_solve_block)
 * and of k single solves (ctn_linsolve_solve), wall and CPU seconds, per column and as
 * a fraction of the factorization. Solves run on one thread, as catena runs them.
 *
 * A block solve takes catena's two-thread path (cholmod_psolve.c) where catena would;
 * --threads 1 keeps cholmod_l_solve2 (as threads=1 does).
 *
 *   bench_block MODEL.cable [--repeat R] [--threads T] [K...]   (default K: 1 4 8 16 32 64)
 */
#include "assemble/asm.h"
#include "linalg/linsolve.h"

#include "bench_common.h"
#include "bench_tangent.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_REPEAT 99

/* Factor K + shift I, the shift doubled until the factorization succeeds. */
static int factor(ctn_linsolve *ls, const ctn_asm *a, const double *Kx, double *t, double *cpu)
{
    double dmax = 0;
    for (size_t q = 0; q < a->ndof; q++) dmax = fmax(dmax, fabs(Kx[a->colptr[q + 1] - 1]));
    for (double shift = 1e-8 * dmax; shift < dmax; shift *= 4) {
        ctn_factor_info info;
        double t0 = now(), c0 = cpu_now();
        if (ctn_linsolve_factor(ls, Kx, shift, &info)) return 1;
        *t = now() - t0;
        *cpu = cpu_now() - c0;
        if (info.ok) return 0;
    }
    return 1;
}

/* Medians of reps timings of one block solve and of k single solves. */
static int time_k(ctn_linsolve *ls, size_t n, size_t k, int reps, double *B, double *X, double out[4])
{
    double tb[MAX_REPEAT], cb[MAX_REPEAT], ts[MAX_REPEAT], cs[MAX_REPEAT];
    for (int r = 0; r < reps; r++) {
        double t0 = now(), c0 = cpu_now();
        if (ctn_linsolve_solve_block(ls, B, X, k)) return 1;
        double t1 = now(), c1 = cpu_now();
        for (size_t j = 0; j < k; j++)
            if (ctn_linsolve_solve(ls, B + n * j, X + n * j)) return 1;
        tb[r] = t1 - t0;
        cb[r] = c1 - c0;
        ts[r] = now() - t1;
        cs[r] = cpu_now() - c1;
    }
    out[0] = median(tb, reps);
    out[1] = median(cb, reps);
    out[2] = median(ts, reps);
    out[3] = median(cs, reps);
    return 0;
}

int main(int argc, char **argv)
{
    int reps = 3, ks[16], nk = 0, threads = 0;
    const char *path = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--repeat") && i + 1 < argc && !parse_count(argv[i + 1], 1, MAX_REPEAT, &reps)) i++;
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc && !parse_count(argv[i + 1], 1, 2, &threads)) i++;
        else if (!path && argv[i][0] != '-') path = argv[i];
        else if (nk < 16 && !parse_count(argv[i], 1, 1024, &ks[nk])) nk++;
        else path = NULL, i = argc;
    }
    if (!path) {
        fprintf(stderr, "usage: bench_block MODEL.cable [--repeat R] [--threads T] [K...]\n");
        return 1;
    }
    if (!nk) {
        static const int def[] = { 1, 4, 8, 16, 32, 64 };
        nk = 6;
        memcpy(ks, def, sizeof def);
    }
    int kmax = 1;
    for (int i = 0; i < nk; i++) kmax = ks[i] > kmax ? ks[i] : kmax;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_asm *a = NULL;
    ctn_linsolve *ls = NULL;
    double *Kx = NULL, *B = NULL, *X = NULL, tf = 0, cf = 0;
    int rc = ctn_ctx_create(&ctx);
    if (!rc) ctn_ctx_set_threads(ctx, 0);           /* as the catena command: no limit */
    if (!rc) rc = bench_tangent(ctx, path, &m, &a, &Kx);
    size_t n = a ? a->ndof : 0;
    if (!rc) {
        B = malloc(n * (size_t)kmax * sizeof *B);
        X = malloc(n * (size_t)kmax * sizeof *X);
        rc = B && X ? 0 : CTN_ERR_NOMEM;
    }
    ctn_pattern pat = { n, a ? a->colptr : NULL, a ? a->rowind : NULL };
    if (!rc) rc = ctn_linsolve_create(ctx, "cholmod", &pat, CTN_LA_ORDER_AUTO, &ls);
    if (!rc) ctn_linsolve_set_threads(ls, threads);
    if (!rc) rc = factor(ls, a, Kx, &tf, &cf);
    if (rc) {
        fprintf(stderr, "bench_block: %s\n", ctn_ctx_message(ctx));
        return 2;
    }
    srand(1);
    for (size_t i = 0; i < n * (size_t)kmax; i++) B[i] = (double)rand() / RAND_MAX - 0.5;
    printf("# %s: %zu DOFs, factor nnz %zu (%s), factorization %.3f s wall, %.3f s CPU; load average %.2f;"
           " medians of %d; threads=%d\n", path, n, ctn_linsolve_factor_nnz(ls), ctn_la_ordering_name(ctn_linsolve_ordering(ls)), tf,
           cf, load_average(), reps, threads);
    printf("%4s %12s %12s %12s %12s %14s %14s %10s\n", "k", "block[s]", "block CPU", "k singles[s]", "singles CPU",
           "block/col[s]", "single/col[s]", "speed-up");
    for (int i = 0; i < nk && !rc; i++) {
        double t[4];
        size_t k = (size_t)ks[i];
        if ((rc = time_k(ls, n, k, reps, B, X, t))) break;
        printf("%4zu %12.4f %12.4f %12.4f %12.4f %14.5f %14.5f %10.2f\n", k, t[0], t[1], t[2], t[3], t[0] / (double)k,
               t[2] / (double)k, t[2] / t[0]);
        fflush(stdout);
    }
    if (rc) fprintf(stderr, "bench_block: %s\n", ctn_ctx_message(ctx));
    free(Kx);
    free(B);
    free(X);
    ctn_linsolve_destroy(&ls);
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return rc ? 2 : 0;
}
