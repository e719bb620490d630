/* bench_floor - where the factorization floor goes (issue 10, item 7).
 *
 * The paper's cable with n elements (default 2e5), solved from the catenary start; the
 * tangent assembled at the solution; then factorize + solve of that one matrix, natural
 * ordering, timed through catena's backend and through bare CHOLMOD calls that differ
 * in one setting each: the long or the int interface, LDL' kept (CHOLMOD's default) or
 * turned into LL' (final_ll, catena's "cholmod"), the factorization with the shift
 * argument (cholmod_factorize_p, beta = 0) or without, the solve into a caller's
 * workspace (cholmod_solve2) or allocating (cholmod_solve). catena's whole iteration is
 * timed with its node-by-node assembly (two threads from 50 000 nodes), the same on one
 * thread, and the generic element loop (the scatter the node-by-node path replaced).
 * Medians of R repetitions after one warm-up; wall and CPU milliseconds. Last, the
 * iteration and the floor (bare long, LDL', factorize + solve) alternately, and the
 * median of their ratio: on a shared machine, the figure to read.
 *
 *   bench_floor [N] [--repeat R]
 */
#include "assemble/asm.h"
#include "linalg/linsolve.h"
#include "problem/overlap.h"

#include "bench_common.h"

#include <cholmod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_REPEAT 99

typedef struct variant {
    const char *name;
    int is_long, final_ll, with_beta, solve2;
} variant;

typedef struct timing {
    double fac, sol, cpu;     /* medians [s] */
    double as;                /* catena's iteration: the assembly alone (in fac) */
} timing;

/* The matrix as CHOLMOD wants it (upper triangle, values), int or long indices. */
static cholmod_sparse *matrix(const ctn_asm *a, const double *Kx, int is_long, cholmod_common *cm)
{
    size_t n = a->ndof, nnz = (size_t)a->colptr[n];
    cholmod_sparse *A = is_long ? cholmod_l_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL, cm)
                                : cholmod_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL, cm);
    if (!A) return NULL;
    for (size_t j = 0; j <= n; j++) {
        if (is_long) ((SuiteSparse_long *)A->p)[j] = a->colptr[j];
        else ((int *)A->p)[j] = a->colptr[j];
    }
    for (size_t k = 0; k < nnz; k++) {
        if (is_long) ((SuiteSparse_long *)A->i)[k] = a->rowind[k];
        else ((int *)A->i)[k] = a->rowind[k];
    }
    memcpy(A->x, Kx, nnz * sizeof(double));
    return A;
}

/* One bare variant: analyze once, then warm-up + reps of factorize + solve. */
static int time_bare(const variant *v, const ctn_asm *a, const double *Kx, int reps, timing *t)
{
    cholmod_common cm;
    double tf[MAX_REPEAT], ts[MAX_REPEAT], tc[MAX_REPEAT], beta[2] = { 0, 0 };
    if (v->is_long) cholmod_l_start(&cm);
    else cholmod_start(&cm);
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_NATURAL;
    cm.postorder = 0;
    cm.final_ll = v->final_ll;
    cholmod_sparse *A = matrix(a, Kx, v->is_long, &cm);
    cholmod_factor *L = !A ? NULL : v->is_long ? cholmod_l_analyze(A, &cm) : cholmod_analyze(A, &cm);
    cholmod_dense *B = !L ? NULL : v->is_long ? cholmod_l_ones(a->ndof, 1, CHOLMOD_REAL, &cm)
                                              : cholmod_ones(a->ndof, 1, CHOLMOD_REAL, &cm);
    cholmod_dense *X = NULL, *Y = NULL, *E = NULL;
    int ok = B != NULL;
    for (int k = -1; ok && k < reps; k++) {
        double c0 = cpu_now(), t0 = now();
        if (v->is_long) ok = v->with_beta ? cholmod_l_factorize_p(A, beta, NULL, 0, L, &cm) : cholmod_l_factorize(A, L, &cm);
        else ok = v->with_beta ? cholmod_factorize_p(A, beta, NULL, 0, L, &cm) : cholmod_factorize(A, L, &cm);
        double t1 = now();
        if (v->solve2) ok = ok && (v->is_long ? cholmod_l_solve2(CHOLMOD_A, L, B, NULL, &X, NULL, &Y, &E, &cm)
                                              : cholmod_solve2(CHOLMOD_A, L, B, NULL, &X, NULL, &Y, &E, &cm));
        else {
            cholmod_dense *Z = v->is_long ? cholmod_l_solve(CHOLMOD_A, L, B, &cm) : cholmod_solve(CHOLMOD_A, L, B, &cm);
            ok = ok && Z;
            if (v->is_long) cholmod_l_free_dense(&Z, &cm);
            else cholmod_free_dense(&Z, &cm);
        }
        double t2 = now(), c2 = cpu_now();
        if (k >= 0) { tf[k] = t1 - t0; ts[k] = t2 - t1; tc[k] = c2 - c0; }
    }
    ok = ok && cm.status == CHOLMOD_OK;
    if (v->is_long) {
        cholmod_l_free_dense(&B, &cm); cholmod_l_free_dense(&X, &cm); cholmod_l_free_dense(&Y, &cm);
        cholmod_l_free_dense(&E, &cm); cholmod_l_free_factor(&L, &cm); cholmod_l_free_sparse(&A, &cm);
        cholmod_l_finish(&cm);
    } else {
        cholmod_free_dense(&B, &cm); cholmod_free_dense(&X, &cm); cholmod_free_dense(&Y, &cm);
        cholmod_free_dense(&E, &cm); cholmod_free_factor(&L, &cm); cholmod_free_sparse(&A, &cm);
        cholmod_finish(&cm);
    }
    if (!ok) return 1;
    t->fac = median(tf, reps);
    t->sol = median(ts, reps);
    t->cpu = median(tc, reps);
    return 0;
}

/* The residual and tangent at d and the tangent's factorization: overlapped as pure
 * Newton does (solve/overlap.c) when `overlap` is set and possible, else one after the
 * other as the other methods do; the assembly's wall time into *t_as (overlapped: the
 * factorization runs beside it). */
static int assemble_factor(ctn_asm *a, ctn_linsolve *ls, const double *d, double *f, double *Kx, int overlap,
                           ctn_factor_info *info, double *t_as)
{
    ctn_overlap o;
    if (overlap && ctn_overlap_possible(a, ls) && ctn_overlap_start(&o, a, ls, Kx, 0.0)) {
        double t0 = now();
        int collapsed = ctn_overlap_assemble(&o, a, d, 0, f, Kx, NULL, NULL);
        *t_as = now() - t0;
        int rc = ctn_overlap_finish(&o, info);
        return rc ? rc : collapsed ? CTN_ERR_LINALG : CTN_OK;
    }
    double t0 = now();
    if (ctn_asm_eval(a, d, 0, f, Kx, NULL, NULL)) return CTN_ERR_LINALG;
    *t_as = now() - t0;
    return ctn_linsolve_factor(ls, Kx, 0.0, info);
}

/* catena's backend ("cholmod", natural ordering) on Kx; with a state d, catena's whole
 * Newton iteration instead: the residual and the tangent assembled at d (ctn_asm_eval,
 * as every iteration does) before the factorize and the solve, which is what the issue's
 * "assembly + factorization + solves per iteration" is. */
static int time_catena(ctn_ctx *ctx, ctn_asm *a, const double *Kx0, const double *d, int overlap, int reps,
                       timing *t)
{
    ctn_pattern pat = { a->ndof, a->colptr, a->rowind };
    ctn_linsolve *ls = NULL;
    ctn_factor_info info;
    double tf[MAX_REPEAT], ts[MAX_REPEAT], tc[MAX_REPEAT], ta[MAX_REPEAT];
    double *f = malloc(a->map.nstate * sizeof *f), *Kx = malloc(a->nnz * sizeof *Kx);
    int rc = f && Kx ? ctn_linsolve_create(ctx, "cholmod", &pat, CTN_ORDER_NATURAL, &ls) : CTN_ERR_NOMEM;
    if (!rc) memcpy(Kx, Kx0, a->nnz * sizeof *Kx);
    for (int k = -1; !rc && k < reps; k++) {
        for (size_t i = 0; !d && i < a->ndof; i++) f[i] = 1.0;
        double c0 = cpu_now(), t0 = now(), tas = 0;
        rc = d ? assemble_factor(a, ls, d, f, Kx, overlap, &info, &tas) : ctn_linsolve_factor(ls, Kx, 0.0, &info);
        double t1 = now();
        if (!rc) rc = info.ok ? ctn_linsolve_solve(ls, f, f) : CTN_ERR_LINALG;
        double t2 = now(), c2 = cpu_now();
        if (k >= 0) { tf[k] = t1 - t0; ts[k] = t2 - t1; tc[k] = c2 - c0; ta[k] = tas; }
    }
    ctn_linsolve_destroy(&ls);
    free(f);
    free(Kx);
    if (rc) return 1;
    t->fac = median(tf, reps);
    t->sol = median(ts, reps);
    t->cpu = median(tc, reps);
    t->as = median(ta, reps);
    return 0;
}

/* catena's iteration (its default assembly on a) and the floor (bare long, LDL',
 * cholmod_l_factorize + cholmod_l_solve, analyzed once) measured alternately, one of
 * each per repetition, so that a slow spell of this shared machine falls on both: the
 * median of the per-repetition ratio, and the medians of each. */
static int time_paired(ctn_ctx *ctx, ctn_asm *a, const double *Kx0, const double *d, int overlap, int reps,
                       double out[3])
{
    ctn_pattern pat = { a->ndof, a->colptr, a->rowind };
    ctn_linsolve *ls = NULL;
    ctn_factor_info info;
    cholmod_common cm;
    double ti[MAX_REPEAT], tb[MAX_REPEAT], r[MAX_REPEAT];
    double *f = malloc(a->map.nstate * sizeof *f), *Kx = malloc(a->nnz * sizeof *Kx);
    int rc = f && Kx ? ctn_linsolve_create(ctx, "cholmod", &pat, CTN_ORDER_NATURAL, &ls) : CTN_ERR_NOMEM;
    cholmod_l_start(&cm);
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_NATURAL;
    cm.postorder = 0;
    cm.final_ll = 0;
    cholmod_sparse *A = rc ? NULL : matrix(a, Kx0, 1, &cm);
    cholmod_factor *L = A ? cholmod_l_analyze(A, &cm) : NULL;
    cholmod_dense *B = L ? cholmod_l_ones(a->ndof, 1, CHOLMOD_REAL, &cm) : NULL;
    if (!rc && !B) rc = CTN_ERR_LINALG;
    for (int k = -1; !rc && k < reps; k++) {
        double t0 = now(), tas;
        rc = assemble_factor(a, ls, d, f, Kx, overlap, &info, &tas);
        if (!rc) rc = info.ok ? ctn_linsolve_solve(ls, f, f) : CTN_ERR_LINALG;
        double t1 = now();
        int ok = cholmod_l_factorize(A, L, &cm);
        cholmod_dense *Z = ok ? cholmod_l_solve(CHOLMOD_A, L, B, &cm) : NULL;
        double t2 = now();
        if (!Z || cm.status != CHOLMOD_OK) rc = CTN_ERR_LINALG;
        cholmod_l_free_dense(&Z, &cm);
        if (k >= 0) { ti[k] = t1 - t0; tb[k] = t2 - t1; r[k] = ti[k] / tb[k]; }
    }
    cholmod_l_free_dense(&B, &cm);
    cholmod_l_free_factor(&L, &cm);
    cholmod_l_free_sparse(&A, &cm);
    cholmod_l_finish(&cm);
    ctn_linsolve_destroy(&ls);
    free(f);
    free(Kx);
    if (rc) return 1;
    out[0] = median(ti, reps);
    out[1] = median(tb, reps);
    out[2] = median(r, reps);
    return 0;
}

static void print_iteration(const char *name, const timing *t)
{
    printf("%-48s %10.2f %10.2f %10.2f %10.2f  (assembly %.2f)\n", name, 1e3 * t->fac, 1e3 * t->sol,
           1e3 * (t->fac + t->sol), 1e3 * t->cpu, 1e3 * t->as);
}

int main(int argc, char **argv)
{
    int n = 200000, reps = 7;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--repeat") && i + 1 < argc) {
            if (parse_count(argv[++i], 1, MAX_REPEAT, &reps)) return 1;
        } else if (parse_count(argv[i], 2, 100000000, &n)) {
            fprintf(stderr, "usage: bench_floor [N] [--repeat R]\n");
            return 1;
        }
    }
    static const variant vs[] = {
        { "bare long, LDL', factorize, solve2", 1, 0, 0, 1 },
        { "bare long, LDL', factorize, solve", 1, 0, 0, 0 },
        { "bare long, LL' (final_ll), factorize, solve2", 1, 1, 0, 1 },
        { "bare long, LDL', factorize_p (beta 0), solve2", 1, 0, 1, 1 },
        { "bare int, LDL', factorize, solve2", 0, 0, 0, 1 },
        { "bare int, LL' (final_ll), factorize_p, solve2", 0, 1, 1, 1 },
    };
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_asm *a = NULL;
    int rc = ctn_ctx_create(&ctx);
    if (!rc) ctn_ctx_set_threads(ctx, 0);           /* as the catena command: no limit */
    if (!rc) rc = build_paper_cable(ctx, n, CTN_START_CATENARY, &m);
    if (!rc) rc = ctn_solve(ctx, m, NULL, &s);
    ctn_asm *a1 = NULL, *ag = NULL;                  /* one thread; the generic loop */
    if (!rc) rc = ctn_asm_create(ctx, m, &a);
    if (!rc) rc = ctn_asm_create_ex(ctx, m, CTN_ASM_ONE_THREAD, &a1);
    if (!rc) rc = ctn_asm_create_ex(ctx, m, CTN_ASM_GENERIC, &ag);
    double *f = a ? malloc(a->map.nstate * sizeof *f) : NULL, *Kx = a ? malloc(a->nnz * sizeof *Kx) : NULL;
    if (!rc && (!f || !Kx)) rc = CTN_ERR_NOMEM;
    double *d = a ? malloc(a->map.nstate * sizeof *d) : NULL;
    if (!rc && !d) rc = CTN_ERR_NOMEM;
    if (!rc) {
        ctn_dofmap_from3(&a->map, ctn_solution_displacements(s), d);
        if (ctn_asm_eval(a, d, 0, f, Kx, NULL, NULL)) rc = CTN_ERR_LINALG;
    }
    if (rc) {
        fprintf(stderr, "bench_floor: %s\n", ctn_ctx_message(ctx));
        return 2;
    }
    printf("# n = %d elements, %zu DOFs, natural ordering, medians of %d; load average %.2f\n", n, a->ndof, reps,
           load_average());
    printf("%-48s %10s %10s %10s %10s\n", "variant", "factor[ms]", "solve[ms]", "total[ms]", "CPU[ms]");
    timing t;
    if (!time_catena(ctx, a, Kx, NULL, 0, reps, &t))
        printf("%-48s %10.2f %10.2f %10.2f %10.2f\n", "catena backend (\"cholmod\")", 1e3 * t.fac, 1e3 * t.sol,
               1e3 * (t.fac + t.sol), 1e3 * t.cpu);
    if (!time_catena(ctx, a, Kx, d, 1, reps, &t)) print_iteration("catena pure Newton (assembly beside factor)", &t);
    if (!time_catena(ctx, a, Kx, d, 0, reps, &t)) print_iteration("catena iteration (assembly + factor, solve)", &t);
    if (!time_catena(ctx, a1, Kx, d, 0, reps, &t)) print_iteration("  the same, assembly on one thread", &t);
    if (!time_catena(ctx, ag, Kx, d, 0, reps, &t)) print_iteration("  the same, generic assembly (scatter)", &t);
    double pr[3];
    for (int ov = 1; ov >= 0; ov--)
        if (!time_paired(ctx, a, Kx, d, ov, reps, pr))
            printf("paired, alternately: %s %.2f ms, floor (bare factorize + solve) %.2f ms, iteration / floor "
                   "%.3f (median of the ratios)\n", ov ? "pure Newton iteration (assembly beside factor)" :
                   "iteration (assembly, then factor)", 1e3 * pr[0], 1e3 * pr[1], pr[2]);
    for (size_t i = 0; i < sizeof vs / sizeof *vs; i++)
        if (!time_bare(&vs[i], a, Kx, reps, &t))
            printf("%-48s %10.2f %10.2f %10.2f %10.2f\n", vs[i].name, 1e3 * t.fac, 1e3 * t.sol, 1e3 * (t.fac + t.sol),
                   1e3 * t.cpu);
        else printf("%-48s failed\n", vs[i].name);
    free(f);
    free(Kx);
    free(d);
    ctn_asm_destroy(&a);
    ctn_asm_destroy(&a1);
    ctn_asm_destroy(&ag);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return 0;
}
