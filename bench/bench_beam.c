/* bench_beam - the corotational beam's kernels per evaluation (issue 23): the closed-form
 * forces with their Jacobian (ctn_beam_eval_cf, beam3_cf.c) against the energy on
 * second-order jets (ctn_beam_eval_jet, beam3.c), on the same random states of a
 * steel tube member of 0.45 m (bench/beam_grid.py's at K = 224), alternated in R rounds
 * in one process; CPU microseconds per evaluation with the tangent and without, medians
 * over the rounds, and the largest difference of the two kernels' tangents.
 *
 *   bench_beam [--rounds R] [--states N] [--rotation MAX]   (defaults 5, 20000, 0.05 rad)
 */
#include "element/beam3.h"

#include "bench_common.h"

#include <string.h>

typedef int (*kernel)(const ctn_beam_props *, unsigned, const double *, const double *, double *, double *,
                      ctn_elem_state *);

static double urand(unsigned *seed, double lo, double hi)
{
    *seed = *seed * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*seed >> 8) & 0xffffff) / (double)0xffffff;
}

/* CPU microseconds per evaluation of kernel k over the n states u (12 each). */
static double time_kernel(kernel k, const ctn_beam_props *p, const double *X, const double *u, int n, int tangent,
                          volatile double *sink)
{
    double f[12], K[78], t0 = cpu_now();
    for (int i = 0; i < n; i++) {
        if (k(p, 0, X, u + 12 * i, f, tangent ? K : NULL, NULL)) continue;
        *sink += f[3] + (tangent ? K[40] : 0);
    }
    return (cpu_now() - t0) * 1e6 / n;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    int rounds = 5, n = 20000;
    double rot = 0.05;
    volatile double sink = 0;                          /* keeps the evaluations */
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--rounds")) rounds = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--states")) n = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--rotation")) rot = atof(argv[i + 1]);
    }
    if (rounds < 1 || rounds > 99 || n < 1) return 2;
    const double E = 2.1e8, G = E / 2.6, L = 100.0 / 224, A = 9.11e-3, I = 9.66e-5;   /* kN, m: d=0.3 t=0.01 */
    ctn_beam_props p = { .L0 = L, .EA = E * A, .A = A, .cy0 = 2 * E * I / L, .cy1 = 2 * E * I / L,
                         .cz0 = 2 * E * I / L, .cz1 = 2 * E * I / L, .kt = G * 2 * I / L,
                         .e2 = { 0, 1, 0 }, .e3 = { 0, 0, 1 }, .spin = 3u };
    const double X[6] = { 0, 0, 0, L, 0, 0 };
    double *u = malloc(sizeof(double) * 12 * (size_t)n), t[4][99], dK = 0;
    if (!u) return 1;
    unsigned seed = 7u;
    for (int i = 0; i < 12 * n; i++) u[i] = i % 6 < 3 ? urand(&seed, -0.01, 0.01) : urand(&seed, -rot, rot);
    for (int i = 0; i < n && i < 1000; i++) {
        double fc[12], fj[12], Kc[78], Kj[78], km = 0, d = 0;
        if (ctn_beam_eval_cf(&p, 0, X, u + 12 * i, fc, Kc, NULL) || ctn_beam_eval_jet(&p, 0, X, u + 12 * i, fj, Kj, NULL))
            continue;
        for (int k = 0; k < 78; k++) {
            km = fmax(km, fabs(Kj[k]));
            d = fmax(d, fabs(Kc[k] - Kj[k]));
        }
        dK = fmax(dK, d / km);
    }
    for (int r = 0; r < rounds; r++) {
        t[0][r] = time_kernel(ctn_beam_eval_jet, &p, X, u, n, 1, &sink);
        t[1][r] = time_kernel(ctn_beam_eval_cf, &p, X, u, n, 1, &sink);
        t[2][r] = time_kernel(ctn_beam_eval_jet, &p, X, u, n, 0, &sink);
        t[3][r] = time_kernel(ctn_beam_eval_cf, &p, X, u, n, 0, &sink);
    }
    for (int k = 0; k < 4; k++) qsort(t[k], (size_t)rounds, sizeof(double), cmp);
    printf("beam kernel, %d states (rotations within %g rad), %d rounds, load %.1f; CPU us per evaluation (median)\n", n,
           rot, rounds, load_average());
    printf("  with the tangent:  jets %.3f  closed form %.3f  (%.1fx)\n", t[0][rounds / 2], t[1][rounds / 2],
           t[0][rounds / 2] / t[1][rounds / 2]);
    printf("  forces only:       jets %.3f  closed form %.3f  (%.1fx)\n", t[2][rounds / 2], t[3][rounds / 2],
           t[2][rounds / 2] / t[3][rounds / 2]);
    printf("  tangents differ by %.3g (relative, largest over 1000 states)\n", dK);
    free(u);
    return 0;
}
