/* The block Lanczos solver's B-orthogonal bases: a new block projected against the basis
 * by classical Gram-Schmidt twice (BLAS-3), then B-orthonormalized in itself by Cholesky
 * QR twice; a block whose columns are (nearly) linearly dependent goes column by column
 * with deflation instead. Every inner product is x^T (B y); B y is formed for the few
 * columns of the block (the basis's B V is not kept: blanczos.c). */
#include "linalg/eigen/blanczos.h"
#include "linalg/lapack.h"

#include <math.h>
#include <string.h>

static double dot(const double *x, const double *y, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++) s += x[i] * y[i];
    return s;
}

void ctn_blz_random(ctn_blz *z, double *x)
{
    for (int i = 0; i < z->n; i++) {
        z->seed = z->seed * 6364136223846793005ULL + 1442695040888963407ULL;
        x[i] = (double)(z->seed >> 11) / 9007199254740992.0 - 0.5;    /* [-0.5, 0.5) */
    }
}

/* Wp (w columns) -= V (V^T B Wp), twice (B Wp formed into the scratch MWp for each
 * pass); coefficients summed into H (ld mcap). Both passes go over the whole basis: a
 * first pass over the last blocks only (where OP V_last lies in exact arithmetic) was
 * measured to leave residuals of 2e-10 to 5e-10 that two full passes bring below
 * 1e-10, and one pass alone stalls the process. */
static void project(ctn_blz *z, double *Wp, double *MWp, int w, double *H)
{
    const int ld = z->mcap, j = z->j;
    double *H2 = z->H + (size_t)ld * (size_t)z->b;
    memset(H, 0, (size_t)ld * (size_t)w * sizeof(double));
    if (j == 0 || w == 0) return;
    for (int pass = 0; pass < 2; pass++) {
        ctn_blz_apply(z, z->ops->bmul, Wp, MWp, w);
        ctn_blz_gemm_t(z, j, w, z->V, MWp, H2, ld);                     /* H2 = V^T B W */
        ctn_blz_gemm_n(z, j, w, -1, z->V, H2, ld, 1, Wp);               /* W -= V H2 */
        for (int c = 0; c < w; c++)
            for (int r = 0; r < j; r++) H[r + (size_t)ld * (size_t)c] += H2[r + (size_t)ld * (size_t)c];
    }
}

void ctn_blz_project(ctn_blz *z, int w)
{
    project(z, z->W, z->MW, w, z->H);
}

/* v -= W[:, 0:q] (W^T B v), twice (B v kept in Mv); coefficients added to coef[0:q];
 * returns the B-norm of what remains. Mv follows v by the same updates; when v lost
 * most of its norm (nv its norm before) Mv is formed again, as the updates left it
 * with their rounding relative to the old norm. */
static double gs_column(ctn_blz *z, double *v, double *Mv, int q, double *coef, double nv)
{
    const int n = z->n;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < q; i++) {
            const double *wi = z->W + (size_t)n * (size_t)i, *mwi = z->MW + (size_t)n * (size_t)i;
            double r = dot(mwi, v, n);
            for (int k = 0; k < n; k++) {
                v[k] -= r * wi[k];
                Mv[k] -= r * mwi[k];
            }
            coef[i] += r;
        }
    double s = dot(v, Mv, n);
    if (!(s > 0.01 * nv * nv)) {
        z->ops->bmul(z->ops->ud, v, Mv);
        s = dot(v, Mv, n);
    }
    return s > 0 ? sqrt(s) : 0;
}

/* Column q of W: a random vector in OP's range, B-orthonormal to V and to W[:, 0:q]. */
static int replacement(ctn_blz *z, int q)
{
    const int n = z->n;
    double *x = z->W + (size_t)n * (size_t)q, *mx = z->MW + (size_t)n * (size_t)q, coef[CTN_BLZ_BMAX];
    ctn_blz_random(z, x);
    z->ops->bmul(z->ops->ud, x, mx);
    int rc = z->ops->solve_block(z->ops->ud, mx, x, 1);                /* x = OP x0 */
    if (rc) return rc;
    z->info->ops++;
    z->info->block_solves++;
    z->ops->bmul(z->ops->ud, x, mx);
    double *H = z->H + (size_t)z->mcap * (size_t)(2 * z->b - 1);        /* a scratch column */
    memset(coef, 0, sizeof coef);
    project(z, x, mx, 1, H);
    z->ops->bmul(z->ops->ud, x, mx);                                /* afresh: x shrank */
    double nrm = gs_column(z, x, mx, q, coef, HUGE_VAL);
    for (int k = 0; k < n; k++) {
        x[k] /= nrm;
        mx[k] /= nrm;
    }
    return nrm > 0 ? CTN_OK : ctn_error(z->ctx, CTN_ERR_NOCONV, "block eigen-solver: no vector left outside the basis");
}

/* Column by column (the block is in W, B W in MW, the columns' norms in n0): the kept
 * columns compacted to W[:, 0:q], their coefficients in Rb (ld b). */
static int gs_block(ctn_blz *z, int w, int room, const double *n0, int *q)
{
    const int n = z->n, b = z->b;
    memset(z->Rb, 0, (size_t)b * (size_t)b * sizeof(double));
    *q = 0;
    for (int c = 0; c < w; c++) {
        double *v = z->W + (size_t)n * (size_t)c, *mv = z->MW + (size_t)n * (size_t)c;
        double nrm = gs_column(z, v, mv, *q, z->Rb + (size_t)b * (size_t)c, n0[c]);
        if (nrm > CTN_BLZ_DEFLATE * n0[c] && *q < room) {
            double *dst = z->W + (size_t)n * (size_t)*q, *mdst = z->MW + (size_t)n * (size_t)*q;
            for (int k = 0; k < n; k++) {
                dst[k] = v[k] / nrm;
                mdst[k] = mv[k] / nrm;
            }
            z->Rb[*q + (size_t)b * (size_t)c] = nrm;
            ++*q;
        } else if (*q < room && z->j + *q < n) {
            int rc = replacement(z, *q);                            /* a dependent column */
            if (rc) return rc;
            ++*q;
        }
    }
    return CTN_OK;
}

/* R = A (q x w, ld b) times R (w x w upper triangular, ld b), in place. */
static void compose(ctn_blz *z, const double *A, int q, int w)
{
    const int b = z->b;
    double out[CTN_BLZ_BMAX * CTN_BLZ_BMAX];
    for (int c = 0; c < w; c++)
        for (int r = 0; r < q; r++) {
            double s = 0;
            for (int k = 0; k <= c; k++) s += A[r + b * k] * z->R[k + b * c];
            out[r + b * c] = s;
        }
    for (int c = 0; c < w; c++)
        for (int r = 0; r < b; r++) z->R[r + b * c] = r < q ? out[r + b * c] : 0;
}

/* One Cholesky QR step on W (w columns): G = W^T B W = U^T U, W = W U^-1, B W likewise,
 * R = U R. 1 when G is not numerically definite or (first, n0 given: the columns' B-norms
 * from G's diagonal into it) a column keeps less than CTN_BLZ_CHOLQR of its norm out of
 * the span of the earlier ones (then nothing is changed). */
static int cholqr(ctn_blz *z, int w, double *n0)
{
    const int b = z->b;
    int info = 0;
    ctn_blz_gemm_t(z, w, w, z->W, z->MW, z->Rb, b);                   /* G = W^T B W */
    for (int c = 0; n0 && c < w; c++) n0[c] = sqrt(fmax(z->Rb[c + b * c], 0));
    dpotrf_("U", &w, z->Rb, &b, &info, 1);
    for (int c = 0; !info && n0 && c < w; c++) info = !(z->Rb[c + b * c] > CTN_BLZ_CHOLQR * n0[c]);
    if (info) return 1;
    for (int c = 0; c < w; c++)
        for (int r = c + 1; r < w; r++) z->Rb[r + b * c] = 0;
    ctn_blz_trsm(z, w, z->Rb, b, z->W);
    ctn_blz_trsm(z, w, z->Rb, b, z->MW);
    compose(z, z->Rb, w, w);
    return 0;
}

int ctn_blz_orthonormalize(ctn_blz *z, int w, int room, int *q)
{
    const int n = z->n, b = z->b;
    double n0[CTN_BLZ_BMAX] = { 0 };
    ctn_blz_apply(z, z->ops->bmul, z->W, z->MW, w);
    memset(z->R, 0, (size_t)b * (size_t)b * sizeof(double));
    for (int c = 0; c < w; c++) z->R[c + b * c] = 1;
    if (w <= room && !cholqr(z, w, n0) && !cholqr(z, w, NULL)) {
        *q = w;
        return CTN_OK;
    }
    for (int c = 0; w > room && c < w; c++) {                  /* |column| (else from G) */
        double *v = z->W + (size_t)n * (size_t)c, *mv = z->MW + (size_t)n * (size_t)c;
        n0[c] = sqrt(fmax(dot(v, mv, n), 0));
    }
    int rc = gs_block(z, w, room, n0, q);                       /* R = Rb R */
    if (!rc) {
        double A[CTN_BLZ_BMAX * CTN_BLZ_BMAX];
        memcpy(A, z->Rb, sizeof(double) * (size_t)b * (size_t)b);
        compose(z, A, *q, w);
    }
    return rc;
}
