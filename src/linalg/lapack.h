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

#endif
