/* catena/parallel.h without MPI (a build without PETSc and MPI: comm_mpi.c is not
 * built): no communicator can be set. */
#include "catena/parallel.h"

#include "core/ctx.h"

#ifndef CTN_HAVE_PETSC
int ctn_parallel_create(ctn_ctx *ctx, const void *mpi_comm, ctn_parallel **out)
{
    (void)mpi_comm;
    if (out) *out = NULL;
    return ctn_error(ctx, CTN_ERR_INVALID, "ctn_parallel_create: catena was built without MPI and PETSc");
}

int ctn_parallel_attach(ctn_parallel *p, ctn_ctx *ctx)
{
    (void)p;
    return ctn_error(ctx, CTN_ERR_INVALID, "ctn_parallel_attach: catena was built without MPI and PETSc");
}

void ctn_parallel_destroy(ctn_parallel **p)
{
    if (p) *p = NULL;
}

int ctn_parallel_rank(const ctn_parallel *p)
{
    (void)p;
    return 0;
}

int ctn_parallel_size(const ctn_parallel *p)
{
    (void)p;
    return 1;
}

int ctn_parallel_max(ctn_parallel *p, int *v)
{
    (void)p;
    (void)v;
    return CTN_OK;
}

int ctn_parallel_available(void) { return 0; }
#else
typedef int ctn_parallel_none_unused;      /* the MPI build's are in comm_mpi.c */
#endif
