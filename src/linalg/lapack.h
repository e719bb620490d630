/* Internal: the Fortran BLAS and LAPACK routines linalg/ calls (the reference interface,
 * column-major, every argument by address, the hidden lengths of character arguments
 * last). Linked from the system's libblas (OpenBLAS on Debian through its alternatives)
 * and liblapack. */
#ifndef CTN_LINALG_LAPACK_H
#define CTN_LINALG_LAPACK_H

#include <stddef.h>

/* C = alpha op(A) op(B) + beta C */
void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k, const double *alpha,
            const double *a, const int *lda, const double *b, const int *ldb, const double *beta, double *c,
            const int *ldc, size_t lta, size_t ltb);
/* B = alpha B op(A)^-1 (side "R") with A triangular */
void dtrsm_(const char *side, const char *uplo, const char *ta, const char *diag, const int *m, const int *n,
            const double *alpha, const double *a, const int *lda, double *b, const int *ldb, size_t ls, size_t lu,
            size_t lt, size_t ld);
/* Cholesky A = R^T R (uplo "U") */
void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info, size_t lu);
/* y = alpha op(A) x + beta y */
void dgemv_(const char *ta, const int *m, const int *n, const double *alpha, const double *a, const int *lda,
            const double *x, const int *incx, const double *beta, double *y, const int *incy, size_t lt);
/* The generalized symmetric-definite problem A x = lambda B x (itype 1) */
void dsygv_(const int *itype, const char *jobz, const char *uplo, const int *n, double *a, const int *lda,
            double *b, const int *ldb, double *w, double *work, const int *lwork, int *info, size_t lj, size_t lu);
/* Eigenvalues (ascending) and eigenvectors of a symmetric matrix */
void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda, double *w, double *work,
            const int *lwork, int *info, size_t lj, size_t lu);
/* Solve A X = B with the Cholesky factor of dpotrf */
void dpotrs_(const char *uplo, const int *n, const int *nrhs, const double *a, const int *lda, double *b,
             const int *ldb, int *info, size_t lu);
/* x = op(A)^-1 x with A triangular */
void dtrsv_(const char *uplo, const char *ta, const char *diag, const int *n, const double *a, const int *lda,
            double *x, const int *incx, size_t lu, size_t lt, size_t ld);

/* The symmetric-definite pencil reduced to standard form: A <- U^-T A U^-1 (itype 1,
 * uplo "U"), B = U^T U from dpotrf */
void dsygst_(const int *itype, const char *uplo, const int *n, double *a, const int *lda, const double *b,
             const int *ldb, int *info, size_t lu);
/* A = Q T Q^T, T tridiagonal (d, e), Q by its reflectors (in A, tau) */
void dsytrd_(const char *uplo, const int *n, double *a, const int *lda, double *d, double *e, double *tau,
             double *work, const int *lwork, int *info, size_t lu);
/* All eigenvalues of a symmetric tridiagonal matrix, ascending in d (d, e overwritten) */
void dsterf_(const int *n, double *d, double *e, int *info);
/* Selected eigenvalues of a symmetric tridiagonal matrix by bisection (order "B": by
 * block, with iblock and isplit for dstein) */
void dstebz_(const char *range, const char *order, const int *n, const double *vl, const double *vu, const int *il,
             const int *iu, const double *abstol, const double *d, const double *e, int *m, int *nsplit, double *w,
             int *iblock, int *isplit, double *work, int *iwork, int *info, size_t lr, size_t lo);
/* Their eigenvectors by inverse iteration */
void dstein_(const int *n, const double *d, const double *e, const int *m, const double *w, const int *iblock,
             const int *isplit, double *z, const int *ldz, double *work, int *iwork, int *ifail, int *info);
/* C <- Q C with Q of dsytrd */
void dormtr_(const char *side, const char *uplo, const char *trans, const int *m, const int *n, const double *a,
             const int *lda, const double *tau, double *c, const int *ldc, double *work, const int *lwork,
             int *info, size_t ls, size_t lu, size_t lt);

#endif
