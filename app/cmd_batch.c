/* catena batch LIST -o DIR [-q]: many models over the ranks of an MPI job, each rank
 * solving its share (model i on rank i mod N) serially with CHOLMOD, each model's result
 * set in DIR/NNNNN_NAME/ (docs/parallel.md). Exit code: the largest over the models. */
#include "app.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define CTN_BATCH_LINE 4096

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* one model, serially (a context without the job's communicator); its exit code */
static int solve_one(const char *model, const char *dir)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    if (ctn_app_ctx_create_local(&ctx)) {
        fprintf(stderr, "catena: out of memory\n");
        return CTN_EXIT_IO;
    }
    int rc = ctn_read_file(ctx, model, &m, &opt), code = CTN_EXIT_OK;
    if (!rc) rc = ctn_model_resolve_targets(ctx, m, &opt, NULL);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    if (!rc && ctn_result_check(ctx, m, s)) {
        ctn_app_fail_model(ctx, CTN_ERR_INVALID, model);
        code = CTN_EXIT_NOCONV;
    } else if (!rc && (rc = ctn_write_results(ctx, dir, m, s))) code = ctn_app_fail(ctx, rc);
    else if (rc) code = ctn_app_fail_model(ctx, rc, model);
    if (!code && s) {
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        if (sum.reason != CTN_CONVERGED) {
            fprintf(stderr, "catena: %s: not converged: %s\n", model, ctn_reason_name(sum.reason));
            code = CTN_EXIT_NOCONV;
        }
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return code;
}

int ctn_cmd_batch(int argc, char **argv)
{
    const char *list = NULL, *out = NULL;
    int quiet = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-o") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(argv[i], "-q") || !strcmp(argv[i], "--quiet")) quiet = 1;
        else if (argv[i][0] != '-' && !list) list = argv[i];
        else {
            fprintf(stderr, "catena batch: unexpected argument '%s'\n", argv[i]);
            return CTN_EXIT_USAGE;
        }
    }
    if (!list || !out) {
        fprintf(stderr, "usage: catena batch LIST -o DIR [-q]\n");
        return CTN_EXIT_USAGE;
    }
    FILE *f = fopen(list, "r");
    if (!f) {
        fprintf(stderr, "catena: %s: %s\n", list, strerror(errno));
        return CTN_EXIT_IO;
    }
    if (mkdir(out, 0777) && errno != EEXIST) {
        fprintf(stderr, "catena: %s: %s\n", out, strerror(errno));
        fclose(f);
        return CTN_EXIT_IO;
    }
    char line[CTN_BATCH_LINE], dir[CTN_BATCH_LINE + 64];
    int rank = ctn_app_mpi_rank(), size = ctn_app_mpi_size(), code = CTN_EXIT_OK;
    long n = 0, mine = 0;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = 0;
        char *p = line + strspn(line, " \t");
        if (!*p || *p == '#') continue;
        if (n++ % size != rank) continue;
        snprintf(dir, sizeof dir, "%s/%05ld_%s", out, n - 1, base_name(p));
        char *dot = strrchr(dir, '.');
        if (dot && !strcmp(dot, ".cable")) *dot = 0;
        int c = solve_one(p, dir);
        if (c > code) code = c;
        mine++;
    }
    fclose(f);
    if (!quiet) printf("batch: %ld models over %d rank%s (%ld on rank 0), results in %s/\n", n, size,
                       size == 1 ? "" : "s", mine, out);
    return code;
}
