/* The MPI job (docs/parallel.md): the process, not the library, initialises MPI and
 * PETSc, when catena runs under mpirun (or is given PETSc options after --petsc), and
 * sets the job's communicator on every context the commands create. Both live in the
 * MPI module (libcatena_mpi.so, catena/parallel.h), loaded only then: a plain run maps none of their
 * libraries. Rank 0 alone prints and writes files: the other ranks' stdout and stderr
 * go to /dev/null (every rank reaches the same result and the same error: the model is
 * replicated), and every rank exits with the largest exit code of the job. */
#include "app.h"

#include <stdlib.h>
#include <string.h>

static struct {
    ctn_parallel_job *mpi;     /* MPI and PETSc, initialised by us */
    ctn_ctx *ctx;              /* owns the communicator's handle */
    ctn_parallel *par;
} job;

static int under_mpirun(void)
{
    return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK");
}

/* argv[k..] after "--petsc" are PETSc's: taken out of argv; their count in *np. */
static int take_petsc(int *argc, char **argv, int *np)
{
    *np = 0;
    for (int i = 1; i < *argc; i++)
        if (!strcmp(argv[i], "--petsc")) {
            *np = *argc - i - 1;
            *argc = i;
            return i;
        }
    return 0;
}

int ctn_app_mpi_init(int *argc, char ***argv)
{
    int np, at = take_petsc(argc, *argv, &np);
    if (!at && !under_mpirun()) return CTN_EXIT_OK;
    if (!ctn_parallel_available()) {
        if (!at) return CTN_EXIT_OK;             /* a serial catena run by mpirun: N copies */
        fprintf(stderr, "catena: --petsc: this catena was built without PETSc and MPI (or its module is missing)\n");
        return CTN_EXIT_USAGE;
    }
    char **pargv = *argv + at, *name = (*argv)[0];
    int pargc = np + 1;
    if (at) pargv[0] = name;                   /* PETSc's argv: the program, its options */
    else pargv = *argv, pargc = 1;
    if (ctn_ctx_create(&job.ctx)) {
        fprintf(stderr, "catena: out of memory\n");
        return CTN_EXIT_IO;
    }
    if (ctn_parallel_job_init(job.ctx, pargc, pargv, &job.mpi) || ctn_parallel_create(job.ctx, NULL, &job.par)) {
        fprintf(stderr, "catena: %s\n", ctn_ctx_message(job.ctx));
        return CTN_EXIT_IO;
    }
    if (ctn_parallel_rank(job.par) > 0 && (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)))
        return CTN_EXIT_IO;
    return CTN_EXIT_OK;
}

int ctn_app_mpi_rank(void) { return job.par ? ctn_parallel_rank(job.par) : 0; }

int ctn_app_mpi_size(void) { return job.par ? ctn_parallel_size(job.par) : 1; }

int ctn_app_mpi_attach(ctn_ctx *ctx) { return job.par ? ctn_parallel_attach(job.par, ctx) : CTN_OK; }

void ctn_app_mpi_report(const ctn_solution *s)
{
    const char *on = getenv("CATENA_MPI_DEBUG");
    if (!job.par || !s || !on || strcmp(on, "1")) return;
    int n = ctn_parallel_size(job.par);
    fprintf(stderr, "catena: mpi: %d rank%s, the tangent %s\n", n, n == 1 ? "" : "s",
            ctn_solution_by_columns(s) ? "by columns" : "whole on every rank");
}

int ctn_app_mpi_finalize(int code)
{
    if (job.par && ctn_parallel_max(job.par, &code)) code = CTN_EXIT_IO;
    ctn_parallel_destroy(&job.par);
    ctn_parallel_job_finalize(&job.mpi);
    ctn_ctx_destroy(&job.ctx);
    return code;
}
