/* bench_psolve - does a block solve scale on two cores? (issue 12, item 5)
 *
 * For a model file: the tangent at the reference state (plus the shift that makes it
 * definite, as bench_block), factored by CHOLMOD (supernodal LL', METIS); then for each
 * k, medians of R repetitions of
 *   one     one k-column cholmod_l_solve2 on one thread;
 *   pair    two k-column cholmod_l_solve2 at the same time on two threads (each its own
 *           cholmod_common and workspace, the same factor): wall time of the pair;
 *   ps1     catena's subtree-parallel solve (cholmod_psolve.c) with its sets one after
 *           the other on one thread;
 *   ps2     the same on two threads;
 * and the largest relative difference of ps2's solution from CHOLMOD's. If a pair takes
 * much less than twice one, the solve is not bound by memory and two threads pay.
 *
 *   bench_psolve MODEL.cable [--repeat R] [K...]      (default K: 1 4)
 */
#include "assemble/asm.h"
#include "linalg/linsolve.h"
#include "linalg/backends/cholmod/psolve.h"

#include "bench_common.h"
#include "bench_tangent.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_REPEAT 99

typedef struct solver {
    cholmod_common cm;
    cholmod_factor *L;
    cholmod_dense *Y, *E;        /* solve2's workspace */
    const double *B;
    double *X;
    size_t n, k;
    int ok;
} solver;

static void *solve2(void *arg)
{
    solver *s = arg;
    ctn_threads_saved saved;
    ctn_threads_push(1, &saved);
    cholmod_dense b = { s->n, s->k, s->n * s->k, s->n, (void *)s->B, NULL, CHOLMOD_REAL, CHOLMOD_DOUBLE };
    cholmod_dense x = b, *xp = &x;
    x.x = s->X;
    s->ok = cholmod_l_solve2(CHOLMOD_A, s->L, &b, NULL, &xp, NULL, &s->Y, &s->E, &s->cm);
    ctn_threads_pop(&saved);
    return NULL;
}

/* K + shift I as CHOLMOD's upper triangle, factored; the shift doubled until it is. */
static cholmod_factor *factor(const ctn_asm *a, const double *Kx, cholmod_common *cm, double *t)
{
    size_t n = a->ndof, nnz = (size_t)a->colptr[n];
    cholmod_sparse *A = cholmod_l_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL, cm);
    if (!A) return NULL;
    SuiteSparse_long *Ap = A->p, *Ai = A->i;
    double *Ax = A->x, dmax = 0;
    for (size_t j = 0; j <= n; j++) Ap[j] = a->colptr[j];
    for (size_t q = 0; q < nnz; q++) Ai[q] = a->rowind[q], Ax[q] = Kx[q];
    for (size_t q = 0; q < n; q++) dmax = fmax(dmax, fabs(Kx[a->colptr[q + 1] - 1]));
    cm->supernodal = CHOLMOD_SUPERNODAL;
    cm->nmethods = 1;
    cm->method[0].ordering = CHOLMOD_METIS;
    cholmod_factor *L = cholmod_l_analyze(A, cm);
    for (double shift = 1e-8 * dmax; L && shift < dmax; shift *= 4) {
        double beta[2] = { shift, 0 }, t0 = now();
        cholmod_l_factorize_p(A, beta, NULL, 0, L, cm);
        *t = now() - t0;
        if (cm->status == CHOLMOD_OK) break;
    }
    if (L && cm->status != CHOLMOD_OK) cholmod_l_free_factor(&L, cm);
    cholmod_l_free_sparse(&A, cm);
    return L;
}

/* Medians of reps timings of: one solve2, a pair of them, psolve on 1 and on 2 threads. */
static int time_k(solver s[2], ctn_psolve *p, size_t k, int reps, double *X1, double out[4])
{
    double t[4][MAX_REPEAT];
    for (int r = 0; r < reps; r++) {
        s[0].k = s[1].k = k;
        double t0 = now();
        solve2(&s[0]);
        double t1 = now();
        pthread_t th;
        int threaded = !pthread_create(&th, NULL, solve2, &s[1]);
        solve2(&s[0]);
        if (threaded) pthread_join(th, NULL);
        double t2 = now();
        if (!threaded || !s[0].ok || !s[1].ok) return 1;
        if (ctn_psolve_solve(p, s[0].L, s[0].B, X1, k, 1)) return 1;
        double t3 = now();
        if (ctn_psolve_solve(p, s[0].L, s[0].B, X1, k, 2)) return 1;
        double t4 = now();
        t[0][r] = t1 - t0, t[1][r] = t2 - t1, t[2][r] = t3 - t2, t[3][r] = t4 - t3;
    }
    for (int i = 0; i < 4; i++) out[i] = median(t[i], reps);
    return 0;
}

static double difference(const double *X, const double *Y, size_t m)
{
    double d = 0, y = 0;
    for (size_t i = 0; i < m; i++) d = fmax(d, fabs(X[i] - Y[i])), y = fmax(y, fabs(Y[i]));
    return d / y;
}

int main(int argc, char **argv)
{
    int reps = 3, ks[16], nk = 0;
    const char *path = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--repeat") && i + 1 < argc && !parse_count(argv[i + 1], 1, MAX_REPEAT, &reps)) i++;
        else if (!path && argv[i][0] != '-') path = argv[i];
        else if (nk < 16 && !parse_count(argv[i], 1, 64, &ks[nk])) nk++;
        else path = NULL, i = argc;
    }
    if (!path) {
        fprintf(stderr, "usage: bench_psolve MODEL.cable [--repeat R] [K...]\n");
        return 1;
    }
    if (!nk) ks[nk++] = 1, ks[nk++] = 4;
    int kmax = 1;
    for (int i = 0; i < nk; i++) kmax = ks[i] > kmax ? ks[i] : kmax;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_asm *a = NULL;
    ctn_psolve *p = NULL;
    solver s[2];
    memset(s, 0, sizeof s);
    cholmod_l_start(&s[0].cm);
    cholmod_l_start(&s[1].cm);
    double *Kx = NULL, *B = NULL, *X = NULL, *X1 = NULL, tf = 0;
    int rc = ctn_ctx_create(&ctx);
    if (!rc) ctn_ctx_set_threads(ctx, 0);           /* as the catena command: no limit */
    if (!rc) rc = bench_tangent(ctx, path, &m, &a, &Kx);
    size_t n = a ? a->ndof : 0, nb = n * (size_t)kmax;
    if (!rc) {
        B = malloc(nb * sizeof *B);
        X = malloc(2 * nb * sizeof *X);
        X1 = malloc(nb * sizeof *X1);
        rc = B && X && X1 ? 0 : CTN_ERR_NOMEM;
    }
    if (!rc && !(s[0].L = s[1].L = factor(a, Kx, &s[0].cm, &tf))) rc = ctn_error(ctx, CTN_ERR_LINALG, "no factor");
    if (!rc) rc = ctn_psolve_create(ctx, s[0].L, &p);
    if (!rc && !p) rc = ctn_error(ctx, CTN_ERR_LINALG, "no split of the tree: nothing to measure");
    if (rc) {
        fprintf(stderr, "bench_psolve: %s\n", ctn_ctx_message(ctx));
        return 2;
    }
    srand(1);
    for (size_t i = 0; i < nb; i++) B[i] = (double)rand() / RAND_MAX - 0.5;
    for (int i = 0; i < 2; i++) s[i].n = n, s[i].B = B, s[i].X = X + nb * (size_t)i;
    double sh[3];
    ctn_psolve_shares(p, sh);
    printf("# %s: %zu DOFs, factor %zu supernodes, %.0f entries (METIS), factorization %.3f s; psolve sets %.3f and "
           "%.3f, top %.3f of the entries; load average %.2f; medians of %d\n", path, n, s[0].L->nsuper,
           (double)s[0].L->xsize, tf, sh[0], sh[1], sh[2], load_average(), reps);
    printf("%4s %10s %10s %10s %10s %10s %10s %12s\n", "k", "one[s]", "pair[s]", "pair/one", "ps1[s]", "ps2[s]",
           "one/ps2", "difference");
    for (int i = 0; i < nk && !rc; i++) {
        double t[4];
        size_t k = (size_t)ks[i];
        if ((rc = time_k(s, p, k, reps, X1, t))) break;
        printf("%4zu %10.4f %10.4f %10.2f %10.4f %10.4f %10.2f %12.2e\n", k, t[0], t[1], t[1] / t[0], t[2], t[3],
               t[0] / t[3], difference(X1, X, n * k));
        fflush(stdout);
    }
    if (rc) fprintf(stderr, "bench_psolve: %s\n", ctn_ctx_message(ctx));
    ctn_psolve_destroy(&p);
    for (int i = 0; i < 2; i++) {
        cholmod_l_free_dense(&s[i].Y, &s[i].cm);
        cholmod_l_free_dense(&s[i].E, &s[i].cm);
    }
    cholmod_l_free_factor(&s[0].L, &s[0].cm);
    cholmod_l_finish(&s[0].cm);
    cholmod_l_finish(&s[1].cm);
    free(Kx);
    free(B);
    free(X);
    free(X1);
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return rc ? 2 : 0;
}
