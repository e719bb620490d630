/*
 * catena/analysis.h - analyses as objects over a problem.
 *
 * A problem (ctn_problem, catena/solve.h) holds what every analysis of a model shares:
 * the DOF map, the sparsity pattern, the element properties, the linear solver's
 * symbolic analysis, the tangent's values and the state vectors. An analysis is one
 * kind of computation on it, registered by name, with options of its own:
 *
 *   "static"     the static analysis by the options' method (newton, auto, arclength):
 *                options ctn_solve_options; makes a new solution
 *   "stability"  the inertia of the tangent at a solution's last step: options
 *                ctn_stability_options; its result is read with ctn_solution_stability
 *   "modal"      the natural modes about a converged solution: options
 *                ctn_modal_options; read with ctn_solution_mode
 *   "buckling"   the linear buckling factors about a converged solution: options
 *                ctn_buckling_options; read with ctn_solution_buckling
 *
 * Every options struct starts with its size (set by its _default function), so that a
 * program built against this header keeps working when later versions add keys at the
 * end: the library reads the keys the caller's size covers and takes the defaults for
 * the rest. A size of 0 (options not initialised by their _default function) is refused.
 *
 *   ctn_analysis *a;
 *   ctn_modal_options mo;
 *   ctn_modal_options_default(&mo);
 *   mo.count = 6;
 *   ctn_analysis_create(problem, "modal", &mo, &a);
 *   ctn_analysis_run(a, &solution);         (solution: a converged static solution)
 *   ctn_analysis_destroy(&a);
 */
#ifndef CATENA_ANALYSIS_H
#define CATENA_ANALYSIS_H

#include <stddef.h>

#include "catena/core.h"
#include "catena/solve.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* Options of the stability analysis: nothing to choose yet but the size. */
typedef struct ctn_stability_options {
    size_t size;          /* sizeof(ctn_stability_options), set by the _default function */
} ctn_stability_options;
void ctn_stability_options_default(ctn_stability_options *opt);
/* The defaults of the modal analysis (count 0: set it to the modes wanted). */
void ctn_modal_options_default(ctn_modal_options *opt);
/* CTN_OK, or CTN_ERR_INVALID with a message naming the option out of range (a count of
 * 0 is in range: no modal analysis). */
int ctn_modal_options_check(ctn_ctx *ctx, const ctn_modal_options *opt);

/* The defaults of the buckling analysis (count 0: set it to the factors wanted). */
void ctn_buckling_options_default(ctn_buckling_options *opt);
/* CTN_OK, or CTN_ERR_INVALID with a message naming the option out of range (a count of
 * 0 is in range: no buckling analysis). */
int ctn_buckling_options_check(ctn_ctx *ctx, const ctn_buckling_options *opt);

/* The buckling analysis works on dense matrices of the free DOFs (LAPACK's dsygv): at
 * most this many free DOFs; beyond, CTN_ERR_MODEL naming the limit. */
#define CTN_BUCKLING_MAX_DOFS 2000

/* Linear buckling about the converged state d of a solution's last step, with f that
 * step's total external loads (dead loads and moments, on the free DOFs): K_T the
 * tangent at d (it must be positive definite), u' = K_T^-1 f the tangent of the load
 * path, K' = dK_T/dlambda along it (a central difference of the tangent at d +- h u'),
 * and the factors lambda of the pencil K_T + (lambda - 1) K' singular: -K' phi = theta
 * K_T phi, lambda = 1 + 1/theta. On a linear pre-buckling path (K_T = K_M + K_G,
 * K_G linear in the load) this is the classical (K_M + lambda K_G^(f)) phi = 0 exactly.
 * docs/theory.md, "Linear buckling". */
typedef struct ctn_buckling_mode {
    double factor;            /* lambda > 0: the load factor on the step's loads */
    const double *shape;      /* phi, 3 translations per node in model node order (0 on
                                 fixed DOFs), scaled so that the largest |component| is 1
                                 and positive. Owned by the solution */
    int node;                 /* user id of the node that moves most */
    double residual;          /* |K(lambda) phi| / (|K_T phi| + |lambda - 1| |K' phi|),
                                 K(lambda) = K_T + (lambda - 1) K' */
} ctn_buckling_mode;

typedef struct ctn_buckling_summary {
    int count;                /* factors stored: the lowest positive ones, at most the
                                 count asked (fewer when the pencil has fewer) */
    int asked;                /* the count asked */
    int ndof;                 /* free DOFs of the dense problem */
    double h;                 /* the central difference's step along u' (h max|u'| is
                                 1e-5 of the model's size) */
    double load_norm;         /* |f| on the free DOFs */
    double t_total;           /* wall seconds of the buckling analysis */
} ctn_buckling_summary;

/* Buckling factors of a solution: the count (0 if no buckling analysis was run) and
 * factor k, lowest first; CTN_ERR_INVALID for k out of range. */
size_t ctn_solution_buckling_count(const ctn_solution *s);
int ctn_solution_buckling(const ctn_solution *s, size_t k, ctn_buckling_mode *out);
/* CTN_ERR_INVALID when no buckling analysis was run on s. */
int ctn_solution_buckling_summary(const ctn_solution *s, ctn_buckling_summary *out);

typedef struct ctn_analysis ctn_analysis;

/* The registered analyses: their count and the name of the i-th ("static",
 * "stability", "modal", "buckling"); NULL for i out of range. */
size_t ctn_analysis_count(void);
const char *ctn_analysis_type(size_t i);

/* An analysis of kind name on problem p, with options (the kind's options struct, its
 * size first; NULL: the defaults, for "static" the problem's own options). The options
 * are checked and copied: the caller's struct may go. CTN_ERR_INVALID for an unknown
 * name (the message lists the known ones), options out of range or not initialised, or
 * static options whose method needs another linear solver than the problem's (create
 * the problem with them). The problem must outlive the analysis. */
int ctn_analysis_create(ctn_problem *p, const char *name, const void *options, ctn_analysis **out);
/* Run it. "static": *s gets a new solution (any earlier *s is left to its owner);
 * the others run about the last step of the converged solution *s and store their
 * results in it. Non-convergence is an outcome (the solution's reason), not an error. */
int ctn_analysis_run(ctn_analysis *a, ctn_solution **s);
const char *ctn_analysis_name(const ctn_analysis *a);
/* NULL or *a == NULL is a harmless no-op; sets *a to NULL. */
void ctn_analysis_destroy(ctn_analysis **a);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
