/* Internal: sparse Cholesky backend (SuiteSparse CHOLMOD). The matrix pattern is fixed
 * at creation (upper triangle, compressed columns, sorted); the symbolic analysis and
 * fill-reducing ordering are done once; each iteration writes the values in place
 * (ctn_chol_values), refactorizes numerically and solves, without allocation. */
#ifndef CTN_LINALG_CHOL_H
#define CTN_LINALG_CHOL_H

#include "catena/solve.h"
#include "core/ctx.h"

typedef struct ctn_chol ctn_chol;

/* n x n symmetric matrix with the given upper pattern (copied). ord picks the ordering
 * (CTN_ORDER_AUTO: natural unless AMD needs under 1/1.1 of its flops). */
int ctn_chol_create(ctn_ctx *ctx, size_t n, const int *colptr, const int *rowind,
                    ctn_ordering ord, ctn_chol **out);
/* The same with indefinite = 1: a simplicial LDL' factorization that accepts
 * indefinite matrices (no pivoting; fails only on a zero pivot), for arc-length
 * continuation through limit points. */
int ctn_chol_create_ex(ctn_ctx *ctx, size_t n, const int *colptr, const int *rowind,
                       ctn_ordering ord, int indefinite, ctn_chol **out);
void ctn_chol_destroy(ctn_chol **c);
/* The values array (nnz, pattern order) to assemble into. */
double *ctn_chol_values(ctn_chol *c);
/* Numeric factorization. CTN_OK, or CTN_ERR_LINALG with *fail_col = the (unpermuted)
 * column whose pivot was not positive (the matrix is not positive definite), or
 * -1 for another backend failure (message in ctx). */
int ctn_chol_factorize(ctn_chol *c, long *fail_col);
/* Factorize A + shift I (shift >= 0), same results as ctn_chol_factorize. */
int ctn_chol_factorize_shifted(ctn_chol *c, double shift, long *fail_col);
/* x = A \ b using the last factorization (x and b may alias). */
int ctn_chol_solve(ctn_chol *c, const double *b, double *x);
ctn_ordering ctn_chol_ordering(const ctn_chol *c);
size_t ctn_chol_factor_nnz(const ctn_chol *c);

#endif
