/* The catena command without its process: dispatch to the sub-commands (the table is in
 * help.c) and the messages of failed calls. main.c runs it once per process;
 * tests/corpus_runner.c runs it once per request, many times in one process. */
#include "app.h"

#include <errno.h>
#include <stdlib.h>
#include <unistd.h>
#include <string.h>

int ctn_app_fail(ctn_ctx *ctx, int status)
{
    const char *msg = ctn_ctx_message(ctx);
    if (status == CTN_ERR_INTERRUPTED) {
        fprintf(stderr, "catena: interrupted; no output was replaced\n");
        return ctn_app_interrupt_code();
    }
    fprintf(stderr, "catena: %s\n", *msg ? msg : ctn_strerror(status));
    if (status == CTN_ERR_MODEL) return CTN_EXIT_MODEL;
    if (status == CTN_ERR_NOCONV) return CTN_EXIT_NOCONV;     /* the eigen-solver */
    return CTN_EXIT_IO;
}

/* catena help [COMMAND] */
static int help(int argc, char **argv)
{
    if (argc < 3) {
        ctn_app_usage(stdout);
        return CTN_EXIT_OK;
    }
    const ctn_app_command *c = ctn_app_command_find(argv[2]);
    if (!c) {
        fprintf(stderr, "catena help: unknown command '%s'\n", argv[2]);
        ctn_app_usage(stderr);
        return CTN_EXIT_USAGE;
    }
    ctn_app_command_help(stdout, c);
    return CTN_EXIT_OK;
}

int ctn_app_fail_model(ctn_ctx *ctx, int status, const char *path)
{
    const char *msg = ctn_ctx_message(ctx);
    size_t n = strlen(path);
    if (status == CTN_ERR_INTERRUPTED || (!strncmp(msg, path, n) && msg[n] == ':')) return ctn_app_fail(ctx, status);
    fprintf(stderr, "catena: %s: %s\n", path, *msg ? msg : ctn_strerror(status));
    if (status == CTN_ERR_MODEL) return CTN_EXIT_MODEL;
    if (status == CTN_ERR_NOCONV) return CTN_EXIT_NOCONV;     /* the eigen-solver */
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

int ctn_app_dispatch(int argc, char **argv)
{
    if (argc < 2) {
        ctn_app_usage(stderr);
        return CTN_EXIT_USAGE;
    }
    const char *name = argv[1];
    if (!strcmp(name, "help") || !strcmp(name, "--help") || !strcmp(name, "-h")) return help(argc, argv);
    if (!strcmp(name, "version") || !strcmp(name, "--version")) {
        printf("catena %s\n", ctn_version());
        return CTN_EXIT_OK;
    }
    const ctn_app_command *c = ctn_app_command_find(name);
    if (!c) {
        fprintf(stderr, "catena: unknown command '%s'\n", name);
        ctn_app_usage(stderr);
        return CTN_EXIT_USAGE;
    }
    if (ctn_app_wants_help(argc - 1, argv + 1)) {
        ctn_app_command_help(stdout, c);
        return CTN_EXIT_OK;
    }
    int code = c->run(argc - 1, argv + 1);
    if (code == CTN_EXIT_USAGE) fprintf(stderr, "catena: 'catena %s --help' lists the options\n", name);
    return code;
}
