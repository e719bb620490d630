/* Internal, the MPI module (dist/plugin.h): the communicator of an analysis over MPI
 * (comm_mpi.c) and the handle the library's ctn_parallel_create gets through the
 * module's ops. The caller owns MPI: the library never initialises or finalises it
 * (the catena command's job does, job.c). */
#ifndef CTN_PLUGIN_MPI_COMM_MPI_H
#define CTN_PLUGIN_MPI_COMM_MPI_H

#include "dist/comm.h"

#include <mpi.h>
#include <stddef.h>

/* The ops of an MPI communicator ("mpi"). */
extern const ctn_comm_ops ctn_comm_mpi_ops;

/* The MPI communicator behind c: MPI_COMM_SELF for any other (the serial one). */
MPI_Comm ctn_comm_mpi_handle(const ctn_comm *c);

/* The handle's ops (dist/plugin.h's create .. max). */
int ctn_mpi_handle_create(ctn_ctx *ctx, const void *mpi_comm, void **out);
int ctn_mpi_handle_attach(void *h, ctn_ctx *ctx);
void ctn_mpi_handle_destroy(void *h);
int ctn_mpi_handle_rank(const void *h);
int ctn_mpi_handle_size(const void *h);
int ctn_mpi_handle_max(void *h, int *v);

/* The catena command's job (job.c): MPI and PETSc initialised and finalised. */
int ctn_mpi_job_init(int argc, char **argv, char *msg, size_t size);
void ctn_mpi_job_finalize(void);

#endif
