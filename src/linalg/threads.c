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
#include <string.h>

typedef int (*get_fn)(void);
typedef void (*set_fn)(int);

static void *symbol(const char *name) { return dlsym(RTLD_DEFAULT, name); }

/* n threads: the calling thread's OpenMP count (which OpenBLAS follows), and for n = 1
 * no active parallel region at all (max-active-levels 0): CHOLMOD's own loops ask for
 * a fixed 4 threads whatever the count says, and on a busy machine their barriers cost
 * more than the loops. */
void ctn_threads_push(int n, ctn_threads_saved *old)
{
    get_fn max = (get_fn)(uintptr_t)symbol("omp_get_max_threads");
    set_fn set = (set_fn)(uintptr_t)symbol("omp_set_num_threads");
    get_fn levels = (get_fn)(uintptr_t)symbol("omp_get_max_active_levels");
    set_fn set_levels = (set_fn)(uintptr_t)symbol("omp_set_max_active_levels");
    old->threads = max && set ? max() : 0;
    old->levels = levels && set_levels ? levels() : -1;
    if (old->threads && n > 0) set(n);
    if (old->levels >= 0 && n == 1) set_levels(0);
}

void ctn_threads_pop(const ctn_threads_saved *old)
{
    set_fn set = (set_fn)(uintptr_t)symbol("omp_set_num_threads");
    set_fn set_levels = (set_fn)(uintptr_t)symbol("omp_set_max_active_levels");
    if (old->threads && set) set(old->threads);
    if (old->levels >= 0 && set_levels) set_levels(old->levels);
}

/* "OpenBLAS 0.3.21 (OpenMP)" from OpenBLAS's own configuration string, or the file the
 * BLAS's dgemm comes from ("reference BLAS (libblas.so.3)"). */
void ctn_blas_name(char *buf, size_t size)
{
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
