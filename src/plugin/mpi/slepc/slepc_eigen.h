/* Internal, the MPI module: the modal analysis's eigenproblem on SLEPc (slepc_eigen.c),
 * the communicator's eigen op (dist/comm.h) when the module is built with SLEPc. SLEPc's
 * headers are included by slepc_eigen.c and job.c (SlepcInitialize) only. */
#ifndef CTN_PLUGIN_MPI_SLEPC_EIGEN_H
#define CTN_PLUGIN_MPI_SLEPC_EIGEN_H

#include "linalg/eigen/eigen.h"
#include "linalg/linsolve.h"

#include <mpi.h>

/* The nev (1 <= nev < n) eigenpairs of K x = lambda M x nearest sigma (K and M on the
 * pattern p, every process passing the whole, replicated): lambda[nev] ascending, *vecs a
 * new n x (nev + 1) array (ctn_free) whose first nev columns are the eigenvectors, the
 * same on every process of comm; info's nconv, restarts (Krylov-Schur's) and ops
 * (solves with MUMPS's factor of K - sigma M). CTN_ERR_NOCONV when fewer than nev
 * converged, CTN_ERR_LINALG for a SLEPc or PETSc error (its message in ctx). */
int ctn_slepc_eigen(MPI_Comm comm, ctn_ctx *ctx, const ctn_pattern *p, const double *Kx, const double *Mx, int nev,
                    double sigma, double *lambda, double **vecs, ctn_eigen_info *info);

#endif
