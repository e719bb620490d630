/* Assembler lifetime and the one element loop. */
#include "assemble/asm.h"

#include <string.h>

int ctn_asm_create(ctn_ctx *ctx, const ctn_model *m, ctn_asm **out)
{
    *out = NULL;
    ctn_asm *a = ctn_calloc(ctx, 1, sizeof(ctn_asm));
    if (!a) return CTN_ERR_NOMEM;
    a->m = m;
    a->nn = m->nodes.n;
    a->ne = m->elements.n;
    int rc = ctn_asm_blocks(ctx, a);
    if (!rc) rc = ctn_asm_pattern(ctx, a);
    if (!rc) rc = ctn_asm_scatter_map(ctx, a);
    if (rc) {
        ctn_asm_destroy(&a);
        return rc;
    }
    *out = a;
    return CTN_OK;
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
    ctn_free(p);
    *a = NULL;
}

/* Reference coordinates X (3 per node) and state entries u (ndof_node per node) of an
 * element's nodes. */
static void gather(const ctn_asm *a, const int *nd, int nnodes, int ndn, const double *d,
                   double *X, double *u)
{
    for (int k = 0; k < nnodes; k++) {
        const double *Xk = a->m->nodes.v[nd[k]].X, *dk = d + ctn_dofmap_node(&a->map, (size_t)nd[k]);
        for (int j = 0; j < 3; j++) X[3 * k + j] = Xk[j];
        for (int j = 0; j < ndn; j++) u[ndn * k + j] = dk[j];
    }
}

int ctn_asm_loop(const ctn_asm *a, const double *d, unsigned mode, int with_K,
                 ctn_asm_visit_fn visit, void *data, size_t *bad)
{
    double *u = a->work, *fe = u + a->maxdof, *Ke = fe + a->maxdof, *X = Ke + ctn_packed_size(a->maxdof);
    ctn_elem_state st;
    ctn_asm_elem el;
    for (size_t k = 0; k < a->nblocks; k++) {
        const ctn_asm_block *b = &a->blocks[k];
        const ctn_element_ops *ops = b->ops;
        const int *conn = ctn_elem_nodes(a->m, b->e0);
        const unsigned char *props = a->props + b->props0;
        el.b = b;
        el.fe = fe;
        el.Ke = with_K ? Ke : NULL;
        el.st = &st;
        for (size_t i = 0; i < b->count; i++) {
            el.e = b->e0 + i;
            el.nodes = conn + i * (size_t)b->nnodes;
            el.slot = a->slot + b->slot0 + i * (size_t)b->nslots;
            gather(a, el.nodes, b->nnodes, ops->ndof_node, d, X, u);
            if (ops->eval(props + i * ops->props_size, mode, X, u, fe, with_K ? Ke : NULL, &st)) {
                if (bad) *bad = el.e;
                return 1;
            }
            visit(data, a, &el);
        }
    }
    return 0;
}

typedef struct assembly {
    double *f, *Kx, U;
} assembly;

/* Add (or, for an entry's first element, assign) an element's packed upper triangle. */
static void scatter_K(const int *slot, int n, const double *Ke, double *Kx)
{
    for (int t = 0; t < n; t++) {
        int s = slot[t];
        if (s >= 0) Kx[s] += Ke[t];
        else if (s <= -2) Kx[-(s + 2)] = Ke[t];
    }
}

static void assemble_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    assembly *as = data;
    int ndn = el->b->ops->ndof_node;
    as->U += el->st->energy;
    for (int k = 0; k < el->b->nnodes; k++) {
        double *fk = as->f + ctn_dofmap_node(&a->map, (size_t)el->nodes[k]);
        for (int j = 0; j < ndn; j++) fk[j] += el->fe[ndn * k + j];
    }
    if (as->Kx) scatter_K(el->slot, el->b->nslots, el->Ke, as->Kx);
}

int ctn_asm_eval(const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx,
                 double *U, size_t *bad)
{
    assembly as = { f, Kx, 0.0 };
    memset(f, 0, a->map.nstate * sizeof(double));
    int collapsed = ctn_asm_loop(a, d, mode, Kx != NULL, assemble_visit, &as, bad);
    if (U) *U = as.U;
    return collapsed;
}

typedef struct compressed {
    size_t n;
} compressed;

static void compressed_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    (void)a;
    if ((el->b->ops->flags & CTN_ELEM_FLEXIBLE) && el->st->N < 0) ((compressed *)data)->n++;
}

size_t ctn_asm_count_compressed(const ctn_asm *a, const double *d)
{
    compressed c = { 0 };
    return ctn_asm_loop(a, d, 0, 0, compressed_visit, &c, NULL) ? 0 : c.n;
}
