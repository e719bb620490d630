/* Internal: the MPI engine as a plugin. PETSc and MPI live in a module of their own,
 * libcatena_mpi.so (src/plugin/mpi/), which the library loads only when a caller asks
 * for a parallel analysis (ctn_parallel_create) and the catena command only under
 * mpirun or with --petsc. A program that never asks maps none of PETSc's and MPI's
 * hundred libraries (the command starts in ~10 ms instead of ~70 ms) and needs none of
 * them installed.
 *
 * The module is built from the same sources as the library it serves, so it works on the
 * library's structures directly (the context, its communicator, the linear solver ops);
 * its entry checks the ABI number and the sizes of those structures and refuses a module
 * of another build. It is opened with RTLD_NODELETE: PETSc and MPI register handlers
 * that must outlive any close. */
#ifndef CTN_DIST_PLUGIN_H
#define CTN_DIST_PLUGIN_H

#include "catena/core.h"

#include <stddef.h>

#define CTN_MPI_PLUGIN_ABI 3      /* 2: ctn_comm_ops.eigen (SLEPc); 3: allgather, create_cols */
#define CTN_MPI_PLUGIN_ENTRY "ctn_mpi_plugin_entry"
#define CTN_MPI_PLUGIN_FILE "libcatena_mpi.so"

struct ctn_linsolve_ops;

typedef struct ctn_mpi_plugin {
    int abi;                   /* CTN_MPI_PLUGIN_ABI */
    /* A communicator on ctx: a duplicate of *mpi_comm (NULL: MPI_COMM_WORLD), set as
     * ctx's (the former one put back by destroy); *impl its handle. MPI must be
     * initialised by the caller (else CTN_ERR_INVALID, message in ctx). */
    int (*create)(ctn_ctx *ctx, const void *mpi_comm, void **impl);
    int (*attach)(void *impl, ctn_ctx *ctx);
    void (*destroy)(void *impl);
    int (*rank)(const void *impl);
    int (*size)(const void *impl);
    int (*max)(void *impl, int *v);           /* *v <- the largest over the processes */
    /* The process's job, for the catena command: MPI and PETSc initialised with PETSc's
     * options argv[0..argc-1] (argv[0] the program); a failure's text in msg. */
    int (*job_init)(int argc, char **argv, char *msg, size_t size);
    void (*job_finalize)(void);
} ctn_mpi_plugin;

/* The module's one exported symbol: its ops if abi and the sizes of the structures it
 * shares with the library match its own, else NULL. */
typedef const ctn_mpi_plugin *(*ctn_mpi_plugin_entry_fn)(int abi, size_t ctx_size, size_t linsolve_ops_size);

/* A loaded module. */
typedef struct ctn_mpi_module {
    void *dl;
    const ctn_mpi_plugin *ops;
} ctn_mpi_module;

/* 1 if this library was built with its MPI module (it may still be missing at run time). */
int ctn_mpi_module_built(void);
/* Load the module (plugin.c says where it is looked for): CTN_ERR_INVALID with the
 * reason in ctx when it is not built, not found, or of another build. */
int ctn_mpi_module_open(ctn_ctx *ctx, ctn_mpi_module *m);
void ctn_mpi_module_close(ctn_mpi_module *m);

#endif
