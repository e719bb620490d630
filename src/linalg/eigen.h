/* Internal: the symmetric generalized eigenproblem A x = lambda B x (A symmetric, B
 * symmetric positive semi-definite) by shift-invert Lanczos: ARPACK's implicitly
 * restarted Lanczos method in its mode 3, the operator (A - sigma B)^-1 B applied by the
 * caller (a factorization it owns), the B inner product by the caller's B x. Finds the
 * nev eigenvalues nearest sigma and their B-orthonormal eigenvectors. The only file that
 * includes ARPACK's header is arpack.c. */
#ifndef CTN_LINALG_EIGEN_H
#define CTN_LINALG_EIGEN_H

#include "core/ctx.h"

typedef struct ctn_eigen_ops {
    void *ud;
    /* y = (A - sigma B)^-1 b (n vectors; y and b do not alias). */
    int (*solve)(void *ud, const double *b, double *y);
    /* y = B x. */
    void (*bmul)(void *ud, const double *x, double *y);
    double *work;             /* n scratch for B x */
} ctn_eigen_ops;

typedef struct ctn_eigen_info {
    int nconv;                /* converged Ritz pairs */
    int restarts;             /* implicit restarts (ARPACK's iterations) */
    int ops;                  /* applications of the operator (solves) */
} ctn_eigen_info;

/* The nev (1 <= nev < n) eigenpairs nearest sigma: lambda[nev] ascending, and in *vecs
 * a new n x ncv array (free with ctn_free) whose first nev columns are the eigenvectors
 * in the order of lambda. CTN_ERR_NOCONV when fewer than nev converged within the
 * iteration limit, CTN_ERR_LINALG for an ARPACK error, a status of ops->solve, or
 * CTN_ERR_NOMEM. */
int ctn_eigen_shift_invert(ctn_ctx *ctx, int n, int nev, double sigma, const ctn_eigen_ops *ops,
                           double *lambda, double **vecs, ctn_eigen_info *info);

#endif
