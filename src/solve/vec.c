/* Small vector helpers and the clock of the solver's timings. */
#include "linalg/pcg.h"
#include "solve/problem.h"

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

double ctn_vec_norm(const double *v, size_t n) { return sqrt(ctn_vec_dot(v, v, n)); }

void ctn_problem_symv(const ctn_problem *p, const double *Ax, const double *x, double *y)
{
    ctn_pattern pat = { p->ndof, p->a->colptr, p->a->rowind };
    ctn_sym_matvec(&pat, Ax, x, y);
}
