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

double ctn_vec_norm(const double *v, size_t n)
{
    ctn_layout one;                              /* a local vector: this process's alone */
    ctn_layout_serial(&one, n, NULL);
    return ctn_layout_norm(&one, v);
}

double ctn_problem_dot(void *p, const double *a, const double *b)
{
    return ctn_layout_dot(&((const ctn_problem *)p)->eq, a, b);
}

void ctn_problem_symv(const ctn_problem *p, const double *Ax, const double *x, double *y)
{
    if (p->dist) ctn_problem_dist_symv(p, Ax ? Ax : p->Kx, x, y);
    else ctn_dmat_symv(&p->K, Ax, x, y);
}
