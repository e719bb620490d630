/* bench_write - the result writers' benchmark (issue 8).
 *
 * Builds the founding paper's cable (as bench_cable does: 200 m level span, unstressed
 * length 250.8777 m, E = 2e8 kN/m^2, A = 3.14e-4 m^2, w = 0.1 kN/m, gravity 0 -1 0) with
 * n elements through the public API, solves it (catenary start: 3 iterations), then
 * times ctn_write_results: result.json (pretty), nodes.csv and elements.csv, each staged,
 * fsync'ed and renamed - what `catena solve -o DIR` does.
 *
 *   bench_write N [--dir DIR] [--repeat R] [--no-write] [--keep]
 *
 * N may be written 1e6. DIR (default bench-write.out) is created if missing; its three
 * files are removed at the end unless --keep. --repeat writes R times and reports the
 * median. --no-write stops after the solve: ru_maxrss is a high-water mark, so the
 * solve's own peak RSS is measured in a process of its own. Prints one line of
 * key=value pairs: bytes written, seconds, MB/s (1e6 bytes per second of wall time,
 * fsync included), the CPU seconds (user + system) of a write, which the load of a
 * shared machine disturbs less than wall time, and peak RSS in MiB. Exit status 0 when it ran, 1 on a usage error,
 * 2 when a library call failed. */
#include "bench_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define MAX_REPEAT 99

static const char *const files[3] = { "result.json", "nodes.csv", "elements.csv" };

typedef struct bench_opts {
    int n;                    /* elements */
    const char *dir;          /* output directory */
    int repeat;               /* writes; the median is reported */
    int no_write;             /* stop after the solve */
    int keep;                 /* leave the files in dir */
} bench_opts;

typedef struct result {
    double t_build, t_solve;  /* wall seconds */
    double t_write;           /* median wall seconds of ctn_write_results */
    double t_min, t_max;      /* fastest and slowest write */
    double cpu_write;         /* median CPU seconds (user + system) of a write */
    long long bytes;          /* bytes of the three files */
    double rss_solve;         /* peak RSS after model + solve [MiB] */
    double rss_end;           /* peak RSS at the end [MiB] */
} result;

static int usage(void)
{
    fprintf(stderr, "usage: bench_write N [--dir DIR] [--repeat R] [--no-write] [--keep]\n");
    return 1;
}

static int parse_args(int argc, char **argv, bench_opts *o)
{
    *o = (bench_opts){ 0, "bench-write.out", 1, 0, 0 };
    if (argc < 2 || parse_count(argv[1], 1, 50000000, &o->n)) return -1;
    for (int i = 2; i < argc; i++) {
        const char *val = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(argv[i], "--no-write")) o->no_write = 1;
        else if (!strcmp(argv[i], "--keep")) o->keep = 1;
        else if (!strcmp(argv[i], "--dir") && val) { o->dir = val; i++; }
        else if (!strcmp(argv[i], "--repeat") && val && !parse_count(val, 1, MAX_REPEAT, &o->repeat)) i++;
        else return -1;
    }
    return 0;
}

/* Total size of the three files in dir; -1 if one is missing. */
static long long written_bytes(const char *dir)
{
    long long total = 0;
    for (int i = 0; i < 3; i++) {
        char path[4096];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, files[i]);
        if (stat(path, &st)) return -1;
        total += (long long)st.st_size;
    }
    return total;
}

static void remove_files(const char *dir)
{
    for (int i = 0; i < 3; i++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, files[i]);
        unlink(path);
    }
    rmdir(dir);
}

/* o->repeat timed ctn_write_results: median, min and max wall time, median CPU time. */
static int time_writes(ctn_ctx *ctx, const bench_opts *o, const ctn_model *m,
                       const ctn_solution *s, result *r)
{
    double t[MAX_REPEAT], c[MAX_REPEAT];
    for (int k = 0; k < o->repeat; k++) {
        double c0 = cpu_now(), t0 = now();
        int rc = ctn_write_results(ctx, o->dir, m, s);
        t[k] = now() - t0;
        c[k] = cpu_now() - c0;
        if (rc) return rc;
    }
    r->cpu_write = median(c, o->repeat);
    r->t_write = median(t, o->repeat);
    r->t_min = t[0];
    r->t_max = t[o->repeat - 1];
    r->bytes = written_bytes(o->dir);
    return CTN_OK;
}

static int run(ctn_ctx *ctx, const bench_opts *o, result *r)
{
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    double t0 = now();
    int rc = build_paper_cable(ctx, o->n, CTN_START_CATENARY, &m);
    r->t_build = now() - t0;
    t0 = now();
    if (!rc) rc = ctn_solve(ctx, m, NULL, &s);
    r->t_solve = now() - t0;
    r->rss_solve = peak_rss_mib();
    if (!rc && !o->no_write) rc = time_writes(ctx, o, m, s, r);
    r->rss_end = peak_rss_mib();
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    return rc;
}

static void print_line(const bench_opts *o, const result *r)
{
    printf("n=%d t_build=%.3f t_solve=%.3f rss_solve_mib=%.1f", o->n, r->t_build, r->t_solve,
           r->rss_solve);
    if (!o->no_write)
        printf(" bytes=%lld t_write=%.3f t_write_min=%.3f t_write_max=%.3f mb_s=%.1f cpu_write=%.3f",
               r->bytes, r->t_write, r->t_min, r->t_max, (double)r->bytes / 1e6 / r->t_write,
               r->cpu_write);
    printf(" rss_end_mib=%.1f\n", r->rss_end);
}

int main(int argc, char **argv)
{
    bench_opts o;
    result r;
    ctn_ctx *ctx = NULL;
    if (parse_args(argc, argv, &o)) return usage();
    memset(&r, 0, sizeof r);
    int rc = ctn_ctx_create(&ctx);
    if (!rc) ctn_ctx_set_threads(ctx, 0);           /* as the catena command: no limit */
    if (!rc) rc = run(ctx, &o, &r);
    if (rc) fprintf(stderr, "bench_write: %s: %s\n", ctn_strerror(rc), ctn_ctx_message(ctx));
    else print_line(&o, &r);
    if (!o.no_write && !o.keep) remove_files(o.dir);
    ctn_ctx_destroy(&ctx);
    return rc ? 2 : 0;
}
