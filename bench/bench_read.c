/* bench_read - reading and setting up a model (issue 10, item 4).
 *
 *   bench_read FILE [--repeat R] [--no-setup]
 *
 * Times ctn_read_file (the file into memory, lines into tokens, directives into the
 * model: numbers, id maps, growth of the arrays) and then ctn_problem_create with the
 * file's own solve options (the DOF map, the sparsity pattern, the scatter map, the
 * ordering and CHOLMOD's symbolic analysis), R times each (default 3), and reports the
 * medians. --no-setup times the reading only. Prints one line of key=value pairs: the
 * file's bytes and lines, the nodes and elements read, wall and CPU seconds (user +
 * system; on a shared machine the CPU time is the steadier figure) of the read and of
 * the setup, MB/s and lines/s of the read, and the peak RSS in MiB. Exit status 0 when it
 * ran, 1 on a usage error, 2 when a library call failed. Make a 1M-line model with
 *   python3 bench/hypar_net.py 500 > net500.cable */
#include "bench_common.h"
#include "assemble/asm.h"
#include "linalg/linsolve.h"
#include "problem/la_options.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#define MAX_REPEAT 99

/* The phases timed, in order. */
enum { READ, VALIDATE, ASSEMBLER, ANALYSIS, NPHASES };
static const char *const phase_names[NPHASES] = { "read", "validate", "asm", "analysis" };

static long long count_lines(const char *path, long long *bytes)
{
    FILE *f = fopen(path, "rb");
    long long n = 0;
    int c, last = '\n';
    *bytes = 0;
    if (!f) return -1;
    while ((c = getc(f)) != EOF) {
        ++*bytes;
        if (c == '\n') n++;
        last = c;
    }
    fclose(f);
    return n + (last != '\n');
}

/* One read, and the setup's steps unless no_setup: the wall and CPU seconds of each
 * phase into wall[], cpu[]; the model's sizes in *nn, *ne. */
static int run_once(const char *path, int no_setup, double *wall, double *cpu, size_t *nn, size_t *ne)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_asm *a = NULL;
    ctn_linsolve *ls = NULL;
    ctn_solve_options opt;
    if (ctn_ctx_create(&ctx)) return 2;
    ctn_ctx_set_threads(ctx, 0);                  /* as the catena command: no limit */
    double t[NPHASES + 1], c[NPHASES + 1];
    t[0] = now(), c[0] = cpu_now();
    int rc = ctn_read_file(ctx, path, &m, &opt);
    t[1] = now(), c[1] = cpu_now();
    if (!rc && !no_setup) rc = ctn_model_validate(m);
    t[2] = now(), c[2] = cpu_now();
    if (!rc && !no_setup) rc = ctn_asm_create(ctx, m, &a);
    t[3] = now(), c[3] = cpu_now();
    if (!rc && !no_setup && a->ndof) {
        ctn_pattern pat = { a->ndof, a->colptr, a->rowind };
        rc = ctn_linsolve_create(ctx, opt.linear_solver ? opt.linear_solver : "cholmod", &pat, ctn_la_ordering_of(opt.ordering), &ls);
    }
    t[4] = now(), c[4] = cpu_now();
    for (int k = 0; k < NPHASES; k++) wall[k] = t[k + 1] - t[k], cpu[k] = c[k + 1] - c[k];
    if (rc) fprintf(stderr, "bench_read: %s\n", ctn_ctx_message(ctx));
    else {
        *nn = ctn_model_node_count(m);
        *ne = ctn_model_element_count(m);
    }
    ctn_linsolve_destroy(&ls);
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return rc ? 2 : 0;
}

int main(int argc, char **argv)
{
    int repeat = 3, no_setup = 0;
    bench_keep_heap();
    if (argc < 2) goto usage;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--no-setup")) no_setup = 1;
        else if (!strcmp(argv[i], "--repeat") && i + 1 < argc && !parse_count(argv[i + 1], 1, MAX_REPEAT, &repeat)) i++;
        else goto usage;
    }
    long long bytes = 0, lines = count_lines(argv[1], &bytes);
    if (lines < 0) {
        fprintf(stderr, "bench_read: %s: cannot open\n", argv[1]);
        return 2;
    }
    double wall[NPHASES][MAX_REPEAT], cpu[NPHASES][MAX_REPEAT];
    size_t nn = 0, ne = 0;
    for (int r = 0; r < repeat; r++) {
        double w[NPHASES], c[NPHASES];
        if (run_once(argv[1], no_setup, w, c, &nn, &ne)) return 2;
        for (int k = 0; k < NPHASES; k++) wall[k][r] = w[k], cpu[k][r] = c[k];
    }
    printf("file=%s bytes=%lld lines=%lld nodes=%zu elements=%zu repeat=%d", argv[1], bytes, lines, nn, ne, repeat);
    double read = median(wall[READ], repeat);
    for (int k = 0; k < (no_setup ? 1 : NPHASES); k++)
        printf(" %s_wall=%.3f %s_cpu=%.3f", phase_names[k], median(wall[k], repeat), phase_names[k], median(cpu[k], repeat));
    printf(" MB_per_s=%.1f Mlines_per_s=%.2f rss_mib=%.0f\n", 1e-6 * (double)bytes / read,
           1e-6 * (double)lines / read, peak_rss_mib());
    return 0;
usage:
    fprintf(stderr, "usage: bench_read FILE [--repeat R] [--no-setup]\n");
    return 1;
}
