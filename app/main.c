/* catena: command-line entry, dispatch to sub-commands. */
#include "app.h"

#include <errno.h>
#include <string.h>

static void usage(FILE *f)
{
    fprintf(f,
            "usage: catena COMMAND [options]\n"
            "\n"
            "commands:\n"
            "  solve MODEL [--json] [-o DIR] [-q]   solve a .cable model (docs/format.md)\n"
            "  compare MODEL [--json] [-o DIR] [-q] FEA of a single span against the closed forms\n"
            "  study MODEL... [options]              FEA against the catenary over cable lengths\n"
            "  convergence MODEL [--n LIST] [...]    mesh convergence to the elastic catenary\n"
            "  help                                  this text\n"
            "\n"
            "exit codes: 0 converged, 1 usage, 2 bad model, 3 not converged, 4 I/O error\n");
}

int ctn_app_fail(ctn_ctx *ctx, int status)
{
    const char *msg = ctn_ctx_message(ctx);
    fprintf(stderr, "catena: %s\n", *msg ? msg : ctn_strerror(status));
    if (status == CTN_ERR_MODEL) return CTN_EXIT_MODEL;
    return CTN_EXIT_IO;
}

int ctn_app_flush(FILE *f, const char *name)
{
    errno = 0;
    int failed = fflush(f) != 0, err = errno;
    if (!failed && !ferror(f)) return CTN_EXIT_OK;
    fprintf(stderr, "catena: %s: write error: %s\n", name, err ? strerror(err) : "I/O error");
    return CTN_EXIT_IO;
}

static int dispatch(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return CTN_EXIT_USAGE;
    }
    if (!strcmp(argv[1], "solve")) return ctn_cmd_solve(argc - 1, argv + 1);
    if (!strcmp(argv[1], "compare")) return ctn_cmd_compare(argc - 1, argv + 1);
    if (!strcmp(argv[1], "study")) return ctn_cmd_study(argc - 1, argv + 1);
    if (!strcmp(argv[1], "convergence")) return ctn_cmd_convergence(argc - 1, argv + 1);
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        usage(stdout);
        return CTN_EXIT_OK;
    }
    fprintf(stderr, "catena: unknown command '%s'\n", argv[1]);
    usage(stderr);
    return CTN_EXIT_USAGE;
}

/* Whatever the command printed must reach stdout: a write error the command did not
 * report itself (it exits CTN_EXIT_IO when it did) makes the exit code CTN_EXIT_IO. */
int main(int argc, char **argv)
{
    int code = dispatch(argc, argv);
    if (code == CTN_EXIT_IO) {
        fclose(stdout);
        return code;
    }
    if (ctn_app_flush(stdout, "stdout")) return CTN_EXIT_IO;
    errno = 0;
    if (fclose(stdout)) {
        fprintf(stderr, "catena: stdout: close failed: %s\n", errno ? strerror(errno) : "I/O error");
        return CTN_EXIT_IO;
    }
    return code;
}
