/*
 * catena/solve.h - the Newton-Raphson solution of a model and its results.
 *
 * ctn_solve() runs pure Newton-Raphson on K_T(d) dd = f_ext - f_int(d), d <- d + dd,
 * from the model's starting displacements, with a sparse Cholesky (CHOLMOD) tangent.
 * Non-convergence is an outcome, not an error: ctn_solve returns CTN_OK with a
 * solution whose reason says why it stopped (ctn_reason). Errors (out of memory,
 * invalid model, backend failure) return a status and no solution.
 */
#ifndef CATENA_SOLVE_H
#define CATENA_SOLVE_H

#include <stddef.h>

#include "catena/core.h"
#include "catena/model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Fill-reducing ordering of the tangent's factorization. */
typedef enum ctn_ordering {
    CTN_ORDER_AUTO = 0,    /* analyze natural and AMD, keep the one with fewer flops
                              (natural on ties within 10 %: it keeps memory access local) */
    CTN_ORDER_NATURAL = 1, /* the model's DOF order */
    CTN_ORDER_AMD = 2      /* approximate minimum degree */
} ctn_ordering;

/* Called after every Newton iteration (the iteration log). it = 1, 2, ...;
 * rnorm = |f_ext - f_int| after the step; dnorm = |dd| of the step. */
typedef void (*ctn_monitor_fn)(void *data, int it, double rnorm, double dnorm);

/* Solver options; ctn_solve_options_default() fills the defaults. */
typedef struct ctn_solve_options {
    double tol;           /* residual test |r| <= tol * |f_ext| (default 1e-10) */
    double dtol;          /* increment test |dd| <= dtol * (|d| + L_ref), L_ref the
                             diagonal of the model's bounding box (default 1e-8) */
    int maxit;            /* most Newton iterations (default 50) */
    ctn_ordering ordering;
    ctn_monitor_fn monitor;  /* NULL: no log */
    void *monitor_data;
} ctn_solve_options;

void ctn_solve_options_default(ctn_solve_options *opt);
/* The options given by the model's `solve` directive (defaults if none). */
void ctn_model_solve_options(const ctn_model *m, ctn_solve_options *opt);
/* Record solve options in the model (what the `solve` directive does). */
int ctn_model_set_solve_options(ctn_model *m, const ctn_solve_options *opt);

/* Why the Newton iteration stopped. Positive: converged; negative: diverged. */
typedef enum ctn_reason {
    CTN_CONVERGED = 1,              /* both residual and increment tests met */
    CTN_DIVERGED_MAXIT = -1,        /* maxit iterations without convergence */
    CTN_DIVERGED_NANORINF = -2,     /* a NaN or Inf appeared; the last finite state is kept */
    CTN_DIVERGED_INDEFINITE = -3    /* tangent not positive definite (compressed or
                                       unrestrained DOF); see fail_node, fail_dir */
} ctn_reason;

/* Name of a reason, e.g. "converged", "tangent not positive definite". */
const char *ctn_reason_name(ctn_reason r);

typedef struct ctn_solution ctn_solution;

/* Summary of a solution. */
typedef struct ctn_solve_summary {
    ctn_reason reason;
    int iterations;       /* Newton steps taken */
    double residual;      /* final |f_ext - f_int| over free DOFs [force] */
    double increment;     /* last |dd| [length] */
    double fext_norm;     /* |f_ext| over free DOFs [force] */
    int fail_node;        /* CTN_DIVERGED_INDEFINITE: user id of the node whose DOF had
                             a non-positive pivot, else 0 */
    int fail_dir;         /* its direction 0 = x, 1 = y, 2 = z, -1 if none */
    ctn_ordering ordering;/* the ordering used (never AUTO) */
    size_t ndof;          /* free DOFs */
    size_t nnz_factor;    /* non-zeros of the Cholesky factor */
    double t_setup;       /* wall seconds: DOF map, pattern, scatter map, ordering and
                             symbolic analysis (once per model) */
    double t_assemble;    /* wall seconds in all iterations: internal forces, tangent
                             values and residual */
    double t_factor;      /* wall seconds in all numeric factorizations */
    double t_solve;       /* wall seconds in all triangular solves */
} ctn_solve_summary;

/* Element state at the solution. */
typedef struct ctn_element_state {
    double length;        /* current length l [length] */
    double strain;        /* strain of the element's measure (Green-Lagrange or engineering) */
    double force;         /* axial tension N (true force, >= 0 in tension) [force] */
    double stress;        /* N / A, A the unstressed area [force/length^2] */
    int slack;            /* 1 if a tension-only element carries no force */
} ctn_element_state;

/* Solve the model. opt NULL: the model's own options. On CTN_OK *out owns a solution
 * (free it with ctn_solution_destroy), whatever the reason. */
int ctn_solve(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt,
              ctn_solution **out);
void ctn_solution_destroy(ctn_solution **s);

void ctn_solution_summary(const ctn_solution *s, ctn_solve_summary *out);
/* Residual norm history: [0] before the first step, [k] after step k. *n gets
 * iterations + 1. Owned by the solution. */
const double *ctn_solution_residual_history(const ctn_solution *s, size_t *n);
/* Increment norm history: [k-1] = |dd| of step k; *n gets iterations. */
const double *ctn_solution_increment_history(const ctn_solution *s, size_t *n);
/* Displacements, 3 per node in model node order. Owned by the solution. */
const double *ctn_solution_displacements(const ctn_solution *s);
/* Support reactions, 3 per node: f_int - f_ext on fixed DOFs, 0 on free ones. */
const double *ctn_solution_reactions(const ctn_solution *s);
/* State of element i (model element order). */
int ctn_solution_element(const ctn_solution *s, size_t i, ctn_element_state *out);

/* Mid-span sag of generated cable i (ctn_model_cable): the distance, along gravity,
 * from the chord's midpoint to the deformed cable at the point whose horizontal
 * projection (normal to gravity) is the chord's midpoint. Without gravity, or for a
 * vertical chord, the point is the one at mid-chord along the chord. */
int ctn_solution_cable_sag(const ctn_model *m, const ctn_solution *s, size_t i, double *sag);

#ifdef __cplusplus
}
#endif
#endif
