/* Linear solver objects: the registry and the calls that dispatch to a backend. */
#include "linalg/linsolve.h"
#include "core/threads.h"
#include "dist/comm.h"

#include <string.h>
#include <time.h>

/* The default is one thread per factorization, measured: CHOLMOD's supernodal
 * factorization on Debian's OpenBLAS for OpenMP, on the K = 400 hypar net (2.1e10 flops)
 * on an idle 2-vCPU machine, took 2.5 s on one thread and 8.6 s on two (CHOLMOD's own
 * loops ask for 4 threads whatever the count says, and the supernodes are mostly too
 * small for a parallel BLAS call to pay its fork and join); OpenBLAS's pthreads build
 * with CHOLMOD's loops serial took 2.3 s wall for twice the CPU. A large dense product
 * does run 1.6 times faster on two threads there, so threads=N stays for machines and
 * factors where it pays. */

struct ctn_linsolve {
    const ctn_linsolve_ops *ops;
    void *impl;
    ctn_ctx *ctx;
    size_t n;                  /* order */
    int threads;               /* asked for: n > 0, or 0 (auto) */
    int used;                  /* threads of the last factorization */
    double cpu;                /* CPU seconds of the last factorization */
};

static double cpu_clock(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static const ctn_linsolve_ops *const solvers[] = {
    &ctn_cholmod_ll_ops, &ctn_cholmod_ldl_ops,
};

/* The PETSc solvers' names: they come with the MPI module (dist/plugin.h) on the
 * communicator it sets, so a name is known before the module is loaded. */
static const char *const module_solvers[] = { "petsc", "petsc-ldl", "petsc-cg", "petsc-inertia" };

int ctn_linsolve_module_name(const char *name)
{
    for (size_t i = 0; name && i < sizeof module_solvers / sizeof *module_solvers; i++)
        if (!strcmp(module_solvers[i], name)) return 1;
    return 0;
}

/* the solver of that name on ctx's communicator, else the registry's */
static const ctn_linsolve_ops *find_ctx(const ctn_ctx *ctx, const char *name)
{
    const ctn_comm *c = ctn_ctx_comm(ctx);
    for (const struct ctn_linsolve_ops *const *s = c->ops->solvers; name && s && *s; s++)
        if (!strcmp((*s)->name, name)) return *s;
    return ctn_linsolve_find(name);
}

const char *ctn_linsolve_default(const ctn_ctx *ctx, const char *name)
{
    int mpi = find_ctx(ctx, "petsc") != NULL;
    if (name && !mpi && !strcmp(name, "cholmod-inertia")) return "cholmod-ldl";
    if (!name || !mpi) return name;
    return !strcmp(name, "cholmod")          ? "petsc"
           : !strcmp(name, "cholmod-ldl")    ? "petsc-ldl"
           : !strcmp(name, "cholmod-inertia") ? "petsc-inertia"
                                              : name;
}

const char *ctn_linsolve_label(const ctn_linsolve *s)
{
    const char *l = s->ops->label ? s->ops->label(s->impl) : NULL;
    return l && *l ? l : s->ops->name;
}

const ctn_linsolve_ops *ctn_linsolve_find(const char *name)
{
    for (size_t i = 0; name && i < sizeof solvers / sizeof *solvers; i++)
        if (!strcmp(solvers[i]->name, name)) return solvers[i];
    return NULL;
}

const char *ctn_la_ordering_name(ctn_la_ordering o)
{
    static const char *const names[] = { "auto", "natural", "amd", "metis" };
    return o >= CTN_LA_ORDER_AUTO && o <= CTN_LA_ORDER_METIS ? names[o] : "?";
}

int ctn_linsolve_create(ctn_ctx *ctx, const char *name, const ctn_pattern *p, ctn_la_ordering ord,
                        ctn_linsolve **out)
{
    return ctn_linsolve_create_threads(ctx, name, p, ord, 0, out);
}

int ctn_linsolve_create_threads(ctn_ctx *ctx, const char *name, const ctn_pattern *p, ctn_la_ordering ord,
                                int threads, ctn_linsolve **out)
{
    ctn_la_options o = { sizeof o, ord, threads, 0 };
    return ctn_linsolve_create_opts(ctx, name, p, &o, out);
}

int ctn_linsolve_create_opts(ctn_ctx *ctx, const char *name, const ctn_pattern *p, const ctn_la_options *opt,
                             ctn_linsolve **out)
{
    ctn_la_options o = { sizeof o, CTN_LA_ORDER_AUTO, 0, 0 };
    if (opt && opt->size) {                    /* the fields the caller's struct has */
        size_t sz = opt->size < sizeof o ? opt->size : sizeof o;
        memcpy(&o, opt, sz);
        o.size = sizeof o;
    }
    int threads = o.threads;
    *out = NULL;
    const ctn_linsolve_ops *ops = find_ctx(ctx, name);
    if (!ops && ctn_linsolve_module_name(name))
        return ctn_error(ctx, CTN_ERR_INVALID, "linear solver '%s' runs in an MPI job: under mpirun, or with --petsc "
                         "(docs/parallel.md)", name);
    if (!ops) return ctn_error(ctx, CTN_ERR_INVALID, "unknown linear solver '%s'", name ? name : "");
    ctn_linsolve *s = ctn_calloc(ctx, 1, sizeof *s);
    if (!s) return CTN_ERR_NOMEM;
    s->ops = ops;
    s->ctx = ctx;
    s->n = p->n;
    s->threads = threads > 0 ? threads : 0;
    int rc = ops->create(ctx, p, &o, &s->impl);
    if (rc) {
        ctn_free(s);
        return rc;
    }
    *out = s;
    return CTN_OK;
}

int ctn_linsolve_create_cols(ctn_ctx *ctx, const char *name, const ctn_pattern *p, size_t n, size_t c0, size_t c1,
                             int threads, ctn_linsolve **out)
{
    ctn_la_options o = { sizeof o, CTN_LA_ORDER_AUTO, threads, 0 };
    *out = NULL;
    const ctn_linsolve_ops *ops = find_ctx(ctx, name);
    if (!ops || !ops->create_cols)
        return ctn_error(ctx, CTN_ERR_INVALID, "linear solver '%s' takes no matrix distributed by columns", name ? name : "");
    ctn_linsolve *s = ctn_calloc(ctx, 1, sizeof *s);
    if (!s) return CTN_ERR_NOMEM;
    s->ops = ops;
    s->ctx = ctx;
    s->n = n;
    s->threads = threads > 0 ? threads : 0;
    int rc = ops->create_cols(ctx, p, n, c0, c1, &o, &s->impl);
    if (rc) {
        ctn_free(s);
        return rc;
    }
    *out = s;
    return CTN_OK;
}

void ctn_linsolve_destroy(ctn_linsolve **s)
{
    if (!s || !*s) return;
    (*s)->ops->destroy((*s)->impl);
    ctn_free(*s);
    *s = NULL;
}

const ctn_linsolve_ops *ctn_linsolve_type(const ctn_linsolve *s) { return s->ops; }

typedef struct factor_call {
    ctn_linsolve *s;
    const double *Kx;
    double shift;
    ctn_factor_info *info;
    int rc;
} factor_call;

static void factor_run(void *arg)
{
    factor_call *f = arg;
    f->rc = f->s->ops->factor(f->s->impl, f->Kx, f->shift, f->info);
}

/* The factorization runs with its own thread count and no OpenMP team larger (both the
 * calling thread's settings, the caller's restored after). */
int ctn_linsolve_factor(ctn_linsolve *s, const double *Kx, double shift, ctn_factor_info *info)
{
    int n = ctn_thr_openmp(s->ctx, s->threads);
    ctn_threads_saved old;
    factor_call f = { s, Kx, shift, info, CTN_OK };
    ctn_threads_push(n, &old);
    double t0 = cpu_clock(CLOCK_PROCESS_CPUTIME_ID);
    ctn_threads_limit(n, factor_run, &f);
    int rc = f.rc;
    s->cpu = cpu_clock(CLOCK_PROCESS_CPUTIME_ID) - t0;
    ctn_threads_pop(&old);
    s->used = old.threads ? n : 1;
    return rc;
}

int ctn_linsolve_feedable(const ctn_linsolve *s) { return s->ops->feedable && s->ops->feedable(s->impl); }

/* CHOLMOD's simplicial factorization calls neither OpenMP nor the BLAS: no thread
 * setting to make (and none to make from another thread than the caller's). */
int ctn_linsolve_factor_feed(ctn_linsolve *s, const double *Kx, double shift, ctn_feed *feed, ctn_factor_info *info)
{
    double t0 = cpu_clock(CLOCK_THREAD_CPUTIME_ID);
    int rc = s->ops->factor_feed(s->impl, Kx, shift, feed, info);
    s->cpu = cpu_clock(CLOCK_THREAD_CPUTIME_ID) - t0;
    s->used = 1;
    return rc;
}

/* Triangular solves are bound by memory traffic: one thread. */
int ctn_linsolve_solve(ctn_linsolve *s, const double *b, double *x)
{
    ctn_threads_saved old;
    ctn_threads_push(1, &old);
    int rc = s->ops->solve(s->impl, b, x);
    ctn_threads_pop(&old);
    return rc;
}

int ctn_linsolve_solve_block(ctn_linsolve *s, const double *B, double *X, size_t k)
{
    ctn_threads_saved old;
    ctn_threads_push(1, &old);
    size_t n = s->n;
    int rc = CTN_OK;
    if (s->ops->solve_block) rc = s->ops->solve_block(s->impl, B, X, k);
    for (size_t j = 0; !s->ops->solve_block && !rc && j < k; j++) rc = s->ops->solve(s->impl, B + n * j, X + n * j);
    ctn_threads_pop(&old);
    return rc;
}

int ctn_linsolve_inertia(ctn_linsolve *s, double tol, long *negative, long *zero, long *first)
{
    if (!s->ops->inertia) return ctn_error(s->ctx, CTN_ERR_INVALID, "linear solver '%s' gives no inertia", s->ops->name);
    return s->ops->inertia(s->impl, tol, negative, zero, first);
}

ctn_la_ordering ctn_linsolve_ordering(const ctn_linsolve *s) { return s->ops->ordering(s->impl); }

size_t ctn_linsolve_factor_nnz(const ctn_linsolve *s) { return s->ops->factor_nnz(s->impl); }

double ctn_linsolve_flops(const ctn_linsolve *s) { return s->ops->flops ? s->ops->flops(s->impl) : 0; }

void ctn_linsolve_set_threads(ctn_linsolve *s, int n)
{
    s->threads = n > 0 ? n : 0;
    if (s->ops->set_threads) s->ops->set_threads(s->impl, s->threads);
}

int ctn_linsolve_threads(const ctn_linsolve *s) { return s->used ? s->used : 1; }

int ctn_linsolve_solve_threads(const ctn_linsolve *s)
{
    return s->ops->solve_threads ? s->ops->solve_threads(s->impl) : 1;
}

double ctn_linsolve_cpu(const ctn_linsolve *s) { return s->cpu; }

size_t ctn_linsolve_order(const ctn_linsolve *s) { return s->n; }
