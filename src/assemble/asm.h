/* Internal: the assembler. Built once per model (symbolic): the DOF map, the element
 * properties of every family, the sparsity pattern of the tangent (upper triangle,
 * compressed columns, rows sorted) and the element-to-value scatter map. Evaluated every
 * iteration without allocation (numeric) by the one element loop, ctn_asm_loop, which
 * assembly, checks and results all use.
 *
 * Elements are kept in blocks: runs of consecutive elements of one family and node
 * count, within which connectivity, properties and scatter slots are strided. */
#ifndef CTN_ASSEMBLE_ASM_H
#define CTN_ASSEMBLE_ASM_H

#include "assemble/dofmap.h"
#include "element/element.h"

typedef struct ctn_asm_block {
    const ctn_element_ops *ops;
    size_t e0, count;          /* model elements e0 .. e0 + count - 1 */
    int nnodes;                /* nodes per element */
    int nedof;                 /* DOFs per element: nnodes * ops->ndof_node */
    int nslots;                /* packed upper-triangle entries: ctn_packed_size(nedof) */
    size_t props0;             /* byte offset of the block's first element's properties */
    size_t slot0;              /* index of its first element's first slot */
} ctn_asm_block;

typedef struct ctn_asm {
    const ctn_model *m;
    size_t nn, ne;                     /* nodes, elements */
    ctn_dofmap map;
    size_t ndof;                       /* free DOFs (equations) = map.ndof */
    int *colptr, *rowind;              /* upper triangle of K, compressed columns, sorted */
    size_t nnz;
    ctn_asm_block *blocks;
    size_t nblocks;
    unsigned char *props;              /* every element's properties (blocks' props0) */
    int *slot;                         /* per element nslots entries: v >= 0 adds into value
                                          v, v <= -2 assigns value -(v + 2) (the first
                                          element to reach an entry: no zeroing pass), -1:
                                          none (a fixed DOF) */
    int maxdof;                        /* largest nedof over the blocks */
    double *work;                      /* 2 maxdof + 3 nnodes_max + maxslots: eval scratch */
    double kscale;                     /* largest element stiffness scale */
} ctn_asm;

int ctn_asm_create(ctn_ctx *ctx, const ctn_model *m, ctn_asm **out);
void ctn_asm_destroy(ctn_asm **a);

/* What the element loop hands each visitor: element e (model order) of block b, its
 * internal forces fe (nedof) and packed tangent Ke (NULL unless asked for), its state. */
typedef struct ctn_asm_elem {
    size_t e;
    const ctn_asm_block *b;
    const int *nodes;          /* node indices */
    const void *props;         /* its properties */
    const double *fe, *Ke;
    const ctn_elem_state *st;
    const int *slot;           /* its scatter slots */
} ctn_asm_elem;
typedef void (*ctn_asm_visit_fn)(void *data, const ctn_asm *a, const ctn_asm_elem *el);

/* The one element loop: evaluate every element at state d (mode CTN_EVAL_*), with the
 * tangent if with_K, and hand each to visit. Returns 0, or 1 when an element collapsed
 * (its index in *bad; the loop stops there): an outcome, not a status. d NULL: no
 * evaluation, the visitor gets each element's properties and slots (fe, Ke, st NULL),
 * as the mass matrix needs them. */
int ctn_asm_loop(const ctn_asm *a, const double *d, unsigned mode, int with_K,
                 ctn_asm_visit_fn visit, void *data, size_t *bad);

/* Internal forces f (state layout) and, if Kx != NULL, the tangent's values (nnz, in the
 * pattern's order) at d; the total stored energy in *U when U != NULL. 0, or 1 when an
 * element collapsed (index in *bad, may be NULL). */
int ctn_asm_eval(const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx,
                 double *U, size_t *bad);

/* The mass matrix's values (nnz, the tangent's pattern and order): the elements' mass
 * ops, lumped or consistent, and the nodes' point masses on the diagonal (mass.c). */
void ctn_asm_mass(const ctn_asm *a, int lumped, double *Mx);
/* The diagonal of the lumped mass matrix (ndof) and in tot[3] the total mass that moves
 * with the free DOFs in x, y, z; 1 with the index of an element whose mass the model
 * cannot tell (NAN) in *bad. */
int ctn_asm_mass_diag(const ctn_asm *a, double *diag, double tot[3], size_t *bad);
/* r_d^T M r_d for the unit translations r_d of the free DOFs along x, y, z (Mx on the
 * tangent's pattern, upper triangle): the mass that moves with them, which the effective
 * masses of all modes of M sum to. With a consistent M it is less than the lumped
 * total: the part of an element's mass coupled to a fixed node does not move with the
 * free ones. */
void ctn_asm_mass_moving(const ctn_asm *a, const double *Mx, double tot[3]);

/* Flexible members (CTN_ELEM_FLEXIBLE) whose own material takes compression and that are
 * compressed at d (0 if an element collapsed); only those with mask[e] != 0 unless mask is
 * NULL. */
size_t ctn_asm_count_compressed(const ctn_asm *a, const double *d, const unsigned char *mask);

/* Family and properties of element e. */
const ctn_asm_block *ctn_asm_block_of(const ctn_asm *a, size_t e);
const void *ctn_asm_props(const ctn_asm *a, size_t e);
/* Temperature change dT (ne, model order) of every element whose family expands. */
void ctn_asm_set_temperatures(ctn_asm *a, const double *dT);
/* Properties of element e afresh from the model (after its l0 changed). */
void ctn_asm_setup_element(ctn_asm *a, size_t e);

/* Build steps of ctn_asm_create (blocks.c, pattern.c). */
int ctn_asm_blocks(ctn_ctx *ctx, ctn_asm *a);
int ctn_asm_pattern(ctn_ctx *ctx, ctn_asm *a);
int ctn_asm_scatter_map(ctn_ctx *ctx, ctn_asm *a);

#endif
