/* Small vector helpers and the clock of the solver's timings. */
#include "linalg/pcg.h"
#include "problem/problem.h"

#include <math.h>
#include <string.h>
#include <time.h>

double ctn_clock(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double ctn_cpu_clock(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double ctn_vec_dot(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) s += a[i] * b[i];
    return s;
}

/* sqrt(ss), where ss is the plain sum of the squares of entry(ud, 0 .. n-1): as it is when
 * ss is a normal number (every Newton iteration's case), else the sum again scaled by the
 * largest entry, so that a load of 1e300 has the norm 1e300, not Inf, and 1e-200 not 0.
 * A NaN stays NaN. */
double ctn_norm_from_ss(double ss, size_t n, ctn_entry_fn entry, const void *ud)
{
    if (isnan(ss) || (ss > 0x1p-900 && ss < 0x1p+900)) return sqrt(ss);
    double big = 0;
    for (size_t i = 0; i < n; i++) big = fmax(big, fabs(entry(ud, i)));
    if (!(big > 0) || isinf(big)) return big;
    double t = 0;
    for (size_t i = 0; i < n; i++) {
        double x = entry(ud, i) / big;
        t += x * x;
    }
    return big * sqrt(t);
}

static double plain_entry(const void *ud, size_t i) { return ((const double *)ud)[i]; }

double ctn_vec_norm(const double *v, size_t n)
{
    return ctn_norm_from_ss(ctn_vec_dot(v, v, n), n, plain_entry, v);
}

void ctn_problem_symv(const ctn_problem *p, const double *Ax, const double *x, double *y)
{
    ctn_pattern pat = { p->ndof, p->a->colptr, p->a->rowind };
    ctn_sym_matvec(&pat, Ax, x, y);
}
