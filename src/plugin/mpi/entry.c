/* The MPI module's entry (dist/plugin.h): the one symbol libcatena_mpi.so exports. */
#include "core/ctx.h"
#include "dist/plugin.h"
#include "linalg/linsolve.h"
#include "plugin/mpi/comm_mpi.h"

static const ctn_mpi_plugin ops = {
    CTN_MPI_PLUGIN_ABI,
    ctn_mpi_handle_create, ctn_mpi_handle_attach, ctn_mpi_handle_destroy,
    ctn_mpi_handle_rank, ctn_mpi_handle_size, ctn_mpi_handle_max,
    ctn_mpi_job_init, ctn_mpi_job_finalize,
};

__attribute__((visibility("default"))) const ctn_mpi_plugin *ctn_mpi_plugin_entry(int abi, size_t ctx_size,
                                                                                    size_t linsolve_ops_size);

const ctn_mpi_plugin *ctn_mpi_plugin_entry(int abi, size_t ctx_size, size_t linsolve_ops_size)
{
    if (abi != CTN_MPI_PLUGIN_ABI || ctx_size != sizeof(ctn_ctx) || linsolve_ops_size != sizeof(ctn_linsolve_ops))
        return NULL;
    return &ops;
}
