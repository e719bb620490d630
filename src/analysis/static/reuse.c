/* A Newton step without a new factorization: once Newton converges quadratically the
 * tangent changes little from one iterate to the next, so the Cholesky factor of the
 * last one is an excellent preconditioner for the current one: conjugate gradients on
 * K(d) dd = r, preconditioned by it, reach the Newton step in a few triangular solves
 * (each a fraction of a factorization's cost), to the accuracy the caller's forcing
 * term asks (correct.c). The step is Newton's on the current tangent, not a chord step:
 * convergence stays quadratic to the tolerance asked, and the residual is never
 * modified. The stability of a state reached this way
 * is checked by a factorization of its own tangent (drive.c): the factor held is of an
 * earlier one, which may be definite where the solution is not. */
#include "problem/problem.h"

#include "linalg/pcg.h"

#define CTN_REUSE_CG_MAX 30   /* conjugate-gradient iterations before factoring instead */

static int apply(void *data, const double *x, double *y)
{
    ctn_problem *p = data;
    ctn_problem_symv(p, p->Kx, x, y);
    return CTN_OK;
}

static int precond(void *data, const double *x, double *y)
{
    ctn_problem *p = data;
    p->sum->solves++;
    return ctn_linsolve_solve(p->ls, x, y);
}

int ctn_problem_reuse_step(ctn_problem *p, double target, double rmax, int *ok)
{
    *ok = 0;
    ctn_problem_settle(p);
    /* Not with fixed moments on spun nodes: their tangent has the non-symmetric term of
     * spin.c, which conjugate gradients on K would leave out (a step that is not
     * Newton's: the roll-up's residual went back up 200 times). */
    if (!p->cg || !p->ls || !p->spd_factor || p->sp) return CTN_OK;
    double t0 = ctn_clock(), res;
    int iters, posdef;
    ctn_pcg g = { .apply = apply, .precond = precond, .data = p, .dot = ctn_problem_dot };
    ctn_pcg_init(&g, p->ndof, p->cg);
    int rc = ctn_pcg_solve(&g, p->r, p->dd, target, CTN_REUSE_CG_MAX, &res, &iters, &posdef);
    p->sum->t_solve += ctn_clock() - t0;
    *ok = !rc && posdef && res <= rmax;
    if (!*ok) return rc;
    p->sum->reused++;
    p->last_definite = 0;          /* the factor held is of a tangent more than one
                                      correction away: stability is checked afresh */
    return rc;
}
