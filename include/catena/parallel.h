/*
 * catena/parallel.h - running an analysis over the processes of an MPI job.
 *
 * The library is a guest: the caller initialises MPI (and PETSc, PetscInitialize,
 * before any PETSc linear solver is used) and finalises them after the last context
 * that uses them is destroyed. A communicator is set on a context with
 * ctn_parallel_create; every analysis of that context then runs on its processes: each
 * process reads and assembles the whole model (the model is replicated), the PETSc
 * linear solvers ("petsc": MUMPS, "petsc-ldl", "petsc-cg") factor and solve over the
 * processes, and every process holds the whole solution. With a communicator set and no
 * linear_solver= asked, the static analysis uses "petsc" (the arc-length method
 * "petsc-ldl"). Built without PETSc and MPI (catena --version says which), create
 * returns CTN_ERR_INVALID. docs/parallel.md.
 *
 * MPI and PETSc are not linked into the library: they live in a module,
 * libcatena_mpi.so, loaded by ctn_parallel_create and ctn_parallel_job_init (looked for
 * beside the library's code, in ../lib of an installation, then on the loader's path).
 */
#ifndef CATENA_PARALLEL_H
#define CATENA_PARALLEL_H

#include "catena/core.h"
#include "catena/solve.h"

#include <stddef.h>

CTN_API_BEGIN

typedef struct ctn_parallel ctn_parallel;

/* Set the communicator *mpi_comm (a pointer to an MPI_Comm; NULL: MPI_COMM_WORLD) on
 * ctx: the library works on a duplicate of it. The handle must be destroyed (which puts
 * the context's former communicator back) before ctx and before MPI is finalised.
 * CTN_ERR_INVALID if MPI is not initialised or catena was built without it. */
int ctn_parallel_create(ctn_ctx *ctx, const void *mpi_comm, ctn_parallel **out);
/* Set p's communicator on another context too (which must not outlive p). */
int ctn_parallel_attach(ctn_parallel *p, ctn_ctx *ctx);
/* NULL or *p NULL: no-op; *p set to NULL. */
void ctn_parallel_destroy(ctn_parallel **p);
/* This process's rank and the number of processes (0 and 1 for NULL). */
int ctn_parallel_rank(const ctn_parallel *p);
int ctn_parallel_size(const ctn_parallel *p);
/* *v <- the largest *v over the processes (a collective call; p NULL: unchanged). */
int ctn_parallel_max(ctn_parallel *p, int *v);
/* 1 if this catena was built with PETSc and MPI and its module loads, else 0. */
int ctn_parallel_available(void);

/* For a program that leaves MPI and PETSc to catena (the catena command): initialise
 * both through the module, with PETSc's options argv[0 .. argc-1] (argv[0] the
 * program's name); ctn_parallel_job_finalize finalises them (after every handle is
 * destroyed). CTN_ERR_INVALID (message in ctx) if the module is not there. */
typedef struct ctn_parallel_job ctn_parallel_job;
int ctn_parallel_job_init(ctn_ctx *ctx, int argc, char **argv, ctn_parallel_job **out);
/* NULL or *job NULL: no-op; *job set to NULL. */
void ctn_parallel_job_finalize(ctn_parallel_job **job);

/* The processes a solution was computed on (1 without a communicator). */
int ctn_solution_ranks(const ctn_solution *s);
/* 1 if its static analysis held the tangent by columns over the ranks (each rank
 * assembled and held only its own nodes' columns: a net on MUMPS, docs/parallel.md), 0
 * if every rank held the whole tangent (or one process solved it). */
int ctn_solution_by_columns(const ctn_solution *s);
/* The linear solver of its static analysis as the results name it ("cholmod",
 * "petsc-mumps", "petsc-cg-gamg", ...); "" if none was used. */
const char *ctn_solution_linear_solver(const ctn_solution *s);

CTN_API_END

#endif
