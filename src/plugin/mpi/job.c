/* The catena command's MPI job (comm_mpi.h): MPI and PETSc initialised by the process,
 * not by the library. PETSc's signal handler is left off (SIGINT and SIGTERM are the
 * command's) and options it does not use are not reported. */
#include "plugin/mpi/comm_mpi.h"

#include <petscsys.h>
#include <stdio.h>
#ifdef CTN_HAVE_SLEPC
#include <slepcsys.h>
#endif

int ctn_mpi_job_init(int argc, char **argv, char *msg, size_t size)
{
    PetscOptionsSetValue(NULL, "-no_signal_handler", NULL);
    PetscOptionsSetValue(NULL, "-options_left", "0");
#ifdef CTN_HAVE_SLEPC
    if (SlepcInitialize(&argc, &argv, NULL, NULL)) {     /* PETSc's too */
#else
    if (PetscInitialize(&argc, &argv, NULL, NULL)) {
#endif
        snprintf(msg, size, "PETSc could not be initialised");
        return CTN_ERR_IO;
    }
    return CTN_OK;
}

void ctn_mpi_job_finalize(void)
{
    PetscBool init = PETSC_FALSE;
#ifdef CTN_HAVE_SLEPC
    SlepcInitialized(&init);
    if (init) SlepcFinalize();                           /* PETSc's too */
#endif
    PetscInitialized(&init);
    if (init) PetscFinalize();
}
