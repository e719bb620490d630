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

typedef struct ctn_analysis ctn_analysis;

/* The registered analyses: their count and the name of the i-th ("static",
 * "stability", "modal"); NULL for i out of range. */
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
