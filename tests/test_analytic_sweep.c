/* Analytic layer: a deterministic pseudo-random sweep over spans, inclinations, lengths
 * (from 1e-14 above the chord to 10x the chord, and below it for elastic cables),
 * weights and stiffnesses. Every solve must succeed and close on the right support;
 * random funicular chains must be solved (closure, equilibrium) or certified slack. */
#include "catena/analytic.h"
#include "check.h"

#include <stdint.h>
#include <stdlib.h>

/* Uniform in [0, 1) from a 64-bit LCG (Knuth's MMIX constants). */
static double uniform(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) * 0x1.0p-53;
}

static void one_span(uint64_t *s)
{
    double l = 1.0 + 999.0 * uniform(s);
    double h = (2.0 * uniform(s) - 1.0) * l * pow(10.0, 2.0 * uniform(s) - 1.0), C = hypot(l, h);
    double w = pow(10.0, 4.0 * uniform(s) - 2.0), EA = pow(10.0, 2.0 + 10.0 * uniform(s));
    double ratio = uniform(s) < 0.5 ? 1.0 + pow(10.0, -1.0 - 13.0 * uniform(s))
                                    : 1.0 + 9.0 * uniform(s);
    double r2 = uniform(s) < 0.3 ? 0.95 + 0.05 * uniform(s) : ratio, x, y;
    ctn_catenary_in ci = {l, h, w, ratio * C};
    ctn_catenary c;
    CHECK_MSG(ctn_catenary_solve(NULL, &ci, &c) == CTN_OK, "l %g h %g S/C %.17g", l, h, ratio);
    CHECK(ctn_catenary_y(&c, l, &y) == CTN_OK && fabs(y - h) <= 1e-12 * C);
    ctn_ecatenary_in ei = {l, h, w, EA, r2 * C};
    ctn_ecatenary e;
    CHECK_MSG(ctn_ecatenary_solve(NULL, &ei, &e) == CTN_OK, "l %g h %g L0/C %.17g EA %g", l, h,
              r2, EA);
    ctn_ecatenary_point(&e, e.in.L0, &x, &y);
    CHECK(fabs(x - l) <= 1e-12 * e.sum.length && fabs(y - h) <= 1e-12 * e.sum.length);
    ctn_parabola_in pi = {l, h, w, r2 * C, EA};
    ctn_parabola p;
    CHECK_MSG(ctn_parabola_solve(NULL, &pi, &p) == CTN_OK, "l %g h %g L0/C %.17g", l, h, r2);
    pi.L0 = ratio * C;
    pi.EA = INFINITY;
    CHECK_MSG(ctn_parabola_solve(NULL, &pi, &p) == CTN_OK, "l %g h %g S/C %.17g", l, h, ratio);
}

/* Closure and joint equilibrium of a solved chain. */
static void check_chain(const ctn_funicular_in *in, const double *xy, const double *N, double Tmax)
{
    CHECK(fabs(xy[2 * in->n] - in->l) <= 1e-12 * (in->l + fabs(in->h)) * in->n);
    CHECK(fabs(xy[2 * in->n + 1] - in->h) <= 1e-12 * (in->l + fabs(in->h)) * in->n);
    for (size_t k = 1; k < in->n; k++) {
        double a[2] = {xy[2 * k] - xy[2 * k - 2], xy[2 * k + 1] - xy[2 * k - 1]};
        double b[2] = {xy[2 * k + 2] - xy[2 * k], xy[2 * k + 3] - xy[2 * k + 1]};
        double la = hypot(a[0], a[1]), lb = hypot(b[0], b[1]);
        CHECK(fabs(N[k] * b[0] / lb - N[k - 1] * a[0] / la + in->P[2 * k - 2]) <= 1e-12 * Tmax);
        CHECK(fabs(N[k] * b[1] / lb - N[k - 1] * a[1] / la + in->P[2 * k - 1]) <= 1e-12 * Tmax);
    }
}

static void one_chain(uint64_t *s, int *slack)
{
    size_t n = 2 + (size_t)(40.0 * uniform(s));
    double *L = malloc(n * sizeof *L), *E = malloc(n * sizeof *E), *P = malloc(2 * n * sizeof *P);
    double *xy = malloc(2 * (n + 1) * sizeof *xy), *N = malloc(n * sizeof *N);
    double l = 1.0 + 99.0 * uniform(s), h = (2.0 * uniform(s) - 1.0) * l, tot = 0.0;
    for (size_t i = 0; i < n; i++) {
        L[i] = 0.1 + uniform(s);
        E[i] = pow(10.0, 2.0 + 8.0 * uniform(s));
        tot += L[i];
        P[2 * i] = 0.3 * (2.0 * uniform(s) - 1.0);
        P[2 * i + 1] = -2.0 * uniform(s);
    }
    double scale = hypot(l, h) * (1.0 + (uniform(s) < 0.5 ? 1e-6 : 3.0) * uniform(s)) / tot;
    for (size_t i = 0; i < n; i++) L[i] *= scale;
    ctn_funicular_in in = {l, h, n, L, uniform(s) < 0.5 ? E : NULL, P};
    ctn_funicular f;
    int st = ctn_funicular_solve(NULL, &in, xy, N, &f);
    CHECK_MSG(st == CTN_OK || st == CTN_ERR_DOMAIN, "n %zu: %s", n, ctn_strerror(st));
    if (st == CTN_OK) check_chain(&in, xy, N, f.sum.T_max);
    *slack += st == CTN_ERR_DOMAIN;
    free(L);
    free(E);
    free(P);
    free(xy);
    free(N);
}

int main(void)
{
    uint64_t s = 20240611u;
    int slack = 0;
    for (int i = 0; i < 5000; i++) one_span(&s);
    for (int i = 0; i < 1000; i++) one_chain(&s, &slack);
    CHECK(slack < 100);                                /* most random chains are taut */
    printf("%d of 1000 random chains certified slack\n", slack);
    CHECK_DONE();
}
