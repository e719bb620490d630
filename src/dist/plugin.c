/* Loading the MPI module (plugin.h). It is looked for beside the code that loads it
 * (the catena command in its build or bin directory, or libcatena.so), then in the
 * library directory of an installation beside that (../lib), then by the dynamic
 * loader's own search (LD_LIBRARY_PATH, the system's directories). */
#define _GNU_SOURCE 1
#include "dist/plugin.h"

#include "core/ctx.h"
#include "linalg/linsolve.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

#ifndef CTN_MPI_PLUGIN_LIBDIR
#define CTN_MPI_PLUGIN_LIBDIR "lib"
#endif

int ctn_mpi_module_built(void)
{
#ifdef CTN_MPI_PLUGIN
    return 1;
#else
    return 0;
#endif
}

/* dir of the object holding this code, into buf ("" if unknown) */
static void own_dir(char *buf, size_t size)
{
    Dl_info info;
    buf[0] = '\0';
    if (!dladdr((void *)own_dir, &info) || !info.dli_fname) return;
    const char *slash = strrchr(info.dli_fname, '/');
    if (!slash) return;
    size_t n = (size_t)(slash - info.dli_fname);
    if (n + 1 > size) return;
    memcpy(buf, info.dli_fname, n);
    buf[n] = '\0';
}

static void *try_open(const char *path, char *why, size_t size)
{
    void *dl = dlopen(path, RTLD_NOW | RTLD_GLOBAL | RTLD_NODELETE);
    if (!dl && !why[0]) {
        const char *e = dlerror();
        snprintf(why, size, "%.500s", e ? e : path);
    }
    return dl;
}

int ctn_mpi_module_open(ctn_ctx *ctx, ctn_mpi_module *m)
{
    m->dl = NULL;
    m->ops = NULL;
    if (!ctn_mpi_module_built())
        return ctn_error(ctx, CTN_ERR_INVALID, "catena was built without MPI and PETSc (docs/parallel.md)");
    char dir[4096], path[4200], why[512] = "";
    own_dir(dir, sizeof dir);
    if (dir[0]) {
        snprintf(path, sizeof path, "%s/%s", dir, CTN_MPI_PLUGIN_FILE);
        m->dl = try_open(path, why, sizeof why);
        if (!m->dl) {
            snprintf(path, sizeof path, "%s/../%s/%s", dir, CTN_MPI_PLUGIN_LIBDIR, CTN_MPI_PLUGIN_FILE);
            m->dl = try_open(path, why, sizeof why);
        }
    }
    if (!m->dl) m->dl = try_open(CTN_MPI_PLUGIN_FILE, why, sizeof why);
    if (!m->dl) return ctn_error(ctx, CTN_ERR_INVALID, "the MPI module %s cannot be loaded: %s", CTN_MPI_PLUGIN_FILE, why);
    ctn_mpi_plugin_entry_fn entry;
    void *sym = dlsym(m->dl, CTN_MPI_PLUGIN_ENTRY);
    memcpy(&entry, &sym, sizeof entry);          /* object pointer to function pointer */
    m->ops = entry ? entry(CTN_MPI_PLUGIN_ABI, sizeof(ctn_ctx), sizeof(ctn_linsolve_ops)) : NULL;
    if (!m->ops) {
        ctn_mpi_module_close(m);
        return ctn_error(ctx, CTN_ERR_INVALID, "the MPI module %s is of another catena build", CTN_MPI_PLUGIN_FILE);
    }
    return CTN_OK;
}

void ctn_mpi_module_close(ctn_mpi_module *m)
{
    if (m->dl) dlclose(m->dl);      /* RTLD_NODELETE: the code stays mapped */
    m->dl = NULL;
    m->ops = NULL;
}
