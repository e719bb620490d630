/* Internal: the modal analysis's working state, shared by modes.c (the solve) and
 * modes_post.c (what is stored of each mode). */
#ifndef CTN_SOLVE_MODES_H
#define CTN_SOLVE_MODES_H

#include "problem/problem.h"

#define CTN_TWO_PI 6.28318530717958647692

typedef struct ctn_modal {
    ctn_problem *p;
    const ctn_modal_options *opt;
    double *Mx, *Ax;          /* nnz: mass and K - sigma M values, pattern order */
    int *mcol, *mrow;         /* M's own upper pattern: its nonzeros only (ndof + 1, mnz) */
    double *mval;             /* mnz: their values */
    double *d;                /* state: the solution's displacements */
    double *diag;             /* ndof: the lumped mass diagonal */
    double *w0, *w1;          /* ndof scratch */
    double *lambda;           /* count: omega^2, ascending */
    ctn_linsolve *ldl;        /* LDL' on the pattern when LL' of K - sigma M failed */
    ctn_linsolve *ls;         /* the factorization in use */
    double sigma;             /* the shift [1/s^2] */
    double ztol;              /* |omega^2| below it: a zero mode */
    double worst;             /* the largest |K phi - omega^2 M phi| / (|K phi| + omega^2 |M phi|)
                                 of the modes that are not zero modes (ctn_modes_fill) */
    int failed;               /* how many of them exceed CTN_MODE_RESIDUAL_MAX */
    ctn_modal_summary sum;
} ctn_modal;

/* Count and mass checks of a modal analysis (before a solve, too): the lumped diagonal
 * into diag (ndof) and the moving mass into tot; CTN_ERR_MODEL at the `modes` line. */
int ctn_modal_check(ctn_problem *p, const ctn_modal_options *o, double *diag, double tot[3]);
/* y = M x, on M's own pattern. */
void ctn_modal_mass(const ctn_modal *md, const double *x, double *y);
/* Store the modes (the first count columns of V, n each) in res (modes_post.c). */
void ctn_modes_fill(ctn_modal *md, double *V, ctn_modes *res);
/* A mode is an eigenpair only when |K phi - omega^2 M phi| <= CTN_MODE_RESIDUAL_MAX
 * (|K phi| + omega^2 |M phi|): converged modes are at 1e-16 to 1e-10 of it; a shift far
 * beyond the spectrum (omega^2 - sigma rounds to -sigma) gives 1e-3 and worse. */
#define CTN_MODE_RESIDUAL_MAX 1e-8

#endif
