/* Internal: the tangent's factorization beside its assembly (overlap.c). */
#ifndef CTN_SOLVE_OVERLAP_H
#define CTN_SOLVE_OVERLAP_H

#include "assemble/asm.h"
#include "linalg/linsolve.h"

/* A factorization of K + shift I running on the context's helper thread
 * (core/threads.h), fed the columns of K by the caller's assembly. */
typedef struct ctn_overlap {
    int running;               /* started, not yet finished or abandoned */
    ctn_ctx *ctx;              /* whose helper runs it */
    int ticket;                /* ctn_thr_start's */
    ctn_feed feed;
    ctn_linsolve *ls;
    const double *Kx;
    double shift;
    int rc;                    /* the factorization's status and outcome */
    ctn_factor_info info;
    double t_fac;              /* its wall seconds */
} ctn_overlap;

/* Whether a factorization can follow the assembly of a (a model assembled node by node,
 * a solver whose next factorization follows the columns, the thread policy's leave). */
int ctn_overlap_possible(const ctn_asm *a, const ctn_linsolve *ls);
/* Start factorizing K + shift I from Kx (being assembled by a) on the helper: 1 if
 * started, 0 if not (not allowed, the helper busy or not startable: nothing to finish
 * then). */
int ctn_overlap_start(ctn_overlap *o, const ctn_asm *a, ctn_linsolve *ls, const double *Kx, double shift);
/* The assembly of f_int and K at d into f and Kx (as ctn_asm_eval), feeding o. */
int ctn_overlap_assemble(ctn_overlap *o, const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx,
                         double *U, size_t *bad);
/* Wait for the factorization: its status, its outcome in *info. */
int ctn_overlap_finish(ctn_overlap *o, ctn_factor_info *info);
/* The factorization is not wanted: stopped between two blocks of rows (the factor held
 * is then of no matrix) and joined. */
void ctn_overlap_abandon(ctn_overlap *o);
/* All of it at once: assembly and factorization overlapped, or one after the other if
 * the thread cannot start; the same results (bench_floor, tests). */
int ctn_overlap_eval_factor(const ctn_asm *a, ctn_linsolve *ls, const double *d, unsigned mode, double *f,
                            double *Kx, double shift, double *U, size_t *bad, int *collapsed,
                            ctn_factor_info *info);

#endif
