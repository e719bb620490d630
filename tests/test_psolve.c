/* The block solves on two threads over CHOLMOD's supernodal factor (cholmod_psolve.c)
 * against CHOLMOD's own solve, on SPD matrices of several shapes: a net's tangent (a
 * grid of strings, 3 DOFs a node), a 3D Laplacian, a chain in nested dissection, a tiny
 * matrix; 1, 4 and 7 columns. The two solves differ by rounding only: each has a small
 * backward error (checked from its residual), and their difference is bounded by the
 * condition number (from power iterations) times the backward errors. One thread and
 * two give identical results; every allocation may fail. The 4-column supernode sweeps
 * by hand (both the baseline's copy and AVX2's) against a plain loop on single
 * supernodes. */
/* ctest-cost: 20 (about the seconds it takes under ASan: ctest -j starts it early) */
#include "linalg/linsolve.h"
#include "linalg/backends/cholmod/psolve.h"
#include "linalg/backends/cholmod/psolve_k4.h"

#include "check.h"

#include <catena.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define EPS 2.220446049250313e-16

/* An entry of the upper triangle into T. */
static void add(cholmod_triplet *T, int i, int j, double v)
{
    if (i > j) {
        int t = i;
        i = j;
        j = t;
    }
    SuiteSparse_long *Ti = T->i, *Tj = T->j;
    double *Tx = T->x;
    Ti[T->nnz] = i;
    Tj[T->nnz] = j;
    Tx[T->nnz++] = v;
}

/* A string between DOF blocks a and b (3 each, -1: fixed): EA/L d d' + T/L (I - d d'). */
static void string(cholmod_triplet *T, int a, int b, const double d[3], double ea, double t)
{
    double k[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) k[i][j] = (ea - t) * d[i] * d[j] + (i == j ? t : 0);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            if (a >= 0 && 3 * a + i <= 3 * a + j) add(T, 3 * a + i, 3 * a + j, k[i][j]);
            if (b >= 0 && 3 * b + i <= 3 * b + j) add(T, 3 * b + i, 3 * b + j, k[i][j]);
            if (a >= 0 && b >= 0) add(T, 3 * a + i, 3 * b + j, -k[i][j]);
        }
}

/* The tangent of a g x g hypar net of prestressed strings, its boundary pinned. */
static cholmod_sparse *net(int g, cholmod_common *cm)
{
    int m = g - 2, n = 3 * m * m;
    cholmod_triplet *T = cholmod_l_allocate_triplet((size_t)n, (size_t)n, (size_t)(2 * g * g * 27), 1, CHOLMOD_REAL, cm);
    for (int y = 0; y < g; y++)
        for (int x = 0; x < g; x++)
            for (int dir = 0; dir < 2; dir++) {
                int x2 = x + !dir, y2 = y + dir;
                if (x2 >= g || y2 >= g) continue;
                int a = x > 0 && y > 0 && x < g - 1 && y < g - 1 ? (y - 1) * m + x - 1 : -1;
                int b = x2 > 0 && y2 > 0 && x2 < g - 1 && y2 < g - 1 ? (y2 - 1) * m + x2 - 1 : -1;
                if (a < 0 && b < 0) continue;
                double z = 0.2 * ((x2 * x2 - y2 * y2) - (x * x - y * y)) / g;
                double d[3] = { !dir, dir, z }, l = sqrt(1 + z * z);
                for (int i = 0; i < 3; i++) d[i] /= l;
                string(T, a, b, d, 2400.0 / l, 1.0 / l);
            }
    cholmod_sparse *A = cholmod_l_triplet_to_sparse(T, 0, cm);
    cholmod_l_free_triplet(&T, cm);
    return A;
}

/* The 7-point Laplacian on a g^3 grid (Dirichlet). */
static cholmod_sparse *laplace3(int g, cholmod_common *cm)
{
    int n = g * g * g;
    cholmod_triplet *T = cholmod_l_allocate_triplet((size_t)n, (size_t)n, (size_t)(4 * n), 1, CHOLMOD_REAL, cm);
    for (int i = 0; i < n; i++) {
        int x = i % g, y = i / g % g, z = i / (g * g);
        add(T, i, i, 6);
        if (x + 1 < g) add(T, i, i + 1, -1);
        if (y + 1 < g) add(T, i, i + g, -1);
        if (z + 1 < g) add(T, i, i + g * g, -1);
    }
    cholmod_sparse *A = cholmod_l_triplet_to_sparse(T, 0, cm);
    cholmod_l_free_triplet(&T, cm);
    return A;
}

/* A chain of n springs, one end fixed, the other free: tridiagonal. */
static cholmod_sparse *chain(int n, cholmod_common *cm)
{
    cholmod_triplet *T = cholmod_l_allocate_triplet((size_t)n, (size_t)n, (size_t)(2 * n), 1, CHOLMOD_REAL, cm);
    for (int i = 0; i < n; i++) {
        add(T, i, i, i + 1 < n ? 2 : 1);
        if (i + 1 < n) add(T, i, i + 1, -1);
    }
    cholmod_sparse *A = cholmod_l_triplet_to_sparse(T, 0, cm);
    cholmod_l_free_triplet(&T, cm);
    return A;
}

/* A small dense SPD matrix: n I + the all-ones matrix. */
static cholmod_sparse *tiny(int n, cholmod_common *cm)
{
    cholmod_triplet *T = cholmod_l_allocate_triplet((size_t)n, (size_t)n, (size_t)(n * n), 1, CHOLMOD_REAL, cm);
    for (int i = 0; i < n; i++)
        for (int j = i; j < n; j++) add(T, i, j, 1 + (i == j ? n : 0));
    cholmod_sparse *A = cholmod_l_triplet_to_sparse(T, 0, cm);
    cholmod_l_free_triplet(&T, cm);
    return A;
}

static double norm2(const double *x, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) s += x[i] * x[i];
    return sqrt(s);
}

/* y = A x for the symmetric A stored upper. */
static void apply(cholmod_sparse *A, const double *x, double *y, cholmod_common *cm)
{
    double one[2] = { 1, 0 }, zero[2] = { 0, 0 };
    cholmod_dense xd = { A->nrow, 1, A->nrow, A->nrow, (void *)x, NULL, CHOLMOD_REAL, CHOLMOD_DOUBLE };
    cholmod_dense yd = xd;
    yd.x = y;
    cholmod_l_sdmult(A, 0, one, zero, &xd, &yd, cm);
}

/* kappa_2(A) from `its` power iterations on A and on A^-1 (the factor's solves): from
 * below, so a bound made with it is, if anything, strict. */
static double condition(cholmod_sparse *A, cholmod_factor *L, cholmod_common *cm, int its)
{
    size_t n = A->nrow;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), lam[2] = { 0, 0 };
    for (int inv = 0; inv < 2 && x && y; inv++) {
        for (size_t i = 0; i < n; i++) x[i] = 1 + 0.1 * (double)(i % 7);
        for (int it = 0; it < its; it++) {
            double s = norm2(x, n);
            for (size_t i = 0; i < n; i++) x[i] /= s;
            if (inv) {
                cholmod_dense bd = { n, 1, n, n, x, NULL, CHOLMOD_REAL, CHOLMOD_DOUBLE };
                cholmod_dense *X = cholmod_l_solve(CHOLMOD_A, L, &bd, cm);
                for (size_t i = 0; X && i < n; i++) y[i] = ((double *)X->x)[i];
                cholmod_l_free_dense(&X, cm);
            } else {
                apply(A, x, y, cm);
            }
            lam[inv] = norm2(y, n);
            for (size_t i = 0; i < n; i++) x[i] = y[i];
        }
    }
    free(x);
    free(y);
    return lam[0] * lam[1];
}

/* Normwise backward error of X as a solution of A X = B, column c. */
static double backward(cholmod_sparse *A, const double *B, const double *X, double anorm, size_t c,
                       cholmod_common *cm)
{
    size_t n = A->nrow;
    double *r = malloc(n * sizeof *r);
    if (!r) return INFINITY;
    apply(A, X + n * c, r, cm);
    for (size_t i = 0; i < n; i++) r[i] -= B[n * c + i];
    double e = norm2(r, n) / (anorm * norm2(X + n * c, n) + norm2(B + n * c, n));
    free(r);
    return e;
}

/* ||A||_2 from 100 power iterations (a lower bound: enough for a relative error). */
static double anorm2(cholmod_sparse *A, cholmod_common *cm)
{
    size_t n = A->nrow;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), l = 0;
    for (size_t i = 0; x && y && i < n; i++) x[i] = 1 + 0.3 * (double)(i % 5);
    for (int it = 0; x && y && it < 100; it++) {
        double s = norm2(x, n);
        for (size_t i = 0; i < n; i++) x[i] /= s;
        apply(A, x, y, cm);
        l = norm2(y, n);
        for (size_t i = 0; i < n; i++) x[i] = y[i];
    }
    free(x);
    free(y);
    return l;
}

/* CHOLMOD's supernodal LL' factor of A (METIS, or CHOLMOD's choice). */
static cholmod_factor *factor(cholmod_sparse *A, int metis, cholmod_common *cm)
{
    cm->supernodal = CHOLMOD_SUPERNODAL;
    cm->nmethods = metis ? 1 : 0;
    cm->method[0].ordering = CHOLMOD_METIS;
    cholmod_factor *L = cholmod_l_analyze(A, cm);
    if (L && !cholmod_l_factorize(A, L, cm)) cholmod_l_free_factor(&L, cm);
    return L;
}

/* One matrix: psolve against cholmod_l_solve for 1, 4 and 7 columns. */
static void compare(const char *name, cholmod_sparse *A, int metis, int expect_plan, cholmod_common *cm)
{
    cholmod_factor *L = factor(A, metis, cm);
    CHECK_MSG(L && L->is_super && L->is_ll, "%s: a supernodal LL' factor", name);
    if (!L) return;
    size_t n = A->nrow;
    ctn_ctx *ctx = NULL;
    ctn_psolve *p = NULL;
    CHECK(ctn_ctx_create(&ctx) == CTN_OK);
    ctn_ctx_set_threads(ctx, 2);                         /* the helper allowed */
    CHECK(ctn_psolve_create(ctx, L, &p) == CTN_OK);
    CHECK_MSG(!expect_plan || p, "%s: a plan (%zu supernodes)", name, L->nsuper);
    double kappa = condition(A, L, cm, 200), an = anorm2(A, cm), worst = 0;
    for (int k = 1; p && k <= 7; k += 3) {
        double *B = malloc(n * (size_t)k * sizeof *B), *X1 = malloc(n * (size_t)k * sizeof *X1);
        double *X2 = malloc(n * (size_t)k * sizeof *X2);
        for (size_t i = 0; i < n * (size_t)k; i++) B[i] = sin(0.7 * (double)i) + 0.01 * (double)(i % 13);
        cholmod_dense Bd = { n, (size_t)k, n * (size_t)k, n, B, NULL, CHOLMOD_REAL, CHOLMOD_DOUBLE };
        cholmod_dense *Xc = cholmod_l_solve(CHOLMOD_A, L, &Bd, cm);
        CHECK(ctn_psolve_solve(p, L, B, X1, (size_t)k, 1) == CTN_OK);
        CHECK(ctn_psolve_solve(p, L, B, X2, (size_t)k, 2) == CTN_OK);
        CHECK_MSG(!memcmp(X1, X2, n * (size_t)k * sizeof *X1), "%s: one thread and two differ", name);
        const double *xc = Xc->x;
        for (int c = 0; c < k; c++) {
            double ep = backward(A, B, X2, an, (size_t)c, cm), ec = backward(A, B, xc, an, (size_t)c, cm);
            double d = 0;
            for (size_t i = 0; i < n; i++) d += (X2[n * c + i] - xc[n * c + i]) * (X2[n * c + i] - xc[n * c + i]);
            d = sqrt(d) / norm2(xc + n * c, n);
            /* backward stable as CHOLMOD's (a Cholesky solve's error is a small multiple
             * of eps), and the two forward errors each within kappa times theirs */
            CHECK_MSG(ep <= 64 * EPS && ep <= 8 * ec + 4 * EPS, "%s k=%d: backward error %.3g (CHOLMOD %.3g)", name,
                      k, ep, ec);
            CHECK_MSG(d <= 2 * kappa * (ep + ec) + 4 * EPS, "%s k=%d: differ by %.3g, kappa %.3g, bound %.3g", name, k,
                      d, kappa, 2 * kappa * (ep + ec));
            if (d > worst) worst = d;
        }
        cholmod_l_free_dense(&Xc, cm);
        free(B);
        free(X1);
        free(X2);
    }
    if (p) {
        double s[3];
        ctn_psolve_shares(p, s);
        CHECK(fabs(s[0] + s[1] + s[2] - 1) < 1e-12 && s[0] > 0 && s[1] > 0 && s[0] + s[1] >= 0.5);
        printf("%-8s n %6zu, %5zu supernodes, sets %.3f %.3f, top %.3f; kappa %.2g, largest difference %.2g\n", name,
               n, L->nsuper, s[0], s[1], s[2], kappa, worst);
    } else {
        printf("%-8s n %6zu, %5zu supernodes: no plan (CHOLMOD's solve is used)\n", name, n, L->nsuper);
    }
    ctn_psolve_destroy(&p);
    CHECK(p == NULL);
    ctn_ctx_destroy(&ctx);
    cholmod_l_free_factor(&L, cm);
}

/* Every allocation of the plan and of the solve's workspace may fail. */
static void alloc_failures(cholmod_sparse *A, cholmod_common *cm)
{
    cholmod_factor *L = factor(A, 1, cm);
    size_t n = A->nrow;
    double *B = calloc(4 * n, sizeof *B), *X = calloc(4 * n, sizeof *X);
    int failures = 0;
    for (size_t i = 0; B && i < 4 * n; i++) B[i] = 1;
    for (long k = 1; L && B && X && k < 100; k++) {
        ctn_ctx *ctx = NULL;
        ctn_psolve *p = NULL;
        ctn_ctx_create(&ctx);
        ctn_ctx_set_threads(ctx, 2);
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_psolve_create(ctx, L, &p);
        CHECK(rc == CTN_OK || (rc == CTN_ERR_NOMEM && !p));
        if (!rc) CHECK(p != NULL);
        if (p) rc = ctn_psolve_solve(p, L, B, X, 4, 2);
        CHECK(rc == CTN_OK || rc == CTN_ERR_NOMEM);
        CHECK(rc == CTN_OK || strstr(ctn_ctx_message(ctx), "memory") != NULL);
        failures += rc == CTN_ERR_NOMEM;
        ctn_psolve_destroy(&p);
        ctn_ctx_destroy(&ctx);
        if (rc == CTN_OK) break;
    }
    CHECK(failures >= 10);
    free(B);
    free(X);
    cholmod_l_free_factor(&L, cm);
}

/* The linear solver's solves, block and single, take the two-thread path from 50 000
 * rows (not under threads=1): block against single solves of the same factor, and the
 * single solves on two threads against CHOLMOD's (threads=1), within rounding (two
 * backward stable solves differ by a few eps times the condition number); a single
 * solve in place (x = b) gives the bits of one out of place. */
static void backend(cholmod_common *cm)
{
    cholmod_sparse *A = net(132, cm);                   /* 3 x 130^2 = 50 700 rows */
    if (!A) return;
    size_t n = A->nrow, nnz = (size_t)((SuiteSparse_long *)A->p)[n];
    int *colptr = malloc((n + 1) * sizeof *colptr), *rowind = malloc(nnz * sizeof *rowind);
    double *B = malloc(4 * n * sizeof *B), *X = malloc(4 * n * sizeof *X), *S = malloc(4 * n * sizeof *S);
    double *S2 = malloc(n * sizeof *S2), *T = malloc(n * sizeof *T);
    ctn_ctx *ctx = NULL;
    ctn_linsolve *ls = NULL;
    ctn_factor_info info = { 0, -1 };
    CHECK(colptr && rowind && B && X && S && S2 && T && ctn_ctx_create(&ctx) == CTN_OK);
    ctn_ctx_set_threads(ctx, 2);
    for (size_t j = 0; colptr && rowind && j <= n; j++) colptr[j] = (int)((SuiteSparse_long *)A->p)[j];
    for (size_t q = 0; colptr && rowind && q < nnz; q++) rowind[q] = (int)((SuiteSparse_long *)A->i)[q];
    for (size_t i = 0; B && i < 4 * n; i++) B[i] = cos(0.3 * (double)i);
    ctn_pattern pat = { n, colptr, rowind };
    cholmod_factor *L = factor(A, 1, cm);
    double kappa = L ? condition(A, L, cm, 30) : INFINITY;
    cholmod_l_free_factor(&L, cm);
    if (ctx && colptr && rowind && B && X && S && S2 && T) {
        CHECK(ctn_linsolve_create(ctx, "cholmod", &pat, CTN_LA_ORDER_METIS, &ls) == CTN_OK);
        if (ls) CHECK(ctn_linsolve_factor(ls, A->x, 0, &info) == CTN_OK && info.ok);
        for (int threads = 0; ls && info.ok && threads < 2; threads++) {
            ctn_linsolve_set_threads(ls, threads);      /* 0: the default, two; then one */
            CHECK(ctn_linsolve_solve_block(ls, B, X, 4) == CTN_OK);
            double d = 0, x = 0;
            for (size_t c = 0; c < 4; c++) {
                CHECK(ctn_linsolve_solve(ls, B + n * c, S + n * c) == CTN_OK);
                for (size_t i = 0; i < n; i++) d = fmax(d, fabs(X[n * c + i] - S[n * c + i])), x = fmax(x, fabs(S[n * c + i]));
            }
            CHECK_MSG(d <= 64 * EPS * kappa * x, "threads=%d: block and single solves differ by %.3g of %.3g (kappa %.3g)",
                      threads, d, x, kappa);
            printf("backend  n %6zu, threads=%d: block solve against single solves %.2g (kappa %.2g)\n", n, threads,
                   d / x, kappa);
            int two = !threads && sysconf(_SC_NPROCESSORS_ONLN) >= 2;
            CHECK_MSG(ctn_linsolve_solve_threads(ls) == (two ? 2 : 1), "threads=%d: solves on %d threads", threads,
                      ctn_linsolve_solve_threads(ls));
            memcpy(T, B, n * sizeof *T);
            CHECK(ctn_linsolve_solve(ls, T, T) == CTN_OK);
            CHECK_MSG(!memcmp(T, S, n * sizeof *T), "threads=%d: a solve in place differs from one out of place", threads);
            if (!threads) memcpy(S2, S, n * sizeof *S2);
            else {
                double e = 0;
                for (size_t i = 0; i < n; i++) e = fmax(e, fabs(S2[i] - S[i]));
                CHECK_MSG(e <= 64 * EPS * kappa * x, "single solves on two threads and CHOLMOD's differ by %.3g", e);
                printf("backend  n %6zu: single solve on two threads against CHOLMOD's %.2g\n", n, e / x);
            }
        }
    }
    ctn_linsolve_destroy(&ls);
    ctn_ctx_destroy(&ctx);
    free(colptr);
    free(rowind);
    free(B);
    free(X);
    free(S);
    free(S2);
    free(T);
    cholmod_l_free_sparse(&A, cm);
}

/* One supernode (nr x nc, a well-conditioned lower triangle over L21) and 4 columns: the
 * kernels' forward and backward sweeps against plain loops, entry by entry. */
static void kernel_case(const ctn_ps4_kernels *k, const char *copy, int nr, int nc)
{
    const int m = nr - nc;
    double *L = malloc((size_t)nr * (size_t)nc * sizeof *L), *Z = malloc((size_t)nc * 4 * sizeof *Z);
    double *Zr = malloc((size_t)nc * 4 * sizeof *Zr), *E = malloc((size_t)(m + 1) * 4 * sizeof *E);
    double *Er = malloc((size_t)(m + 1) * 4 * sizeof *Er);
    for (int c = 0; c < nc; c++)
        for (int r = 0; r < nr; r++)
            L[r + (size_t)nr * c] = r < c ? 0 : r == c ? 2 + 0.1 * (c % 3) : 0.3 * sin(1.3 * r + 0.7 * c) / (1 + r - c);
    for (int i = 0; i < 4 * nc; i++) Z[i] = Zr[i] = cos(0.37 * i);
    for (int i = 0; i < 4 * m; i++) E[i] = 99;                      /* overwritten */
    k->forward(L, nr, nc, Z, E);
    for (int c = 0; c < 4; c++) {                                   /* plain: Z = L11 \ Z, E = L21 Z */
        for (int u = 0; u < nc; u++) {
            Zr[4 * u + c] /= L[u + (size_t)nr * u];
            for (int t = u + 1; t < nc; t++) Zr[4 * t + c] -= L[t + (size_t)nr * u] * Zr[4 * u + c];
        }
        for (int i = 0; i < m; i++) {
            Er[4 * i + c] = 0;
            for (int u = 0; u < nc; u++) Er[4 * i + c] += L[nc + i + (size_t)nr * u] * Zr[4 * u + c];
        }
    }
    double worst = 0;
    for (int i = 0; i < 4 * nc; i++) worst = fmax(worst, fabs(Z[i] - Zr[i]) / (1 + fabs(Zr[i])));
    for (int i = 0; i < 4 * m; i++) worst = fmax(worst, fabs(E[i] - Er[i]) / (1 + fabs(Er[i])));
    CHECK_MSG(worst <= 1e-14, "%s forward nr %d nc %d: differs by %.3g", copy, nr, nc, worst);
    for (int i = 0; i < 4 * m; i++) E[i] = Er[i] = sin(0.91 * i);
    k->backward(L, nr, nc, Z, E);
    for (int c = 0; c < 4; c++)                                     /* plain: Z = L11' \ (Z - L21' E) */
        for (int u = nc - 1; u >= 0; u--) {
            double s = Zr[4 * u + c];
            for (int t = u + 1; t < nr; t++) s -= L[t + (size_t)nr * u] * (t < nc ? Zr[4 * t + c] : Er[4 * (t - nc) + c]);
            Zr[4 * u + c] = s / L[u + (size_t)nr * u];
        }
    worst = 0;
    for (int i = 0; i < 4 * nc; i++) worst = fmax(worst, fabs(Z[i] - Zr[i]) / (1 + fabs(Zr[i])));
    CHECK_MSG(worst <= 1e-14, "%s backward nr %d nc %d: differs by %.3g", copy, nr, nc, worst);
    free(L);
    free(Z);
    free(Zr);
    free(E);
    free(Er);
}

static void kernels(void)
{
    ctn_ps4_kernels k[2] = { { ctn_ps4_forward_base, ctn_ps4_backward_base } };
    const char *name[2] = { "baseline", "avx2" };
    int copies = 1;
#if CTN_PS4_AVX2
    if (__builtin_cpu_supports("avx2")) k[copies++] = (ctn_ps4_kernels){ ctn_ps4_forward_avx2, ctn_ps4_backward_avx2 };
#endif
    const int shapes[][2] = { { 1, 1 }, { 3, 3 }, { 4, 4 }, { 9, 4 }, { 5, 5 }, { 20, 8 }, { 40, 13 }, { 7, 2 } };
    for (int c = 0; c < copies; c++)
        for (size_t s = 0; s < sizeof shapes / sizeof *shapes; s++) kernel_case(&k[c], name[c], shapes[s][0], shapes[s][1]);
    ctn_ps4_kernels chosen;
    ctn_ps4_choose(&chosen);
    CHECK(chosen.forward == k[copies - 1].forward && chosen.backward == k[copies - 1].backward);
    printf("4-column sweeps: %d cop%s checked (%s chosen)\n", copies, copies > 1 ? "ies" : "y", name[copies - 1]);
}

int main(void)
{
    ctn_threads_saved saved;
    ctn_threads_push(1, &saved);                 /* CHOLMOD's BLAS on one thread, as catena's solves */
    cholmod_common cm;
    cholmod_l_start(&cm);
    cm.print = 0;
    cholmod_sparse *A[4] = { net(42, &cm), laplace3(14, &cm), chain(3000, &cm), tiny(5, &cm) };
    CHECK(A[0] && A[1] && A[2] && A[3]);
    if (A[0] && A[1] && A[2] && A[3]) {
        compare("net", A[0], 1, 1, &cm);
        compare("net-amd", A[0], 0, 1, &cm);
        compare("laplace", A[1], 1, 1, &cm);
        compare("chain", A[2], 1, 1, &cm);
        compare("tiny", A[3], 0, 0, &cm);
        alloc_failures(A[0], &cm);
    }
    backend(&cm);
    kernels();
    for (int i = 0; i < 4; i++) cholmod_l_free_sparse(&A[i], &cm);
    cholmod_l_finish(&cm);
    ctn_threads_pop(&saved);
    CHECK_DONE();
}
