/* Internal: a symmetric sparse matrix over a layout (layout.h): the upper triangle of
 * the columns a process owns, in compressed columns whose row indices are local to the
 * layout (the owned entries, then the ghosts). The assembly writes its values (x) in
 * the pattern's order; the linear solvers factor them; a product with a vector reads
 * the vector's ghosts. One process: the whole matrix, the pattern of linalg/. */
#ifndef CTN_DIST_MATRIX_H
#define CTN_DIST_MATRIX_H

#include "dist/layout.h"

typedef struct ctn_dmat {
    const ctn_layout *lay;     /* rows and columns */
    const int *colptr;         /* owned columns + 1 */
    const int *rowind;         /* colptr[owned] local row indices */
    double *x;                 /* values, pattern order */
} ctn_dmat;

/* y = A x over the owned entries (x's ghosts current: ctn_layout_ghosts); with values
 * Ax in place of A's own when Ax is not NULL (a second matrix on the same pattern: the
 * mass of a modal analysis). */
void ctn_dmat_symv(const ctn_dmat *A, const double *Ax, const double *x, double *y);

#endif
