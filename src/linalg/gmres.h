/* Internal: restarted GMRES(m) with right preconditioning, for non-symmetric systems
 * A x = b whose symmetric part a factorization nearly inverts. The caller supplies the
 * operator and the preconditioner as callbacks and the workspace (no allocation). */
#ifndef CTN_LINALG_GMRES_H
#define CTN_LINALG_GMRES_H

#include "catena/core.h"

typedef struct ctn_gmres {
    size_t n;                  /* order */
    int m;                     /* Krylov vectors per cycle */
    int (*apply)(void *data, const double *x, double *y);     /* y = A x */
    int (*precond)(void *data, const double *x, double *y);   /* y = M^-1 x (y may be x) */
    void *data;
    /* a . b over the vectors' layout; NULL: the plain local sum (pcg.h) */
    double (*dot)(void *data, const double *a, const double *b);
    double *V, *H;             /* workspace (ctn_gmres_init) */
} ctn_gmres;

/* Doubles of workspace for order n and m vectors. */
size_t ctn_gmres_work_size(size_t n, int m);
/* Lay the workspace out; set apply, precond and data afterwards. */
void ctn_gmres_init(ctn_gmres *g, size_t n, int m, double *work);
/* Solve from x0 = M^-1 b until |b - A x| <= rtol |b| or maxcycles restarts; *rel gets
 * the relative residual reached (an outcome: the caller judges it), *iters the
 * iterations. A status only for a failed callback. */
int ctn_gmres_solve(ctn_gmres *g, const double *b, double *x, double rtol, int maxcycles,
                    double *rel, int *iters);

#endif
