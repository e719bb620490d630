/* bench_eigen - the two shift-invert eigen-solvers on one factor (issue 12).
 *
 * For a model file: the tangent K and the consistent mass M at the reference state
 * (a prestressed net is stable there), K factored once (LL', sigma = 0: the factor a
 * modal analysis reuses from the static solve's stability check); then the nev lowest
 * eigenpairs of K x = lambda M x by ARPACK (one vector per solve) and by block Lanczos
 * (linalg/eigen/eigen.h), each timed (wall and CPU) with its solves, block solves and
 * restarts, its largest residual |K x - lambda M x| / |K x|, and the largest relative
 * difference of its eigenvalues from the other's. The factorization, the solves and
 * ARPACK on one thread; the block solver's dense work on two from 50 000 DOFs, as in
 * catena (BENCH_THREADS=1 or 2 sets it; BENCH_NO_ARPACK=1 runs the block solver only).
 *
 *   bench_eigen MODEL.cable [NEV]            (default NEV 20)
 */
#include "assemble/asm.h"
#include "linalg/eigen/eigen.h"
#include "linalg/linsolve.h"
#include "linalg/pcg.h"

#include "bench_common.h"
#include "bench_tangent.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct bench {
    ctn_linsolve *ls;
    ctn_pattern pat;
    const double *Kx, *Mx;
    int solves;
    double t_solve;
} bench;

static int op_solve(void *ud, const double *b, double *y)
{
    bench *B = ud;
    double t0 = now();
    int rc = ctn_linsolve_solve(B->ls, b, y);
    B->t_solve += now() - t0;
    B->solves++;
    return rc;
}

static int op_solve_block(void *ud, const double *X, double *Y, int k)
{
    bench *B = ud;
    double t0 = now();
    int rc = ctn_linsolve_solve_block(B->ls, X, Y, (size_t)k);
    B->t_solve += now() - t0;
    B->solves += k;
    return rc;
}

static void op_mass(void *ud, const double *x, double *y)
{
    bench *B = ud;
    ctn_sym_matvec(&B->pat, B->Mx, x, y);
}

static void op_stiff(void *ud, const double *x, double *y)
{
    bench *B = ud;
    ctn_sym_matvec(&B->pat, B->Kx, x, y);
}

static void op_abs(void *ud, const double *x, double lambda, double *y)
{
    bench *B = ud;
    ctn_sym_matvec_abs_pair(&B->pat, B->Kx, B->Mx, fabs(lambda), x, y);
}

/* Largest |K x - lambda M x| / |K x| over the nev pairs. */
static double residual(bench *B, const double *lam, const double *V, int nev)
{
    size_t n = B->pat.n;
    double worst = 0, *k = malloc(n * sizeof *k), *m = malloc(n * sizeof *m);
    for (int c = 0; k && m && c < nev; c++) {
        op_stiff(B, V + n * (size_t)c, k);
        op_mass(B, V + n * (size_t)c, m);
        double r = 0, s = 0;
        for (size_t i = 0; i < n; i++) {
            r += (k[i] - lam[c] * m[i]) * (k[i] - lam[c] * m[i]);
            s += k[i] * k[i];
        }
        worst = fmax(worst, sqrt(r / s));
    }
    free(k);
    free(m);
    return worst;
}

static int run(ctn_ctx *ctx, bench *B, int block, int nev, double *lam)
{
    ctn_eigen_ops ops = { .ud = B, .solve = op_solve, .bmul = op_mass, .solve_block = op_solve_block,
                          .amul = op_stiff, .absmul = op_abs,
                          .threads = getenv("BENCH_THREADS") ? atoi(getenv("BENCH_THREADS")) : 0 };
    ctn_eigen_info info;
    double *V = NULL, *work = malloc(B->pat.n * sizeof *work);
    ops.work = work;
    B->solves = 0;
    B->t_solve = 0;
    double t0 = now(), c0 = cpu_now();
    int rc = block ? ctn_eigen_block(ctx, (int)B->pat.n, nev, 0.0, &ops, lam, &V, &info)
                   : ctn_eigen_shift_invert(ctx, (int)B->pat.n, nev, 0.0, &ops, lam, &V, &info);
    double t = now() - t0, c = cpu_now() - c0;
    if (!rc)
        printf("%-7s %8.3f %8.3f %8.3f %7d %7d %8d %9.1e %9.3f %9.4f\n", block ? "block" : "arpack", t, c, B->t_solve,
               B->solves, block ? info.block_solves : 0, info.restarts, residual(B, lam, V, nev), lam[0], lam[nev - 1]);
    else printf("%-7s failed: %s\n", block ? "block" : "arpack", ctn_ctx_message(ctx));
    fflush(stdout);
    ctn_free(V);
    free(work);
    return rc;
}

int main(int argc, char **argv)
{
    int nev = 20;
    if (argc < 2 || argc > 3 || (argc == 3 && parse_count(argv[2], 1, 1000, &nev))) {
        fprintf(stderr, "usage: bench_eigen MODEL.cable [NEV]\n");
        return 1;
    }
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_asm *a = NULL;
    bench B;
    memset(&B, 0, sizeof B);
    double *Kx = NULL, *Mx = NULL, la[1000], lb[1000];
    int rc = ctn_ctx_create(&ctx);
    if (!rc) ctn_ctx_set_threads(ctx, 0);           /* as the catena command: no limit */
    if (!rc) rc = bench_tangent(ctx, argv[1], &m, &a, &Kx);
    if (!rc && !(Mx = calloc(a->nnz, sizeof *Mx))) rc = CTN_ERR_NOMEM;
    if (!rc) rc = ctn_asm_mass(ctx, a, 0, Mx);
    B.pat = (ctn_pattern){ a ? a->ndof : 0, a ? a->colptr : NULL, a ? a->rowind : NULL };
    B.Kx = Kx;
    B.Mx = Mx;
    ctn_factor_info info = { 0, -1 };
    double t0 = now(), c0 = cpu_now();
    if (!rc) rc = ctn_linsolve_create(ctx, "cholmod", &B.pat, CTN_LA_ORDER_AUTO, &B.ls);
    double t1 = now(), c1 = cpu_now();
    ctn_linsolve_set_threads(B.ls, 1);
    if (!rc) rc = ctn_linsolve_factor(B.ls, Kx, 0.0, &info);
    if (!rc && !info.ok) rc = ctn_error(ctx, CTN_ERR_LINALG, "K is not positive definite at the reference state");
    if (rc) {
        fprintf(stderr, "bench_eigen: %s\n", ctn_ctx_message(ctx));
        return 2;
    }
    FILE *lf = fopen("/proc/loadavg", "r");
    double load = 0;
    if (lf && fscanf(lf, "%lf", &load) != 1) load = 0;
    if (lf) fclose(lf);
    printf("# %s: %zu DOFs, nev %d, factor nnz %zu; analysis %.3f s; factorization %.3f s wall, %.3f s CPU (1 thread);"
           " load average %.2f\n", argv[1], B.pat.n, nev, ctn_linsolve_factor_nnz(B.ls), t1 - t0, now() - t1,
           cpu_now() - c1 + 0 * c0, load);
    printf("%-7s %8s %8s %8s %7s %7s %8s %9s %9s %9s\n", "solver", "wall[s]", "CPU[s]", "solves[s]", "solves", "blocks",
           "restarts", "residual", "lambda_1", "lambda_n");
    int ra = getenv("BENCH_NO_ARPACK") ? 1 : run(ctx, &B, 0, nev, la);
    int rb = run(ctx, &B, 1, nev, lb);
    if (!ra && !rb) {
        double dmax = 0;
        for (int k = 0; k < nev; k++) dmax = fmax(dmax, fabs(la[k] - lb[k]) / fabs(la[k]));
        printf("# largest relative difference of the eigenvalues: %.1e\n", dmax);
    }
    ctn_linsolve_destroy(&B.ls);
    free(Kx);
    free(Mx);
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return ra || rb ? 3 : 0;
}
