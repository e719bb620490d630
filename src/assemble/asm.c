/* Assembler lifetime and the one element loop. */
#include "assemble/asm.h"

#include <stdint.h>
#include <string.h>

int ctn_asm_create(ctn_ctx *ctx, const ctn_model *m, ctn_asm **out)
{
    return ctn_asm_create_ex(ctx, m, 0, out);
}

int ctn_asm_create_ex(ctn_ctx *ctx, const ctn_model *m, unsigned flags, ctn_asm **out)
{
    *out = NULL;
    ctn_asm *a = ctn_calloc(ctx, 1, sizeof(ctn_asm));
    if (!a) return CTN_ERR_NOMEM;
    a->m = m;
    a->flags = flags;
    a->nn = m->nodes.n;
    a->ne = m->elements.n;
    int rc = ctn_asm_blocks(ctx, a);
    if (!rc) rc = ctn_asm_pattern(ctx, a);
    if (!rc && (!a->gather || a->gather->mixed)) rc = ctn_asm_scatter_map(ctx, a);   /* else when needed */
    if (rc) {
        ctn_asm_destroy(&a);
        return rc;
    }
    *out = a;
    return CTN_OK;
}

int ctn_asm_need_slots(ctn_ctx *ctx, ctn_asm *a)
{
    return a->slot ? CTN_OK : ctn_asm_scatter_map(ctx, a);
}

void ctn_asm_destroy(ctn_asm **a)
{
    if (!a || !*a) return;
    ctn_asm *p = *a;
    ctn_dofmap_free(&p->map);
    ctn_free(p->colptr);
    ctn_free(p->rowind);
    ctn_free(p->slot);
    ctn_free(p->blocks);
    ctn_free(p->props);
    ctn_free(p->work);
    ctn_asm_gather_free(&p->gather);
    ctn_free(p);
    *a = NULL;
}

/* Reference coordinates X (3 per node) and state entries u (ndof_node per node) of an
 * element's nodes. */
static inline void gather(const ctn_asm *a, const int *nd, int nnodes, int ndn, const double *d,
                          double *X, double *u)
{
    int u3 = a->map.uniform == 3;                       /* the common layout: 3 i */
    for (int k = 0; k < nnodes; k++) {
        const double *Xk = a->m->nodes.v[nd[k]].X;
        const double *dk = d + (u3 ? 3 * (size_t)nd[k] : ctn_dofmap_node(&a->map, (size_t)nd[k]));
        for (int j = 0; j < 3; j++) X[3 * k + j] = Xk[j];
        for (int j = 0; j < ndn; j++) u[ndn * k + j] = dk[j];
    }
}

/* The loop over the elements of one block (see ctn_asm_loop). Inline, so that the
 * assembly's visitor and the common shape (2 nodes of 3 DOFs) are compiled into it. */
static inline __attribute__((always_inline)) int block_loop(const ctn_asm *a, const ctn_asm_block *b, const double *d, unsigned mode,
                             int with_K, ctn_asm_visit_fn visit, void *data, size_t *bad, double *u,
                             double *fe, double *Ke, double *X)
{
    const ctn_element_ops *ops = b->ops;
    const int *conn = ctn_elem_nodes(a->m, b->e0);
    const unsigned char *props = a->props + b->props0;
    int two3 = b->nnodes == 2 && ops->ndof_node == 3;
    ctn_elem_state st;
    ctn_asm_elem el = { 0, b, NULL, NULL, d ? fe : NULL, d && with_K ? Ke : NULL, d ? &st : NULL, NULL };
    for (size_t i = 0; i < b->count; i++) {
        el.e = b->e0 + i;
        el.nodes = conn + i * (size_t)b->nnodes;
        el.slot = a->slot ? a->slot + b->slot0 + i * (size_t)b->nslots : NULL;
        el.props = props + i * ops->props_size;
        if (!d) {                                       /* properties only: no state */
            visit(data, a, &el);
            continue;
        }
        if (two3) gather(a, el.nodes, 2, 3, d, X, u);
        else gather(a, el.nodes, b->nnodes, ops->ndof_node, d, X, u);
        if (ops->eval(el.props, mode, X, u, fe, with_K ? Ke : NULL, &st)) {
            if (bad) *bad = el.e;
            return 1;
        }
        visit(data, a, &el);
    }
    return 0;
}

/* The common shape, 2 nodes of 3 DOFs, with its scratch on the stack (registers and
 * store forwarding, no aliasing with the model), else the generic scratch. */
static inline __attribute__((always_inline)) int any_block(const ctn_asm *a, const ctn_asm_block *b, const double *d, unsigned mode,
                            int with_K, ctn_asm_visit_fn visit, void *data, size_t *bad)
{
    if (b->nedof == 6) {
        double u[6], fe[6], Ke[21], X[6];
        return block_loop(a, b, d, mode, with_K, visit, data, bad, u, fe, Ke, X);
    }
    double *u = a->work, *fe = u + a->maxdof, *Ke = fe + a->maxdof, *X = Ke + ctn_packed_size(a->maxdof);
    return block_loop(a, b, d, mode, with_K, visit, data, bad, u, fe, Ke, X);
}

/* Every block, or (skip_axial) those the node-by-node path leaves to it. */
static inline __attribute__((always_inline)) int loop(const ctn_asm *a, const double *d, unsigned mode, int with_K,
                       ctn_asm_visit_fn visit, void *data, size_t *bad, int skip_axial)
{
    for (size_t k = 0; k < a->nblocks; k++) {
        const ctn_asm_block *b = &a->blocks[k];
        if (skip_axial && ctn_asm_block_axial(b)) continue;
        if (any_block(a, b, d, mode, with_K, visit, data, bad)) return 1;
    }
    return 0;
}

int ctn_asm_loop(const ctn_asm *a, const double *d, unsigned mode, int with_K,
                 ctn_asm_visit_fn visit, void *data, size_t *bad)
{
    return loop(a, d, mode, with_K, visit, data, bad, 0);
}

typedef struct assembly {
    double *f, *Kx, U;
} assembly;

/* Add (or, for an entry's first element, assign) an element's packed upper triangle. */
static inline void scatter_K(const int *slot, int n, const double *Ke, double *Kx)
{
    for (int t = 0; t < n; t++) {
        int s = slot[t];
        if (s >= 0) Kx[s] += Ke[t];
        else if (s <= -2) Kx[-(s + 2)] = Ke[t];
    }
}

static inline void scatter_f(const ctn_asm *a, const int *nd, int nnodes, int ndn, const double *fe, double *f)
{
    int u3 = a->map.uniform == 3;
    for (int k = 0; k < nnodes; k++) {
        double *fk = f + (u3 ? 3 * (size_t)nd[k] : ctn_dofmap_node(&a->map, (size_t)nd[k]));
        for (int j = 0; j < ndn; j++) fk[j] += fe[ndn * k + j];
    }
}

static inline __attribute__((always_inline)) void assemble_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    assembly *as = data;
    as->U += el->st->energy;
    if (el->b->nslots == 21) {                      /* two nodes of three DOFs */
        scatter_f(a, el->nodes, 2, 3, el->fe, as->f);
        if (as->Kx) scatter_K(el->slot, 21, el->Ke, as->Kx);
        return;
    }
    scatter_f(a, el->nodes, el->b->nnodes, el->b->ops->ndof_node, el->fe, as->f);
    if (as->Kx) scatter_K(el->slot, el->b->nslots, el->Ke, as->Kx);
}

int ctn_asm_eval(const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx,
                 double *U, size_t *bad)
{
    assembly as = { f, Kx, 0.0 };
    if (a->gather && a->gather->q0 == 0 && a->gather->q1 == a->nn) {   /* axial members node by node */
        size_t first = SIZE_MAX, later = SIZE_MAX;
        int collapsed = ctn_asm_gather_eval(a, d, mode, f, Kx, &as.U, &first);
        if (a->gather->mixed) collapsed |= loop(a, d, mode, Kx != NULL, assemble_visit, &as, &later, 1);
        if (U) *U = as.U;
        if (bad && collapsed) *bad = first < later ? first : later;
        return collapsed;
    }
    memset(f, 0, a->map.nstate * sizeof(double));
    int collapsed = loop(a, d, mode, Kx != NULL, assemble_visit, &as, bad, 0);
    if (U) *U = as.U;
    return collapsed;
}

int ctn_asm_can_feed(const ctn_asm *a) { return a->gather && !a->gather->mixed; }

int ctn_asm_threads(const ctn_asm *a) { return (a->flags & CTN_ASM_ONE_THREAD) ? 1 : 0; }


typedef struct compressed {
    size_t n;
    const unsigned char *mask;
} compressed;

static void compressed_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    compressed *c = data;
    (void)a;
    if ((el->b->ops->flags & CTN_ELEM_FLEXIBLE) && el->st->N < 0 && (!c->mask || c->mask[el->e])) c->n++;
}

size_t ctn_asm_count_compressed(const ctn_asm *a, const double *d, const unsigned char *mask)
{
    compressed c = { 0, mask };
    return ctn_asm_loop(a, d, 0, 0, compressed_visit, &c, NULL) ? 0 : c.n;
}
