/* Lateral-torsional buckling of a deep simply supported beam with fork supports (ends
 * held in y, z and twist, free to turn about y and z, no warping restraint) under a
 * uniform moment M about its strong axis, by linear buckling (`buckling count=2`) of the
 * corotational beam: the closed form (Timoshenko and Gere, no warping stiffness)
 *   M_cr = (pi / L) sqrt(E Iz G J), and the second mode's 2 M_cr,
 * for a section deep enough (Iy / Iz = 1e6) that the in-plane deflection before
 * buckling changes it by 5e-7 (the factor 1 / sqrt((1 - Iz/Iy)(1 - GJ/(E Iy)))).
 * The beam has no geometric term of its own for the coupling of twist and lateral
 * bending: it comes from the finite-rotation kinematics (the corotated frame and the
 * local rotations' logarithm), with the end moments conjugate to the rotation vectors.
 * Measured: the error falls 4 times per halving of the elements (O(h^2)): n = 8, 16,
 * 32 give 1.1e-2, 2.8e-3, 7.0e-4 relative; Richardson's extrapolation from 16 and 32
 * within 1e-5 of the closed form. */
#include "check.h"
#include "run_text.h"

#include <stdio.h>

#define PI 3.14159265358979323846

static const double E = 2.1e11, G = 8.1e10, Iz = 1e-6, J = 1e-7, L = 10, M = 1000;

/* The first two buckling factors with n elements. */
static int factors(int n, double f[2])
{
    char text[1024];
    snprintf(text, sizeof text,
             "material steel E=%.17g G=%.17g\n"
             "section deep material=steel A=1e-2 Iy=1 Iz=%.17g J=%.17g\n"
             "node 1 0 0 0 fix=xyzrx\nnode 2 %g 0 0 fix=yzrx\n"
             "beam 1 1 2 section=deep orient=0,0,1 n=%d\n"
             "load 1 0 0 0 0 %g 0\nload 2 0 0 0 0 %g 0\n"
             "buckling count=2\n", E, G, Iz, J, L, n, M, -M);
    run r = run_text("ltb", text);
    int rc = r.rc || ctn_solution_buckling_count(r.s) != 2;
    CHECK_MSG(rc == 0, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
    for (size_t k = 0; !rc && k < 2; k++) {
        ctn_buckling_mode b;
        rc = ctn_solution_buckling(r.s, k, &b);
        f[k] = b.factor;
    }
    done(&r);
    return rc;
}

int main(void)
{
    const double Mcr = PI / L * sqrt(E * Iz * G * J);
    double f[3][2], err[3];
    for (int i = 0; i < 3; i++) {
        if (factors(8 << i, f[i])) CHECK_DONE();
        err[i] = f[i][0] * M / Mcr - 1;
        CHECK_MSG(err[i] > 0, "n = %d: %g from above", 8 << i, err[i]);
        CHECK_CLOSE(f[i][1] * M, 2 * Mcr, 5 * err[i], 0);   /* the second mode: 2 M_cr, 4 times the error */
    }
    for (int i = 0; i < 2; i++) {
        double ratio = err[i] / err[i + 1];
        CHECK_MSG(ratio > 3.8 && ratio < 4.2, "O(h^2): error ratio %g from n = %d", ratio, 8 << i);
    }
    CHECK(err[2] < 1e-3);
    double rich = (4 * f[2][0] - f[1][0]) / 3 * M;
    CHECK_CLOSE(rich, Mcr, 1e-5, 0);
    CHECK_DONE();
}
