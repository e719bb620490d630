/* Internal: the tangent's assembly overlapped with its factorization (overlap.c). */
#ifndef CTN_SOLVE_OVERLAP_H
#define CTN_SOLVE_OVERLAP_H

#include "assemble/asm.h"
#include "linalg/linsolve.h"

#define CTN_OVERLAP_MIN_DOF 30000   /* below, a thread's start costs what it saves */

typedef struct ctn_overlap {
    int collapsed;             /* an element collapsed (bad: the first); the factor is
                                  then of meaningless values */
    size_t bad;
    double U;                  /* stored energy */
    ctn_factor_info info;      /* the factorization's outcome */
    double t_asm, t_fac;       /* wall seconds of each (they overlap) */
} ctn_overlap;

/* Whether ctn_overlap_eval_factor can overlap these (a model assembled node by node, a
 * factorization that follows the columns, two CPUs). */
int ctn_overlap_possible(const ctn_asm *a, const ctn_linsolve *ls);
/* f_int and K at d into f and Kx (as ctn_asm_eval) on a second thread, and K + shift I
 * factorized on the calling thread as its columns are done. The same results as
 * ctn_asm_eval then ctn_linsolve_factor, which it falls back to if the thread cannot
 * start. A status only for the factorization's failure (a pivot is an outcome). */
int ctn_overlap_eval_factor(const ctn_asm *a, ctn_linsolve *ls, const double *d, unsigned mode, double *f,
                            double *Kx, double shift, ctn_overlap *out);

#endif
