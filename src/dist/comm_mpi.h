/* Internal: the communicator of an analysis over MPI (comm_mpi.c), built only with
 * PETSc and MPI (CTN_HAVE_PETSC). The caller owns MPI: the library never initialises or
 * finalises it; the public entry is ctn_parallel_create (catena/parallel.h). */
#ifndef CTN_DIST_COMM_MPI_H
#define CTN_DIST_COMM_MPI_H

#include "dist/comm.h"

#include <mpi.h>

/* The ops of an MPI communicator ("mpi"). */
extern const ctn_comm_ops ctn_comm_mpi_ops;

/* The MPI communicator behind c: MPI_COMM_SELF for any other (the serial one). */
MPI_Comm ctn_comm_mpi_handle(const ctn_comm *c);

#endif
