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
#include "core/feed.h"
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

/* A block the node-by-node path takes: a family with eval_axial (two nodes of 3 DOFs). */
static inline int ctn_asm_block_axial(const ctn_asm_block *b)
{
    return b->ops->eval_axial && b->nnodes == 2 && b->ops->ndof_node == 3;
}

/* An axial element at a node (gather.c): element e of block blk, whose other node is
 * nb >> 1, the node being its first (nb & 1 == 0) or second. */
typedef struct ctn_asm_inc {
    int e, nb, blk;
} ctn_asm_inc;

/* An axial element as its lower node evaluates it (gather.c): element e of block blk,
 * joining nodes n1 and n2 (its first and second). */
typedef struct ctn_asm_ev {
    int e, blk, n1, n2;
} ctn_asm_ev;

/* An axial element's evaluation, kept for its two nodes (gather.c). */
typedef struct ctn_asm_kept {
    int e;                             /* the element, -1: none */
    double k[6], f[6];                 /* k's upper triangle; the forces on its nodes */
} ctn_asm_kept;

/* The node-by-node assembly of the axial families (those with eval_axial) when every
 * node has 3 DOFs (gather.c): each node sums its axial elements' k into its diagonal
 * block and their forces into its internal force, and writes its columns of the tangent
 * in the pattern's order: every stored value and every force written once, no zeroing
 * and no scatter map read. The other families add theirs afterwards through the generic
 * loop (their slots then all add). */
typedef struct ctn_asm_gather {
    int *inc_ptr;                      /* nn + 1: node q's axial elements, in model order */
    ctn_asm_inc *inc;
    int *order;                        /* per node, its list by (other node, element) */
    int *adj_ptr, *adj;                /* node adjacency (self included, sorted): CSR */
    int maxdeg;                        /* most axial elements at one node */
    int maxadj;                        /* most neighbours of one node (self included) */
    ctn_ctx *ctx;                      /* the context it was built in: its helper thread */
    int threads;                       /* 1, or 2: the nodes in two halves (core/threads.h) */
    double *work;                      /* per thread (maxdeg + maxadj) * 6 on its own cache
                                          lines: a node's elements' k, its neighbours' blocks */
    double *X;                         /* nn * 3: the nodes' reference coordinates, copied
                                          at creation as the properties are */
    unsigned char *free;               /* nn: node q's free directions, bit j for j; bits
                                          3 .. 7: a plain node and its lower neighbours'
                                          count (gather.c) */
    ctn_asm_kept *keep;                /* threads * KEEP (gather.c): elements evaluated
                                          for the nodes of a chunk */
    int mixed;                         /* other families too: the generic loop adds them */
    int *ev_ptr;                       /* nn + 1: the elements whose lower node is q, */
    ctn_asm_ev *ev;                    /* in model order */
    size_t q0, q1;                     /* the nodes whose lists are held: 0 .. nn, or a
                                          process's range (ctn_asm_gather_keep) */
} ctn_asm_gather;

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
                                          none (a fixed DOF); NULL until
                                          needed when every element is assembled node by
                                          node (ctn_asm_need_slots) */
    int maxdof;                        /* largest nedof over the blocks */
    double *work;                      /* 2 maxdof + 3 nnodes_max + maxslots: eval scratch */
    double kscale;                     /* largest element stiffness scale */
    ctn_asm_gather *gather;            /* the node-by-node path (gather.c), NULL if off */
    unsigned flags;                    /* CTN_ASM_* it was created with */
} ctn_asm;

int ctn_asm_create(ctn_ctx *ctx, const ctn_model *m, ctn_asm **out);
/* As ctn_asm_create; CTN_ASM_GENERIC: every family through the generic element loop
 * (the reference the node-by-node path is tested against); CTN_ASM_ONE_THREAD. */
enum { CTN_ASM_GENERIC = 1, CTN_ASM_ONE_THREAD = 2 };
int ctn_asm_create_ex(ctn_ctx *ctx, const ctn_model *m, unsigned flags, ctn_asm **out);
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
    const int *slot;           /* its scatter slots (NULL: the map is not built) */
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
 * ops, lumped or consistent, and the nodes' point masses on the diagonal (mass.c); the
 * scatter map built first if it is not (CTN_ERR_NOMEM). */
int ctn_asm_mass(ctn_ctx *ctx, ctn_asm *a, int lumped, double *Mx);
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
/* Properties of element e afresh from the model (after its l0 changed), at the
 * temperature change dT it is at (the one ctn_asm_set_temperatures gave it; 0 for none):
 * a length that changes keeps the element's thermal state. */
void ctn_asm_setup_element(ctn_asm *a, size_t e, double dT);
/* Sever element e (its family's sever op: force and stiffness zero, mass kept) until
 * ctn_asm_setup_element restores it; CTN_ERR_INVALID for a family without the op. */
int ctn_asm_sever_element(ctn_asm *a, size_t e);

/* Build steps of ctn_asm_create (blocks.c, pattern.c). */
int ctn_asm_blocks(ctn_ctx *ctx, ctn_asm *a);
int ctn_asm_pattern(ctn_ctx *ctx, ctn_asm *a);
int ctn_asm_scatter_map(ctn_ctx *ctx, ctn_asm *a);
/* The scatter map, built when first needed: a model assembled node by node alone has
 * none until something adds element matrices through it (the mass matrix). */
int ctn_asm_need_slots(ctn_ctx *ctx, ctn_asm *a);
/* The node-by-node path (gather.c): built from the node adjacency (CSR ptr/adj, taken
 * over when it is used, else left to the caller) if every node has 3 DOFs and some block
 * is axial; evaluated like ctn_asm_eval's axial part (f and Kx entirely written). */
int ctn_asm_gather_build(ctn_ctx *ctx, ctn_asm *a, int **ptr, int **adj);
void ctn_asm_gather_free(ctn_asm_gather **g);
int ctn_asm_gather_eval(const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx,
                        double *U, size_t *bad);
/* Whether ctn_asm_eval_feed can assemble this model (every element node by node), and
 * ctn_asm_eval done that way on the calling thread alone, node after node, publishing to
 * feed the tangent's columns done as it goes (all of them at the end, even if an element
 * collapsed): a factorization on another thread follows it (solve/overlap.c; gather.c). */
int ctn_asm_can_feed(const ctn_asm *a);
int ctn_asm_eval_feed(const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx, double *U,
                      size_t *bad, ctn_feed *feed);
/* A process's share of ctn_asm_eval for a model ctn_asm_can_feed assembles (every element
 * node by node), on the calling thread: the internal forces of nodes q0 .. q1 - 1 (f's
 * other entries untouched), and, if Kx != NULL, their columns of the tangent from Kx[0]
 * (the columns of their free DOFs, which are consecutive, in the pattern's order); the
 * energy of the elements whose lower node is one of them in *U; 1 with the first
 * collapsed element of theirs in *bad (SIZE_MAX if none). */
int ctn_asm_gather_eval_nodes(const ctn_asm *a, const double *d, unsigned mode, size_t q0, size_t q1, double *f,
                              double *Kx, double *U, size_t *bad);
/* The node-by-node tables of nodes q0 .. q1 - 1 kept alone (a process that assembles
 * those only: problem/dist.c): their element lists and adjacency moved to the front and
 * the rest released. Afterwards only ctn_asm_gather_eval_nodes within that range reads
 * them; ctn_asm_eval takes the generic element loop, for the internal forces alone (Kx
 * NULL: no scatter map is built). CTN_OK (a shrink the allocator refuses keeps the
 * larger blocks). */
int ctn_asm_gather_keep(ctn_asm *a, size_t q0, size_t q1);
/* The threads= option the assembly was created under, as the thread policy is asked
 * (core/threads.h): 1 (CTN_ASM_ONE_THREAD), or 0 (auto). */
int ctn_asm_threads(const ctn_asm *a);

#endif
