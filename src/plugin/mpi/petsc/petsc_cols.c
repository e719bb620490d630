/* A matrix distributed by columns (petsc.h, linsolve.h's create_cols): a process holds
 * columns c0 .. c1 - 1 of the upper triangle, assembled by its own elements, and owns
 * the same rows of the PETSc matrix (MATSBAIJ: the upper triangle by rows). Column j's
 * entry (i, j), i <= j, is row i's: this process's when i >= c0, else a process of a
 * lower rank's, reached through PETSc's stash at the assembly (MatSetValues of
 * off-process rows). No process holds the whole pattern or the whole tangent. */
#include "plugin/mpi/petsc/petsc.h"

/* The preallocation of the owned rows: d[i - c0] the entries of row i in this process's
 * columns (the diagonal block: every one of them is its upper triangle's), o[i - c0]
 * those in the later ranks' columns (counted there and summed here, MPI_Reduce_scatter). */
int ctn_petsc_cols_count(ctn_ctx *ctx, MPI_Comm comm, const ctn_pattern *p, PetscInt n, PetscInt c0, PetscInt *d,
                         PetscInt *o)
{
    int size = 1, rc = CTN_OK;
    MPI_Comm_size(comm, &size);
    PetscInt m = (PetscInt)p->n;
    int *below = ctn_calloc(ctx, (size_t)(c0 > 0 ? c0 : 1), sizeof(int));
    int *mine = ctn_calloc(ctx, (size_t)(m > 0 ? m : 1), sizeof(int));
    int *recv = ctn_calloc(ctx, (size_t)size, sizeof(int));
    if (!below || !mine || !recv) {
        rc = CTN_ERR_NOMEM;
        goto done;
    }
    for (PetscInt j = 0; j < m; j++) d[j] = 0;
    for (PetscInt j = 0; j < m; j++)
        for (int k = p->colptr[j]; k < p->colptr[j + 1]; k++) {
            PetscInt i = p->rowind[k];
            if (i >= c0) d[i - c0]++;
            else below[i]++;
        }
    /* the counts of rows 0 .. n - 1, every process's share summed onto its owner */
    int count = (int)m;
    if (MPI_Allgather(&count, 1, MPI_INT, recv, 1, MPI_INT, comm) != MPI_SUCCESS) {
        rc = ctn_error(ctx, CTN_ERR_IO, "PETSc: the preallocation's exchange failed");
        goto done;
    }
    int *all = ctn_calloc(ctx, (size_t)(n > 0 ? n : 1), sizeof(int));
    if (!all) {
        rc = CTN_ERR_NOMEM;
        goto done;
    }
    for (PetscInt i = 0; i < c0; i++) all[i] = below[i];
    if (MPI_Reduce_scatter(all, mine, recv, MPI_INT, MPI_SUM, comm) != MPI_SUCCESS)
        rc = ctn_error(ctx, CTN_ERR_IO, "PETSc: the preallocation's exchange failed");
    ctn_free(all);
    for (PetscInt j = 0; !rc && j < m; j++) o[j] = mine[j];
done:
    ctn_free(below);
    ctn_free(mine);
    ctn_free(recv);
    return rc;
}

/* The owned columns' values, + shift on the diagonal (each column's last entry), into
 * A (INSERT_VALUES: every entry has one column, so one process); rows and vals: scratch
 * of the longest column. */
PetscErrorCode ctn_petsc_cols_set(Mat A, const ctn_pattern *p, PetscInt c0, const double *Kx, double shift,
                                  PetscInt *rows, PetscScalar *vals)
{
    for (size_t j = 0; j < p->n; j++) {
        int k0 = p->colptr[j], len = p->colptr[j + 1] - k0;
        if (!len) continue;
        for (int t = 0; t < len; t++) {
            rows[t] = p->rowind[k0 + t];
            vals[t] = Kx[k0 + t];
        }
        vals[len - 1] += shift;
        PetscInt col = c0 + (PetscInt)j;
        PetscErrorCode e = MatSetValues(A, len, rows, 1, &col, vals, INSERT_VALUES);
        if (e) return e;
    }
    return 0;
}
