/* corpus_runner: the catena command run many times in one process (tests/cli/errors.sh in
 * a sanitizer build).
 *
 * A sanitized process costs ~0.1 s to start and to leak-check at exit, and the error
 * corpus runs the command ~1500 times: most of the sanitizer build's test time went to
 * process starts. This program starts once and runs the command (app/dispatch.c, the
 * code the catena program runs) once per request, each with its own stdout and stderr
 * files and its exit code, and after each a leak check whose report (if any) lands in
 * that request's stderr, where the script looks for sanitizer reports as before. A crash
 * ends the runner; the script sees the pipe close, reports the case, starts a new one.
 *
 * Requests on fd 3, each a run of NUL-terminated fields: OUT, ERR, N, then the N
 * arguments after the program's name ("solve", MODEL, ...). OUT and ERR are truncated
 * or created. Replies on fd 4: "CODE ENDED\n", the exit code and 1 when the runner ends
 * after this run (a leak was found: the leaked blocks would be reported again after
 * every later run, so the caller starts a new runner), else 0. The runner's own stdin is
 * the caller's (the script gives /dev/null). Exit 0 at the end of the requests, 1 on a
 * malformed request.
 *
 * What differs from the program (main.c): nothing of the command; the process start-up
 * (signals, the heap settings, MPI) is done once, and stdout is flushed, not closed,
 * after each run, so a write error on it is found by the flush. The library holds no
 * process-wide state, so runs cannot see each other: a test of that claim too. */
#include "app.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define CTN_RUNNER_LSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CTN_RUNNER_LSAN 1
#endif
#endif
#ifdef CTN_RUNNER_LSAN
int __lsan_do_recoverable_leak_check(void);
#endif

#define REQ_FD 3
#define REPLY_FD 4
#define MAX_ARGS 64

/* One NUL-terminated field from fd into a new string; NULL at the end of input or on
 * an error (*eof set at a clean end before the field's first byte). */
static char *field(int fd, int *eof)
{
    size_t n = 0, cap = 64;
    char *s = malloc(cap);
    if (!s) return NULL;
    for (;;) {
        char c;
        ssize_t r = read(fd, &c, 1);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) {
            *eof = r == 0 && n == 0;
            free(s);
            return NULL;
        }
        if (n + 1 >= cap) {
            char *t = realloc(s, cap *= 2);
            if (!t) {
                free(s);
                return NULL;
            }
            s = t;
        }
        s[n++] = c;
        if (!c) return s;
    }
}

/* fd onto target (1 or 2) from the file path, truncated; 0 or -1. */
static int redirect(const char *path, int target)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) return -1;
    int rc = dup2(fd, target) < 0 ? -1 : 0;
    close(fd);
    return rc;
}

/* Run the command once with argv[1..argc-1]; its exit code as main.c would give it.
 * *leaked: the leak check after it found a leak (reported on the run's stderr). */
static int run(int argc, char **argv, int *leaked)
{
    int code = ctn_app_dispatch(argc, argv);
    if (code != CTN_EXIT_IO && ctn_app_flush(stdout, "stdout")) code = CTN_EXIT_IO;
    fflush(stdout);
    clearerr(stdout);
#ifdef CTN_RUNNER_LSAN
    fflush(stderr);
    *leaked = __lsan_do_recoverable_leak_check() != 0;   /* a report goes to this run's stderr */
#else
    *leaked = 0;
#endif
    fflush(stderr);
    return code;
}

static int serve(void)
{
    int saved_out = dup(1), saved_err = dup(2);
    if (saved_out < 0 || saved_err < 0) return 1;
    for (;;) {
        int eof = 0, argc = 0, bad = 0, code = -1, leaked = 0;
        char *out = field(REQ_FD, &eof), *err = NULL, *count = NULL;
        char *argv[MAX_ARGS + 2] = { "catena" };
        if (!out) return eof ? 0 : 1;
        err = field(REQ_FD, &eof);
        count = err ? field(REQ_FD, &eof) : NULL;
        long n = count ? strtol(count, NULL, 10) : -1;
        if (n < 0 || n > MAX_ARGS) bad = 1;
        for (argc = 1; !bad && argc <= n; argc++)
            if (!(argv[argc] = field(REQ_FD, &eof))) bad = 1;
        if (!bad) {
            fflush(stdout);
            fflush(stderr);
            if (redirect(out, 1) || redirect(err, 2)) {
                code = CTN_EXIT_IO;
            } else {
                argv[argc] = NULL;
                code = run(argc, argv, &leaked);
            }
            dup2(saved_out, 1);
            dup2(saved_err, 2);
            dprintf(REPLY_FD, "%d %d\n", code, leaked);
            if (leaked) _exit(0);              /* not the exit-time check: reported */
        }
        for (int i = 1; i < argc && argv[i]; i++) free(argv[i]);
        free(out);
        free(err);
        free(count);
        if (bad) return 1;
    }
}

int main(void)
{
    ctn_app_signals_install();
    ctn_process_heap();
    int argc = 1;
    char *args[] = { "corpus_runner", NULL }, **argv = args;
    if (ctn_app_mpi_init(&argc, &argv)) return 1;
    return ctn_app_mpi_finalize(serve());
}
