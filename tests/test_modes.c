/* Modal analysis (issue 12), each check against an independent truth:
 * - mass matrices: the element's total mass and rigid-body translation exact (both
 *   matrices), the assembled matrix of a free element and point masses;
 * - the taut string: the discrete frequencies of N elements in closed form (lumped
 *   omega^2 = 4 T/(m' h^2) sin^2(k/2), consistent 6 T/(m' h^2) (1 - cos k)/(2 + cos k),
 *   k = j pi / N), and the O(h^2) convergence to f_j = j/(2L) sqrt(T/m'), from above
 *   (consistent) and from below (lumped), m' the stretched mass per length;
 * - Irvine's suspended cable (shallow, level): antisymmetric in-plane modes at
 *   omega_bar = 2 n pi, out-of-plane at n pi, the first symmetric in-plane mode on the
 *   root of tan(w/2) = w/2 - (4/lambda^2)(w/2)^3 on both sides of and at the crossover
 *   lambda^2 = 4 pi^2;
 * - eigenpairs of a hypar net: |K phi - omega^2 M phi| / |K phi| <= 1e-10,
 *   M-orthonormality, the eigenvalues of a dense solve (LAPACK dsygv) of the same K and
 *   M; a shift finds the modes nearest it; every free DOF asked for;
 * - a node held only by slack members: three zero modes naming it;
 * - errors: count out of range, no mass, a weight without units (file:line); every
 *   allocation failure: CTN_ERR_NOMEM and no leak. */
#include "element/cable2.h"
#include "analysis/modal/modal.h"
#include "catena.h"
#include "check.h"

#include <stdlib.h>

#define PI 3.14159265358979323846

/* LAPACK: the generalized symmetric-definite eigenproblem (the dense reference). */
void dsygv_(const int *itype, const char *jobz, const char *uplo, const int *n, double *a, const int *lda,
            double *b, const int *ldb, double *w, double *work, const int *lwork, int *info, size_t ljobz,
            size_t luplo);

static ctn_model *read_model(ctn_ctx *ctx, const char *text, ctn_solve_options *opt)
{
    ctn_model *m = NULL;
    int rc = ctn_read_string(ctx, "test.cable", text, strlen(text), &m, opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    return m;
}

/* ---- mass matrices ---- */

/* Full 6 x 6 from the packed upper triangle. */
static void unpack6(const double *P, double M[6][6])
{
    for (int i = 0; i < 6; i++)
        for (int j = i; j < 6; j++) M[i][j] = M[j][i] = P[ctn_packed_index(6, i, j)];
}

static void test_element_mass(void)
{
    ctn_cable_props p = { .EA = 1000, .l0 = 2.5, .A = 1.0, .strain = CTN_STRAIN_GREEN_LAGRANGE, .l0_ref = 2.5, .mass = 7.5 };
    for (int lumped = 0; lumped < 2; lumped++) {
        double P[21], M[6][6];
        ctn_cable2_ops.mass(&p, NULL, lumped, P);
        unpack6(P, M);
        for (int d = 0; d < 3; d++) {                  /* rigid translation along d */
            double f[6] = { 0 }, total = 0;
            for (int i = 0; i < 6; i++)
                for (int j = 0; j < 6; j++) f[i] += M[i][j] * (j % 3 == d);
            for (int i = 0; i < 6; i++) total += f[i];
            CHECK(total == 7.5);                       /* r^T M r = m l0, exactly */
            for (int i = 0; i < 6; i++) CHECK(f[i] == (i % 3 == d ? 3.75 : 0.0));   /* M r: half at each node */
        }
        CHECK(M[0][3] == (lumped ? 0.0 : 1.25));       /* m l0 / 6 off the diagonal */
        CHECK(M[0][1] == 0.0 && M[0][4] == 0.0);       /* no coupling of directions */
    }
    CHECK(ctn_spring2_ops.mass == NULL);               /* springs are massless */
}

/* A free element (no supports: the assembler alone) and a point mass. */
static void test_assembled_mass(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_model(ctx,
        "units kN m\nmaterial steel E=2e8\nsection s material=steel A=1e-4 w=0.5\n"
        "node 1 0 0 0\nnode 2 3 4 0 mass=2\nelement 1 1 2 section=s l0=4\n", NULL);
    ctn_asm *a = NULL;
    CHECK(m && ctn_asm_create(ctx, m, &a) == CTN_OK);
    if (a) {
        double *Mx = calloc(a->nnz, sizeof(double)), diag[6], tot[3], ms = 0.5 / 9.80665 * 4;   /* w/g l0 */
        size_t bad;
        CHECK(a->ndof == 6 && a->nnz == 21);
        for (int lumped = 0; lumped < 2; lumped++) {
            CHECK(ctn_asm_mass(ctx, a, lumped, Mx) == CTN_OK);
            double sum = 0;                            /* r_x^T M r_x over the pattern */
            for (int c = 0; c < 6; c++)
                for (int k = a->colptr[c]; k < a->colptr[c + 1]; k++) {
                    int r = a->rowind[k];
                    if (r % 3 == 0 && c % 3 == 0) sum += (r == c ? 1 : 2) * Mx[k];
                }
            CHECK_CLOSE(sum, ms + 2, 1e-15, 0);
        }
        CHECK(ctn_asm_mass_diag(a, diag, tot, &bad) == 0);
        CHECK_CLOSE(tot[1], ms + 2, 1e-15, 0);
        CHECK_CLOSE(diag[4], ms / 2 + 2, 1e-15, 0);
        free(Mx);
    }
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* ---- solved models ---- */

typedef struct run {
    ctn_ctx *ctx;
    ctn_model *m;
    ctn_problem *p;
    ctn_solution *s;
} run;

static int solve_text(run *r, const char *text)
{
    ctn_solve_options opt;
    memset(r, 0, sizeof *r);
    ctn_ctx_create(&r->ctx);
    r->m = read_model(r->ctx, text, &opt);
    int rc = r->m ? ctn_problem_create(r->ctx, r->m, &opt, &r->p) : CTN_ERR_MODEL;
    if (!rc) rc = ctn_problem_solve(r->p, &r->s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(r->ctx));
    return rc;
}

static void run_free(run *r)
{
    ctn_solution_destroy(&r->s);
    ctn_problem_destroy(&r->p);
    ctn_model_destroy(&r->m);
    ctn_ctx_destroy(&r->ctx);
}

static double mode_freq(const run *r, size_t k)
{
    ctn_mode md;
    return ctn_solution_mode(r->s, k, &md) ? NAN : md.frequency;
}

/* A string of length 1 m, tension T = 100 N, m = 0.01 kg/m unstressed, N elements. */
static int string_run(run *r, int N, const char *mass, int count)
{
    char text[512];
    snprintf(text, sizeof text,
             "units N m\nmaterial steel E=2e11 strain=engineering\nsection s material=steel A=1e-6 mass=0.01\n"
             "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\n"
             "cable 1 2 section=s n=%d length=1 shape=straight N0=100\nmodes count=%d mass=%s\n", N, count, mass);
    return solve_text(r, text);
}

static void test_taut_string(void)
{
    const double T = 100, EA = 2e11 * 1e-6, mp = 0.01 / (1 + T / EA);   /* m' = m l0 / l */
    for (int lumped = 0; lumped < 2; lumped++) {
        double err[3][3];                               /* [N level][mode j] */
        for (int lev = 0; lev < 3; lev++) {
            int N = 10 << lev;
            run r;
            if (string_run(&r, N, lumped ? "lumped" : "consistent", 6) == CTN_OK) {
                CHECK(ctn_solution_mode_count(r.s) == 6);
                for (int j = 1; j <= 3; j++) {
                    double h = 1.0 / N, k = j * PI / N, w2 = lumped ? 4 * T / (mp * h * h) * pow(sin(k / 2), 2)
                                                                 : 6 * T / (mp * h * h) * (1 - cos(k)) / (2 + cos(k));
                    double fd = sqrt(w2) / (2 * PI), fc = j / 2.0 * sqrt(T / mp);
                    for (int pair = 0; pair < 2; pair++)        /* y and z: a double mode */
                        CHECK_CLOSE(mode_freq(&r, (size_t)(2 * (j - 1) + pair)), fd, 1e-9, 0);
                    err[lev][j - 1] = (mode_freq(&r, (size_t)(2 * (j - 1))) - fc) / fc;
                }
            }
            run_free(&r);
        }
        for (int j = 0; j < 3; j++) {
            CHECK(lumped ? err[0][j] < 0 : err[0][j] > 0);    /* lumped below, consistent above */
            for (int lev = 1; lev < 3; lev++) {
                double ratio = err[lev - 1][j] / err[lev][j];
                CHECK_MSG(ratio > 3.8 && ratio < 4.2, "O(h^2): error ratio %g (mode %d, lumped %d)", ratio, j + 1, lumped);
            }
        }
    }
}

/* ---- Irvine ---- */

/* The first root in (pi, 3 pi) of tan(w/2) = w/2 - (4/l2)(w/2)^3 (bisection on
 * g(x) = sin x - cos x (x - 4 x^3 / l2), x = w/2 in (pi/2, 3 pi/2)). */
static double irvine_symmetric(double l2)
{
    double lo = PI / 2 + 1e-12, hi = 3 * PI / 2 - 1e-12;
    for (int it = 0; it < 200; it++) {
        double x = 0.5 * (lo + hi), gx = sin(x) - cos(x) * (x - 4 * x * x * x / l2);
        double glo = sin(lo) - cos(lo) * (lo - 4 * lo * lo * lo / l2);
        if ((gx > 0) == (glo > 0)) lo = x;
        else hi = x;
    }
    return lo + hi;                                     /* w = 2 x */
}

/* In-plane (x-y) mode symmetric (+1) or antisymmetric (-1) about mid-span, 0 if out of
 * plane; nodes 1 and 2 are the ends, the interior is numbered from 3 in order. */
static int classify(const run *r, size_t k)
{
    ctn_mode md;
    if (ctn_solution_mode(r->s, k, &md)) return 2;
    size_t nn = ctn_model_node_count(r->m);
    double inplane = 0, outplane = 0, sym = 0, anti = 0;
    for (size_t i = 2; i < nn; i++) {
        size_t j = nn + 1 - i;                          /* the mirror node */
        const double *u = md.shape + 3 * i, *v = md.shape + 3 * j;
        inplane += u[1] * u[1];
        outplane += u[2] * u[2];
        sym += (u[1] - v[1]) * (u[1] - v[1]);
        anti += (u[1] + v[1]) * (u[1] + v[1]);
    }
    if (outplane > inplane) return 0;
    return sym < anti ? 1 : -1;
}

/* A level span L = 100 m, w = 0.1 kN/m, EA given, unstressed length S; lambda^2 and
 * the frequency unit sqrt(H/m)/L/(2 pi) (omega_bar = 2 pi) from the solved state. */
static int irvine_run(run *r, double EA, double S, double *l2, double *f0)
{
    const double L = 100, w = 0.1, g = 9.80665;
    char text[640];
    snprintf(text, sizeof text,
             "units kN m\nmaterial steel E=%.17g strain=engineering\nsection s material=steel A=1 w=%g\n"
             "gravity 0 -1 0\nnode 1 0 0 0 fix=xyz\nnode 2 %g 0 0 fix=xyz\n"
             "cable 1 2 section=s n=120 length=%.17g shape=%s\nmodes count=8\n", EA, w, L, S,
             S > L ? "arc" : "straight");
    if (solve_text(r, text)) return 1;
    double H = fabs(ctn_solution_reactions(r->s)[0]), d = 0;
    ctn_solution_cable_sag(r->m, r->s, 0, &d);
    double Le = L * (1 + 8 * (d / L) * (d / L));        /* Irvine's L_e, level span */
    *l2 = pow(w * L / H, 2) * L / (H * Le / EA);
    *f0 = sqrt(H / (w / g)) / L / (2 * PI);             /* omega_bar = omega L / sqrt(H/m) */
    return 0;
}

/* The unstressed length that gives lambda^2 = target with EA chosen for sag L/50:
 * H = wL^2/(8d), S = L (1 + 8/3 (d/L)^2) - H L_e / EA (the shallow parabola). */
static void irvine_design(double target, double *EA, double *S)
{
    const double L = 100, w = 0.1, d0 = 2, H0 = w * L * L / (8 * d0);
    double Le = L * (1 + 8 * (d0 / L) * (d0 / L)), H = H0, d = d0;
    *EA = target * H0 * Le / (pow(w * L / H0, 2) * L);
    for (int it = 0; it < 5; it++) {                    /* L_e depends on the sag */
        H = cbrt(pow(w * L, 2) * L * *EA / (target * Le));
        d = w * L * L / (8 * H);
        Le = L * (1 + 8 * (d / L) * (d / L));
    }
    *S = L * (1 + 8.0 / 3 * (d / L) * (d / L)) - H * Le / *EA;
}

static void test_irvine(void)
{
    const double targets[3] = { 2 * PI * PI, 4 * PI * PI, 8 * PI * PI };
    for (int t = 0; t < 3; t++) {
        run r;
        double l2 = 0, f0 = 0, EA, S;
        irvine_design(targets[t], &EA, &S);
        if (irvine_run(&r, EA, S, &l2, &f0) == 0) {
            CHECK_CLOSE(l2, targets[t], 1e-2, 0);
            double anti = 0, sym = 0, out = 0;          /* the first of each kind */
            for (size_t k = 0; k < ctn_solution_mode_count(r.s); k++) {
                int c = classify(&r, k);
                double wbar = mode_freq(&r, k) / f0;
                if (c == -1 && !anti) anti = wbar;
                if (c == 1 && !sym) sym = wbar;
                if (c == 0 && !out) out = wbar;
            }
            CHECK_CLOSE(anti, 2 * PI, 3e-3, 0);         /* shallow theory: sag/span 1/50 */
            CHECK_CLOSE(out, PI, 3e-3, 0);
            CHECK_CLOSE(sym, irvine_symmetric(l2), 1e-3, 0);
            if (t == 0) CHECK(sym < anti);              /* below the crossover */
            if (t == 1) CHECK_CLOSE(sym, anti, 5e-3, 0);
            if (t == 2) CHECK(sym > anti);
        }
        run_free(&r);
    }
}

/* ---- eigenpairs against a dense reference ---- */

/* A 6 x 6 hypar net (25 free nodes, 75 DOFs), tension-only strands, snow. */
static const char *net_text(char *buf, size_t size, const char *modes)
{
    int k = 6, n = 0, e = 1;
    double h = 100.0 / k;
    n += snprintf(buf + n, size - (size_t)n, "units kN m\nmaterial strand E=1.6e8 tension-only\n"
                  "section s material=strand A=1.5e-4 mass=0.0012\n%s\n", modes);
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++) {
            double x = -50 + i * h, y = -50 + j * h;
            n += snprintf(buf + n, size - (size_t)n, "node %d %g %g %.17g%s\n", i * (k + 1) + j + 1, x, y,
                          10 * (x * x - y * y) / 2500, i % k && j % k ? "" : " fix=xyz");
        }
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++)
            for (int d = 0; d < 2; d++) {
                int i2 = i + (d == 0), j2 = j + (d == 1);
                if (i2 > k || j2 > k || (d == 1 && i % k == 0) || (d == 0 && j % k == 0)) continue;
                n += snprintf(buf + n, size - (size_t)n, "element %d %d %d section=s N0=10\n", e++,
                              i * (k + 1) + j + 1, i2 * (k + 1) + j2 + 1);
            }
    for (int i = 1; i < k; i++)
        for (int j = 1; j < k; j++) n += snprintf(buf + n, size - (size_t)n, "load %d 0 0 -0.5\n", i * (k + 1) + j + 1);
    return buf;
}

/* phi (ndof) of mode k. */
static void mode_vector(const run *r, size_t k, double *phi)
{
    const ctn_problem *p = r->p;
    ctn_mode md;
    ctn_solution_mode(r->s, k, &md);
    for (size_t i = 0; i < r->m->nodes.n; i++)
        for (int d = 0; d < 3; d++) {
            int q = p->a->map.eq[3 * i + (size_t)d];
            if (q >= 0) phi[q] = md.shape[3 * i + (size_t)d];
        }
}

/* Dense copies of K (at the solution) and M, column-major n x n. */
static void dense(const ctn_problem *p, const double *Ax, double *A)
{
    size_t n = p->ndof;
    memset(A, 0, n * n * sizeof(double));
    for (size_t c = 0; c < n; c++)
        for (int k = p->a->colptr[c]; k < p->a->colptr[c + 1]; k++) {
            size_t r = (size_t)p->a->rowind[k];
            A[r + n * c] = A[c + n * r] = Ax[k];
        }
}

static void check_pairs(run *r, int lumped, const double *ref, size_t first)
{
    ctn_problem *p = r->p;
    size_t n = p->ndof, count = ctn_solution_mode_count(r->s);
    double *Mx = calloc(p->a->nnz, sizeof(double)), *phi = calloc(n * count, sizeof(double));
    double *Kp = calloc(n, sizeof(double)), *Mp = calloc(n, sizeof(double));
    CHECK(ctn_asm_mass(p->ctx, p->a, lumped, Mx) == CTN_OK);
    for (size_t k = 0; k < count; k++) mode_vector(r, k, phi + n * k);
    for (size_t k = 0; k < count; k++) {
        ctn_mode md;
        ctn_solution_mode(r->s, k, &md);
        ctn_problem_symv(p, p->Kx, phi + n * k, Kp);
        ctn_problem_symv(p, Mx, phi + n * k, Mp);
        double rr = 0;
        for (size_t i = 0; i < n; i++) rr += pow(Kp[i] - md.eigenvalue * Mp[i], 2);
        CHECK_MSG(sqrt(rr) / ctn_vec_norm(Kp, n) <= 1e-10, "mode %zu residual %g", k + 1, sqrt(rr) / ctn_vec_norm(Kp, n));
        for (size_t j = 0; j < count; j++)             /* phi_j^T M phi_k = delta_jk */
            CHECK_CLOSE(ctn_vec_dot(phi + n * j, Mp, n), j == k ? 1.0 : 0.0, 1e-10, 1e-10);
        CHECK_CLOSE(md.eigenvalue, ref[first + k], 1e-9, 0);
    }
    free(Mx); free(phi); free(Kp); free(Mp);
}

/* The dense eigenvalues of K phi = lambda M phi (ascending) into w (n). */
static int dense_eigenvalues(run *r, int lumped, double *w)
{
    ctn_problem *p = r->p;
    int n = (int)p->ndof, one = 1, lwork = 8 * n, info = 0;
    double *K = malloc((size_t)n * (size_t)n * sizeof(double)), *M = malloc((size_t)n * (size_t)n * sizeof(double));
    double *Mx = calloc(p->a->nnz, sizeof(double)), *work = malloc((size_t)lwork * sizeof(double));
    CHECK(ctn_asm_mass(p->ctx, p->a, lumped, Mx) == CTN_OK);
    dense(p, p->Kx, K);
    dense(p, Mx, M);
    dsygv_(&one, "N", "U", &n, K, &n, M, &n, w, work, &lwork, &info, 1, 1);
    free(K); free(M); free(Mx); free(work);
    return info;
}

static void test_net_pairs(void)
{
    static char buf[16384];
    for (int lumped = 0; lumped < 2; lumped++) {
        run r;
        char line[64];
        snprintf(line, sizeof line, "modes count=12 mass=%s", lumped ? "lumped" : "consistent");
        if (solve_text(&r, net_text(buf, sizeof buf, line)) == CTN_OK) {
            double w[75];
            CHECK(r.p->ndof == 75 && ctn_solution_mode_count(r.s) == 12);
            CHECK(dense_eigenvalues(&r, lumped, w) == 0);
            check_pairs(&r, lumped, w, 0);
            ctn_modal_summary ms;
            CHECK(ctn_solution_modal_summary(r.s, &ms) == CTN_OK && ms.max_residual <= 1e-10);
            CHECK_MSG(ms.factorizations == 0 && ms.reused_factor == 1, "factorizations %d, reused %d",
                      ms.factorizations, ms.reused_factor); /* Newton's last steps reused an older
                                                     factor: the stability check factored K_T here */
            ctn_modal_options o = { .size = sizeof(ctn_modal_options), .count = 5, .mass = lumped ? CTN_MASS_LUMPED : CTN_MASS_CONSISTENT };
            o.shift = sqrt(w[20]) / (2 * PI);           /* nearest the 21st: modes 19 .. 23 */
            CHECK(ctn_problem_modes(r.p, r.s, &o) == CTN_OK);
            check_pairs(&r, lumped, w, 18);
            o.count = 75;                               /* every free DOF */
            o.shift = 0;
            CHECK(ctn_problem_modes(r.p, r.s, &o) == CTN_OK);
            check_pairs(&r, lumped, w, 0);
        }
        run_free(&r);
    }
}

/* ---- the two eigen-solvers ---- */

static double mode_eigenvalue(const run *r, size_t k)
{
    ctn_mode md;
    return ctn_solution_mode(r->s, k, &md) ? NAN : md.eigenvalue;
}

/* A flat square net, k x k cells of 10 m, prestressed to 10 kN, edges pinned: the
 * symmetry x <-> y makes double eigenvalues. */
static const char *flat_net_text(char *buf, size_t size, int k, const char *modes)
{
    int n = snprintf(buf, size, "units kN m\nmaterial strand E=1.6e8\nsection s material=strand A=1.5e-4 "
                     "mass=0.0012\n%s\n", modes);
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++)
            n += snprintf(buf + n, size - (size_t)n, "node %d %d %d 0%s\n", i * (k + 1) + j + 1, 10 * i, 10 * j,
                          i % k && j % k ? "" : " fix=xyz");
    for (int i = 0, e = 1; i <= k; i++)
        for (int j = 0; j <= k; j++)
            for (int d = 0; d < 2; d++) {
                int i2 = i + (d == 0), j2 = j + (d == 1);
                if (i2 > k || j2 > k || (d == 1 && i % k == 0) || (d == 0 && j % k == 0)) continue;
                n += snprintf(buf + n, size - (size_t)n, "element %d %d %d section=s N0=10\n", e++, i * (k + 1) + j + 1,
                              i2 * (k + 1) + j2 + 1);
            }
    return buf;
}

/* The model's modes by block Lanczos (its `modes` line), then again by ARPACK on the same
 * problem: both against the dense eigenvalues (dsygv), residuals and M-orthonormality
 * (check_pairs), and against each other. */
static void both_solvers(const char *text, int lumped, int count)
{
    run r;
    if (solve_text(&r, text) != CTN_OK) {
        run_free(&r);
        return;
    }
    size_t n = r.p->ndof;
    double *w = malloc(n * sizeof *w), *lb = malloc((size_t)count * sizeof *lb);
    ctn_modal_summary ms;
    CHECK(ctn_solution_modal_summary(r.s, &ms) == CTN_OK && ms.solver == CTN_EIGEN_BLOCK && ms.block_solves > 0);
    CHECK(dense_eigenvalues(&r, lumped, w) == 0);
    check_pairs(&r, lumped, w, 0);
    for (int k = 0; k < count; k++) lb[k] = mode_eigenvalue(&r, (size_t)k);
    ctn_modal_options o = { .size = sizeof(ctn_modal_options), .count = count, .mass = lumped ? CTN_MASS_LUMPED : CTN_MASS_CONSISTENT,
                            .solver = CTN_EIGEN_ARPACK };
    CHECK(ctn_problem_modes(r.p, r.s, &o) == CTN_OK);
    CHECK(ctn_solution_modal_summary(r.s, &ms) == CTN_OK && ms.solver == CTN_EIGEN_ARPACK && ms.block_solves == 0);
    check_pairs(&r, lumped, w, 0);
    for (int k = 0; k < count; k++) CHECK_CLOSE(mode_eigenvalue(&r, (size_t)k), lb[k], 1e-10, 0);
    free(w);
    free(lb);
    run_free(&r);
}

/* The default (auto) takes ARPACK below CTN_EIGEN_BLOCK_DOFS free DOFs. */
static void test_auto_solver(void)
{
    static char buf[32768];
    run r;
    if (solve_text(&r, net_text(buf, sizeof buf, "modes count=6")) == CTN_OK) {
        ctn_modal_summary ms;
        CHECK(r.p->ndof < CTN_EIGEN_BLOCK_DOFS);
        CHECK(ctn_solution_modal_summary(r.s, &ms) == CTN_OK && ms.solver == CTN_EIGEN_ARPACK && ms.block_solves == 0);
    }
    run_free(&r);
}

static void test_block_solver(void)
{
    static char buf[32768];
    char line[96];
    for (int lumped = 0; lumped < 2; lumped++) {
        const char *mass = lumped ? "lumped" : "consistent";
        snprintf(line, sizeof line, "modes count=20 mass=%s solver=block", mass);
        both_solvers(flat_net_text(buf, sizeof buf, 6, line), lumped, 20);      /* double eigenvalues */
        snprintf(line, sizeof line, "modes count=12 mass=%s solver=block", mass);
        both_solvers(net_text(buf, sizeof buf, line), lumped, 12);              /* the hypar net */
        snprintf(line, sizeof line, "modes count=70 mass=%s solver=block", mass);
        both_solvers(net_text(buf, sizeof buf, line), lumped, 70);              /* 70 of 75 */
        snprintf(buf, sizeof buf,
                 "units N m\nmaterial steel E=2e11 strain=engineering\nsection s material=steel A=1e-6 mass=0.01\n"
                 "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=5 length=1 shape=straight "
                 "N0=100\nmodes count=12 mass=%s solver=block\n", mass);
        both_solvers(buf, lumped, 12);                                           /* every DOF: 12 of 12 */
    }
}

/* ---- mechanisms ---- */

static void test_mechanism(void)
{
    run r;
    if (solve_text(&r, "units N m\nmaterial steel E=2e11 strain=engineering\nmaterial rope E=2e11 tension-only\n"
                       "section s material=steel A=1e-6 mass=0.01\nsection r material=rope A=1e-6 mass=0.01\n"
                       "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\nnode 10 0.5 0.2 0\n"
                       "cable 1 2 section=s n=4 length=1 shape=straight N0=100\n"
                       "element 101 1 10 section=r l0=0.7\nelement 102 10 2 section=r l0=0.7\nmodes count=5\n") == CTN_OK) {
        ctn_modal_summary ms;
        CHECK(ctn_solution_modal_summary(r.s, &ms) == CTN_OK && ms.zero_modes == 3);
        for (size_t k = 0; k < 5; k++) {
            ctn_mode md;
            ctn_solution_mode(r.s, k, &md);
            CHECK(md.kind == (k < 3 ? CTN_MODE_ZERO : CTN_MODE_VIBRATION));
            if (k < 3) CHECK(md.nnodes == 1 && md.nodes[0] == 10 && md.node == 10 && md.frequency == 0);
        }
    }
    run_free(&r);
}

/* ---- errors ---- */

static void expect_error(const char *text, int code, const char *what)
{
    ctn_ctx *ctx = NULL;
    ctn_solve_options opt;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "bad.cable", text, strlen(text), &m, &opt);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == code && strstr(ctn_ctx_message(ctx), what), "rc %d, message '%s', expected '%s'", rc,
              ctn_ctx_message(ctx), what);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_errors(void)
{
    const char *head = "units N m\nmaterial steel E=2e11\nsection s material=steel A=1e-6 mass=0.01\n"
                       "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=2 length=1 shape=straight N0=100\n";
    char text[1024];
    snprintf(text, sizeof text, "%smodes count=4\n", head);
    expect_error(text, CTN_ERR_MODEL, "bad.cable:7: modes: count=4 is more than the 3 free DOFs");
    snprintf(text, sizeof text, "%smodes count=0\n", head);
    expect_error(text, CTN_ERR_MODEL, "bad.cable:7: count must be an integer from 1");
    expect_error("units N m\nmaterial steel E=2e11\nsection s material=steel A=1e-6\n"
                 "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=2 length=1 shape=straight N0=100\n"
                 "modes count=1\n", CTN_ERR_MODEL, "bad.cable:7: modes: no free DOF carries mass");
    expect_error("material steel E=2e11\nsection s material=steel A=1e-6 w=1\ngravity 0 -1 0\n"
                 "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\ncable 1 2 section=s n=2 length=1.1\n"
                 "modes count=1\n", CTN_ERR_MODEL, "bad.cable:2: section 's': its weight w=1 gives no mass");
    expect_error("units N m\nmaterial steel E=2e11\nsection s material=steel A=1e-6 mass=-1\n", CTN_ERR_MODEL,
                 "bad.cable:3: section: mass must be >= 0");
    expect_error("units N m\nnode 1 0 0 0 mass=-2\n", CTN_ERR_MODEL, "bad.cable:2: node 1: mass must be >= 0");
    snprintf(text, sizeof text, "%snode 30 0.5 0 0\nspring 9 30 1 k=10\nmodes count=5\n", head);
    expect_error(text, CTN_ERR_MODEL, "bad.cable:9: modes: count=5 is more than the 3 free DOFs that carry mass");
}

/* Every allocation of a modal analysis may fail: CTN_ERR_NOMEM, no leak (ASan). */
static void test_alloc_failures(void)
{
    static char buf[16384];
    net_text(buf, sizeof buf, "modes count=4");
    int failures = 0;
    for (long k = 1; k < 100000; k++) {
        ctn_ctx *ctx = NULL;
        ctn_solve_options opt;
        ctn_model *m = NULL;
        ctn_solution *s = NULL;
        ctn_ctx_create(&ctx);
        int rc = ctn_read_string(ctx, "net.cable", buf, strlen(buf), &m, &opt);
        ctn_ctx_fail_alloc_at(ctx, k);
        if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
        ctn_ctx_fail_alloc_at(ctx, 0);
        CHECK(rc == CTN_OK || rc == CTN_ERR_NOMEM);
        int done = rc == CTN_OK;
        if (done) CHECK(ctn_solution_mode_count(s) == 4);
        failures += rc == CTN_ERR_NOMEM;
        ctn_solution_destroy(&s);
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
        if (done) break;
    }
    CHECK(failures > 10);
}

int main(void)
{
    test_element_mass();
    test_assembled_mass();
    test_taut_string();
    test_irvine();
    test_net_pairs();
    test_block_solver();
    test_auto_solver();
    test_mechanism();
    test_errors();
    test_alloc_failures();
    CHECK_DONE();
}
