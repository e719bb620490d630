/* Internal: preconditioned conjugate gradients for a symmetric positive definite system
 * A x = b, the operator and the preconditioner given as callbacks (like gmres.h), the
 * workspace the caller's (no allocation). catena uses it to take a Newton step on the
 * current tangent with the Cholesky factor of an earlier one as the preconditioner. */
#ifndef CTN_LINALG_PCG_H
#define CTN_LINALG_PCG_H

#include "catena/core.h"
#include "linalg/linsolve.h"

typedef struct ctn_pcg {
    size_t n;                  /* order */
    int (*apply)(void *data, const double *x, double *y);     /* y = A x */
    int (*precond)(void *data, const double *x, double *y);   /* y = M^-1 x */
    void *data;
    /* a . b over the vectors' layout (a distributed engine's reduction); NULL: the plain
       local sum, which is what it is in one process */
    double (*dot)(void *data, const double *a, const double *b);
    double *r, *z, *p, *q;     /* workspace: 4 n doubles (ctn_pcg_init) */
} ctn_pcg;

/* Lay out the workspace (4 n doubles). */
void ctn_pcg_init(ctn_pcg *g, size_t n, double *work);
/* From x0 = M^-1 b, iterate until |b - A x| <= target or maxit iterations; *res gets
 * |b - A x| reached, *iters the iterations (preconditioner calls: iters + 1). *posdef = 0
 * if a search direction had p'Ap <= 0 (A is not positive definite there: stopped). A
 * status only for a failed callback. */
int ctn_pcg_solve(ctn_pcg *g, const double *b, double *x, double target, int maxit, double *res,
                  int *iters, int *posdef);
/* y = A x, A symmetric given by the upper triangle on pattern p with values Ax. */
void ctn_sym_matvec(const ctn_pattern *p, const double *Ax, const double *x, double *y);
/* y0 = A x0 and y1 = A x1 in one pass over A (each entry read once for both; the
 * same arithmetic as two ctn_sym_matvec). */
void ctn_sym_matvec2(const ctn_pattern *p, const double *Ax, const double *x0, const double *x1, double *y0,
                     double *y1);
/* y += |A| |x| (entrywise absolute values; the rounding bound of A x). */
void ctn_sym_matvec_abs(const ctn_pattern *p, const double *Ax, const double *x, double *y);
/* y += |A| |x| + s |B| |x| (s >= 0), A and B on the same pattern: one pass over both. */
void ctn_sym_matvec_abs_pair(const ctn_pattern *p, const double *Ax, const double *Bx, double s, const double *x,
                             double *y);

#endif
