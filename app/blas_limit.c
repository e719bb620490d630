/* The BLAS under an address-space limit (`ulimit -v`; issue 28, item 6).
 *
 * Debian's OpenBLAS (0.3.21, libopenblas0-openmp) reserves a 128 MiB buffer for each of
 * its threads in its library constructor, before main, and when the allocation fails it
 * retries forever: under `ulimit -v 300000` the program spun at 100 % CPU before it had
 * read a byte. Its thread count there is OpenMP's default (OMP_NUM_THREADS, else the
 * CPUs this process may run on).
 *
 * The executable's pre-initialisation array runs before any shared library's
 * constructor (ELF DT_PREINIT_ARRAY), so catena looks at the limit first: if the address
 * space left cannot hold a buffer per thread and a margin, it runs itself again with
 * OMP_NUM_THREADS=1 (one buffer; the environment cannot be changed in place this early)
 * and catena's context then runs one thread (so the BLAS never grows a second buffer);
 * if even one buffer does not fit, it ends at once with exit 4 and a message naming the
 * limit. Without a limit (the usual
 * case) nothing is done. This is the program's own start-up, not the library's: a
 * program that links libcatena decides for itself. */
#define _GNU_SOURCE                      /* sched_getaffinity, CPU_COUNT */
#include "app.h"

#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#define CTN_BLAS_BUFFER (((size_t)128 << 20) + 4096)   /* one thread's, measured */
#define CTN_BLAS_MARGIN ((size_t)8 << 20)              /* what a small run needs beside */
#define CTN_CAPPED "CATENA_BLAS_ONE_THREAD"            /* set by the re-execution below */

static int capped;   /* the pre-initialisation asked for one thread */

/* Whether n bytes of address space are free now (reserved, nothing committed). */
static int room_for(size_t n)
{
    void *p = mmap(NULL, n, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) return 0;
    munmap(p, n);
    return 1;
}

/* The value of NAME in envp (the C library's environment is not set up yet when the
 * pre-initialisation runs: getenv and setenv cannot be used), or NULL. */
static const char *env_of(char **envp, const char *name)
{
    size_t n = strlen(name);
    for (char **e = envp; e && *e; e++)
        if (!strncmp(*e, name, n) && (*e)[n] == '=') return *e + n + 1;
    return NULL;
}

/* OpenMP's default thread count, as the BLAS will read it. */
static int default_threads(char **envp)
{
    const char *v = env_of(envp, "OMP_NUM_THREADS");
    if (v && *v) {
        long n = strtol(v, NULL, 10);
        if (n > 0) return n > 1024 ? 1024 : (int)n;
    }
    cpu_set_t set;
    if (!sched_getaffinity(0, sizeof set, &set) && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

static void say(const char *s)
{
    size_t n = strlen(s);
    while (n > 0) {
        ssize_t k = write(2, s, n);
        if (k <= 0) return;
        s += k;
        n -= (size_t)k;
    }
}

/* Run this program again with OMP_NUM_THREADS=1 (and the marker that says so) in its
 * environment: the only way to give the BLAS's constructor a thread count before it
 * runs. Returns only if the exec failed. */
static void again_with_one_thread(char **argv, char **envp)
{
    size_t n = 0;
    while (envp && envp[n]) n++;
    char **env = calloc(n + 3, sizeof *env);
    if (!env) return;
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (strncmp(envp[i], "OMP_NUM_THREADS=", 16)) env[k++] = envp[i];
    env[k++] = "OMP_NUM_THREADS=1";
    env[k++] = CTN_CAPPED "=1";
    env[k] = NULL;
    execve("/proc/self/exe", argv, env);
    free(env);
}

static void before_libraries(int argc, char **argv, char **envp)
{
    (void)argc;
    struct rlimit r;
    if (getrlimit(RLIMIT_AS, &r) || r.rlim_cur == RLIM_INFINITY) return;
    int t = default_threads(envp);
    if (t == 1 && env_of(envp, CTN_CAPPED)) capped = 1;
    if (room_for((size_t)t * CTN_BLAS_BUFFER + CTN_BLAS_MARGIN)) return;
    if (t > 1 && room_for(CTN_BLAS_BUFFER + CTN_BLAS_MARGIN)) again_with_one_thread(argv, envp);
    char msg[320];
    snprintf(msg, sizeof msg,
             "catena: the address-space limit (ulimit -v %llu) leaves too little to start: the BLAS library "
             "reserves %zu MiB per thread when it loads, and catena needs %zu MiB beside; raise the limit by "
             "at least %zu MiB\n",
             (unsigned long long)(r.rlim_cur >> 10), CTN_BLAS_BUFFER >> 20, CTN_BLAS_MARGIN >> 20,
             (CTN_BLAS_BUFFER + CTN_BLAS_MARGIN + ((size_t)1 << 20) - 1) >> 20);
    say(msg);
    _exit(CTN_EXIT_IO);
}

__attribute__((section(".preinit_array"), used))
static void (*const ctn_app_preinit)(int, char **, char **) = before_libraries;

int ctn_app_blas_capped(void) { return capped; }
