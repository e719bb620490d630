/* Element layer: the two-node cable kernel.
 * - tangent against central finite differences of the internal force, random
 *   geometries, both strain measures (relative error < 1e-6);
 * - objectivity: a rigid rotation + translation leaves N unchanged, rotates f;
 * - the axial laws against their closed forms; tension-only slack. */
#include "check.h"
#include "element/element.h"

#include <stdlib.h>

static double urand(unsigned *seed, double lo, double hi)
{
    *seed = *seed * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*seed >> 8) & 0xffffff) / (double)0xffffff;
}

/* The full symmetric 6 x 6 matrix from the kernel's packed upper triangle. */
static void unpack(const double *P, double K[36])
{
    for (int i = 0; i < 6; i++)
        for (int j = i; j < 6; j++) K[6 * i + j] = K[6 * j + i] = P[ctn_packed_index(i, j)];
}

/* max |K - K_fd| / max |K| for one configuration. */
static double tangent_error(const ctn_cable_props *p, const double X[6], const double u[6])
{
    double f[6], P[CTN_EPACKED], K[36], kmax = 0, emax = 0;
    ctn_cable2_eval(p, X, u, f, P, NULL);
    unpack(P, K);
    for (int j = 0; j < 6; j++) {
        double up[6], um[6], fp[6], fm[6];
        double h = 1e-6 * (1.0 + fabs(X[j]));
        for (int k = 0; k < 6; k++) up[k] = um[k] = u[k];
        up[j] += h;
        um[j] -= h;
        ctn_cable2_eval(p, X, up, fp, NULL, NULL);
        ctn_cable2_eval(p, X, um, fm, NULL, NULL);
        for (int i = 0; i < 6; i++) {
            double fd = (fp[i] - fm[i]) / (2 * h);
            emax = fmax(emax, fabs(K[6 * i + j] - fd));
            kmax = fmax(kmax, fabs(K[6 * i + j]));
        }
    }
    return emax / kmax;
}

static void test_tangent_fd(void)
{
    unsigned seed = 12345;
    for (int strain = 0; strain < 2; strain++)
        for (int trial = 0; trial < 200; trial++) {
            double X[6], u[6];
            for (int k = 0; k < 6; k++) X[k] = urand(&seed, -10, 10);
            for (int k = 0; k < 6; k++) u[k] = urand(&seed, -0.5, 0.5);
            double l0x = sqrt((X[3] - X[0]) * (X[3] - X[0]) + (X[4] - X[1]) * (X[4] - X[1]) +
                              (X[5] - X[2]) * (X[5] - X[2]));
            ctn_cable_props p = { urand(&seed, 1e3, 1e5), l0x * urand(&seed, 0.8, 1.2),
                                  (ctn_strain)strain, 0 };
            double err = tangent_error(&p, X, u);
            CHECK_MSG(err < 1e-6, "strain %d trial %d: relative tangent error %.3g", strain, trial, err);
        }
}

/* Rotation matrix about unit axis n by angle t (Rodrigues). */
static void rotation(const double n[3], double t, double R[9])
{
    double c = cos(t), s = sin(t), C = 1 - c;
    double x = n[0], y = n[1], z = n[2];
    double r[9] = { c + x * x * C, x * y * C - z * s, x * z * C + y * s,
                    y * x * C + z * s, c + y * y * C, y * z * C - x * s,
                    z * x * C - y * s, z * y * C + x * s, c + z * z * C };
    for (int i = 0; i < 9; i++) R[i] = r[i];
}

static void test_objectivity(void)
{
    unsigned seed = 777;
    for (int strain = 0; strain < 2; strain++)
        for (int trial = 0; trial < 50; trial++) {
            double X[6], u[6], f[6], ur[6], fr[6], R[9], n[3], t[3];
            for (int k = 0; k < 6; k++) X[k] = urand(&seed, -5, 5);
            for (int k = 0; k < 6; k++) u[k] = urand(&seed, -0.3, 0.3);
            for (int k = 0; k < 3; k++) { n[k] = urand(&seed, -1, 1); t[k] = urand(&seed, -100, 100); }
            double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int k = 0; k < 3; k++) n[k] /= nn;
            rotation(n, urand(&seed, -3, 3), R);
            ctn_cable_props p = { 5e4, 9.0, (ctn_strain)strain, 0 };
            ctn_elem_state s0, s1;
            ctn_cable2_eval(&p, X, u, f, NULL, &s0);
            /* rigidly moved current configuration x' = R x + t, as a displacement from X */
            for (int a = 0; a < 2; a++)
                for (int i = 0; i < 3; i++) {
                    double xr = t[i];
                    for (int j = 0; j < 3; j++) xr += R[3 * i + j] * (X[3 * a + j] + u[3 * a + j]);
                    ur[3 * a + i] = xr - X[3 * a + i];
                }
            ctn_cable2_eval(&p, X, ur, fr, NULL, &s1);
            CHECK_CLOSE(s1.N, s0.N, 1e-10, 1e-12 * fabs(s0.N));
            for (int a = 0; a < 2; a++)
                for (int i = 0; i < 3; i++) {
                    double rf = 0;
                    for (int j = 0; j < 3; j++) rf += R[3 * i + j] * f[3 * a + j];
                    CHECK_CLOSE(fr[3 * a + i], rf, 1e-9, 1e-9 * fabs(s0.N));
                }
        }
}

static void test_axial_laws(void)
{
    double X[6] = { 0, 0, 0, 3, 4, 0 };             /* reference length 5 */
    for (int k = 0; k < 4; k++) {
        double lam = 0.9 + 0.1 * k;                   /* 0.9 .. 1.2 */
        double u[6] = { 0, 0, 0, 3 * (lam - 1), 4 * (lam - 1), 0 }, f[6];
        ctn_cable_props gl = { 1000, 5, CTN_STRAIN_GREEN_LAGRANGE, 0 };
        ctn_cable_props en = { 1000, 5, CTN_STRAIN_ENGINEERING, 0 };
        ctn_elem_state s;
        ctn_cable2_eval(&gl, X, u, f, NULL, &s);
        CHECK_CLOSE(s.l, 5 * lam, 1e-14, 0);
        CHECK_CLOSE(s.strain, (lam * lam - 1) / 2, 1e-12, 1e-15);
        CHECK_CLOSE(s.N, 1000 * (lam * lam - 1) / 2 * lam, 1e-12, 1e-12);
        CHECK_CLOSE(f[3], s.N * 0.6, 1e-14, 1e-14);
        CHECK_CLOSE(f[1], -s.N * 0.8, 1e-14, 1e-14);
        ctn_cable2_eval(&en, X, u, f, NULL, &s);
        CHECK_CLOSE(s.strain, lam - 1, 1e-12, 1e-15);
        CHECK_CLOSE(s.N, 1000 * (lam - 1), 1e-12, 1e-12);
    }
}

static void test_tension_only(void)
{
    double X[6] = { 0, 0, 0, 10, 0, 0 }, u[6] = { 0, 0, 0, -0.5, 0, 0 }, f[6], K[CTN_EPACKED];
    ctn_cable_props p = { 1000, 10, CTN_STRAIN_GREEN_LAGRANGE, 1 };
    ctn_elem_state s;
    ctn_cable2_eval(&p, X, u, f, K, &s);
    CHECK(s.slack == 1);
    CHECK(s.N == 0);
    double kmax = 0;
    for (int i = 0; i < CTN_EPACKED; i++) kmax = fmax(kmax, fabs(K[i]));
    CHECK(kmax == 0);
    u[3] = 0.5;
    ctn_cable2_eval(&p, X, u, f, K, &s);
    CHECK(s.slack == 0 && s.N > 0);
    double u0[6] = { 1, 2, 3, 1, 2, 3 - 10 };      /* collapse: node 2 onto node 1 */
    double X0[6] = { 0, 0, 0, 0, 0, 10 };
    CHECK(ctn_cable2_eval(&p, X0, u0, f, K, &s) == CTN_ERR_DOMAIN);
}

/* dU/du = f: the energy is the potential of the internal forces (central differences). */
static void test_energy_gradient(void)
{
    unsigned seed = 4242;
    for (int strain = 0; strain < 2; strain++)
        for (int trial = 0; trial < 50; trial++) {
            double X[6], u[6], f[6];
            for (int k = 0; k < 6; k++) X[k] = urand(&seed, -10, 10);
            for (int k = 0; k < 6; k++) u[k] = urand(&seed, -0.5, 0.5);
            ctn_cable_props p = { 3e4, 12.0, (ctn_strain)strain, trial % 2 };
            ctn_elem_state s, sp, sm;
            ctn_cable2_eval(&p, X, u, f, NULL, &s);
            for (int j = 0; j < 6; j++) {
                double up[6], um[6], fd[6], h = 1e-6;
                for (int k = 0; k < 6; k++) up[k] = um[k] = u[k];
                up[j] += h;
                um[j] -= h;
                ctn_cable2_eval(&p, X, up, fd, NULL, &sp);
                ctn_cable2_eval(&p, X, um, fd, NULL, &sm);
                CHECK_CLOSE((sp.energy - sm.energy) / (2 * h), f[j], 1e-6, 1e-6 * fabs(s.N) + 1e-9);
            }
        }
}

int main(void)
{
    test_energy_gradient();
    test_tangent_fd();
    test_objectivity();
    test_axial_laws();
    test_tension_only();
    CHECK_DONE();
}
