/* Internal: the PETSc linear solvers (petsc_backend.c): the tangent's rows a process
 * owns in a PETSc matrix over the context's communicator (MPI, plugin/mpi/comm_mpi.h; one
 * process without one), factored by MUMPS (KSPPREONLY + PCCHOLESKY) or solved by a
 * Krylov method (CG + GAMG), PETSc options passed through (KSPSetFromOptions). The
 * model is replicated: every process holds the whole pattern and values and passes its
 * owned rows; or, for a net, the tangent is distributed by columns (create_cols,
 * petsc_cols.c: each process its own columns' values). The solution reaches every
 * process whole. The only place that includes
 * PETSc's headers, with comm_mpi.c. */
#ifndef CTN_PLUGIN_MPI_PETSC_H
#define CTN_PLUGIN_MPI_PETSC_H

#include "linalg/linsolve.h"

#include <petscksp.h>

typedef enum ctn_petsc_kind {
    CTN_PETSC_MUMPS = 0,       /* "petsc": LL' semantics: a factor with a non-positive
                                  pivot (MUMPS's inertia) is a failed one, as CHOLMOD's */
    CTN_PETSC_MUMPS_LDL = 1,   /* "petsc-ldl": indefinite, its negative pivots (INFOG(12)) */
    CTN_PETSC_CG = 2,          /* "petsc-cg": CG + GAMG (any KSP/PC by the options) */
    CTN_PETSC_INERTIA = 3      /* "petsc-inertia": petsc-ldl that also counts null pivots
                                  (ICNTL(24), INFOG(28)): the stability check's count */
} ctn_petsc_kind;

/* The owned rows of the pattern as compressed rows (petsc_rows.c): rows [lo, hi) of the
 * upper triangle (SBAIJ) or of the whole symmetric matrix (full, AIJ), columns global
 * and sorted, and for each entry its position in the pattern's values. */
typedef struct ctn_petsc_rows {
    PetscInt lo, hi;
    PetscInt *ptr;             /* hi - lo + 1 */
    PetscInt *col;             /* ptr[hi - lo] */
    size_t *slot;              /* ptr[hi - lo]: index into the pattern's values */
    PetscScalar *val;          /* ptr[hi - lo]: the values passed */
} ctn_petsc_rows;

int ctn_petsc_rows_build(ctn_ctx *ctx, const ctn_pattern *p, PetscInt lo, PetscInt hi, int full, ctn_petsc_rows *r);
void ctn_petsc_rows_free(ctn_petsc_rows *r);
/* r->val <- Kx at the slots, + shift on the diagonal. */
void ctn_petsc_rows_fill(ctn_petsc_rows *r, const double *Kx, double shift);

/* A matrix distributed by columns (petsc_cols.c): p this process's columns c0 .. (p->n
 * of them, row indices global) of the n x n upper triangle. The preallocation of the
 * same rows (d: in this process's columns, o: in later ranks'; p->n each), and the
 * values (+ shift on the diagonal) set into A; rows and vals scratch of the longest
 * column. */
int ctn_petsc_cols_count(ctn_ctx *ctx, MPI_Comm comm, const ctn_pattern *p, PetscInt n, PetscInt c0, PetscInt *d,
                         PetscInt *o);
PetscErrorCode ctn_petsc_cols_set(Mat A, const ctn_pattern *p, PetscInt c0, const double *Kx, double shift,
                                  PetscInt *rows, PetscScalar *vals);

extern const ctn_linsolve_ops ctn_petsc_mumps_ops, ctn_petsc_ldl_ops, ctn_petsc_cg_ops, ctn_petsc_inertia_ops;

#endif
