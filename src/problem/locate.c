/* The column of a failed factorization that its solver did not name (MUMPS pivots:
 * "petsc" reports a tangent that is not positive definite without a column). Every
 * process holds the whole tangent (docs/parallel.md), or gathers it when the ranks hold
 * its columns (dist.c), so CHOLMOD's LL' without pivoting names it as in one process:
 * called once, when a solve ends on it. */
#include "problem/problem.h"

long ctn_problem_fail_col(ctn_problem *p, double shift)
{
    ctn_linsolve *ll = NULL;
    ctn_pattern pat;
    ctn_factor_info info = { 1, -1 };
    double *Kx = NULL;
    if (!p->ndof || ctn_problem_whole_K(p, &pat, &Kx)) return -1;
    if (ctn_linsolve_create_threads(p->ctx, "cholmod", &pat, CTN_LA_ORDER_AUTO, p->opt.threads, &ll)) {
        ctn_problem_whole_K_done(p, &pat, Kx);
        return -1;
    }
    if (ctn_linsolve_factor(ll, Kx, shift, &info)) info.fail_col = -1;
    ctn_linsolve_destroy(&ll);
    ctn_problem_whole_K_done(p, &pat, Kx);
    return info.ok ? -1 : info.fail_col;
}
