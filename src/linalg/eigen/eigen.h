/* Internal: the symmetric generalized eigenproblem A x = lambda B x (A symmetric, B
 * symmetric positive semi-definite) by shift-invert Lanczos, the operator
 * (A - sigma B)^-1 B applied by the caller (a factorization it owns), the B inner
 * product by the caller's B x. Two solvers find the nev eigenvalues nearest sigma and
 * their B-orthonormal eigenvectors:
 *   ctn_eigen_shift_invert  ARPACK's implicitly restarted Lanczos method in its mode 3,
 *                           one vector at a time (arpack.c, the only file that includes
 *                           ARPACK's header);
 *   ctn_eigen_block         a thick-restarted block Lanczos method with full
 *                           re-orthogonalization, the operator applied to blocks of
 *                           vectors (one multi-right-hand-side solve each), the dense work
 *                           by BLAS-3 and LAPACK (blanczos*.c). */
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
    /* The block solver's (ARPACK's needs neither): Y = (A - sigma B)^-1 X for k columns
     * of n (Y and X do not alias), and y = A x (the residual check). */
    int (*solve_block)(void *ud, const double *X, double *Y, int k);
    void (*amul)(void *ud, const double *x, double *y);
    /* y = |A| |x| + |lambda| |B| |x| (entrywise absolute values): eps times it bounds the
     * rounding of the residual A x - lambda B x itself. */
    void (*absmul)(void *ud, const double *x, double lambda, double *y);
    /* Optional (NULL: bmul or amul twice): y0 = B x0, y1 = B x1, or with A, in one pass
     * over the matrix (the block solver's products go by pairs of columns). */
    void (*bmul2)(void *ud, const double *x0, const double *x1, double *y0, double *y1);
    void (*amul2)(void *ud, const double *x0, const double *x1, double *y0, double *y1);
    /* Block solver: its threads for the dense work over the basis. 0: two where the
     * thread policy allows it (core/threads.h, CTN_THR_LANCZOS), else one; 1: one; 2:
     * two halves (on two threads where the policy allows). With two,
     * bmul, amul and absmul are called from two threads at once (on different
     * vectors); the solves always from the calling thread. */
    int threads;
    /* The solve's threads= option (0 auto, 1, n): the helpers the thread policy lets the
     * block solver keep busy (core/threads.h). */
    int asked;
} ctn_eigen_ops;

typedef struct ctn_eigen_info {
    int nconv;                /* converged Ritz pairs */
    int restarts;             /* implicit restarts (ARPACK's iterations) */
    int ops;                  /* applications of the operator (solves) */
    int block;                /* block solver: the block width */
    int block_solves;         /* block solver: multi-right-hand-side solves */
    double max_residual;      /* block solver: largest |A x - lambda B x| / |A x| of the
                                 pairs returned (the denominator at least |sigma| |B x|) */
    double max_floor;         /* block solver: the largest eps | |A||x| + |lambda||B||x| | /
                                 |A x| of a pair above 1e-10: the rounding of its residual */
} ctn_eigen_info;

/* The nev (1 <= nev < n) eigenpairs nearest sigma: lambda[nev] ascending, and in *vecs
 * a new n x ncv array (free with ctn_free) whose first nev columns are the eigenvectors
 * in the order of lambda. CTN_ERR_NOCONV when fewer than nev converged within the
 * iteration limit, CTN_ERR_LINALG for an ARPACK error, a status of ops->solve, or
 * CTN_ERR_NOMEM. */
int ctn_eigen_shift_invert(ctn_ctx *ctx, int n, int nev, double sigma, const ctn_eigen_ops *ops,
                           double *lambda, double **vecs, ctn_eigen_info *info);

/* As ctn_eigen_shift_invert (same arguments, results and statuses; ops->solve_block,
 * ops->bmul, ops->amul and ops->absmul are used): block Lanczos on (A - sigma B)^-1 B in
 * the B inner product, blocks of 4 columns (nev when fewer, at least 2), a basis of at
 * most min(n, nev + max(nev, 64)) columns (memory: two n x that arrays, the basis and
 * B times it), thick restarts keeping nev + 4 Ritz vectors. A pair is converged when its
 * Ritz estimate is below 1e-12 |theta| (theta = 1 / (lambda - sigma)) and then, after a
 * final Rayleigh-Ritz of (A, B) on the nev vectors, checked for all nev together, when
 * its true residual |A x - lambda B x| / |A x| <= 1e-10 or within 10 times the rounding
 * bound of that residual (ops->absmul; info->max_floor): double precision can show no
 * better. When b of the nev eigenvalues are equal (a block Krylov space holds at most b
 * copies) a second round from a random block checks that no copy was missed.
 * CTN_ERR_NOCONV when a residual stops halving for 8 checks (the Ritz pairs of T hold
 * no more digits: a shift within about 1e-8 of an eigenvalue) or after 300 blocks. nev
 * may equal n. */
int ctn_eigen_block(ctn_ctx *ctx, int n, int nev, double sigma, const ctn_eigen_ops *ops, double *lambda,
                    double **vecs, ctn_eigen_info *info);

#endif
