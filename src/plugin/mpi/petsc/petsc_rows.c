/* The owned rows of a symmetric pattern (upper triangle, compressed columns) as the
 * compressed rows PETSc takes (petsc.h). Columns are visited in order: a row's entries
 * below the diagonal come with its own column (rows ascending, the diagonal last), the
 * ones right of it with the later columns, so every row's columns come out sorted. */
#include "plugin/mpi/petsc/petsc.h"

static int owned(const ctn_petsc_rows *r, PetscInt i) { return i >= r->lo && i < r->hi; }

/* visit(r, row, col, slot) for every stored entry of the owned rows, in row-sorted order */
static void walk(const ctn_pattern *p, ctn_petsc_rows *r, int full, size_t *count, int fill)
{
    for (size_t j = 0; j < p->n; j++)
        for (int k = p->colptr[j]; k < p->colptr[j + 1]; k++) {
            PetscInt i = p->rowind[k], jj = (PetscInt)j;
            PetscInt rows[2] = { i, jj }, cols[2] = { jj, i };
            int n = full && i != jj ? 2 : 1;
            for (int t = 0; t < n; t++) {
                if (!owned(r, rows[t])) continue;
                size_t row = (size_t)(rows[t] - r->lo);
                if (fill) {
                    size_t at = (size_t)r->ptr[row] + count[row]++;
                    r->col[at] = cols[t];
                    r->slot[at] = (size_t)k;
                } else count[row]++;
            }
        }
}

int ctn_petsc_rows_build(ctn_ctx *ctx, const ctn_pattern *p, PetscInt lo, PetscInt hi, int full, ctn_petsc_rows *r)
{
    size_t m = (size_t)(hi - lo);
    r->lo = lo;
    r->hi = hi;
    r->col = NULL;
    r->slot = NULL;
    r->val = NULL;
    r->ptr = ctn_calloc(ctx, m + 1, sizeof(PetscInt));
    size_t *count = ctn_calloc(ctx, m ? m : 1, sizeof(size_t));
    if (!r->ptr || !count) goto fail;
    walk(p, r, full, count, 0);
    for (size_t i = 0; i < m; i++) r->ptr[i + 1] = r->ptr[i] + (PetscInt)count[i];
    size_t nnz = (size_t)r->ptr[m];
    r->col = ctn_malloc(ctx, nnz ? nnz : 1, sizeof(PetscInt));
    r->slot = ctn_malloc(ctx, nnz ? nnz : 1, sizeof(size_t));
    r->val = ctn_calloc(ctx, nnz ? nnz : 1, sizeof(PetscScalar));
    if (!r->col || !r->slot || !r->val) goto fail;
    for (size_t i = 0; i < m; i++) count[i] = 0;
    walk(p, r, full, count, 1);
    ctn_free(count);
    return CTN_OK;
fail:
    ctn_free(count);
    ctn_petsc_rows_free(r);
    return CTN_ERR_NOMEM;
}

void ctn_petsc_rows_free(ctn_petsc_rows *r)
{
    ctn_free(r->ptr);
    ctn_free(r->col);
    ctn_free(r->slot);
    ctn_free(r->val);
    r->ptr = r->col = NULL;
    r->slot = NULL;
    r->val = NULL;
}

void ctn_petsc_rows_fill(ctn_petsc_rows *r, const double *Kx, double shift)
{
    for (PetscInt i = r->lo; i < r->hi; i++)
        for (PetscInt k = r->ptr[i - r->lo]; k < r->ptr[i - r->lo + 1]; k++)
            r->val[k] = Kx[r->slot[k]] + (r->col[k] == i ? shift : 0.0);
}
