/* Dynamics, the rest of issue 26 (docs/validation.md section 19), each against an
 * independent truth:
 * - modal damping (`damping modal=`): a 2-DOF chain (two springs k = 4, two masses 1,
 *   along x) released from rest in each of its modes phi_i (the static step under
 *   K phi_i = omega_i^2 M phi_i, then that load taken off by a step function at t = 0)
 *   decays as x0 e^(-zeta_i omega_i t)(cos omega_d t + zeta_i / sqrt(1 - zeta_i^2) sin
 *   omega_d t) at its own ratio, both DOFs, omega_i^2 = k (3 -+ sqrt 5) / 2 in closed form;
 *   the error O(dt^2) (ratio 4 +- 0.5 on halving dt), below 2e-4 of the amplitude; one
 *   ratio for all modes (`modal=Z modes=2`); the other mode stays unexcited;
 * - wind drag on the relative velocity (`relative_wind=1`): a bar blown from rest by a
 *   wind V, y = V t - (2 / (k l)) ln(1 + k l V t / 2) exactly (the air's velocity relative
 *   to it decays as u' = -(k l / 2) u^2), O(dt^2); the energy balance with the drag's work;
 *   the drag's velocity derivative in the effective tangent (Newton's iterations at a
 *   step where it dominates); its errors;
 * - a snap load: a mass falling h on a slack rope until it is taut, the peak tension
 *   against the energy estimate m g + sqrt((m g)^2 + 2 k m g h) (exact for the elastic
 *   rope), implicit (first order in dt: the slack-taut kink is not located) and explicit;
 * - every allocation failure of a run with modal damping, reactions and frames:
 *   CTN_ERR_NOMEM and no leak (ASan). */
/* ctest-cost: 3 */
#include "catena.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static ctn_solution *solve_text(ctn_ctx *ctx, const char *text, int *rc)
{
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    *rc = ctn_read_string(ctx, "dyn2.cable", text, strlen(text), &m, &opt);
    if (!*rc) *rc = ctn_solve(ctx, m, &opt, &s);
    ctn_model_destroy(&m);
    return s;
}

/* The chain released in mode `mode` (0, 1) with `damping` and dt; the largest error of
 * x2, x3 against the closed form, relative to the amplitude a. */
static double modal_decay(int mode, const char *damping, double zeta, double dt)
{
    const double k = 4, a = 0.1, sgn = mode ? -1 : 1;
    double w2 = k * (3 - sgn * sqrt(5.0)) / 2, w = sqrt(w2), r = (1 + sgn * sqrt(5.0)) / 2;
    double d[2] = { a, a * r }, F[2] = { w2 * d[0], w2 * d[1] };   /* K phi = w^2 M phi */
    char text[2048];
    snprintf(text, sizeof text,
             "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 mass=1 fix=yz\nnode 3 2 0 0 mass=1 fix=yz\n"
             "spring 1 1 2 k=4\nspring 2 2 3 k=4\nfunction on step t0=0\nstep release\n"
             "load 2 %.17g 0 0\nload 3 %.17g 0 0\nload 2 %.17g 0 0 fn=on\nload 3 %.17g 0 0 fn=on\n"
             "%s\ndynamics dt=%.17g t_end=10 rho_inf=1\nrecord node=2 dof=ux\nrecord node=3 dof=ux\n",
             F[0], F[1], -F[0], -F[1], damping, dt);
    ctn_ctx *ctx = NULL;
    int rc;
    ctn_ctx_create(&ctx);
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    size_t rows = 0, cols = 0;
    const double *h = ctn_solution_history(s, &rows, &cols);
    double wd = w * sqrt(1 - zeta * zeta), err = rows ? 0 : INFINITY;
    for (size_t i = 0; h && i < rows; i++) {
        double t = h[3 * i], g = exp(-zeta * w * t) * (cos(wd * t) + zeta / sqrt(1 - zeta * zeta) * sin(wd * t));
        err = fmax(err, fmax(fabs(h[3 * i + 1] - d[0] * g), fabs(h[3 * i + 2] - d[1] * g)) / a);
    }
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
    return err;
}

static void test_modal_damping(void)
{
    static const double zeta[2] = { 0.02, 0.1 };
    for (int mode = 0; mode < 2; mode++) {
        double e1 = modal_decay(mode, "damping modal=0.02,0.1", zeta[mode], 0.005);
        double e2 = modal_decay(mode, "damping modal=0.02,0.1", zeta[mode], 0.0025);
        printf("modal damping, mode %d at zeta %g: error / amplitude %.3g, %.3g at dt = 5, 2.5 ms (ratio %.2f)\n",
               mode + 1, zeta[mode], e1, e2, e1 / e2);
        CHECK(e1 < 2e-4 && e2 < 1e-4);
        CHECK_CLOSE(e1 / e2, 4.0, 0, 0.5);
    }
    double e = modal_decay(1, "damping modal=0.05 modes=2", 0.05, 0.005);
    printf("modal damping, one ratio for two modes: mode 2 at 0.05: error / amplitude %.3g\n", e);
    CHECK(e < 2e-4);
    CHECK(modal_decay(1, "damping modal=0.05 modes=1", 0.05, 0.005) > 0.1);   /* mode 2 left undamped */
}

static void test_modal_errors(void)
{
    static const char *const bad[][2] = {
        { "damping modal=0.02,0.1 modes=3", "dyn2.cable:6: damping: modes=3 but modal= gives 2 ratios" },
        { "damping modal=1.2", "dyn2.cable:6: damping: modal ratio 1 must be from 0 to below 1 (found 1.2)" },
        { "damping modes=2", "dyn2.cable:6: damping: modes= goes with modal=" },
        { "damping modal=0.1 modes=3", "modes: count=3 is more than the 2 free DOFs" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char text[1024];
        snprintf(text, sizeof text, "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 mass=1 fix=yz\nnode 3 2 0 0 mass=1 fix=yz\n"
                 "spring 1 1 2 k=4\nspring 2 2 3 k=4\n%s\nload 3 1 0 0\ndynamics dt=0.01 t_end=0.1\n", bad[i][0]);
        ctn_ctx *ctx = NULL;
        int rc;
        ctn_ctx_create(&ctx);
        ctn_solution *s = solve_text(ctx, text, &rc);
        CHECK_MSG(rc != CTN_OK && strstr(ctn_ctx_message(ctx), bad[i][1]), "%s: %s", bad[i][0], ctn_ctx_message(ctx));
        ctn_solution_destroy(&s);
        ctn_ctx_destroy(&ctx);
    }
}

/* Every allocation of a run with modal damping, a moving support, a reaction record and
 * frames fails in turn: CTN_ERR_NOMEM each time, then a run that completes. */
static void test_allocations(void)
{
    const char *text = "material m E=4 strain=engineering\nsection s material=m A=1 mass=0.6\n"
                       "node 1 0 0 0 fix=xyz mass=0.5\nnode 2 1 0 0 fix=yz mass=1\nnode 3 2 0 0 fix=yz mass=1\n"
                       "element 1 1 2 section=s\nelement 2 2 3 section=s\n"
                       "function g harmonic amp=0.01 freq=0.2\ndisplace 1 x=1 fn=g\n"
                       "damping modal=0.05 modes=2 beta=0.01\n"
                       "dynamics dt=0.01 t_end=0.2 output_every=3 vtu=1\nrecord node=1 reaction\n";
    ctn_ctx *ctx = NULL;
    int rc, done = 0, failures = 0;
    ctn_ctx_create(&ctx);
    for (long k = 1; !done && k < 5000; k++) {
        ctn_ctx_fail_alloc_at(ctx, k);
        ctn_solution *s = solve_text(ctx, text, &rc);
        ctn_ctx_fail_alloc_at(ctx, 0);
        if (rc) {
            failures++;
            CHECK_MSG(rc == CTN_ERR_NOMEM, "allocation %ld: status %d (%s)", k, rc, ctn_ctx_message(ctx));
        } else {
            done = 1;
            CHECK(ctn_solution_frame_count(s) == 8);                     /* rows 0, 3, ..., 18, 20 */
        }
        ctn_solution_destroy(&s);
    }
    CHECK(done && failures > 20);
    ctn_ctx_destroy(&ctx);
}

/* A bar (along x, both ends free in y only, point masses 1 and 1, no stiffness against
 * the translation) in a wind V along y (rho 1.25, cd 1.2, d 0.1: k = rho cd d / 2), from
 * rest: the air's velocity relative to it, u = V - y', obeys 2 u' = -k l u^2, so
 * y = V t - (2 / (k l)) ln(1 + k l V t / 2) exactly. Returns the largest error of y; the
 * Newton iterations and the relative energy balance error in *its, *energy. */
static double wind_bar(double V, double dt, double t_end, int *its, double *energy)
{
    char text[1024];
    snprintf(text, sizeof text,
             "material m E=1000 strain=engineering\nsection s material=m A=1 mass=0\n"
             "node 1 0 0 0 fix=xz mass=1\nnode 2 1 0 0 fix=xz mass=1\nelement 1 1 2 section=s\n"
             "wind all dir=0,1,0 speed=%.17g rho=1.25 cd=1.2 d=0.1\n"
             "dynamics dt=%.17g t_end=%.17g rho_inf=1 relative_wind=1\nrecord node=1 dof=uy\nrecord node=2 dof=uy\n",
             V, dt, t_end);
    ctn_ctx *ctx = NULL;
    int rc;
    ctn_ctx_create(&ctx);
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    size_t rows = 0, cols = 0;
    const double *h = ctn_solution_history(s, &rows, &cols);
    double c = 0.5 * 1.25 * 1.2 * 0.1 / 2, err = rows ? 0 : INFINITY;
    for (size_t i = 0; h && i < rows; i++) {
        double t = h[3 * i], y = V * t - log(1 + c * V * t) / c;
        err = fmax(err, fmax(fabs(h[3 * i + 1] - y), fabs(h[3 * i + 2] - y)));
    }
    ctn_dynamics_summary sum;
    memset(&sum, 0, sizeof sum);
    ctn_solution_dynamics_summary(s, &sum);
    *its = sum.iterations;
    *energy = sum.energy_error;
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
    return err;
}

static void test_relative_wind(void)
{
    int i1, i2, i3;
    double en1, en2, en3;
    double e1 = wind_bar(10, 0.01, 5, &i1, &en1), e2 = wind_bar(10, 0.005, 5, &i2, &en2);
    printf("relative wind, a bar blown from rest (y(5) = 21.8386): error %.3g, %.3g at dt = 10, 5 ms (ratio %.2f); "
           "energy balance %.2g, %.2g\n", e1, e2, e1 / e2, en1, en2);
    CHECK(e1 < 1e-6 * 21.84 * 4 && e2 < 1e-6 * 21.84);
    CHECK_CLOSE(e1 / e2, 4.0, 0, 0.5);
    CHECK(en1 < 1e-8 && en2 < 1e-8);                 /* the drag's work is in W */
    wind_bar(100, 0.2, 2, &i3, &en3);                /* c2 dq/dv dominates the tangent */
    printf("relative wind at V = 100, dt = 0.2: %d Newton iterations over 10 steps\n", i3);
    CHECK(i3 <= 50);                                 /* without its velocity tangent: 234 and 4 halvings */
    static const char *const bad[][2] = {
        { "dynamics dt=0.01 t_end=0.1", "dyn2.cable:7: dynamics: a `wind` acts in a dynamics analysis on the velocity" },
        { "dynamics dt=0.01 t_end=0.1 relative_wind=1\nwind all dir=0,1,0 pressure=10 d=0.1",
          "dyn2.cable:8: wind: relative_wind=1 needs the air's density: give speed= and rho= (not pressure=)" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char text[1024];
        snprintf(text, sizeof text, "node 1 0 0 0 fix=xyz\nnode 2 1 0 0 mass=1 fix=xz\n"
                 "material m E=1000\nsection s material=m A=1 mass=0\nelement 1 1 2 section=s\n%s\n%s\n",
                 i ? "record node=2" : "wind all dir=0,1,0 speed=10 rho=1.25 d=0.1", bad[i][0]);
        ctn_ctx *ctx = NULL;
        int rc;
        ctn_ctx_create(&ctx);
        ctn_solution *s = solve_text(ctx, text, &rc);
        CHECK_MSG(rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), bad[i][1]), "%s", ctn_ctx_message(ctx));
        ctn_solution_destroy(&s);
        ctn_ctx_destroy(&ctx);
    }
}

/* A snap load: a mass m = 1 on a slack tension-only rope (EA = 1e4, l0 = 1, engineering
 * strain, massless) hung 0.9 below its anchor, released under its weight: it falls h = 0.1
 * freely, then the rope (a spring k = EA / l0 once taut) arrests it. Energy: m g (h +
 * delta) = k delta^2 / 2, so the peak tension k delta = m g + sqrt((m g)^2 + 2 k m g h)
 * (150.2245). The largest recorded force against it. */
static double snap_peak(const char *method, double dt)
{
    char text[1024];
    snprintf(text, sizeof text,
             "material rope E=1e4 strain=engineering tension-only\nsection s material=rope A=1 mass=0\n"
             "node 1 0 0 0 fix=xyz\nnode 2 0 -0.9 0 mass=1 fix=xz\nelement 1 1 2 section=s l0=1\n"
             "load 2 0 -9.81 0\ndynamics dt=%.17g t_end=0.2 %s\nrecord element=1 force\n", dt, method);
    ctn_ctx *ctx = NULL;
    int rc;
    ctn_ctx_create(&ctx);
    ctn_solution *s = solve_text(ctx, text, &rc);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    size_t rows = 0, cols = 0;
    const double *h = ctn_solution_history(s, &rows, &cols);
    double peak = 0;
    for (size_t i = 0; h && i < rows; i++) peak = fmax(peak, h[2 * i + 1]);
    ctn_solution_destroy(&s);
    ctn_ctx_destroy(&ctx);
    return peak;
}

static void test_snap(void)
{
    double mg = 9.81, k = 1e4, want = mg + sqrt(mg * mg + 2 * k * mg * 0.1);
    double e1 = snap_peak("rho_inf=1", 2e-4) / want - 1, e2 = snap_peak("rho_inf=1", 1e-4) / want - 1;
    double e3 = snap_peak("method=central", 1e-4) / want - 1;
    printf("snap load: peak tension vs the energy estimate %.7g: genalpha %.3g, %.3g at dt = 0.2, 0.1 ms; central %.3g "
           "at 0.1 ms\n", want, e1, e2, e3);
    CHECK(fabs(e1) < 2e-5 && fabs(e2) < 1e-5 && fabs(e2) < 0.6 * fabs(e1));   /* first order: the kink at the snap */
    CHECK(fabs(e3) < 1e-5);
}

int main(void)
{
    test_snap();
    test_relative_wind();
    test_modal_damping();
    test_modal_errors();
    test_allocations();
    CHECK_DONE();
}
