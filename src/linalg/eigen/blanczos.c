/* Shift-invert block Lanczos with full re-orthogonalization and thick restarts, for the
 * nev eigenpairs of A x = lambda B x nearest sigma: the eigenvalues theta = 1 / (lambda -
 * sigma) of largest magnitude of OP = (A - sigma B)^-1 B, self-adjoint in the B inner
 * product. The basis V grows by blocks W = OP V_last, B-orthonormalized against V
 * (blanczos_orth.c); T = V^T B OP V is kept, its eigenpairs (LAPACK dsyev) are the Ritz
 * pairs, and OP V = V T + W_new R e_last^T gives each Ritz pair's residual |R s_last|
 * without forming it. When V is full, the nkeep best Ritz vectors and the pending block
 * start it again (T then diagonal plus the block's column). B V is not kept: B is
 * sparse and cheap beside the solves, and a second basis of that size would double the
 * memory that the process writes for the first time. docs/theory.md, "Modal analysis". */
#include "linalg/eigen/blanczos.h"
#include "linalg/lapack.h"
#include "linalg/linsolve.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define BLZ_TOL 1e-12       /* Ritz estimate / |theta|: time to check the true residual */
#define BLZ_RESID 1e-10     /* true residual of a converged pair */
#define BLZ_FLOOR 10        /* ... or within this factor of its rounding bound */
#define BLZ_SPREAD 1e4      /* |theta| this much above the rest: solved apart ... */
#define BLZ_SPLIT 1e-12     /* ... when that moves no other by more than this times
                               the largest of them */
#define BLZ_GUARD 0.1       /* the guard pair of the second round is converged within
                               this fraction of its gap below the wanted ones */
#define BLZ_STALL 8         /* checks without halving the residual: the end */
#define BLZ_MAXBLOCKS 300   /* most block expansions */
#define BLZ_WIDTH 4         /* columns of a block (bench/bench_eigen: 4 took the fewest
                               columns and the least time on the hypar nets) */
#define BLZ_EXTRA 64        /* the basis holds nev + max(nev, this) columns */
#define BLZ_KEEP 6          /* a restart keeps the nev + BLZ_KEEP b best Ritz vectors (the
                               K = 400 net: 128 solves, against 140 keeping nev + 2 b and
                               152 keeping nev + b; nev + 8 b no fewer) */

static double nrm2(const double *x, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++) s += x[i] * x[i];
    return sqrt(s);
}

static void blz_free(ctn_blz *z)
{
    double *p[] = { z->V, z->W, z->MW, z->X, z->T, z->S, z->theta, z->H, z->Y, z->R, z->Rb, z->est, z->work,
                    z->C, z->lam0, z->Cpart, z->Rot };
    for (size_t i = 0; i < sizeof p / sizeof *p; i++) ctn_free(p[i]);
    ctn_free(z->order);
}

static int blz_alloc(ctn_blz *z)
{
    ctn_ctx *c = z->ctx;
    size_t n = (size_t)z->n, m = (size_t)z->mcap, b = (size_t)z->b, wb = b > 3 ? b : 3, ws = (size_t)z->ws;
    size_t nx = (size_t)z->nx;
    z->lwork = 66 * z->mcap;
    z->V = ctn_malloc(c, n * m, sizeof(double));
    z->W = ctn_malloc(c, n * ws, sizeof(double));
    z->MW = ctn_malloc(c, n * ws, sizeof(double));
    z->X = ctn_malloc(c, n * nx, sizeof(double));
    z->T = ctn_calloc(c, m * m, sizeof(double));
    z->S = ctn_malloc(c, m * m, sizeof(double));
    z->Y = ctn_malloc(c, 2 * m * m, sizeof(double));
    z->theta = ctn_malloc(c, m, sizeof(double));
    z->est = ctn_malloc(c, m, sizeof(double));
    z->H = ctn_malloc(c, m * 2 * wb, sizeof(double));
    z->R = ctn_calloc(c, b * b, sizeof(double));
    z->Rb = ctn_calloc(c, b * b, sizeof(double));
    z->work = ctn_malloc(c, (size_t)z->lwork, sizeof(double));
    z->order = ctn_malloc(c, m, sizeof(int));
    z->C = ctn_malloc(c, nx * nx, sizeof(double));
    z->lam0 = ctn_malloc(c, (size_t)z->nev, sizeof(double));
    z->Cpart = ctn_malloc(c, m * m, sizeof(double));
    z->Rot = ctn_malloc(c, 2 * CTN_BLZ_ROWS * m, sizeof(double));
    return z->V && z->W && z->MW && z->X && z->T && z->S && z->Y && z->theta && z->est && z->H && z->R &&
           z->Rb && z->work && z->order && z->C && z->lam0 && z->Cpart && z->Rot ? CTN_OK : CTN_ERR_NOMEM;
}

/* Append the new block W[:, 0:q] to the basis (its pages populated first). */
static void append(ctn_blz *z, int q)
{
    size_t n = (size_t)z->n, j = (size_t)z->j;
    ctn_blz_populate_wait(z, z->j + q);
    ctn_blz_copy(z, z->V + n * j, z->W, n * (size_t)q);
    z->j += q;
    z->mw_pending = 1;                  /* B W, from the orthonormalization: B V_pending */
}

/* A new block: OP applied to random vectors (in OP's range, as B may be singular),
 * B-orthonormalized against the basis and in itself, appended. */
static int start(ctn_blz *z)
{
    int w = z->b, q = 0;
    for (int c = 0; c < w; c++) ctn_blz_random(z, z->W + (size_t)z->n * (size_t)c);
    ctn_blz_apply(z, z->ops->bmul, z->W, z->MW, w);
    int rc = z->ops->solve_block(z->ops->ud, z->MW, z->W, w);
    z->info->block_solves++;
    z->info->ops += w;
    if (!rc) ctn_blz_project(z, w);
    if (!rc) rc = ctn_blz_orthonormalize(z, w, (z->mcap < z->n ? z->mcap : z->n) - z->j, &q);
    if (!rc) append(z, q);
    return rc;
}

/* OP applied to the pending block, its column of T, the new block appended. */
static int expand(ctn_blz *z)
{
    const int n = z->n, w = z->j - z->ne, ld = z->mcap;
    if (!z->mw_pending) ctn_blz_apply(z, z->ops->bmul, z->V + (size_t)n * (size_t)z->ne, z->MW, w);
    int q = 0, rc = z->ops->solve_block(z->ops->ud, z->MW, z->W, w);
    z->info->block_solves++;
    z->info->ops += w;
    if (rc) return rc;
    ctn_blz_project(z, w);
    for (int c = 0; c < w; c++)
        memcpy(z->T + (size_t)ld * (size_t)(z->ne + c), z->H + (size_t)ld * (size_t)c, (size_t)z->j * sizeof(double));
    rc = ctn_blz_orthonormalize(z, w, (z->mcap < n ? z->mcap : n) - z->j, &q);
    if (rc) return rc;
    z->w = w;
    z->q = q;
    z->ne = z->j;
    append(z, q);
    return CTN_OK;
}

/* dsyev on T[idx, idx] (m rows of the permutation idx from `at`): the values into
 * theta[at..], the vectors scattered into S's columns at.. (zero off the block). */
static int eig_block(ctn_blz *z, const int *idx, int at, int m)
{
    const int ld = z->mcap;
    int info = 0;
    double *A = z->Y;
    for (int c = 0; c < m; c++)
        for (int r = 0; r <= c; r++) {
            int i = idx[at + r], j = idx[at + c];
            A[r + (size_t)m * (size_t)c] = i <= j ? z->T[i + (size_t)ld * (size_t)j] : z->T[j + (size_t)ld * (size_t)i];
        }
    dsyev_("V", "U", &m, A, &m, z->theta + at, z->work, &z->lwork, &info, 1, 1);
    if (info) return ctn_error(z->ctx, CTN_ERR_LINALG, "block eigen-solver: LAPACK dsyev failed (info %d)", info);
    for (int c = 0; c < m; c++) {
        double *col = z->S + (size_t)ld * (size_t)(at + c);
        memset(col, 0, (size_t)z->ne * sizeof(double));
        for (int r = 0; r < m; r++) col[idx[at + r]] = A[r + (size_t)m * (size_t)c];
    }
    return CTN_OK;
}

/* The eigenpairs of T[0:ne, 0:ne]. A dense eigen-solver is accurate to eps |T|: with a
 * shift near an eigenvalue one theta is huge and would leave no digit of the others. Its
 * rows are then solved apart when their coupling c to the rest (rounding: the exact one
 * is a converged residual) moves no eigenvalue by more than BLZ_SPLIT theta_rest
 * (c^2 / theta_big <= BLZ_SPLIT theta_rest). */
static int eig_T(ctn_blz *z)
{
    const int ne = z->ne, ld = z->mcap;
    int *idx = z->order, nl = 0;
    double tmax = 0, srest = 0, worst = 0;
    for (int i = 0; i < ne; i++) tmax = fmax(tmax, fabs(z->T[i + (size_t)ld * (size_t)i]));
    for (int i = 0; i < ne; i++)
        if (fabs(z->T[i + (size_t)ld * (size_t)i]) <= tmax / BLZ_SPREAD) idx[nl++] = i;
    for (int i = 0, h = nl; i < ne; i++)
        if (fabs(z->T[i + (size_t)ld * (size_t)i]) > tmax / BLZ_SPREAD) idx[h++] = i;
    for (int r = 0; r < nl; r++) srest = fmax(srest, fabs(z->T[idx[r] + (size_t)ld * (size_t)idx[r]]));
    for (int h = nl; h < ne; h++) {
        double c2 = 0, d = fabs(z->T[idx[h] + (size_t)ld * (size_t)idx[h]]);
        for (int r = 0; r < nl; r++) {
            int i = idx[h], j = idx[r];
            double t = i <= j ? z->T[i + (size_t)ld * (size_t)j] : z->T[j + (size_t)ld * (size_t)i];
            c2 += t * t;
        }
        worst = fmax(worst, c2 / (d * srest));
    }
    if (nl == 0 || nl == ne || !(worst <= BLZ_SPLIT)) {
        for (int i = 0; i < ne; i++) idx[i] = i;
        return eig_block(z, idx, 0, ne);
    }
    int rc = eig_block(z, idx, 0, nl);
    return rc ? rc : eig_block(z, idx, nl, ne - nl);
}

/* Ritz pairs of T[0:ne, 0:ne], ordered by |theta| descending, their estimates |R s_last|;
 * the number of the first nev that converged. */
static int ritz(ctn_blz *z, int *nconv)
{
    const int ne = z->ne, ld = z->mcap, b = z->b;
    int rc = eig_T(z);
    if (rc) return rc;
    for (int i = 0; i < ne; i++) {                                  /* insertion by |theta| */
        int k = i;
        for (; k > 0 && fabs(z->theta[z->order[k - 1]]) < fabs(z->theta[i]); k--) z->order[k] = z->order[k - 1];
        z->order[k] = i;
    }
    *nconv = 0;
    for (int i = 0; i < ne; i++) {
        const double *s = z->S + (size_t)ld * (size_t)i + (ne - z->w);   /* last block's rows */
        double e = 0;
        for (int r = 0; r < z->q; r++) {
            double t = 0;
            for (int c = 0; c < z->w; c++) t += z->R[r + b * c] * s[c];
            e += t * t;
        }
        z->est[i] = sqrt(e);
    }
    for (int k = 0; k < z->need && k < ne; k++) {
        double t = fabs(z->theta[z->order[k]]), gap = k == z->nev ? fabs(z->theta[z->order[k - 1]]) - t : 0;
        *nconv += z->est[z->order[k]] <= fmax(BLZ_TOL * t, BLZ_GUARD * gap);   /* the guard: */
    }                                           /* known to lie below the wanted ones */
    return CTN_OK;
}

/* Y[:, 0:k] = S[:, order[0:k]]: the k best Ritz vectors of T. */
static void select_ritz(ctn_blz *z, int k)
{
    const int ne = z->ne, ld = z->mcap;
    for (int i = 0; i < k; i++)
        memcpy(z->Y + (size_t)ld * (size_t)i, z->S + (size_t)ld * (size_t)z->order[i], (size_t)ne * sizeof(double));
}

/* X = V[:, 0:ne] S[:, order[0:k]]: the k best Ritz vectors. */
static void ritz_vectors(ctn_blz *z, int k)
{
    select_ritz(z, k);
    ctn_blz_gemm_n(z, z->ne, k, 1, z->V, z->Y, z->mcap, 0, z->X);
}

/* The final Rayleigh-Ritz: X = the nev + b best Ritz vectors, the pencil (X^T A X,
 * X^T B X) solved by LAPACK (dsygv), the nev eigenvalues nearest sigma kept (lambda
 * ascending, C B-orthonormal), so that the pairs come from A and B themselves, not from
 * T (whose entries carry the rounding of the solves); the b more vectors complete a
 * cluster of close eigenvalues that the nev-th would cut. A X and B X are formed ws
 * columns at a time in W and B W (not kept: fresh memory costs more than the products). */
static int rayleigh_ritz(ctn_blz *z, double *lambda)
{
    const int k = z->nev + z->b < z->ne ? z->nev + z->b : z->ne, one_i = 1;
    const size_t n = (size_t)z->n;
    double *G = z->Y, *F = z->Y + (size_t)k * (size_t)k;          /* k x k each */
    int info = 0;
    z->p = k;
    ctn_blz_populate_wait(z, CTN_BLZ_ALL);
    ritz_vectors(z, k);
    z->mw_pending = 0;                  /* W and B W: scratch from here */
    for (int c0 = 0; c0 < k; c0 += z->ws) {
        const int mc = k - c0 < z->ws ? k - c0 : z->ws;
        ctn_blz_apply(z, z->ops->amul, z->X + n * (size_t)c0, z->W, mc);
        ctn_blz_gemm_t(z, k, mc, z->X, z->W, G + (size_t)k * (size_t)c0, k);     /* X^T A X */
        ctn_blz_apply(z, z->ops->bmul, z->X + n * (size_t)c0, z->MW, mc);
        ctn_blz_gemm_t(z, k, mc, z->X, z->MW, F + (size_t)k * (size_t)c0, k);    /* X^T B X */
    }
    dsygv_(&one_i, "V", "U", &k, G, &k, F, &k, z->est, z->work, &z->lwork, &info, 1, 1);
    if (info) return ctn_error(z->ctx, CTN_ERR_LINALG, "block eigen-solver: LAPACK dsygv failed (info %d)", info);
    int lo = 0;                                     /* the nev nearest sigma: a window */
    while (lo + z->nev < k && fabs(z->est[lo] - z->sigma) > fabs(z->est[lo + z->nev] - z->sigma)) lo++;
    memcpy(lambda, z->est + lo, (size_t)z->nev * sizeof(double));
    memcpy(z->C, G + (size_t)k * (size_t)lo, (size_t)k * (size_t)z->nev * sizeof(double));
    return CTN_OK;
}

/* The largest true residual |A x - lambda B x| / |A x| of the pairs (lambda, X C) that
 * are above 1e-10 and more than 10 times their rounding bound (0 if none: converged);
 * the largest of all in info->max_residual. By chunks of ws / 2 pairs: X C into B W, A
 * and B times it into W, then the rounding bounds (absmul) of those above 1e-10 into the
 * rest of B W (their columns of X C moved to the front). */
static double residuals(ctn_blz *z, const double *lambda)
{
    const int n = z->n, k = z->p, m = z->ws / 2;
    double open = 0, lam[CTN_BLZ_BMAX], den[CTN_BLZ_BMAX], res[CTN_BLZ_BMAX];
    z->info->max_residual = 0;
    for (int c0 = 0; c0 < z->nev; c0 += m) {
        int mc = z->nev - c0 < m ? z->nev - c0 : m, cnt = 0;
        const double *C = z->C + (size_t)k * (size_t)c0;
        double *Ax = z->W, *Bx = z->W + (size_t)n * (size_t)m, *x = z->MW, *abs = z->MW + (size_t)n * (size_t)m;
        ctn_blz_gemm_n(z, k, mc, 1, z->X, C, k, 0, x);
        ctn_blz_apply(z, z->ops->amul, x, Ax, mc);
        ctn_blz_apply(z, z->ops->bmul, x, Bx, mc);
        for (int c = 0; c < mc; c++) {
            double *ax = Ax + (size_t)n * (size_t)c, *bx = Bx + (size_t)n * (size_t)c;
            double an = nrm2(ax, n), bn = nrm2(bx, n), d = fmax(an, fabs(z->sigma) * bn);
            for (int i = 0; i < n; i++) ax[i] -= lambda[c0 + c] * bx[i];
            double r = d > 0 ? nrm2(ax, n) / d : 0;
            z->info->max_residual = fmax(z->info->max_residual, r);
            if (r <= BLZ_RESID) continue;
            if (cnt < c) memcpy(x + (size_t)n * (size_t)cnt, x + (size_t)n * (size_t)c, (size_t)n * sizeof(double));
            lam[cnt] = lambda[c0 + c];
            den[cnt] = d;
            res[cnt++] = r;
        }
        if (!cnt) continue;
        ctn_blz_apply_abs(z, x, lam, abs, cnt);
        for (int c = 0; c < cnt; c++) {
            double fl = DBL_EPSILON * nrm2(abs + (size_t)n * (size_t)c, n) / den[c];   /* rounding of the residual */
            z->info->max_floor = fmax(z->info->max_floor, fl);
            if (res[c] > BLZ_FLOOR * fl) open = fmax(open, res[c]);
        }
    }
    return open;
}

/* Thick restart: the keep best Ritz vectors (formed in V's place, row by row) and, if
 * pending, the pending block become the basis; T = diag(theta) until the block's column
 * is computed. */
static void restart(ctn_blz *z, int keep, int pending)
{
    const size_t n = (size_t)z->n, k = (size_t)keep, q = pending ? (size_t)(z->j - z->ne) : 0, ld = (size_t)z->mcap;
    select_ritz(z, keep);
    ctn_blz_rotate(z, z->ne, keep, z->Y, z->mcap);
    memmove(z->V + n * k, z->V + n * (size_t)z->ne, n * q * sizeof(double));
    memset(z->T, 0, ld * ld * sizeof(double));
    for (size_t i = 0; i < k; i++) z->T[i + ld * i] = z->theta[z->order[i]];
    z->ne = (int)k;
    z->j = (int)(k + q);
    z->info->restarts++;
}

/* A second round, when the first found b equal eigenvalues (a block Krylov space holds
 * at most b copies of a multiple eigenvalue: there may be more): the nev converged Ritz
 * vectors kept (their residuals are below the tolerance: dropping them leaves T exact
 * to it) and a new random block; it ends when one more pair than wanted has converged,
 * so that a copy the first round missed has come in. Again until a round changes
 * nothing. */
static int verify(ctn_blz *z, const double *lambda, int *round)
{
    memcpy(z->lam0, lambda, (size_t)z->nev * sizeof(double));
    restart(z, z->nev, 0);
    z->need = z->nev + 1;
    ++*round;
    return start(z);
}

/* A run of b equal eigenvalues (relative 1e-8) among the nev: as many copies as a block
 * Krylov space holds; there may be more, which it has missed. */
static int crowded(const ctn_blz *z, const double *lambda)
{
    for (int k = 0, run = 1; k + 1 < z->nev; k++) {
        run = fabs(lambda[k + 1] - lambda[k]) <= 1e-8 * fmax(fabs(lambda[k]), fabs(lambda[k + 1])) ? run + 1 : 1;
        if (run >= z->b) return 1;
    }
    return 0;
}

/* The nev eigenvalues of this round are those of the last (relative 1e-9). */
static int unchanged(const ctn_blz *z, const double *lambda)
{
    for (int k = 0; k < z->nev; k++)
        if (!(fabs(lambda[k] - z->lam0[k]) <= 1e-9 * fabs(z->lam0[k]) + DBL_MIN)) return 0;
    return 1;
}

/* Expand until the nev pairs converged (estimates, then the true residuals of the final
 * Rayleigh-Ritz, lambda), and a second round agrees. */
static int iterate(ctn_blz *z, double *lambda)
{
    int stall = 0, nconv = 0, round = 0;
    double best = HUGE_VAL;
    for (int it = 0; it < BLZ_MAXBLOCKS; it++) {
        if (z->mcap < z->n && z->j + z->b > z->mcap) restart(z, z->nkeep, 1);
        if (z->j == z->ne) break;                       /* nothing pending: no way on */
        int rc = expand(z);
        if (!rc) rc = ritz(z, &nconv);
        if (rc) return rc;
        z->info->nconv = nconv < z->nev ? nconv : z->nev;
        if (nconv < z->need && z->j > z->ne) continue;
        if ((rc = rayleigh_ritz(z, lambda))) return rc;
        double open = residuals(z, lambda);
        int done = open == 0 || z->j == z->ne;
        if (done && (z->j == z->ne || z->nev + 1 >= z->n || (round ? unchanged(z, lambda) : !crowded(z, lambda))))
            return CTN_OK;
        if (done) {
            if ((rc = verify(z, lambda, &round))) return rc;
            stall = 0;
            best = HUGE_VAL;
            continue;
        }
        stall = open <= 0.5 * best ? 0 : stall + 1;
        best = fmin(best, open);
        if (stall >= BLZ_STALL)
            return ctn_error(z->ctx, CTN_ERR_NOCONV, "block eigen-solver: the residual stalled at %.1e", open);
    }
    return ctn_error(z->ctx, CTN_ERR_NOCONV, "block eigen-solver: %d of %d modes converged in %d block solves",
                     z->info->nconv, z->nev, z->info->block_solves);
}

/* The eigenvectors X C into V's first columns. */
static void finish(ctn_blz *z)
{
    ctn_blz_gemm_n(z, z->p, z->nev, 1, z->X, z->C, z->p, 0, z->V);
}

int ctn_eigen_block(ctn_ctx *ctx, int n, int nev, double sigma, const ctn_eigen_ops *ops, double *lambda,
                    double **vecs, ctn_eigen_info *info)
{
    ctn_blz z;
    memset(&z, 0, sizeof z);
    memset(info, 0, sizeof *info);
    *vecs = NULL;
    if (nev < 1 || nev > n) return ctn_error(ctx, CTN_ERR_INVALID, "eigen-solver: %d modes of %d unknowns", nev, n);
    z.ctx = ctx;
    z.ops = ops;
    z.info = info;
    z.n = n;
    z.nev = nev;
    z.sigma = sigma;
    z.seed = 0x2545F4914F6CDD1DULL;
    z.b = nev < BLZ_WIDTH ? (nev > 2 ? nev : 2) : BLZ_WIDTH;
    if (z.b > n) z.b = n;
    z.mcap = nev + (nev > BLZ_EXTRA ? nev : BLZ_EXTRA);
    if (z.mcap > n) z.mcap = n;
    z.nkeep = nev + BLZ_KEEP * z.b;
    if (z.nkeep > z.mcap - z.b) z.nkeep = z.mcap - z.b > nev ? z.mcap - z.b : nev;
    z.nx = nev + z.b;
    z.ws = 2 * z.b > 8 ? 2 * z.b : 8;
    z.need = nev;
    z.threads = ctn_blz_threads(ctx, ops->threads, n);
    z.asked = ops->threads == 1 ? 1 : ops->asked;
    info->block = z.b;
    ctn_threads_saved saved;
    ctn_threads_push(1, &saved);
    int rc = blz_alloc(&z);
    if (!rc) ctn_blz_populate_start(&z);
    if (!rc) rc = start(&z);
    if (!rc) rc = iterate(&z, lambda);
    ctn_blz_populate_stop(&z);
    ctn_threads_pop(&saved);
    if (!rc) {
        finish(&z);
        *vecs = z.V;
        z.V = NULL;
    }
    blz_free(&z);
    return rc;
}
