/* catena: command-line entry, dispatch to sub-commands (the table is in help.c). */
#include "app.h"

#include <SuiteSparse_config.h>
#include <errno.h>
#include <stdlib.h>
#include <unistd.h>
#include <string.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

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


static int dispatch(int argc, char **argv)
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

/* Whatever the command printed must reach stdout: a write error the command did not
 * report itself (it exits CTN_EXIT_IO when it did) makes the exit code CTN_EXIT_IO. */
/* Large arrays (patterns, orderings' workspace, factors, result vectors) from the heap,
 * and kept by the process after free instead of returned to the system: glibc maps every
 * block above 32 MiB afresh and unmaps it on free, so each symbolic analysis of a big
 * net paid its arrays' page faults again (measured on the K = 400 net: the orderings'
 * analyses 3.6 s of CPU with fresh mappings, 1.7 s without). The process, not the
 * library, owns this choice. */
static void keep_heap(void)
{
#ifdef M_MMAP_MAX
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);           /* never trim */
#endif
}

/* CHOLMOD's blocks (the factor, its analysis's and factorization's work arrays) advised
 * for transparent huge pages as the library's own are (ctn_mem_huge): on the VM of
 * bench/RESULTS.md a page fault costs 16-32 us, and the K = 1000 net's 5.7 GB were 1.1
 * million of them. SuiteSparse's allocator is process-wide: the process, not the
 * library, sets it. */
static void *huge_malloc(size_t n)
{
    void *p = malloc(n);
    ctn_mem_huge(p, n);
    return p;
}

static void *huge_calloc(size_t n, size_t size)
{
    void *p = calloc(n, size);
    if (p) ctn_mem_huge(p, n * size);        /* calloc checked n * size */
    return p;
}

static void *huge_realloc(void *p, size_t n)
{
    void *q = realloc(p, n);
    ctn_mem_huge(q, n);
    return q;
}

static void huge_pages(void)
{
    SuiteSparse_config.malloc_func = huge_malloc;
    SuiteSparse_config.calloc_func = huge_calloc;
    SuiteSparse_config.realloc_func = huge_realloc;
    SuiteSparse_config.free_func = free;
}

/* The whole heap advised for huge pages, the small blocks too: with keep_heap's settings
 * every block comes from the heap and the heap is never trimmed, so a block as large as
 * the system lends (the machine's memory, or half, ...), advised and freed at once,
 * leaves the heap's address range reserved (nothing is touched) and advised for what
 * follows. Not under a memory checker
 * (AddressSanitizer's and valgrind's allocators are not glibc's heap). */
#define CTN_HUGE_HEAP_MIN ((size_t)256 << 20)
static void huge_heap(void)
{
#if defined(M_MMAP_MAX) && !defined(__SANITIZE_ADDRESS__)
    const char *pre = getenv("LD_PRELOAD");
    if (pre && strstr(pre, "vgpreload")) return;
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page <= 0) return;
    size_t want = (size_t)pages * (size_t)page, cap = (size_t)64 << 30, n = want < cap ? want : cap;
    void *p = malloc(n);
    while (!p && n / 2 >= CTN_HUGE_HEAP_MIN) p = malloc(n /= 2);    /* what the system lends */
    ctn_mem_huge(p, n);
    free(p);
#endif
}

int main(int argc, char **argv)
{
    ctn_app_signals_install();
    keep_heap();
    huge_pages();
    huge_heap();
    int code = ctn_app_mpi_init(&argc, &argv);
    if (!code) code = dispatch(argc, argv);
    if (code == CTN_EXIT_IO) {
        fclose(stdout);
        return ctn_app_mpi_finalize(code);
    }
    if (ctn_app_flush(stdout, "stdout")) return ctn_app_mpi_finalize(CTN_EXIT_IO);
    errno = 0;
    if (fclose(stdout)) {
        fprintf(stderr, "catena: stdout: close failed: %s\n", errno ? strerror(errno) : "I/O error");
        code = CTN_EXIT_IO;
    }
    return ctn_app_mpi_finalize(code);
}
