/* Internal: the buckling analysis (buckling.c); its options: problem/buckling_options.h. */
#ifndef CTN_ANALYSIS_BUCKLING_H
#define CTN_ANALYSIS_BUCKLING_H

#include "problem/buckling_options.h"
#include "problem/problem.h"

/* The buckling factors about the last step of the converged solution s, stored in it
 * (replacing earlier ones). Errors: CTN_ERR_MODEL at opt->line for a count above the
 * free DOFs, more free DOFs than CTN_BUCKLING_MAX_DOFS, a step without loads, or a
 * loaded state that is not stable; CTN_ERR_INVALID for a solution that did not
 * converge; CTN_ERR_LINALG when LAPACK fails. */
int ctn_problem_buckling(ctn_problem *p, ctn_solution *s, const ctn_buckling_options *opt);
/* The checks that need only the problem (count above the free DOFs, more free DOFs than
 * CTN_BUCKLING_MAX_DOFS), made before the static solve too: CTN_ERR_MODEL at opt->line. */
int ctn_buckling_check(ctn_problem *p, const ctn_buckling_options *opt);
/* The non-linear check (buckling_check.c): the path from the solved state d0 (state)
 * under lambda (f + a0 K0 phi), fs the step's loads (state), K0 the tangent's values at
 * d0, phi the first mode (ndof) of linear factor lam1; its kind and factor into sum.
 * CTN_ERR_MODEL at `line` for a model with loads that follow the geometry. */
int ctn_buckling_nonlinear(ctn_problem *p, const ctn_solution *s, const double *d0, const double *fs, const double *K0,
                           const double *phi, double lam1, int line, ctn_buckling_summary *sum);

#endif
