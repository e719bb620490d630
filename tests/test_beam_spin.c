/* Beams at large 3D rotations (issue 23): the nodes' rotations composed (R = exp(w) R,
 * assemble/rot_compose.c), the elements' rotation forces the true moments (beam3.h,
 * spin), a `load` moment a fixed spatial moment with its tangent term (problem/spin.c).
 * Against closed forms, the tip's rotations free:
 * - the cantilever rolled into a full circle by M = 2 pi EI / L about z, and about the
 *   skew axis (0, 1, 1) / sqrt 2: the tip back at the root (about z to 1e-9 L; about
 *   the skew axis the solution leaves the plane by 1e-5 L, measured: asserted 1e-4),
 *   its rotation the identity at |psi| = 2 pi (along z in the plane: past the
 *   singularity of the additive update), the clamp's moment -M;
 * - the same cantilever (Iy = Iz) under the fixed end moment m = M (1, 0, 1) / sqrt 2,
 *   |m| = 2 pi EI / L: Kirchhoff's rod under a pure end moment is a helix about m (the
 *   internal moment is m everywhere, so the tangent turns about m at |m| / EI per unit
 *   length): tip at (m.e1) m L + (1 - cos) / Omega m x e1_perp + sin / Omega e1_perp, one
 *   full turn; the error falls as h^2 (n = 10, 20, 40); the clamp's moment is -m (a
 *   moment conjugate to the rotation vector would leave it off by the Jacobian of exp).
 * All under the default strategy (`auto`) and linear solver; the full circle about z
 * and the helix at n = 20 also by pure Newton: `auto` within 3 iterations of it (its
 * merit rejected Newton's steps here and it did not converge in 580 iterations:
 * analysis/static/correct.c, the watchdog).
 * Stability with fixed moments (analysis/stability/stability.c): the full circle and the
 * helix are stable (the whole non-symmetric tangent's determinant; the symmetric part
 * alone has 2 negative eigenvalues at the full circle), and a column with a negligible
 * fixed torque keeps the symmetric count: 0, 1, 2 below, between and above its two
 * Euler loads.
 * ctest-cost: 3 */
#include "check.h"
#include "run_text.h"

#include <stdio.h>

#define PI 3.14159265358979323846

/* A cantilever (L = 10, EI = 1e5, GJ = 5e4) of n elements, the tip free, under the end
 * moment m in `steps` steps of the default strategy (of pure Newton if newton); the tip's
 * displacement u and rotation vector psi, the clamp's reaction moment mr, the
 * iterations in *its. 1 if it did not solve. */
static int solve_cantilever(int n, const double m[3], int steps, int newton, double u[3], double psi[3], double mr[3],
                            int *its, ctn_stability *stab)
{
    char text[1024];
    snprintf(text, sizeof text,
             "material m E=1e7 G=5e6\n"
             "section s material=m A=1 Iy=1e-2 Iz=1e-2 J=1e-2\n"
             "node 1 0 0 0 fix=xyzrxryrz\n"
             "node 2 10 0 0\n"
             "beam 1 1 2 section=s orient=0,0,1 n=%d\n"
             "load 2 0 0 0 %.17g %.17g %.17g\n"
             "solve %ssteps=%d\n", n, m[0], m[1], m[2], newton ? "method=newton linear_solver=cholmod-ldl " : "",
             steps);
    run r = run_text("spin", text);
    ctn_step_result st;
    ctn_solve_summary sum;
    const double *th = NULL, *mo = NULL;
    int bad = r.rc || ctn_solution_step(r.s, 0, &st) || ctn_solution_step_rotations(r.s, 0, &th, &mo);
    CHECK_MSG(!bad, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
    for (int k = 0; !bad && k < 3; k++) {
        u[k] = st.d[3 + k];                      /* node 2 is the model's second */
        psi[k] = th[3 + k];
        mr[k] = ctn_solution_reaction_moments(r.s)[k];
    }
    if (!bad) {
        ctn_solution_summary(r.s, &sum);
        *its = sum.iterations;
        CHECK(ctn_solution_stability(r.s, stab) == CTN_OK);
    }
    done(&r);
    return bad;
}

static int cantilever(int n, const double m[3], int steps, double u[3], double psi[3], double mr[3])
{
    int its;
    ctn_stability st;
    return solve_cantilever(n, m, steps, 0, u, psi, mr, &its, &st);
}

/* The default strategy's iterations against pure Newton's on the same model. */
static void against_newton(const char *what, int n, const double m[3], int steps)
{
    double u[3], psi[3], mr[3];
    int a = 0, nw = 0;
    ctn_stability st;
    if (solve_cantilever(n, m, steps, 1, u, psi, mr, &nw, &st) || solve_cantilever(n, m, steps, 0, u, psi, mr, &a, &st)) return;
    printf("%s: %d iterations (auto), %d (pure Newton); stable %d\n", what, a, nw, st.stable);
    CHECK(a <= nw + 3);
    CHECK(st.stable && st.negative == 0);   /* the path is unique: its whole tangent never
                                               singular, so as definite as at the start */
}

/* The full circle about the unit axis a (across the member). */
static void full_circle(const double a[3])
{
    const double L = 10, M = 2 * PI * 1e5 / L;
    double m[3] = { M * a[0], M * a[1], M * a[2] }, u[3], psi[3], mr[3];
    if (cantilever(20, m, 20, u, psi, mr)) return;
    double tol = a[2] == 1 ? 1e-9 : 1e-4, p = sqrt(psi[0] * psi[0] + psi[1] * psi[1] + psi[2] * psi[2]);
    printf("full circle about (%g, %g, %g): tip at %.3g %.3g %.3g from the root, |psi| - 2 pi = %.3g\n", a[0], a[1],
           a[2], L + u[0], u[1], u[2], p - 2 * PI);
    CHECK(fabs(u[0] + L) < tol * L && fabs(u[1]) < tol * L && fabs(u[2]) < tol * L);
    CHECK(fabs(p - 2 * PI) < tol);              /* the identity, at the shell |psi| = 2 pi */
    for (int k = 0; k < 3; k++) {
        if (a[2] == 1) CHECK_CLOSE(psi[k], 2 * PI * a[k], 0, 1e-9);   /* in the plane: along z */
        CHECK_CLOSE(mr[k], -m[k], 0, 1e-9 * M);
    }
}

/* Kirchhoff's helix: the tip's distance from the closed form. */
static double helix_error(int n, int steps)
{
    const double L = 10, EI = 1e5, M = 2 * PI * EI / L, s = 1 / sqrt(2.0);
    const double mh[3] = { s, 0, s }, m[3] = { M * s, 0, M * s };
    double u[3], psi[3], mr[3], ca = mh[0], Om = M / EI, dp[3], mxd[3], e = 0;
    if (cantilever(n, m, steps, u, psi, mr)) return 1e30;
    for (int k = 0; k < 3; k++) {
        dp[k] = (k == 0) - ca * mh[k];           /* e1 less its part along m */
        CHECK_CLOSE(mr[k], -m[k], 0, 1e-9 * M);
    }
    mxd[0] = mh[1] * dp[2] - mh[2] * dp[1];
    mxd[1] = mh[2] * dp[0] - mh[0] * dp[2];
    mxd[2] = mh[0] * dp[1] - mh[1] * dp[0];
    for (int k = 0; k < 3; k++) {
        double x = ca * mh[k] * L + sin(Om * L) / Om * dp[k] + (1 - cos(Om * L)) / Om * mxd[k];
        double xh = (k == 0 ? L : 0) + u[k];
        e += (xh - x) * (xh - x);
    }
    return sqrt(e);
}

/* A cantilever column (Iy = 2 Iz) under an axial tip load P, with a small fixed torque
 * (1e-6: the tip's rotations spun, the tangent's skew part negligible), straight:
 * stable below the weak Euler load pi^2 E Iz / (4 L^2) = 1233.7, one negative
 * eigenvalue between it and the strong one 2467.4, two above (the determinant's sign
 * alone would call that stable). */
static void column(double P, long negative)
{
    char text[1024];
    snprintf(text, sizeof text,
             "material m E=1e7 G=5e6\n"
             "section s material=m A=1 Iy=1e-2 Iz=5e-3 J=1e-2\n"
             "node 1 0 0 0 fix=xyzrxryrz\nnode 2 10 0 0\n"
             "beam 1 1 2 section=s orient=0,0,1 n=10\n"
             "load 2 %.17g 0 0 1e-6 0 0\n", -P);
    run r = run_text("column", text);
    ctn_stability st;
    CHECK_MSG(r.rc == CTN_OK, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
    if (!r.rc && ctn_solution_stability(r.s, &st) == CTN_OK) {
        printf("column P = %g: stable %d, %ld negative\n", P, st.stable, st.negative);
        CHECK(st.stable == (negative == 0) && st.negative == negative);
    }
    done(&r);
}

int main(void)
{
    const double z[3] = { 0, 0, 1 }, skew[3] = { 0, 1 / sqrt(2.0), 1 / sqrt(2.0) };
    full_circle(z);
    full_circle(skew);
    const double M = 2 * PI * 1e5 / 10, s = 1 / sqrt(2.0), mz[3] = { 0, 0, M }, mh[3] = { M * s, 0, M * s };
    against_newton("full circle about z", 20, mz, 20);
    against_newton("helix, n = 20", 20, mh, 20);
    column(1000, 0);
    column(1800, 1);
    column(3000, 2);
    double e10 = helix_error(10, 20), e20 = helix_error(20, 20), e40 = helix_error(40, 40);
    printf("helix: tip error %.4g %.4g %.4g (n = 10, 20, 40), ratios %.3f %.3f\n", e10, e20, e40, e10 / e20,
           e20 / e40);
    CHECK(e10 < 0.03 * 10);                      /* 2 % of L at n = 10 */
    CHECK(e10 / e20 > 3.8 && e10 / e20 < 4.2);   /* O(h^2) */
    CHECK(e20 / e40 > 3.8 && e20 / e40 < 4.2);
    CHECK_DONE();
}
