/* Matrices over a layout (matrix.h). */
#include "dist/matrix.h"

#include "linalg/pcg.h"

void ctn_dmat_symv(const ctn_dmat *A, const double *Ax, const double *x, double *y)
{
    /* one process: the owned columns are the matrix (a distributed product adds the
       contributions of the columns to rows owned elsewhere, through the communicator) */
    ctn_pattern pat = { ctn_layout_owned(A->lay), A->colptr, A->rowind };
    ctn_sym_matvec(&pat, Ax ? Ax : A->x, x, y);
}
