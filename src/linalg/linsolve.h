/* Internal: linear solvers for the symmetric tangent, as objects behind an ops table
 * registered by name (like PETSc's KSP/PC types). A solver is set up once on a pattern
 * (symbolic work: ordering, analysis), then factors values given in the pattern's order
 * (with an optional diagonal shift) and solves, without allocation. The caller owns the
 * values; nothing outside linalg/ sees a backend's storage.
 *
 *   "cholmod"      CHOLMOD LL' (supernodal or simplicial as CHOLMOD chooses): the
 *                  factorization fails on a non-positive pivot, which is reported with
 *                  its column: the matrix is not positive definite.
 *   "cholmod-ldl"  CHOLMOD simplicial LDL' without pivoting: accepts indefinite
 *                  matrices (fails only on a zero pivot) and gives their inertia. */
#ifndef CTN_LINALG_LINSOLVE_H
#define CTN_LINALG_LINSOLVE_H

#include "core/ctx.h"
#include "core/feed.h"

/* linalg's own options (the solve layer translates its public ones into these: linalg
 * knows no public solve header). The fill-reducing ordering: AUTO lets the backend
 * choose (the CHOLMOD backends: cholmod_order.c). */
typedef enum ctn_la_ordering {
    CTN_LA_ORDER_AUTO = 0,
    CTN_LA_ORDER_NATURAL,
    CTN_LA_ORDER_AMD,
    CTN_LA_ORDER_METIS
} ctn_la_ordering;
/* "auto", "natural", "amd", "metis" ("?" if none). */
const char *ctn_la_ordering_name(ctn_la_ordering o);

/* The library's own call instead of a hand-written kernel (bench/bench_kernels.c
 * measures one against the other; bench/RESULTS.md, "Hand-written kernels"). */
enum {
    CTN_LA_PLAIN_SYMBOLIC = 1u,  /* cholmod_l_analyze_p on the DOF pattern, not the
                                    analysis from the node graph (cholmod_symbolic.c) */
    CTN_LA_PLAIN_ORDER = 2u,     /* AUTO: cholmod_l_analyze's own choice (nmethods), not
                                    the candidates counted on the node graph */
    CTN_LA_PLAIN_SOLVE = 4u      /* cholmod_l_solve2 always, not the two-thread sweeps
                                    (cholmod_psolve.c) */
};

/* A solver's options; size first (sizeof, or 0 for the defaults of every field). */
typedef struct ctn_la_options {
    size_t size;
    ctn_la_ordering ordering;
    int threads;              /* the solve's threads= (0 auto, 1, n) */
    unsigned plain;           /* CTN_LA_PLAIN_* bits; 0 in catena's own use */
} ctn_la_options;

/* A symmetric matrix's upper triangle in compressed columns, rows sorted. */
typedef struct ctn_pattern {
    size_t n;                 /* order */
    const int *colptr;        /* n + 1 */
    const int *rowind;        /* colptr[n] */
} ctn_pattern;

/* Outcome of a numeric factorization (not a status). */
typedef struct ctn_factor_info {
    int ok;                   /* 1 if factored */
    long fail_col;            /* not ok: the column (pattern order) of the failing pivot,
                                 -1 if unknown */
} ctn_factor_info;

typedef struct ctn_linsolve_ops {
    const char *name;
    int indefinite;           /* 1: factors indefinite matrices and gives their inertia */
    int (*create)(ctn_ctx *ctx, const ctn_pattern *p, const ctn_la_options *o, void **impl);
    void (*destroy)(void *impl);
    int (*factor)(void *impl, const double *Kx, double shift, ctn_factor_info *info);
    int (*solve)(void *impl, const double *b, double *x);
    /* Optional (NULL): pivots of the last factorization below -tol (negative) and within
     * +-tol (zero), and the column (pattern order) of the first of either, -1 if none. */
    int (*inertia)(void *impl, double tol, long *negative, long *zero, long *first);
    ctn_la_ordering (*ordering)(const void *impl);    /* the ordering chosen */
    size_t (*factor_nnz)(const void *impl);        /* non-zeros of the factor */
    double (*flops)(const void *impl);             /* of one numeric factorization */
    /* Optional (NULL: column by column with solve): X = K \ B for an n x k block stored
     * by columns (leading dimension n; X and B do not alias). One pass over the factor
     * for all k columns: level-3 BLAS in a supernodal factor. */
    int (*solve_block)(void *impl, const double *B, double *X, size_t k);
    /* Optional: the solve's threads= option (0 auto, 1, n), which the backend's parallel
     * sites hand to the thread policy (core/threads.h); create is given it first. */
    void (*set_threads)(void *impl, int asked);
    /* Optional (both or neither): whether the next factorization can start before the
     * matrix is complete, and that factorization, which waits on feed for the columns it
     * needs (the assembly's thread publishes them in order), or gives up when the feed
     * is stopped. The same factor as factor. */
    int (*feedable)(const void *impl);
    int (*factor_feed)(void *impl, const double *Kx, double shift, ctn_feed *feed, ctn_factor_info *info);
    /* Optional (NULL: one): the threads of the last solve. */
    int (*solve_threads)(const void *impl);
    /* Optional (NULL: the name): what the results call the solver used ("petsc-mumps",
     * "petsc-cg-gamg": the PETSc types the options chose). */
    const char *(*label)(const void *impl);
    /* Optional (NULL: the solver takes whole matrices only): as create, for this process's
     * share of a matrix distributed over the processes of the context's communicator by
     * columns: p holds columns c0 .. c1 - 1 of the n x n upper triangle (p->n = c1 - c0,
     * colptr from 0, row indices global), the processes' ranges consecutive in rank order;
     * factor is then given those columns' values, solve the whole right-hand side and
     * gives the whole solution on every process. */
    int (*create_cols)(ctn_ctx *ctx, const ctn_pattern *p, size_t n, size_t c0, size_t c1,
                       const ctn_la_options *o, void **impl);
} ctn_linsolve_ops;

typedef struct ctn_linsolve ctn_linsolve;

/* The registered solver of that name, NULL if none (the process's own: the PETSc ones
 * are found by ctn_linsolve_create on an MPI communicator, dist/plugin.h). */
const ctn_linsolve_ops *ctn_linsolve_find(const char *name);
/* 1 if name is one of the MPI module's solvers ("petsc", "petsc-ldl", "petsc-cg",
 * "petsc-inertia"), loaded or not. */
int ctn_linsolve_module_name(const char *name);
/* The solver an analysis of ctx uses for the one it names ("cholmod" or "cholmod-ldl",
 * a strategy's default or the file's; "cholmod-inertia": the stability check's count,
 * "cholmod-ldl" in one process): on an MPI communicator (dist/plugin.h) the PETSc one
 * of the same kind ("petsc", "petsc-ldl", "petsc-inertia"), else the name itself. */
const char *ctn_linsolve_default(const ctn_ctx *ctx, const char *name);
/* The solver's label (ops->label, else its name). */
const char *ctn_linsolve_label(const ctn_linsolve *s);
/* Set up solver `name` on pattern p (symbolic work, done once) for a solve that asked
 * for `threads` (its threads= option: 0 auto, 1, n; ctn_linsolve_create: 0). */
int ctn_linsolve_create(ctn_ctx *ctx, const char *name, const ctn_pattern *p, ctn_la_ordering ord,
                        ctn_linsolve **out);
int ctn_linsolve_create_threads(ctn_ctx *ctx, const char *name, const ctn_pattern *p, ctn_la_ordering ord,
                                int threads, ctn_linsolve **out);
/* The same with every option (o NULL or o->size 0: the defaults). */
int ctn_linsolve_create_opts(ctn_ctx *ctx, const char *name, const ctn_pattern *p, const ctn_la_options *o,
                             ctn_linsolve **out);
/* Set up solver `name` on this process's columns c0 .. c1 - 1 of an n x n matrix
 * distributed by columns (create_cols above): CTN_ERR_INVALID if it takes whole
 * matrices only. */
int ctn_linsolve_create_cols(ctn_ctx *ctx, const char *name, const ctn_pattern *p, size_t n, size_t c0, size_t c1,
                             int threads, ctn_linsolve **out);
void ctn_linsolve_destroy(ctn_linsolve **s);
const ctn_linsolve_ops *ctn_linsolve_type(const ctn_linsolve *s);
/* Factor K + shift I from values Kx (pattern order). A failed pivot is an outcome in
 * *info (status CTN_OK); a backend failure is a status (message in the context). */
int ctn_linsolve_factor(ctn_linsolve *s, const double *Kx, double shift, ctn_factor_info *info);
/* Whether the next factorization can follow an assembly on another thread, and that
 * factorization: it waits on feed for the columns it needs (published in order by the
 * assembling thread) and returns once it is done, or without a factor (info->ok = 0,
 * fail_col = -1) if the feed is stopped; the same factor as ctn_linsolve_factor. It may
 * run on a thread of its own; its CPU time is that thread's. */
int ctn_linsolve_feedable(const ctn_linsolve *s);
int ctn_linsolve_factor_feed(ctn_linsolve *s, const double *Kx, double shift, ctn_feed *feed, ctn_factor_info *info);
/* x = K \ b with the last factorization (x and b may alias). */
int ctn_linsolve_solve(ctn_linsolve *s, const double *b, double *x);
/* X = K \ B for the n x k block B (columns, leading dimension n; X and B do not alias):
 * the backend's block solve, else k single solves. One thread, as ctn_linsolve_solve. */
int ctn_linsolve_solve_block(ctn_linsolve *s, const double *B, double *X, size_t k);
/* Inertia of the last factorization (pivots within +-tol count as zero; first: the
 * column of the first non-positive one, -1 if none): CTN_ERR_INVALID if the solver
 * cannot tell. */
int ctn_linsolve_inertia(ctn_linsolve *s, double tol, long *negative, long *zero, long *first);
ctn_la_ordering ctn_linsolve_ordering(const ctn_linsolve *s);
size_t ctn_linsolve_factor_nnz(const ctn_linsolve *s);
double ctn_linsolve_flops(const ctn_linsolve *s);
/* The solve's threads= option: the OpenMP threads of the numeric factorizations (n > 0
 * that many, 0 the default, one thread; linsolve.c says why; at most the context's
 * limit, ctn_thr_openmp) and what the backend's parallel sites ask the thread policy. The threads of the last one, and its
 * CPU seconds. */
void ctn_linsolve_set_threads(ctn_linsolve *s, int n);
int ctn_linsolve_threads(const ctn_linsolve *s);
/* The threads of the last triangular solve (1 before any). */
int ctn_linsolve_solve_threads(const ctn_linsolve *s);
double ctn_linsolve_cpu(const ctn_linsolve *s);
/* The order of the matrix. */
size_t ctn_linsolve_order(const ctn_linsolve *s);

/* Threads (threads.c): run the calling thread's OpenMP regions on n threads (its own
 * setting, which OpenBLAS follows) until ctn_threads_pop restores the caller's;
 * fn(arg) with every OpenMP region it enters, those that ask for a number of threads
 * too, limited to n threads (the calling thread's limit: threads.c says why and how);
 * the name of the BLAS loaded in the process. */
typedef struct ctn_threads_saved {
    int threads;               /* the caller's count, 0 without OpenMP */
} ctn_threads_saved;
void ctn_threads_push(int n, ctn_threads_saved *old);
void ctn_threads_pop(const ctn_threads_saved *old);
void ctn_threads_limit(int n, void (*fn)(void *), void *arg);
void ctn_blas_name(char *buf, size_t size);

/* The backends (one file each). */
extern const ctn_linsolve_ops ctn_cholmod_ll_ops;
extern const ctn_linsolve_ops ctn_cholmod_ldl_ops;

#endif
