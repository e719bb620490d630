/* Internal to the block Lanczos solver: its state, shared by blanczos.c (the Lanczos
 * process, Rayleigh-Ritz, restarts, convergence) and blanczos_orth.c (the B-orthogonal
 * bases). Columns are of length n, column-major; the basis V holds j columns, the first
 * ne of them expanded (the operator applied, their column of T known), the rest the
 * pending block. */
#ifndef CTN_LINALG_BLANCZOS_H
#define CTN_LINALG_BLANCZOS_H

#include "linalg/eigen/eigen.h"

#include <pthread.h>
#include <stddef.h>

#define CTN_BLZ_BMAX 16            /* widest block */
#define CTN_BLZ_DEFLATE 1e-10      /* a column of a projected block this much smaller
                                      after the block's earlier columns are taken out
                                      of it is linearly dependent on them */
#define CTN_BLZ_CHOLQR 1e-6        /* Cholesky QR only for blocks better conditioned
                                      than 1 / this (it squares the condition: W^T B W
                                      holds a block of condition 1e8 to no digit) */

typedef struct ctn_blz {
    ctn_ctx *ctx;
    const ctn_eigen_ops *ops;
    ctn_eigen_info *info;
    int n, nev, b, mcap;       /* order, wanted pairs, block width, most basis columns */
    int nkeep;                 /* Ritz vectors kept by a restart */
    double sigma;
    double *V;                 /* n x mcap: the basis (B-orthonormal) */
    double *W, *MW;            /* n x ws: a new block and B times it (MW: also B times the
                                  block a solve or a projection works on; the columns
                                  from b: the residuals' scratch) */
    int ws;                    /* max(2 b, 8) */
    int nx;                    /* columns of X: nev + b */
    double *X;                 /* n x nx: the final Rayleigh-Ritz's Ritz vectors */
    double *Rot;               /* 2 x CTN_BLZ_ROWS x mcap: ctn_blz_rotate's rows, per thread */
    double *C;                 /* p x nev: the final Rayleigh-Ritz's eigenvectors */
    int p;                     /* its Ritz vectors, min(nev + b, ne) */
    double *lam0;              /* nev: the eigenvalues of the round before */
    int need;                  /* Ritz pairs that must converge: nev, then nev + 1 */
    double *T;                 /* mcap x mcap: V^T B OP V (upper triangle) */
    double *S, *theta;         /* mcap x mcap, mcap: Ritz vectors and values of T */
    double *H;                 /* mcap x 2b: coefficients of a block against V (two passes) */
    double *Y;                 /* 2 mcap x mcap: selected Ritz vectors of T; the final
                                  Rayleigh-Ritz's two nev x nev matrices */
    double *R;                 /* b x b: OP V_last = V H + W_new R (rows: new columns) */
    double *Rb;                /* b x b: scratch */
    double *est;               /* mcap: Ritz estimates */
    double *work;              /* lwork: LAPACK */
    int lwork;
    int *order;                /* mcap: Ritz indices, |theta| descending */
    int j, ne;                 /* basis columns, expanded columns */
    int w;                     /* width of the last expanded block (columns of R) */
    int q;                     /* columns of the new block (rows of R) */
    int mw_pending;            /* MW[:, 0:j - ne] holds B times the pending block */
    unsigned long long seed;   /* random replacements of dependent columns */
    int threads;               /* 1, or 2: the dense work split between two (blanczos_par.c) */
    int asked;                 /* the solve's threads= (ops->threads), for the thread policy */
    double *Cpart;             /* mcap x mcap: the helper thread's half of a product A^T B */
    /* The helper thread that populates the basis's pages (blanczos_par.c): pf_units
     * units (columns), those below pf_next claimed (pf_busy the one it works on, -1). */
    int pf_on, pf_units, pf_next, pf_busy, pf_stop;
    long page;
    int pf_ticket;             /* the helper's job (core/threads.h) */
    pthread_mutex_t pf_lock;
    pthread_cond_t pf_done;
} ctn_blz;

/* W (w columns) -= V[:, 0:j] (V^T B W), twice (classical Gram-Schmidt, BLAS-3; B W
 * formed in MW for each pass); the sum of the coefficients into H (j x w). */
void ctn_blz_project(ctn_blz *z, int w);
/* B-orthonormalize W (w columns, already projected; B W in MW): the new block's columns
 * into W[:, 0:q] (B W into MW), q <= room, and R (q x w) with W_in = V H + W_new R.
 * Cholesky QR twice; a column that is linearly dependent on the rest (or w > room) goes
 * through Gram-Schmidt column by column, a dependent column replaced by a random vector
 * in OP's range orthogonal to the basis while there is room. */
int ctn_blz_orthonormalize(ctn_blz *z, int w, int room, int *q);
/* A fixed pseudo-random vector (runs repeat exactly). */
void ctn_blz_random(ctn_blz *z, double *x);

/* blanczos_par.c: the halves of the dense work (ops->threads: 0 two where the thread
 * policy allows CTN_THR_LANCZOS, 1 one, 2 two); the second half runs on the context's
 * helper when the policy allows it and one is free, else after the first. Tall
 * matrices are n rows (ld n); the rows are split between the halves, so the results do
 * not depend on the threads beyond the rounding of the sum of two halves in
 * ctn_blz_gemm_t. */
int ctn_blz_threads(const ctn_ctx *ctx, int asked, int n);
/* C (k x w, ld ldc) = A^T B: A n x k, B n x w. */
void ctn_blz_gemm_t(ctn_blz *z, int k, int w, const double *A, const double *B, double *C, int ldc);
/* C = alpha A B + beta C: A n x k, B k x w (ld ldb), C n x w. */
void ctn_blz_gemm_n(ctn_blz *z, int k, int w, double alpha, const double *A, const double *B, int ldb, double beta,
                    double *C);
/* X (n x w) = X U^-1, U w x w upper triangular (ld ldu). */
void ctn_blz_trsm(ctn_blz *z, int w, const double *U, int ldu, double *X);
/* V[:, 0:k] = V[:, 0:ne] Y (Y ne x k, ld ldy; k <= ne), in place: by chunks of
 * CTN_BLZ_ROWS rows, each formed in Rot and copied back. */
#define CTN_BLZ_ROWS 256
void ctn_blz_rotate(ctn_blz *z, int ne, int k, const double *Y, int ldy);
/* dst[0:count] = src[0:count] (no overlap). */
void ctn_blz_copy(ctn_blz *z, double *dst, const double *src, size_t count);
/* Y[:, c] = op(X[:, c]) for the k columns (op: ops->bmul or ops->amul), half of them on
 * the helper thread. */
void ctn_blz_apply(ctn_blz *z, void (*op)(void *ud, const double *x, double *y), const double *X, double *Y, int k);
/* Y[:, c] = ops->absmul(X[:, c], lambda[c]) (Y zeroed first) for the k columns. */
void ctn_blz_apply_abs(ctn_blz *z, const double *X, const double *lambda, double *Y, int k);
/* The helper thread that populates V ahead of the process, then X
 * (two threads only); wait: V's columns 0 .. upto - 1 populated (the caller
 * populates those not yet claimed), upto = CTN_BLZ_ALL: X and W's scratch as well; stop:
 * the thread ended (before anything is written that was not waited for). */
#define CTN_BLZ_ALL 0x7fffffff
void ctn_blz_populate_start(ctn_blz *z);
void ctn_blz_populate_wait(ctn_blz *z, int upto);
void ctn_blz_populate_stop(ctn_blz *z);

#endif
