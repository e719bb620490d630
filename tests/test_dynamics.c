/* Dynamics (catena/analysis.h "dynamics", docs/theory.md "Dynamics", docs/validation.md
 * section 17), each against an independent truth:
 * - the large-amplitude pendulum (one stiff cable element, a point mass, its weight a
 *   load): the period 4 sqrt(L/g) K(sin(theta0/2)), K the complete elliptic integral
 *   (by the arithmetic-geometric mean), from the zero crossings of x interpolated
 *   linearly, to 1e-6 with dt = 1e-4 (generalized-alpha, rho_inf = 1);
 * - energy: the same pendulum released at 90 degrees, rho_inf = 1: the largest
 *   |E_k + U - W| over a period falls as dt^2 (ratios 4 +- 0.4 for dt = 4, 2, 1 ms);
 * - algorithmic damping: a linear SDOF (a spring along its axis and a point mass) decays
 *   per step as the spectral radius of the method's amplification matrix (built here
 *   from its definition, eigenvalues of the cubic), fitted from the history by the
 *   two-term recurrence d(n+1) = p d(n) - q d(n-1), |lambda| = sqrt(q), to 1e-8, at
 *   omega dt = 1 for genalpha rho_inf = 0, 0.5, 0.8 and HHT alpha = -0.2; at omega dt =
 *   1e5 (a three-term recurrence fitted: the spurious root has not decayed; the three
 *   roots nearly coincide, so 1e-5) the radius is within 1e-3 of rho_inf (Chung and
 *   Hulbert's design) for genalpha 0.3, 0.6, 0.8 and HHT 0.6;
 * - special cases: HHT alpha = 0 is Newmark's average acceleration bit for bit;
 * - the taut string plucked at mid-span (engineering strain, tension T0, mass per
 *   unstressed length m0): the mid-point history against d'Alembert's triangle wave of
 *   amplitude h and period 2 L / c, c = sqrt(T0 / m), m = m0 l0 / l; the error over a
 *   period falls on refinement (n = 20, 40, 80 elements, dt = l / (2 c));
 * - explicit central differences on the same string at the stable step of the mesh:
 *   within 1e-3 h of d'Alembert (the magic step l / c is exact for the linear string);
 *   dt above the stable step: CTN_ERR_MODEL naming the limit;
 * - Rayleigh damping: the SDOF decay x0 e^(-zeta w t) (cos wd t + zeta / sqrt(1 -
 *   zeta^2) sin wd t) with zeta = alpha / (2 w) + beta w / 2, to O(dt^2) (ratio 4 +-
 *   0.4); damping ratio= freq= gives alpha and beta that meet both ratios;
 * - the energy balance with damping: E_k + U - W + D stays at its start to 1e-3;
 * - errors: no mass, dt above the explicit limit, a step after the dynamics line;
 * - harmonic forces and support motions, ramps and tables against closed forms; the
 *   modal frequencies of a sagging cable in its free vibration's spectrum; the analysis
 *   object and every allocation failure. */
/* ctest-cost: 15 (about the seconds it takes under ASan: ctest -j starts it early) */
#include "catena.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define PI 3.14159265358979323846

static ctn_solution *solve_text(ctn_ctx *ctx, const char *text, int *rc)
{
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    *rc = ctn_read_string(ctx, "dyn.cable", text, strlen(text), &m, &opt);
    if (!*rc) *rc = ctn_solve(ctx, m, &opt, &s);
    ctn_model_destroy(&m);
    return s;
}

/* K(k) by the arithmetic-geometric mean: pi / (2 AGM(1, sqrt(1 - k^2))). */
static double ellip_k(double k)
{
    double a = 1, b = sqrt(1 - k * k);
    for (int i = 0; i < 40; i++) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
    }
    return PI / (2 * a);
}

/* The pendulum of length L at theta0 from the downward vertical, mass 1, g = 9.81. */
static ctn_solution *pendulum(ctn_ctx *ctx, double theta0, double dt, double t_end, const char *method)
{
    char text[1024];
    snprintf(text, sizeof text,
             "material stiff E=1e12\n"
             "section rod material=stiff A=1 mass=0\n"
             "node 1 0 0 0 fix=xyz\n"
             "node 2 %.17g %.17g 0 mass=1 fix=z\n"
             "element 1 1 2 section=rod\n"
             "load 2 0 -9.81 0\n"
             "dynamics dt=%.17g t_end=%.17g %s\n"
             "record node=2 dof=ux\n",
             sin(theta0), -cos(theta0), dt, t_end, method);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK && s, "%s", ctn_ctx_message(ctx));
    return s;
}

/* Times where column c (x = x0 + column) crosses zero, linearly interpolated. */
static size_t crossings(const ctn_solution *s, size_t c, double x0, double *tz, size_t max)
{
    size_t rows, cols, n = 0;
    const double *h = ctn_solution_history(s, &rows, &cols);
    for (size_t r = 1; r < rows && n < max; r++) {
        double a = x0 + h[(r - 1) * (cols + 1) + c + 1], b = x0 + h[r * (cols + 1) + c + 1];
        if ((a > 0 && b <= 0) || (a < 0 && b >= 0)) {
            double ta = h[(r - 1) * (cols + 1)], tb = h[r * (cols + 1)];
            tz[n++] = ta + (tb - ta) * a / (a - b);
        }
    }
    return n;
}

static void test_pendulum_period(double theta0)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double T = 4 * sqrt(1 / 9.81) * ellip_k(sin(theta0 / 2));
    ctn_solution *s = pendulum(ctx, theta0, 1e-4, 1.3 * T, "method=genalpha rho_inf=1");
    double tz[8];
    size_t n = s ? crossings(s, 0, sin(theta0), tz, 8) : 0;
    CHECK(n >= 3);
    if (n >= 3) {
        printf("pendulum at %.4f rad: period %.10f s, 4 sqrt(L/g) K(sin(theta0/2)) = %.10f s (relative error %.2e)\n",
               theta0, tz[2] - tz[0], T, (tz[2] - tz[0]) / T - 1);
        CHECK_CLOSE(tz[2] - tz[0], T, 1e-6, 0);
        CHECK_CLOSE(tz[0], T / 4, 1e-6, 0);
    }
    ctn_dynamics_summary d;
    CHECK(s && ctn_solution_dynamics_summary(s, &d) == CTN_OK && d.reason == CTN_CONVERGED && d.cuts == 0);
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

/* The largest |E_k + U - W| over the rows, by m g L = 9.81. */
static double energy_drift(const ctn_solution *s)
{
    size_t rows;
    const double *e = ctn_solution_energy(s, &rows);
    double worst = 0;
    for (size_t r = 0; e && r < rows; r++) worst = fmax(worst, fabs(e[4 * r] + e[4 * r + 1] - e[4 * r + 2] + e[4 * r + 3]));
    return worst / 9.81;
}

static void test_energy_order(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double T = 4 * sqrt(1 / 9.81) * ellip_k(sin(PI / 4)), err[3];
    for (int i = 0; i < 3; i++) {
        ctn_solution *s = pendulum(ctx, PI / 2, 2e-3 / (1 << i), T, "method=genalpha rho_inf=1");
        err[i] = s ? energy_drift(s) : NAN;
        ctn_solution_destroy(&s);
    }
    printf("energy: max |E - E0| / (m g L) at dt = 2, 1, 0.5 ms: %.3e %.3e %.3e (ratios %.3f %.3f)\n", err[0], err[1],
           err[2], err[0] / err[1], err[1] / err[2]);
    CHECK_CLOSE(err[0] / err[1], 4.0, 0.1, 0);
    CHECK_CLOSE(err[1] / err[2], 4.0, 0.1, 0);
    CHECK(err[0] < 1e-3);
    ctn_ctx_destroy(&ctx);
}

/* The SDOF: a spring k = w^2 (mass 1) along x, node 2 released at u0 from its rest
 * length 1. */
static ctn_solution *sdof(ctn_ctx *ctx, double w, double u0, double dt, double t_end, const char *method,
                          const char *extra)
{
    char text[1024];
    snprintf(text, sizeof text,
             "node 1 0 0 0 fix=xyz\n"
             "node 2 %.17g 0 0 mass=1 fix=yz\n"
             "spring 1 1 2 k=%.17g l0=1\n"
             "%s\n"
             "dynamics dt=%.17g t_end=%.17g %s\n"
             "record node=2 dof=ux\n",
             1 + u0, w * w, extra, dt, t_end, method);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK && s, "%s", ctn_ctx_message(ctx));
    return s;
}

/* The largest |root| of lambda^3 - tr lambda^2 + c2 lambda - dA (roots within |2|): a
 * real root by bisection, the quadratic left. */
static double cubic_radius(double tr, double c2, double dA)
{
    double lo = -2, hi = 2;
    for (int it = 0; it < 200; it++) {
        double m = 0.5 * (lo + hi), f = ((m - tr) * m + c2) * m - dA, flo = ((lo - tr) * lo + c2) * lo - dA;
        if ((f > 0) == (flo > 0)) lo = m;
        else hi = m;
    }
    double r = 0.5 * (lo + hi), p = r - tr, q = c2 + r * p;   /* l^2 + p l + q */
    double disc = p * p - 4 * q;
    double big = disc < 0 ? sqrt(q) : fmax(fabs((-p + sqrt(disc)) / 2), fabs((-p - sqrt(disc)) / 2));
    return fmax(big, fabs(r));
}

/* The spectral radius of the generalized-alpha amplification matrix at W = w h for an
 * undamped SDOF (am, af, gamma, beta): the map (d, h v, h^2 a) -> the next, from the
 * method's three equations, and the largest |root| of its characteristic cubic. */
static double spectral_radius(double W, double am, double af, double g, double b)
{
    /* unknowns x = (d1, hv1, hha1): rows: (1 - am) hha1 + W^2 (1 - af) d1 = -am hha0 - W^2 af d0;
       d1 - b hha1 = d0 + hv0 + (1/2 - b) hha0;  hv1 - g hha1 = hv0 + (1 - g) hha0 */
    double L[3][3] = { { W * W * (1 - af), 0, 1 - am }, { 1, 0, -b }, { 0, 1, -g } };
    double R[3][3] = { { -W * W * af, 0, -am }, { 1, 1, 0.5 - b }, { 0, 1, 1 - g } };
    double A[3][3], inv[3][3], det = 0;
    for (int i = 0; i < 3; i++)                       /* inv = L^-1 by cofactors */
        for (int j = 0; j < 3; j++) {
            int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            inv[i][j] = L[r0][c0] * L[r1][c1] - L[r0][c1] * L[r1][c0];
        }
    for (int k = 0; k < 3; k++) det += L[0][k] * inv[k][0];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            A[i][j] = 0;
            for (int k = 0; k < 3; k++) A[i][j] += inv[i][k] / det * R[k][j];
        }
    double tr = A[0][0] + A[1][1] + A[2][2];          /* lambda^3 - tr l^2 + c2 l - dA = 0 */
    double c2 = A[0][0] * A[1][1] - A[0][1] * A[1][0] + A[0][0] * A[2][2] - A[0][2] * A[2][0] + A[1][1] * A[2][2] -
                A[1][2] * A[2][1];
    double dA = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    return cubic_radius(tr, c2, dA);
}

/* |lambda| of the principal roots from the history (rows from..to; the displacement from
 * rest is u0 + the recorded one, from the start geometry): least squares for p, q in
 * d(n+1) = p d(n) - q d(n-1). */
static double fitted_radius(const ctn_solution *s, double u0, size_t from, size_t to)
{
    size_t rows, cols;
    const double *h = ctn_solution_history(s, &rows, &cols);
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    for (size_t n = from; n + 1 < to && n + 1 < rows; n++) {
        double x1 = u0 + h[n * (cols + 1) + 1], x0 = -u0 - h[(n - 1) * (cols + 1) + 1], y = u0 + h[(n + 1) * (cols + 1) + 1];
        a11 += x1 * x1;
        a12 += x1 * x0;
        a22 += x0 * x0;
        b1 += x1 * y;
        b2 += x0 * y;
    }
    double q = (a11 * b2 - a12 * b1) / (a11 * a22 - a12 * a12);
    return sqrt(q);
}

/* The spectral radius of the three-term recurrence d(n+1) = p1 d(n) + p2 d(n-1) + p3
 * d(n-2) fitted to rows from..to by least squares (every root of the method: where the
 * spurious root has not decayed, as at omega dt >> 1). */
static double fitted_radius3(const ctn_solution *s, double u0, size_t from, size_t to)
{
    size_t rows, cols;
    const double *h = ctn_solution_history(s, &rows, &cols);
    double N[3][3] = { { 0 } }, b[3] = { 0 }, p[3];
    for (size_t n = from; n + 1 < to && n + 1 < rows; n++) {
        double x[3], y = u0 + h[(n + 1) * (cols + 1) + 1];
        for (int k = 0; k < 3; k++) x[k] = u0 + h[(n - (size_t)k) * (cols + 1) + 1];
        for (int i = 0; i < 3; i++) {
            b[i] += x[i] * y;
            for (int j = 0; j < 3; j++) N[i][j] += x[i] * x[j];
        }
    }
    double det = N[0][0] * (N[1][1] * N[2][2] - N[1][2] * N[2][1]) - N[0][1] * (N[1][0] * N[2][2] - N[1][2] * N[2][0]) +
                 N[0][2] * (N[1][0] * N[2][1] - N[1][1] * N[2][0]);
    for (int c = 0; c < 3; c++) {                     /* Cramer */
        double M[3][3];
        memcpy(M, N, sizeof M);
        for (int i = 0; i < 3; i++) M[i][c] = b[i];
        p[c] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
    }
    return cubic_radius(p[0], -p[1], p[2]);
}

static void test_spectral_radius(const char *method, double W)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double w = 2.0, dt = W / w;
    ctn_solution *s = sdof(ctx, w, 1e-3, dt, 200 * dt, method, "");
    ctn_dynamics_summary d;
    if (s && !ctn_solution_dynamics_summary(s, &d)) {
        double want = spectral_radius(W, d.alpha_m, d.alpha_f, d.gamma, d.beta), got = W > 10 ? fitted_radius3(s, 1e-3, 3, 20) : fitted_radius(s, 1e-3, 60, 200);
        printf("spectral radius %s at omega dt = %g: fitted %.12f, amplification matrix %.12f\n", method, W, got, want);
        /* at omega dt >> 1 the three roots nearly coincide (a triple root at infinity):
           their sensitivity to the history's round-off is eps^(1/3), about 1e-5 */
        CHECK_CLOSE(got, want, W > 10 ? 1e-5 : 1e-8, 0);
        if (W > 10) CHECK_CLOSE(got, d.rho_inf, 0, 1e-3);   /* the limit omega dt -> infinity */
        CHECK(want < 1);
    }
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

/* HHT with alpha = 0 and Newmark (1/2, 1/4) are the same equations: the same bits. */
static void test_special_cases(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_solution *a = pendulum(ctx, 1.0, 2e-3, 0.5, "method=hht alpha=0");
    ctn_solution *b = pendulum(ctx, 1.0, 2e-3, 0.5, "method=newmark gamma=0.5 beta=0.25");
    size_t ra, rb, ca, cb;
    const double *ha = ctn_solution_history(a, &ra, &ca), *hb = ctn_solution_history(b, &rb, &cb);
    CHECK(ha && hb && ra == rb && ca == cb && ra == 251);
    CHECK(ha && hb && ra == rb && !memcmp(ha, hb, ra * (ca + 1) * sizeof(double)));
    ctn_solution_destroy(&a);
    ctn_solution_destroy(&b);
    ctn_ctx_destroy(&ctx);
}

/* The taut string: L = 1 between fixed ends, n elements, tension T0 = 1 in the straight
 * string (engineering strain, EA = 100: l0 = l / (1 + T0 / EA)), m0 = 1 per unstressed
 * length, plucked to h at mid-span (y only: x and z fixed). c = sqrt(T0 / m), m = m0 l0 /
 * l the mass per current length. */
static const double string_h = 1e-3, string_EA = 100;

static ctn_solution *plucked_string(ctn_ctx *ctx, int n, double dt, double t_end, const char *method, int expect_ok)
{
    size_t size = 512 + 192 * (size_t)n;
    char *text = malloc(size), *p = text;
    double l = 1.0 / n, l0 = l / (1 + 1 / string_EA);
    p += sprintf(p, "material m E=%.17g strain=engineering\nsection s material=m A=1 mass=1\n", string_EA);
    for (int j = 0; j <= n; j++) {
        double x = j * l, y = string_h * (1 - fabs(2 * x - 1));
        p += sprintf(p, "node %d %.17g %.17g 0 fix=%s\n", j + 1, x, y, j == 0 || j == n ? "xyz" : "xz");
    }
    for (int j = 0; j < n; j++) p += sprintf(p, "element %d %d %d section=s l0=%.17g\n", j + 1, j + 1, j + 2, l0);
    sprintf(p, "dynamics dt=%.17g t_end=%.17g %s\nrecord node=%d dof=uy\n", dt, t_end, method, n / 2 + 1);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    if (expect_ok) CHECK_MSG(rc == CTN_OK && s, "%s", ctn_ctx_message(ctx));
    free(text);
    return s;
}

static double string_c(void) { return sqrt(1.0 / (1.0 / (1 + 1 / string_EA))); }

/* d'Alembert's mid-point: a triangle wave between h and -h, period 2 L / c. */
static double dalembert_mid(double t)
{
    double ph = fmod(t * string_c() / 2.0, 1.0);      /* fraction of the period */
    return string_h * (ph < 0.5 ? 1 - 4 * ph : 4 * ph - 3);
}

/* The largest |y_mid - d'Alembert| over the history, by h. */
static double pluck_error(const ctn_solution *s)
{
    size_t rows, cols;
    const double *hs = ctn_solution_history(s, &rows, &cols);
    double worst = 0;
    for (size_t r = 0; hs && r < rows; r++)
        worst = fmax(worst, fabs(string_h + hs[r * (cols + 1) + 1] - dalembert_mid(hs[r * (cols + 1)])));
    return hs ? worst / string_h : NAN;
}

static void test_string_implicit(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double err[3], T = 2.0 / string_c();
    for (int i = 0; i < 3; i++) {
        int n = 20 << i;
        ctn_solution *s = plucked_string(ctx, n, 0.5 / (n * string_c()), T, "method=genalpha rho_inf=1 mass=lumped", 1);
        err[i] = s ? pluck_error(s) : NAN;
        ctn_solution_destroy(&s);
    }
    printf("string pluck, implicit: max |y_mid - d'Alembert| / h over a period at n = 20, 40, 80: %.3e %.3e %.3e\n",
           err[0], err[1], err[2]);
    CHECK(err[1] < err[0] && err[2] < err[1] && err[2] < 0.1);
    ctn_ctx_destroy(&ctx);
}

static void test_string_central(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int n = 40;
    double T = 2.0 / string_c(), magic = 1.0 / (n * string_c());
    ctn_solution *s = plucked_string(ctx, n, 1.001 * magic, T, "method=central", 0);     /* above the limit */
    CHECK(!s && ctn_ctx_code(ctx) == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "stable step"));
    printf("central above its limit: %s\n", ctn_ctx_message(ctx));
    ctn_ctx_clear(ctx);
    s = plucked_string(ctx, n, 0.999 * magic, T, "method=central", 1);
    ctn_dynamics_summary d;
    if (s && !ctn_solution_dynamics_summary(s, &d)) {
        double err = pluck_error(s);
        printf("string pluck, central at 0.999 l/c (stable step %.9g = %.9f l/c): max error / h %.3e\n", d.dt_stable,
               d.dt_stable / magic, err);
        CHECK(d.dt_stable <= magic && d.dt_stable > 0.999 * magic);
        CHECK(err < 1e-2);
    }
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

/* The damped SDOF against x0 e^(-zeta w t) (cos wd t + zeta / sqrt(1 - zeta^2) sin wd
 * t): the largest error over 3 periods, by x0. */
static double damped_error(ctn_ctx *ctx, double w, double a, double b, double dt)
{
    char extra[128];
    snprintf(extra, sizeof extra, "damping alpha=%.17g beta=%.17g", a, b);
    double u0 = 1e-3, zeta = a / (2 * w) + b * w / 2, wd = w * sqrt(1 - zeta * zeta);
    ctn_solution *s = sdof(ctx, w, u0, dt, 3 * 2 * PI / w, "method=genalpha rho_inf=1", extra);
    size_t rows, cols;
    const double *h = ctn_solution_history(s, &rows, &cols);
    double worst = h ? 0 : NAN;
    for (size_t r = 0; h && r < rows; r++) {
        double t = h[r * (cols + 1)], x = u0 * exp(-zeta * w * t) * (cos(wd * t) + zeta / sqrt(1 - zeta * zeta) * sin(wd * t));
        worst = fmax(worst, fabs(u0 + h[r * (cols + 1) + 1] - x));
    }
    ctn_dynamics_summary d;
    if (s && !ctn_solution_dynamics_summary(s, &d)) CHECK_MSG(d.energy_error < 1e-3, "energy balance %g", d.energy_error);
    ctn_solution_destroy(&s);
    return worst / u0;
}

static void test_rayleigh(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double w = 3.0, e[3];
    for (int i = 0; i < 3; i++) e[i] = damped_error(ctx, w, 0.3, 0.02, 0.02 / (1 << i));
    printf("Rayleigh SDOF (zeta = %.3f): max error / x0 at dt = 20, 10, 5 ms: %.3e %.3e %.3e (ratios %.3f %.3f)\n",
           0.3 / (2 * w) + 0.02 * w / 2, e[0], e[1], e[2], e[0] / e[1], e[1] / e[2]);
    CHECK_CLOSE(e[0] / e[1], 4.0, 0.1, 0);
    CHECK_CLOSE(e[1] / e[2], 4.0, 0.1, 0);
    CHECK(e[2] < 1e-3);
    /* ratio= freq=: alpha, beta meeting both ratios */
    const char *text = "node 1 0 0 0 fix=xyz\nnode 2 1.001 0 0 mass=1 fix=yz\nspring 1 1 2 k=4 l0=1\n"
                       "damping ratio=0.02,0.05 freq=0.5,8\ndynamics dt=0.01 t_end=0.1\n";
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    ctn_dynamics_summary d;
    CHECK(s && !ctn_solution_dynamics_summary(s, &d));
    if (s) {
        double w1 = 2 * PI * 0.5, w2 = 2 * PI * 8;
        CHECK_CLOSE(d.damping_alpha / (2 * w1) + d.damping_beta * w1 / 2, 0.02, 1e-12, 0);
        CHECK_CLOSE(d.damping_alpha / (2 * w2) + d.damping_beta * w2 / 2, 0.05, 1e-12, 0);
    }
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

/* Errors at the dynamics line: a model without mass, a step after the line. */
static void test_errors(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    const char *nomass = "material m E=1\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0\n"
                         "element 1 1 2 section=s\nload 2 1 0 0\ndynamics dt=0.1 t_end=1\n";
    ctn_solution *s = solve_text(ctx, nomass, &rc);
    CHECK(!s && rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "dyn.cable:7:") &&
          strstr(ctn_ctx_message(ctx), "node 2") && strstr(ctn_ctx_message(ctx), "section 's'"));
    printf("no mass: %s\n", ctn_ctx_message(ctx));
    const char *late = "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 mass=1\nspring 1 1 2 k=1\ndynamics dt=0.1 t_end=1\n"
                       "step two\nload 2 1 0 0\n";
    s = solve_text(ctx, late, &rc);
    CHECK(!s && rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "dyn.cable:4:") &&
          strstr(ctn_ctx_message(ctx), "after the last"));
    ctn_ctx_destroy(&ctx);
}

/* The largest |x - want(t)| over the SDOF's history (x = the recorded ux: the mass starts
 * at rest at its spring's rest length here). */
static double sdof_error(const ctn_solution *s, double (*want)(double t, const double *par), const double *par)
{
    size_t rows, cols;
    const double *h = ctn_solution_history(s, &rows, &cols);
    double worst = h ? 0 : NAN;
    for (size_t r = 0; h && r < rows; r++) worst = fmax(worst, fabs(h[r * (cols + 1) + 1] - want(h[r * (cols + 1)], par)));
    return worst;
}

/* x'' + w^2 x = w^2 U sin(W t) from rest (a force k U sin, or a support moving U sin):
 * x = U / (1 - r^2) (sin W t - r sin w t), r = W / w. par: w, W, U. */
static double harmonic_response(double t, const double *par)
{
    double r = par[1] / par[0];
    return par[2] / (1 - r * r) * (sin(par[1] * t) - r * sin(par[0] * t));
}

/* A ramp of F to its full value at t1: x = F/k (t/t1 - sin(w t) / (w t1)) for t <= t1,
 * then free vibration about F/k. par: w, t1, F/k. */
static double ramp_response(double t, const double *par)
{
    double w = par[0], t1 = par[1], xs = par[2];
    if (t <= t1) return xs * (t / t1 - sin(w * t) / (w * t1));
    double x1 = xs * (1 - sin(w * t1) / (w * t1)), v1 = xs * (1 - cos(w * t1)) / t1;
    return xs + (x1 - xs) * cos(w * (t - t1)) + v1 / w * sin(w * (t - t1));
}

/* The SDOF (k = w^2 = 4, m = 1, at rest at its rest length) driven by `drive` lines. */
static ctn_solution *driven(ctn_ctx *ctx, const char *support, const char *drive, double dt, double t_end)
{
    char text[2048];
    snprintf(text, sizeof text,
             "node 1 0 0 0 fix=%s\nnode 2 1 0 0 mass=1 fix=yz\nspring 1 1 2 k=4\n%s\n"
             "dynamics dt=%.17g t_end=%.17g method=genalpha rho_inf=1\nrecord node=2 dof=ux\n",
             support, drive, dt, t_end);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK && s, "%s", ctn_ctx_message(ctx));
    return s;
}

static void test_time_functions(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double e[2], par[3] = { 2.0, 1.3, 0.01 };
    const char *force = "function f harmonic amp=1 freq=0.20690142964317865\nload 2 0.04 0 0 fn=f";   /* 1.3 rad/s */
    const char *base = "function f harmonic amp=0.01 freq=0.20690142964317865\ndisplace 1 x=1 fn=f";
    for (int which = 0; which < 2; which++) {
        for (int i = 0; i < 2; i++) {
            ctn_solution *s = driven(ctx, "xyz", which ? base : force, 0.01 / (1 << i), 10);
            e[i] = s ? sdof_error(s, harmonic_response, par) / 0.01 : NAN;
            ctn_solution_destroy(&s);
        }
        printf("harmonic %s: max error / U at dt = 10, 5 ms: %.3e %.3e (ratio %.3f)\n", which ? "support motion" : "force",
               e[0], e[1], e[0] / e[1]);
        CHECK_CLOSE(e[0] / e[1], 4.0, 0.1, 0);
        /* the trapezoidal rule's phase error, w t (w dt)^2 / 12 over t = 10 s, on the
           largest response (1 + r) / (1 - r^2) U */
        double r = par[1] / par[0], bound = (1 + r) / (1 - r * r) * par[0] * 10 * pow(par[0] * 0.005, 2) / 12;
        CHECK_MSG(e[1] < bound, "%g >= %g", e[1], bound);
    }
    /* a ramp, and the same ramp as a table: the same history */
    char path[] = "/tmp/catena-dyn-table-XXXXXX", drive[512];
    int fd = mkstemp(path);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (f) {
        fprintf(f, "# t, value\n0, 0\n2.5, 1\n\n9 1\n");
        fclose(f);
    }
    double rp[3] = { 2.0, 2.5, 0.05 };
    ctn_solution *a = driven(ctx, "xyz", "function r ramp t0=0 t1=2.5\nload 2 0.2 0 0 fn=r", 0.005, 6);
    snprintf(drive, sizeof drive, "function r table %s\nload 2 0.2 0 0 fn=r", path);
    ctn_solution *b = driven(ctx, "xyz", drive, 0.005, 6);
    double ea = a ? sdof_error(a, ramp_response, rp) / 0.05 : NAN;
    printf("ramp: max error / (F/k) at dt = 5 ms: %.3e\n", ea);
    CHECK(ea < 1e-4);
    size_t ra, rb, ca, cb;
    const double *ha = ctn_solution_history(a, &ra, &ca), *hb = ctn_solution_history(b, &rb, &cb);
    CHECK(ha && hb && ra == rb && !memcmp(ha, hb, ra * (ca + 1) * sizeof(double)));
    ctn_solution_destroy(&a);
    ctn_solution_destroy(&b);
    /* a table whose times do not increase: its file's line */
    f = fopen(path, "w");
    if (f) {
        fprintf(f, "0 0\n1 1\n0.5 2\n");
        fclose(f);
    }
    char text[1024];
    snprintf(text, sizeof text, "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 mass=1\nspring 1 1 2 k=4\nfunction r table %s\n", path);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    char want[128];
    snprintf(want, sizeof want, "%s:3: table times must increase: t=0.5 is not after t=1", path);
    CHECK_MSG(!s && rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), want), "%s", ctn_ctx_message(ctx));
    remove(path);
    ctn_ctx_destroy(&ctx);
}

/* |X(f)|^2 summed over the recorded columns: the history's discrete Fourier transform. */
static double power(const double *h, size_t rows, size_t cols, double f)
{
    double sum = 0;
    for (size_t c = 1; c <= cols; c++) {
        double re = 0, im = 0;
        for (size_t r = 0; r < rows; r++) {
            double ph = 2 * PI * f * h[r * (cols + 1)];
            re += h[r * (cols + 1) + c] * cos(ph);
            im += h[r * (cols + 1) + c] * sin(ph);
        }
        sum += re * re + im * im;
    }
    return sum;
}

/* Free vibration about a sagging cable (210 m of the founding paper's strand over a 200 m
 * span, 20 elements): after the static step, a short pulse (two ramps) at node 8, 400 s
 * undamped; the spectrum of node 8's motion peaks within the resolution 1 / T of each of
 * the modal analysis's six lowest frequencies (the trapezoidal rule's period error,
 * (w dt)^2 / 12, is below it). */
static void test_sagging_cable_spectrum(void)
{
    const char *text = "units kN m\nmaterial steel E=2.0e8\nsection strand material=steel A=3.14e-4 w=0.1\n"
                       "gravity 0 -1 0\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n"
                       "cable 1 2 section=strand n=20 length=210 shape=arc\nstep hang\nmodes count=6\n"
                       "function up ramp t0=0 t1=0.1\nfunction down ramp t0=0.1 t1=0.2\n"
                       "load 8 1 1 1 fn=up\nload 8 -1 -1 -1 fn=down\n"
                       "dynamics dt=0.05 t_end=400 method=genalpha rho_inf=1\nrecord node=8\n";
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(s && rc == CTN_OK && ctn_solution_mode_count(s) == 6, "%s", ctn_ctx_message(ctx));
    size_t rows, cols;
    const double *h = s ? ctn_solution_history(s, &rows, &cols) : NULL;
    for (size_t k = 0; h && k < ctn_solution_mode_count(s); k++) {
        ctn_mode md;
        ctn_solution_mode(s, k, &md);
        double T = h[(rows - 1) * (cols + 1)], best = -1, at = 0;
        for (int i = -20; i <= 20; i++) {                  /* f_k +- 2 / T */
            double f = md.frequency + i * 0.1 / T, pw = power(h, rows, cols, f);
            if (pw > best) {
                best = pw;
                at = f;
            }
        }
        printf("mode %zu: %.6f Hz, spectrum's peak %.6f Hz (%+.2f / T)\n", k + 1, md.frequency, at, (at - md.frequency) * T);
        CHECK(fabs(at - md.frequency) <= 1.0 / T);
        CHECK(fabs(at - md.frequency) < 1.9 / T);          /* a peak, not the window's edge */
    }
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
}

/* The analysis object: from rest (*s NULL) the file's history bit for bit; after a static
 * solution a step "dynamics" added; options not set refused. Every allocation failure of
 * the file's run: CTN_ERR_NOMEM, no leak (ASan). */
static void test_object(void)
{
    const char *base = "node 1 0 0 0 fix=xyz\nnode 2 1.001 0 0 mass=1 fix=yz\nspring 1 1 2 k=4 l0=1\n"
                       "record node=2 dof=ux\nrecord element=1 force\n";
    char text[1024];
    snprintf(text, sizeof text, "%sdamping alpha=0.1\nfunction f harmonic amp=1 freq=0.3\nload 2 0.01 0 0 fn=f\n"
             "dynamics dt=0.01 t_end=1 method=hht alpha=-0.05\n", base);
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    int rc;
    ctn_solution *file = solve_text(ctx, text, &rc);
    ctn_model *m = NULL;
    ctn_problem *p = NULL;
    ctn_solution *s = NULL;
    ctn_analysis *a = NULL;
    ctn_solve_options opt;
    CHECK(ctn_read_string(ctx, "dyn.cable", text, strlen(text), &m, &opt) == CTN_OK);
    ctn_dynamics_options o = opt.dynamics, bad;
    memset(&bad, 0, sizeof bad);
    ctn_solve_options_default(&opt);                  /* the problem without the dynamics line */
    CHECK(ctn_problem_create(ctx, m, &opt, &p) == CTN_OK);
    CHECK(ctn_analysis_create(p, "dynamics", &bad, &a) == CTN_ERR_INVALID && !a);
    CHECK(ctn_analysis_create(p, "dynamics", &o, &a) == CTN_OK);
    CHECK(ctn_analysis_run(a, &s) == CTN_OK && s && ctn_solution_step_count(s) == 1);
    size_t r1, r2, c1, c2;
    const double *h1 = ctn_solution_history(file, &r1, &c1), *h2 = ctn_solution_history(s, &r2, &c2);
    CHECK(h1 && h2 && r1 == r2 && c1 == c2 && c1 == 2 && r1 == 101 && !memcmp(h1, h2, r1 * (c1 + 1) * sizeof(double)));
    CHECK(!strcmp(ctn_solution_history_name(s, 0), "2.ux") && !strcmp(ctn_solution_history_name(s, 1), "1.force") &&
          !ctn_solution_history_name(s, 2));
    ctn_solution_destroy(&s);
    CHECK(ctn_problem_solve(p, &s) == CTN_OK && ctn_solution_step_count(s) == 1);   /* static first */
    CHECK(ctn_analysis_run(a, &s) == CTN_OK && ctn_solution_step_count(s) == 2);
    ctn_step_result st;
    CHECK(ctn_solution_step(s, 1, &st) == CTN_OK && !strcmp(st.name, "dynamics") && st.reason == CTN_CONVERGED);
    ctn_analysis_destroy(&a);
    ctn_solution_destroy(&s);
    ctn_problem_destroy(&p);
    ctn_model_destroy(&m);
    ctn_solution_destroy(&file);
    int done = 0, failures = 0;
    for (long k = 1; !done && k < 5000; k++) {
        ctn_ctx_fail_alloc_at(ctx, k);
        s = solve_text(ctx, text, &rc);
        ctn_ctx_fail_alloc_at(ctx, 0);
        if (rc) {
            failures++;
            CHECK_MSG(rc == CTN_ERR_NOMEM, "allocation %ld: status %d (%s)", k, rc, ctn_ctx_message(ctx));
        } else {
            done = 1;
            CHECK(ctn_solution_history(s, NULL, NULL) != NULL);
        }
        ctn_solution_destroy(&s);
    }
    CHECK(done && failures > 20);
    ctn_ctx_destroy(&ctx);
}

/* A mass on two springs in parallel (k = 20 each, m = 1) in equilibrium under W = 10
 * (uy = -W / 2k), one spring removed at t = 0.3 (`remove`): the mass oscillates about
 * -W / k, y = -W/k + W/(2k) cos(w (t - 0.3)), w = sqrt(k / m); the removed spring's
 * force is 0 from then on, the other's k (l - l0); the problem, solved again, has both. */
static void test_removal(void)
{
    const char *text = "node 1 0 0 0 fix=xyz\nnode 2 0 -1 0 mass=1 fix=xz\nspring 1 1 2 k=20\nspring 2 1 2 k=20\n"
                       "step weight\nload 2 0 -10 0\nremove element=2 t=0.3\n"
                       "dynamics dt=0.001 t_end=2 method=genalpha rho_inf=1\nrecord node=2 dof=uy\n"
                       "record element=1 force\nrecord element=2 force\n";
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_problem *p = NULL;
    ctn_solution *s = NULL;
    CHECK(ctn_read_string(ctx, "dyn.cable", text, strlen(text), &m, &opt) == CTN_OK);
    CHECK_MSG(ctn_problem_create(ctx, m, &opt, &p) == CTN_OK && ctn_problem_solve(p, &s) == CTN_OK, "%s", ctn_ctx_message(ctx));
    size_t rows = 0, cols = 0;
    const double *h = s ? ctn_solution_history(s, &rows, &cols) : NULL;
    double worst = 0, w = sqrt(20.0), f2 = 0, f1 = 0;
    for (size_t r = 0; h && r < rows; r++) {
        const double *row = h + r * (cols + 1);
        double t = row[0], y = t < 0.3 ? -0.25 : -0.5 + 0.25 * cos(w * (t - 0.3));
        worst = fmax(worst, fabs(row[1] - y));
        if (t > 0.3 + 1e-9) f2 = fmax(f2, fabs(row[3]));
        f1 = fmax(f1, fabs(row[2] - 20 * (-row[1])));
    }
    printf("removal: max |y - closed form| = %.3e (of an amplitude 0.25), removed spring's force %g, the other's "
           "k (l - l0) to %.1e\n", worst, f2, f1);
    CHECK(h && rows == 2001 && cols == 3);
    CHECK(worst < 1e-4 && f2 == 0 && f1 < 1e-9);
    ctn_solution_destroy(&s);
    ctn_solve_options_default(&opt);                  /* statics again: both springs back */
    ctn_step_result st;
    CHECK(ctn_problem_solve(p, &s) == CTN_OK && s && !ctn_solution_step(s, 0, &st) && fabs(st.d[4] + 0.25) < 1e-12);
    ctn_solution_destroy(&s);
    ctn_problem_destroy(&p);
    ctn_model_destroy(&m);
    int rc;
    s = solve_text(ctx, "material m E=1e8\nsection s material=m A=1\nnode 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyz\n"
                        "catenary 1 1 2 section=s length=1.1\nremove element=1 t=1\n", &rc);
    CHECK_MSG(!s && rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "dyn.cable:6: remove: element 1 is a catenary"),
              "%s", ctn_ctx_message(ctx));
    ctn_ctx_destroy(&ctx);
}

/* A tension-only chain of 20 bars (EA = 1e4, 0.5 per unstressed length, l0 = 0.6) hung
 * between supports 10 apart (chord 0.5 each: slack at the start), dropped under its
 * weight by the explicit method: the stable step is that of the taut bars, l0 sqrt(m' /
 * EA) (Gershgorin on the slack members' k e e^T: 4 EA / l0 over the lumped m' l0), not
 * unbounded (the start's tangent is zero). Energy is conserved through the snaps as dt
 * falls: the balance's error at 0.3 and 0.1 of the stable step (measured 8.5e-3,
 * 1.25e-3: the snaps' kinks make it faster than first order, slower than second). */
static double slack_chain(ctn_ctx *ctx, double frac, double *dt_stable)
{
    char text[4096], *p = text;
    int n = 20;
    double l0 = 0.6, EA = 1e4, mass = 0.5;
    p += sprintf(p, "material m E=%g tension-only\nsection s material=m A=1 w=%g mass=%g\ngravity 0 -9.81 0\n", EA, mass, mass);
    for (int j = 0; j <= n; j++) p += sprintf(p, "node %d %g 0 0%s\n", j + 1, 0.5 * j, j == 0 || j == n ? " fix=xyz" : "");
    for (int j = 0; j < n; j++) p += sprintf(p, "element %d %d %d section=s l0=%g\n", j + 1, j + 1, j + 2, l0);
    sprintf(p, "dynamics dt=%.17g t_end=1.5 method=central\nrecord node=11\n", frac * l0 * sqrt(mass / EA));
    int rc;
    ctn_solution *s = solve_text(ctx, text, &rc);
    ctn_dynamics_summary d;
    double err = NAN;
    CHECK_MSG(s && !ctn_solution_dynamics_summary(s, &d), "%s", ctn_ctx_message(ctx));
    if (s && d.reason == CTN_CONVERGED) {
        err = d.energy_error;
        *dt_stable = d.dt_stable;
    }
    ctn_solution_destroy(&s);
    return err;
}

static void test_slack_chain_central(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double want = 0.6 * sqrt(0.5 / 1e4), stable = 0, e3 = slack_chain(ctx, 0.3, &stable), e1 = slack_chain(ctx, 0.1, &stable);
    printf("slack chain, central: stable step %.9g, l0 sqrt(m'/EA) = %.9g; energy balance at 0.3 and 0.1 of it: %.2e "
           "%.2e\n", stable, want, e3, e1);
    CHECK_CLOSE(stable, want, 1e-12, 0);
    CHECK(e1 < e3 / 4 && e1 < 2e-3);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_pendulum_period(PI / 3);
    test_pendulum_period(2.0);
    test_energy_order();
    test_spectral_radius("method=genalpha rho_inf=0.5", 1.0);
    test_spectral_radius("method=genalpha rho_inf=0.8", 1.0);
    test_spectral_radius("method=hht alpha=-0.2", 1.0);
    test_spectral_radius("method=genalpha rho_inf=0", 1.0);
    test_spectral_radius("method=genalpha rho_inf=0.6", 1e5);
    test_spectral_radius("method=genalpha rho_inf=0.3", 1e5);
    test_spectral_radius("method=hht rho_inf=0.6", 1e5);
    test_spectral_radius("method=genalpha rho_inf=0.8", 1e5);
    test_special_cases();
    test_string_implicit();
    test_string_central();
    test_rayleigh();
    test_errors();
    test_time_functions();
    test_sagging_cable_spectrum();
    test_object();
    test_removal();
    test_slack_chain_central();
    CHECK_DONE();
}
