/* Shared by the benchmark programs (each bench program is one .c file): the clock, peak
 * memory, medians, counts written as 1e6, and the founding paper's cable with n elements. */
#ifndef CTN_BENCH_COMMON_H
#define CTN_BENCH_COMMON_H

#include <catena.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <sys/resource.h>
#include <time.h>

#define SPAN 200.0            /* level span [m] */
#define LENGTH 250.8777       /* unstressed length [m] */

static inline double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The catena command's heap policy (app/main.c, keep_heap): freed memory stays with the
 * process, so a phase timed after another does not pay the page faults of fresh memory
 * the command would not pay either. */
static inline void bench_keep_heap(void)
{
#ifdef M_MMAP_MAX
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);
#endif
}

/* CPU seconds of the process, all threads. */
static inline double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The 1-minute load average, 0 if unknown. */
static inline double load_average(void)
{
    double l = 0;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f && fscanf(f, "%lf", &l) != 1) l = 0;
    if (f) fclose(f);
    return l;
}

static inline double peak_rss_mib(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru)) return NAN;
    return (double)ru.ru_maxrss / 1024.0;                    /* ru_maxrss is in KiB */
}

static inline int cmp_double(const void *x, const void *y)
{
    double p = *(const double *)x, q = *(const double *)y;
    return (p > q) - (p < q);
}

/* Median of v[0..n), n >= 1 (v is sorted in place). */
static inline double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* An integer written as 1000, 1e6, ... within [lo, hi]; 0 on success. */
static inline int parse_count(const char *s, int lo, int hi, int *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !(v >= lo && v <= hi) || v != floor(v)) return -1;
    *out = (int)v;
    return 0;
}

/* The paper's cable: 200 m level span, unstressed length 250.8777 m, E = 2e8 kN/m^2,
 * A = 3.14e-4 m^2, w = 0.1 kN/m, gravity (0, -1, 0), n elements on the arc, Newton from
 * `start`. */
static inline int build_paper_cable(ctn_ctx *ctx, int n, ctn_cable_start start, ctn_model **out)
{
    const double A[3] = { 0, 0, 0 }, B[3] = { SPAN, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = n, .length = LENGTH, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = start, .prestress = CTN_PRESTRESS_NONE };
    ctn_model *m = NULL;
    int rc = ctn_model_create(ctx, &m);
    if (!rc) rc = ctn_model_set_units(m, "kN", "m");
    if (!rc) rc = ctn_model_set_gravity(m, g);
    if (!rc) rc = ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0);
    if (!rc) rc = ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1);
    if (!rc) rc = ctn_model_add_node(m, 1, A, CTN_FIX_ALL);
    if (!rc) rc = ctn_model_add_node(m, 2, B, CTN_FIX_ALL);
    if (!rc) rc = ctn_model_add_cable(m, 1, 2, "strand", &spec, NULL, NULL);
    if (rc) ctn_model_destroy(&m);
    *out = m;
    return rc;
}

#endif
