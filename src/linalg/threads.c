/* The threads of the numeric factorization and the BLAS under it.
 *
 * CHOLMOD's supernodal factorization spends its time in the BLAS and in a few OpenMP
 * loops of its own; Debian's OpenBLAS for OpenMP (libopenblas0-openmp, installed by
 * scripts/deps.sh) runs its threads in the same OpenMP pool, so one setting, the OpenMP
 * thread count of the calling thread, sizes both: one threading layer. catena sets it for
 * the duration of each factorization and restores the caller's value afterwards (it is
 * the calling thread's own setting, so nothing else in the process changes).
 *
 * catena does not link the OpenMP runtime or the BLAS itself: both come with CHOLMOD.
 * They are looked up at run time in the loaded process, so that the same library works
 * on a reference BLAS (no threads) or without OpenMP (one thread). */
#define _GNU_SOURCE                      /* RTLD_DEFAULT, dladdr */
#include "linalg/linsolve.h"

#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <pthread.h>
#include <string.h>

typedef int (*get_fn)(void);
typedef void (*set_fn)(int);

static void *symbol(const char *name) { return dlsym(RTLD_DEFAULT, name); }

/* n threads for the calling thread's OpenMP regions (its nthreads ICV, which OpenBLAS
 * follows): the thread's own setting, nothing else in the process changes. */
void ctn_threads_push(int n, ctn_threads_saved *old)
{
    get_fn max = (get_fn)(uintptr_t)symbol("omp_get_max_threads");
    set_fn set = (set_fn)(uintptr_t)symbol("omp_set_num_threads");
    old->threads = max && set ? max() : 0;
    if (old->threads && n > 0) set(n);
}

/* fn(arg) with every OpenMP region it enters limited to n threads, the limit being the
 * calling thread's own. CHOLMOD 3's supernodal factorization has loops of its own that
 * ask for 4 threads through a num_threads clause (CHOLMOD_OMP_NUM_THREADS), which the
 * thread count does not bound: under threads=1 they started threads the caller had not
 * allowed (and on a busy machine their barriers cost more than the loops, commit
 * 7efaa9d); under threads=2, teams of 4 (CHOLMOD's) and of 2 (the BLAS's) in turn made
 * libgomp end and start two threads at each change (1 110 threads for one solve of the
 * K = 100 net). Until now max-active-levels 0 kept them off for n = 1, but libgomp keeps
 * that setting for the whole process. An OpenMP thread limit bounds every team, and
 * within a teams construct it belongs to the thread that entered it: libgomp's entry
 * point of `#pragma omp teams num_teams(1) thread_limit(n)` (GOMP_teams_reg, OpenMP
 * 5.0; LLVM's runtime provides it as well) runs fn on the calling thread with its limit
 * set to n and restores it after. Without it (no OpenMP, or an older runtime) fn runs
 * as it is. */
void ctn_threads_limit(int n, void (*fn)(void *), void *arg)
{
    typedef void (*teams_fn)(void (*)(void *), void *, unsigned, unsigned, unsigned);
    teams_fn teams = (teams_fn)(uintptr_t)symbol("GOMP_teams_reg");
    if (teams && n > 0) teams(fn, arg, 1, (unsigned)n, 0);
    else fn(arg);
}

void ctn_threads_pop(const ctn_threads_saved *old)
{
    set_fn set = (set_fn)(uintptr_t)symbol("omp_set_num_threads");
    if (old->threads && set) set(old->threads);
}

/* "OpenBLAS 0.3.21 (OpenMP)" from OpenBLAS's own configuration string, or the file the
 * BLAS's dgemm comes from ("reference BLAS (libblas.so.3)"). openblas_get_config writes a
 * static buffer of OpenBLAS's at every call: the name is made once in the process
 * (pthread_once) and copied from there, so that solves in several threads do not race. */
static char blas_name[96];
static pthread_once_t blas_once = PTHREAD_ONCE_INIT;
static void blas_name_once(void);

void ctn_blas_name(char *buf, size_t size)
{
    pthread_once(&blas_once, blas_name_once);
    snprintf(buf, size, "%s", blas_name);
}

static void blas_name_once(void)
{
    char *buf = blas_name;
    size_t size = sizeof blas_name;
    typedef char *(*config_fn)(void);
    config_fn config = (config_fn)(uintptr_t)symbol("openblas_get_config");
    get_fn parallel = (get_fn)(uintptr_t)symbol("openblas_get_parallel");
    if (config) {
        char version[32] = "";
        const char *c = config();
        if (c) sscanf(c, "OpenBLAS %31s", version);
        int par = parallel ? parallel() : -1;
        snprintf(buf, size, "OpenBLAS %s (%s)", version, par == 2 ? "OpenMP" : par == 1 ? "pthreads" : par == 0 ? "sequential" : "?");
        return;
    }
    Dl_info info;
    void *gemm = symbol("dgemm_");
    if (gemm && dladdr(gemm, &info) && info.dli_fname) {
        const char *file = strrchr(info.dli_fname, '/');
        const char *kind = strstr(info.dli_fname, "/blas/") ? "reference BLAS" : "BLAS";
        snprintf(buf, size, "%s (%s)", kind, file ? file + 1 : info.dli_fname);
        return;
    }
    snprintf(buf, size, "none");
}
