/* Internal: DOF map, sparsity pattern of the tangent, element-to-slot scatter map and
 * the one element loop. Built once per model (symbolic), evaluated every iteration
 * without allocation (numeric). */
#ifndef CTN_ASSEMBLE_ASM_H
#define CTN_ASSEMBLE_ASM_H

#include "element/element.h"
#include "model/model.h"

#define CTN_EDOF 6                     /* DOFs of a two-node element */
#define CTN_ESLOTS CTN_EPACKED         /* upper-triangle entries of its 6x6 matrix */

typedef struct ctn_asm {
    const ctn_model *m;
    size_t nn, ne;                     /* nodes, elements */
    size_t ndof;                       /* free DOFs (equations) */
    int *eq;                           /* 3 per node: equation number, -1 if fixed */
    int *dof_node, *dof_dir;           /* per equation: node index and direction */
    int *colptr, *rowind;              /* upper triangle of K, compressed columns, sorted */
    size_t nnz;
    int *slot;                         /* CTN_ESLOTS per element: v >= 0 adds into value v,
                                          v <= -2 assigns value -(v + 2) (the first element
                                          to reach an entry: no zeroing pass), -1: none */
    ctn_cable_props *props;            /* per element */
    unsigned char *tension_only;       /* per element: the material's own flag */
    const ctn_element_ops *ops;
} ctn_asm;

int ctn_asm_create(ctn_ctx *ctx, const ctn_model *m, ctn_asm **out);
void ctn_asm_destroy(ctn_asm **a);

/* Internal forces f (3 per node) and, if Kx != NULL, the tangent's values (nnz, in the
 * pattern's order) at displacements d (3 per node). On CTN_ERR_DOMAIN *bad is the index
 * of an element that collapsed to zero length. */
int ctn_asm_eval(const ctn_asm *a, const double *d, double *f, double *Kx, size_t *bad);
/* The same, with the total strain energy in *U (when U != NULL) from the same pass. */
int ctn_asm_eval_energy(const ctn_asm *a, const double *d, double *f, double *Kx, double *U,
                        size_t *bad);

/* Elements of two-way material in compression at d (0 if one collapsed). */
size_t ctn_asm_count_compressed(const ctn_asm *a, const double *d);
/* on = 1: every element behaves as tension-only (compression cut off); 0: back to the
 * materials' own behaviour. */
void ctn_asm_cut_compression(ctn_asm *a, int on);


/* Reference coordinates X and displacements u of element e's nodes, from d. */
void ctn_asm_gather(const ctn_asm *a, size_t e, const double *d, double *X, double *u);

/* Build steps of ctn_asm_create, one file each (dofmap.c, pattern.c). */
int ctn_asm_number_dofs(ctn_ctx *ctx, ctn_asm *a);
int ctn_asm_element_props(ctn_ctx *ctx, ctn_asm *a);
int ctn_asm_pattern(ctn_ctx *ctx, ctn_asm *a);
int ctn_asm_scatter_map(ctn_ctx *ctx, ctn_asm *a);

/* Local upper-triangle index of the pair (i, j), i <= j < CTN_EDOF. */
static inline int ctn_asm_local_slot(int i, int j)
{
    return ctn_packed_index(i, j);
}

#endif
