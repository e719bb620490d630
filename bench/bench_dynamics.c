/* The dynamics analysis's cost (issue 26): a taut line of n elements (L = 100 m, EA =
 * 1e6 N, T0 = 1e4 N in the straight line, 1 kg/m, plucked 0.1 m at mid-span, every
 * interior node free in x, y, z), through `steps` implicit steps and an explicit run.
 *   static:   the same model solved statically in 100 increments (pure Newton, threads=1: no factorization
 *             beside the assembly, as the dynamics' own), one iteration's time =
 *             (assembly + factorization + solves) / iterations;
 *   implicit: generalized-alpha, rho_inf = 0.9, dt = 1 ms (10 transverse Courant numbers),
 *             time per step / (the static iteration x Newton iterations per step): the
 *             issue's target is <= 1.5;
 *   explicit: central differences at 0.9 of the bar's step l / sqrt(EA / m), element-steps
 *             per second (target >= 1e6 on one core).
 * Usage: bench_dynamics [N [STEPS [EXPLICIT_STEPS]]] (defaults 10000 100 2000). */
#include "bench_common.h"

#include <string.h>

static char *line_model(int n, const char *tail)
{
    size_t size = 1024 + 200 * (size_t)n + strlen(tail);
    char *text = malloc(size), *p = text;
    if (!text) return NULL;
    double L = 100, l = L / n, EA = 1e6, T0 = 1e4, l0 = l / (1 + T0 / EA);
    p += sprintf(p, "material m E=%.17g strain=engineering\nsection s material=m A=1 mass=1\n", EA);
    for (int j = 0; j <= n; j++) {
        double x = j * l, y = 0.1 * (1 - fabs(2 * x / L - 1));
        p += sprintf(p, "node %d %.17g %.17g 0%s\n", j + 1, x, y, j == 0 || j == n ? " fix=xyz" : "");
    }
    for (int j = 0; j < n; j++) p += sprintf(p, "element %d %d %d section=s l0=%.17g\n", j + 1, j + 1, j + 2, l0);
    sprintf(p, "%s", tail);
    return text;
}

static int run(ctn_ctx *ctx, const char *text, ctn_solution **s, double *wall)
{
    ctn_model *m = NULL;
    ctn_solve_options opt;
    int rc = ctn_read_string(ctx, "line.cable", text, strlen(text), &m, &opt);
    double t0 = now();
    if (!rc) rc = ctn_solve(ctx, m, &opt, s);
    *wall = now() - t0;
    ctn_model_destroy(&m);
    if (rc) fprintf(stderr, "bench_dynamics: %s\n", ctn_ctx_message(ctx));
    return rc;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 10000, steps = argc > 2 ? atoi(argv[2]) : 100;
    int esteps = argc > 3 ? atoi(argv[3]) : 2000;
    bench_keep_heap();
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    char tail[256];
    ctn_solution *s = NULL;
    double wall, dt = 1e-3, l = 100.0 / n, dte = 0.9 * l / sqrt(1e6 / 1.0);
    /* static */
    char *text = line_model(n, "solve method=newton threads=1 steps=100\n");
    if (!text || run(ctx, text, &s, &wall)) return 1;
    ctn_solve_summary ss;
    ctn_solution_summary(s, &ss);
    double it_static = (ss.t_assemble + ss.t_factor + ss.t_solve) / ss.iterations;
    printf("n = %d elements, %zu free DOFs\n", n, ss.ndof);
    printf("static:   %d Newton iterations, %.3f ms each (assembly %.3f, factorization %.3f, solve %.3f ms)\n",
           ss.iterations, 1e3 * it_static, 1e3 * ss.t_assemble / ss.iterations, 1e3 * ss.t_factor / ss.iterations,
           1e3 * ss.t_solve / ss.iterations);
    ctn_solution_destroy(&s);
    free(text);
    /* implicit */
    snprintf(tail, sizeof tail, "solve threads=1\ndynamics dt=%.17g t_end=%.17g method=genalpha rho_inf=0.9\nrecord node=%d\n",
             dt, steps * dt, n / 2 + 1);
    text = line_model(n, tail);
    if (!text || run(ctx, text, &s, &wall)) return 1;
    ctn_dynamics_summary d;
    ctn_solution_dynamics_summary(s, &d);
    double per_step = d.t_total / (double)d.steps, its = (double)d.iterations / d.substeps;
    ctn_solution_summary(s, &ss);                     /* the dynamics' own assembly, factorization, solves */
    printf("implicit: %zu steps (%d substeps), %.2f Newton iterations per step, %.3f ms per step, %.3f ms per "
           "iteration: %.2f x the static iteration\n", d.steps, d.substeps, its, 1e3 * per_step, 1e3 * per_step / its,
           per_step / (its * it_static));
    printf("          per step: assembly %.3f ms, factorization %.3f ms, solve %.3f ms, other %.3f ms\n",
           1e3 * ss.t_assemble / d.steps, 1e3 * ss.t_factor / d.steps, 1e3 * ss.t_solve / d.steps,
           1e3 * (per_step - (ss.t_assemble + ss.t_factor + ss.t_solve) / d.steps));
    ctn_solution_destroy(&s);
    free(text);
    /* explicit */
    snprintf(tail, sizeof tail, "dynamics dt=%.17g t_end=%.17g method=central\nrecord node=%d\n", dte, esteps * dte, n / 2 + 1);
    text = line_model(n, tail);
    if (!text || run(ctx, text, &s, &wall)) return 1;
    ctn_solution_dynamics_summary(s, &d);
    printf("explicit: %zu steps of %.3g s (stable step %.3g s), %.3f s: %.3g element-steps per second\n", d.steps, d.dt,
           d.dt_stable, d.t_total, (double)n * (double)d.steps / d.t_total);
    ctn_solution_destroy(&s);
    free(text);
    ctn_ctx_destroy(&ctx);
    return 0;
}
