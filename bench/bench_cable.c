/* bench_cable - the single-cable benchmark (issue 2).
 *
 * The founding paper's cable - 200 m level span, unstressed length 250.8777 m,
 * E = 2e8 kN/m^2, A = 3.14e-4 m^2, w = 0.1 kN/m, gravity 0 -1 0 - generated with n
 * elements (shape=arc), built through the public API and solved with ctn_solve
 * (tol 1e-10). Then the floor: CHOLMOD's numeric factorization + solve alone, through
 * the library's backend (linalg/backends/cholmod/chol.h), on the same matrix - the tangent assembled at
 * the final displacements - with the natural and with the AMD ordering.
 *
 *   bench_cable N [--method auto|newton] [--start arc|catenary] [--ordering auto|natural|amd] [--tol T]
 *                 [--maxit M] [--maxcuts C] [--repeat R] [--floor-repeat F]
 *                 [--table] [--log]
 *
 * N may be written 1e6. --repeat solves R times and reports the run of median wall
 * time; --floor-repeat times F factorize + solve pairs (median, default 5). Prints one
 * line of key=value pairs (times in seconds, memory in MiB); --table adds a readable
 * breakdown, --log the iteration log (stderr). Exit status: 0 when the benchmark ran
 * (converged or not), 1 on a usage error, 2 when a library call failed. */
#include "assemble/asm.h"
#include "linalg/linsolve.h"
#include "problem/la_options.h"

#include "bench_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#define MAX_REPEAT 99

typedef struct bench_opts {
    int n;                    /* elements */
    ctn_method method;        /* solution strategy (library default: AUTO) */
    ctn_ordering ordering;    /* fill-reducing ordering asked for (default AUTO) */
    double tol;               /* residual tolerance, relative to |f_ext| */
    int maxit;                /* Newton iterations per load increment */
    int maxcuts;              /* increment halvings, -1: the library's default */
    int repeat;               /* solves; the one of median wall time is reported */
    int floor_repeat;         /* factorize + solve pairs of the floor (median) */
    int table;                /* also print a readable breakdown */
    int log;                  /* iteration log to stderr */
    ctn_cable_start start;    /* Newton start: the paper's arc (default) or the catenary */
} bench_opts;

/* Wall-clock stamps taken by the iteration monitor. */
typedef struct stamps {
    double t0;                /* when ctn_solve was called */
    double *t;                /* t[k-1]: end of iteration k, seconds since t0 */
    int cap;                  /* entries of t */
    int log;                  /* print each iteration to stderr */
} stamps;

/* Timings of one solve. */
typedef struct run_times {
    ctn_solve_summary sum;
    double wall;              /* ctn_solve */
    double t_dtest;           /* from the call to the end of iteration it_dtest */
    int it_dtest;             /* first iteration meeting the increment test, 0 if none */
    double t_steady;          /* per iteration from the end of the first to the end of the
                                 last: without the one-off work before and after the loop
                                 and without the first factorization (allocates L) */
    double t_first;           /* from the end of setup to the end of iteration 1: the
                                 start state, the first residual, iteration 1 */
} run_times;

/* What the benchmark measured. */
typedef struct result {
    run_times run;            /* the solve of median wall time */
    double t_build;           /* model building through the public API */
    double rel_res;           /* final |r| / |f_ext| */
    double rss_solve;         /* peak RSS after model + solve [MiB] */
    double rss_all;           /* peak RSS at the end, floor included [MiB] */
    long allocs_solve;        /* allocations through the context in one ctn_solve */
    long allocs_short;        /* the same in a solve of at most 2 iterations */
    int its_short;            /* iterations of that solve */
    double t_pattern;         /* ctn_asm_create: DOF map, pattern, scatter map */
    double t_analyze[3];      /* [ordering]: ctn_linsolve_create (ordering + analysis) */
    double floor[3];          /* [ordering]: median factorize + solve */
    double floor_fac[3];      /* [ordering]: median factorize */
    size_t lnz[3];            /* [ordering]: non-zeros of L */
    const char *floor_at;     /* "final" or "guess": displacements of the floor's matrix */
} result;

static const char *ordering_name(ctn_ordering o)
{
    return o == CTN_ORDER_NATURAL ? "natural" : o == CTN_ORDER_AMD ? "amd" : "auto";
}

/* ---- arguments ---- */

static int usage(void)
{
    fprintf(stderr, "usage: bench_cable N [--method auto|newton] [--start arc|catenary] [--ordering auto|natural|amd]\n"
                    "                     [--tol T] [--maxit M] [--maxcuts C] [--repeat R]\n"
                    "                     [--floor-repeat F] [--table] [--log]\n");
    return 1;
}

static int parse_method(const char *s, ctn_method *out)
{
    if (!strcmp(s, "auto")) *out = CTN_METHOD_AUTO;
    else if (!strcmp(s, "newton")) *out = CTN_METHOD_NEWTON;
    else return -1;
    return 0;
}

static int parse_ordering(const char *s, ctn_ordering *out)
{
    if (!strcmp(s, "auto")) *out = CTN_ORDER_AUTO;
    else if (!strcmp(s, "natural")) *out = CTN_ORDER_NATURAL;
    else if (!strcmp(s, "amd")) *out = CTN_ORDER_AMD;
    else return -1;
    return 0;
}

static int parse_tol(const char *s, double *out)
{
    char *end;
    *out = strtod(s, &end);
    return end == s || *end || !(*out > 0) || !isfinite(*out) ? -1 : 0;
}

/* One option name with its value (NULL if missing); 0 on success. */
static int parse_option(const char *name, const char *val, bench_opts *o)
{
    if (!val) return -1;
    if (!strcmp(name, "--method")) return parse_method(val, &o->method);
    if (!strcmp(name, "--start")) {
        if (!strcmp(val, "arc")) o->start = CTN_START_ARC;
        else if (!strcmp(val, "catenary")) o->start = CTN_START_CATENARY;
        else return -1;
        return 0;
    }
    if (!strcmp(name, "--ordering")) return parse_ordering(val, &o->ordering);
    if (!strcmp(name, "--tol")) return parse_tol(val, &o->tol);
    if (!strcmp(name, "--maxit")) return parse_count(val, 1, 100000, &o->maxit);
    if (!strcmp(name, "--maxcuts")) return parse_count(val, 0, 60, &o->maxcuts);
    if (!strcmp(name, "--repeat")) return parse_count(val, 1, MAX_REPEAT, &o->repeat);
    if (!strcmp(name, "--floor-repeat")) return parse_count(val, 1, MAX_REPEAT, &o->floor_repeat);
    return -1;
}

static int parse_args(int argc, char **argv, bench_opts *o)
{
    *o = (bench_opts){ 0, CTN_METHOD_AUTO, CTN_ORDER_AUTO, 1e-10, 50, -1, 1, 5, 0, 0, CTN_START_ARC };
    if (argc < 2 || parse_count(argv[1], 1, 50000000, &o->n)) return -1;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--table")) o->table = 1;
        else if (!strcmp(argv[i], "--log")) o->log = 1;
        else if (parse_option(argv[i], i + 1 < argc ? argv[i + 1] : NULL, o)) return -1;
        else i++;
    }
    return 0;
}

/* ---- the model ---- */

/* Starting displacements of the Newton iteration, 3 per node. */
static int guess_displacements(const ctn_model *m, double *d)
{
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info info;
        int rc = ctn_model_node(m, i, &info);
        if (rc) return rc;
        memcpy(d + 3 * i, info.guess, sizeof info.guess);
    }
    return CTN_OK;
}

/* |f_ext| over the free DOFs: the scale of the residual test. */
static int fext_norm(const ctn_model *m, double *out)
{
    size_t nn = ctn_model_node_count(m);
    double *f = malloc(3 * nn * sizeof *f), s = 0;
    int rc = f ? ctn_model_external_forces(m, f) : CTN_ERR_NOMEM;
    for (size_t i = 0; i < nn && !rc; i++) {
        ctn_node_info info;
        if ((rc = ctn_model_node(m, i, &info))) break;
        for (int k = 0; k < 3; k++)
            if (!(info.fix >> k & 1u)) s += f[3 * i + k] * f[3 * i + k];   /* free DOF */
    }
    free(f);
    *out = sqrt(s);
    return rc;
}

/* ---- the solve ---- */

static void monitor(void *data, const ctn_iterate *i)
{
    stamps *s = data;
    double t = now() - s->t0;
    int it = i->iteration;
    if (it >= 1 && it <= s->cap) s->t[it - 1] = t;
    if (s->log)
        fprintf(stderr, "it %4d  t %9.4f s  |r| %.6e  |dd| %.3e%s\n", it, t, i->residual, i->increment,
                i->rejected ? "  rejected" : "");
}

static void solve_options(const bench_opts *o, stamps *st, ctn_solve_options *opt)
{
    ctn_solve_options_default(opt);
    opt->method = o->method;
    opt->ordering = o->ordering;
    opt->tol = o->tol;
    opt->maxit = o->maxit;
    opt->maxcuts = o->maxcuts;
    opt->monitor = monitor;
    opt->monitor_data = st;
}

/* First iteration k with |dd_k| <= dtol (|d| + L_ref), |d| the final displacement norm
 * and L_ref over-estimated (docs/solver.md's increment test, applied afterwards); 0 if none.
 * Tells when the iteration reached the solution, whatever the residual test said. */
static int first_increment_met(const ctn_solution *s, double dtol, size_t nn)
{
    size_t k, nd;
    const double *dh = ctn_solution_increment_history(s, &nd);
    const double *d = ctn_solution_displacements(s);
    double dn = 0, lref = sqrt(SPAN * SPAN + 0.25 * LENGTH * LENGTH);
    for (k = 0; k < 3 * nn; k++) dn += d[k] * d[k];
    for (k = 0; k < nd; k++)
        if (dh[k] <= dtol * (sqrt(dn) + lref)) return (int)k + 1;
    return 0;
}

/* One timed ctn_solve into *sol (replacing it); its figures in *rt. */
static int solve_once(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt,
                      stamps *st, ctn_solution **sol, run_times *rt)
{
    ctn_solution_destroy(sol);
    st->t0 = now();
    int rc = ctn_solve(ctx, m, opt, sol);
    rt->wall = now() - st->t0;
    if (rc) return rc;
    ctn_solution_summary(*sol, &rt->sum);
    rt->it_dtest = first_increment_met(*sol, opt->dtol, ctn_model_node_count(m));
    rt->t_dtest = rt->it_dtest && rt->it_dtest <= st->cap ? st->t[rt->it_dtest - 1] : NAN;
    int its = rt->sum.iterations;
    rt->t_steady = its >= 2 && its <= st->cap ? (st->t[its - 1] - st->t[0]) / (its - 1) : NAN;
    rt->t_first = its >= 1 ? st->t[0] - rt->sum.t_setup : NAN;
    return CTN_OK;
}

static int cmp_wall(const void *x, const void *y)
{
    return cmp_double(&((const run_times *)x)->wall, &((const run_times *)y)->wall);
}

/* Allocations through the context in a solve of at most 2 iterations (no cut-back), to
 * compare with a full solve: the difference is what the iterations allocate. */
static int count_short(ctn_ctx *ctx, const ctn_model *m, ctn_solve_options opt, result *r)
{
    ctn_solution *s = NULL;
    ctn_solve_summary sum;
    opt.maxit = 2;
    opt.maxcuts = 0;
    opt.monitor = NULL;
    long before = ctn_ctx_alloc_count(ctx);
    int rc = ctn_solve(ctx, m, &opt, &s);
    r->allocs_short = ctn_ctx_alloc_count(ctx) - before;
    ctn_solution_summary(s, &sum);
    r->its_short = rc ? 0 : sum.iterations;
    ctn_solution_destroy(&s);
    return rc;
}

/* Solve o->repeat times (identical runs but for their timings), keep the run of median
 * wall time in r->run and the last solution in *keep. */
static int run_solves(ctn_ctx *ctx, const ctn_model *m, const bench_opts *o, result *r,
                      ctn_solution **keep)
{
    ctn_solve_options opt;
    run_times runs[MAX_REPEAT];
    long cuts = o->maxcuts >= 0 ? o->maxcuts : 10, cap = 2L * o->maxit * (cuts + 1);
    stamps st = { 0, NULL, cap < 1000000 ? (int)cap : 1000000, o->log };  /* 2: relaxation */
    int rc = CTN_OK;
    double fn = 0;
    if (!(st.t = malloc((size_t)st.cap * sizeof *st.t))) return CTN_ERR_NOMEM;
    solve_options(o, &st, &opt);
    for (int k = 0; k < o->repeat && !rc; k++) {
        long before = ctn_ctx_alloc_count(ctx);
        rc = solve_once(ctx, m, &opt, &st, keep, &runs[k]);
        r->allocs_solve = ctn_ctx_alloc_count(ctx) - before;
    }
    free(st.t);
    r->rss_solve = peak_rss_mib();
    if (rc) return rc;
    qsort(runs, (size_t)o->repeat, sizeof *runs, cmp_wall);
    r->run = runs[o->repeat / 2];
    if ((rc = fext_norm(m, &fn))) return rc;
    r->rel_res = r->run.sum.residual / fn;
    return count_short(ctx, m, opt, r);
}

/* ---- the floor: CHOLMOD's numeric factorization + solve alone ---- */

/* reps timed factorize + solve pairs after one warm-up (the first factorization
 * allocates L's values, the first solve its workspace); medians in *fac and *tot.
 * CTN_ERR_LINALG if the matrix is not positive definite. */
static int time_factor_solve(ctn_linsolve *ch, const double *Kx, size_t ndof, double *b, int reps,
                             double *fac, double *tot)
{
    double tf[MAX_REPEAT], tt[MAX_REPEAT];
    ctn_factor_info info;
    for (int k = -1; k < reps; k++) {
        for (size_t i = 0; i < ndof; i++) b[i] = 1.0;
        double t0 = now();
        int rc = ctn_linsolve_factor(ch, Kx, 0.0, &info);
        double t1 = now();
        if (!rc && !info.ok) rc = CTN_ERR_LINALG;
        if (!rc) rc = ctn_linsolve_solve(ch, b, b);
        double t2 = now();
        if (rc) return rc;
        if (k >= 0) {
            tf[k] = t1 - t0;
            tt[k] = t2 - t0;
        }
    }
    *fac = median(tf, reps);
    *tot = median(tt, reps);
    return CTN_OK;
}

/* Analysis and floor of one ordering, the tangent assembled at displacements d. */
static int floor_ordering(ctn_ctx *ctx, const ctn_asm *a, const double *d, ctn_ordering ord,
                          int reps, result *r)
{
    ctn_linsolve *ch = NULL;
    ctn_pattern pat = { a->ndof, a->colptr, a->rowind };
    double *f = malloc(a->map.nstate * sizeof *f), *b = malloc(a->ndof * sizeof *b);
    double *Kx = malloc((a->nnz ? a->nnz : 1) * sizeof *Kx);
    int rc = f && b && Kx ? CTN_OK : CTN_ERR_NOMEM;
    double t0 = now();
    if (!rc) rc = ctn_linsolve_create(ctx, "cholmod", &pat, ctn_la_ordering_of(ord), &ch);
    r->t_analyze[ord] = now() - t0;
    if (!rc && ctn_asm_eval(a, d, 0, f, Kx, NULL, NULL)) rc = CTN_ERR_LINALG;
    if (!rc) rc = time_factor_solve(ch, Kx, a->ndof, b, reps, &r->floor_fac[ord], &r->floor[ord]);
    if (!rc) r->lnz[ord] = ctn_linsolve_factor_nnz(ch);
    ctn_linsolve_destroy(&ch);
    free(f);
    free(b);
    free(Kx);
    return rc;
}

/* The floor with both orderings at the final displacements; should that tangent not
 * be positive definite (a failed solve), at the starting displacements instead. */
static int run_floor(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s, int reps,
                     result *r)
{
    ctn_asm *a = NULL;
    double *d0 = malloc(3 * ctn_model_node_count(m) * sizeof *d0);
    const double *d = ctn_solution_displacements(s);
    int rc = d0 ? guess_displacements(m, d0) : CTN_ERR_NOMEM;
    double t0 = now();
    if (!rc) rc = ctn_asm_create(ctx, m, &a);
    r->t_pattern = now() - t0;
    r->floor_at = "final";
    for (int pass = 0; pass < 2 && !rc; pass++) {
        rc = floor_ordering(ctx, a, d, CTN_ORDER_NATURAL, reps, r);
        if (!rc) rc = floor_ordering(ctx, a, d, CTN_ORDER_AMD, reps, r);
        if (rc != CTN_ERR_LINALG || pass) break;
        ctn_ctx_clear(ctx);
        rc = CTN_OK;
        d = d0;
        r->floor_at = "guess";
    }
    ctn_asm_destroy(&a);
    free(d0);
    return rc;
}

/* ---- output ---- */

/* Per-iteration figures of the reported solve. */
typedef struct per_iteration {
    double total;             /* (ctn_solve - setup) / iterations: everything but setup */
    double assemble, factor, solve;
    double other;             /* total - the three phases */
    double ratio;             /* total / floor of the ordering used */
    double ratio_steady;      /* run_times.t_steady / floor */
} per_iteration;

static per_iteration per_iter(const result *r)
{
    const ctn_solve_summary *s = &r->run.sum;
    double k = s->iterations > 0 ? s->iterations : NAN;
    per_iteration p;
    p.total = (r->run.wall - s->t_setup) / k;
    p.assemble = s->t_assemble / k;
    p.factor = s->t_factor / k;
    p.solve = s->t_solve / k;
    p.other = p.total - p.assemble - p.factor - p.solve;
    p.ratio = p.total / r->floor[s->ordering];
    p.ratio_steady = r->run.t_steady / r->floor[s->ordering];
    return p;
}

static const char *reason_key(ctn_reason why)
{
    switch (why) {
    case CTN_CONVERGED: return "converged";
    case CTN_DIVERGED_MAXIT: return "maxit";
    case CTN_DIVERGED_NANORINF: return "nanorinf";
    case CTN_DIVERGED_INDEFINITE: return "indefinite";
    default: return "diverged";
    }
}

static void print_line(const bench_opts *o, const result *r)
{
    const ctn_solve_summary *s = &r->run.sum;
    per_iteration p = per_iter(r);
    printf("n=%d ndof=%zu method=%s start=%s ordering=%s reason=%s at_floor=%d its=%d it_dtest=%d"
           " rel_res=%.3e", o->n, s->ndof, o->method == CTN_METHOD_NEWTON ? "newton" : "auto",
           o->start == CTN_START_CATENARY ? "catenary" : "arc",
           ordering_name(s->ordering), reason_key(s->reason), s->floor, s->iterations,
           r->run.it_dtest, r->rel_res);
    printf(" t_build=%.6g t_solve=%.6g t_setup=%.6g t_dtest=%.6g", r->t_build, r->run.wall,
           s->t_setup, r->run.t_dtest);
    printf(" t_iter=%.6g asm_it=%.6g fac_it=%.6g sol_it=%.6g other_it=%.6g ns_elem_it=%.1f",
           p.total, p.assemble, p.factor, p.solve, p.other, 1e9 * p.total / o->n);
    printf(" t_steady=%.6g ratio_steady=%.3f t_first=%.6g", r->run.t_steady, p.ratio_steady,
           r->run.t_first);
    printf(" floor=%.6g ratio=%.3f floor_nat=%.6g floor_amd=%.6g fac_nat=%.6g fac_amd=%.6g",
           r->floor[s->ordering], p.ratio, r->floor[CTN_ORDER_NATURAL], r->floor[CTN_ORDER_AMD],
           r->floor_fac[CTN_ORDER_NATURAL], r->floor_fac[CTN_ORDER_AMD]);
    printf(" lnz=%zu lnz_nat=%zu lnz_amd=%zu floor_at=%s", s->nnz_factor,
           r->lnz[CTN_ORDER_NATURAL], r->lnz[CTN_ORDER_AMD], r->floor_at);
    printf(" t_pattern=%.6g t_an_nat=%.6g t_an_amd=%.6g rss_mib=%.1f rss_all_mib=%.1f",
           r->t_pattern, r->t_analyze[CTN_ORDER_NATURAL], r->t_analyze[CTN_ORDER_AMD],
           r->rss_solve, r->rss_all);
    printf(" allocs=%ld allocs_short=%ld its_short=%d\n", r->allocs_solve, r->allocs_short,
           r->its_short);
}

static void print_table(const bench_opts *o, const result *r)
{
    const ctn_solve_summary *s = &r->run.sum;
    per_iteration p = per_iter(r);
    printf("single cable, n = %d elements, %zu free DOFs, tol %.0e, method %s\n", o->n,
           s->ndof, o->tol, o->method == CTN_METHOD_NEWTON ? "newton" : "auto");
    printf("  %s after %d iterations%s, |r|/|f_ext| = %.3e; increment test first met at it %d\n",
           ctn_reason_name(s->reason), s->iterations, s->floor ? " (residual at its round-off"
           " floor)" : "", r->rel_res, r->run.it_dtest);
    printf("  model build  %9.4f s\n  ctn_solve    %9.4f s, of which setup %.4f s\n",
           r->t_build, r->run.wall, s->t_setup);
    printf("  setup parts (timed apart): pattern + scatter map %.4f s, analysis natural "
           "%.4f s, amd %.4f s\n", r->t_pattern, r->t_analyze[CTN_ORDER_NATURAL],
           r->t_analyze[CTN_ORDER_AMD]);
    printf("  per iteration %9.5f s: assembly %.5f, factor %.5f, solve %.5f, other %.5f\n",
           p.total, p.assemble, p.factor, p.solve, p.other);
    printf("  per iteration, steady (iterations 2..last) %.5f s; ratio to the floor %.2f;"
           " setup to end of iteration 1: %.5f s\n", r->run.t_steady, p.ratio_steady,
           r->run.t_first);
    printf("  floor (factor + solve): natural %.5f s, amd %.5f s (lnz %zu / %zu); "
           "%s used; ratio %.2f\n", r->floor[CTN_ORDER_NATURAL], r->floor[CTN_ORDER_AMD],
           r->lnz[CTN_ORDER_NATURAL], r->lnz[CTN_ORDER_AMD], ordering_name(s->ordering),
           p.ratio);
    printf("  peak RSS %.1f MiB after the solve, %.1f MiB with the floor\n", r->rss_solve,
           r->rss_all);
}

/* ---- driver ---- */

static int run(ctn_ctx *ctx, const bench_opts *o, result *r)
{
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    double t0 = now();
    int rc = build_paper_cable(ctx, o->n, o->start, &m);
    r->t_build = now() - t0;
    if (!rc) rc = run_solves(ctx, m, o, r, &s);
    if (!rc) rc = run_floor(ctx, m, s, o->floor_repeat, r);
    r->rss_all = peak_rss_mib();
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    return rc;
}

int main(int argc, char **argv)
{
    bench_opts o;
    result r;
    ctn_ctx *ctx = NULL;
    if (parse_args(argc, argv, &o)) return usage();
    memset(&r, 0, sizeof r);
    int rc = ctn_ctx_create(&ctx);
    if (!rc) ctn_ctx_set_threads(ctx, 0);           /* as the catena command: no limit */
    if (!rc) rc = run(ctx, &o, &r);
    if (rc) fprintf(stderr, "bench_cable: %s: %s\n", ctn_strerror(rc), ctn_ctx_message(ctx));
    else {
        print_line(&o, &r);
        if (o.table) print_table(&o, &r);
    }
    ctn_ctx_destroy(&ctx);
    return rc ? 2 : 0;
}
