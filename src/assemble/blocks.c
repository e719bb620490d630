/* Element blocks, their properties, and the DOF map the families ask for. */
#include "assemble/asm.h"

#include <math.h>
#include <string.h>

/* Count the blocks (out == NULL) or fill them; returns the count. Offsets (properties,
 * slots) follow the blocks in model order. */
static size_t scan_blocks(const ctn_model *m, ctn_asm_block *out)
{
    size_t n = 0, props = 0, slot = 0;
    ctn_asm_block cur;
    memset(&cur, 0, sizeof cur);
    for (size_t e = 0; e <= m->elements.n; e++) {
        const ctn_element *el = e < m->elements.n ? &m->elements.v[e] : NULL;
        const ctn_element_ops *ops = el ? ctn_element_family(el->type) : NULL;
        if (el && cur.count && cur.ops == ops && cur.nnodes == el->nnodes) {
            cur.count++;
            continue;
        }
        if (cur.count) {                                /* close the current block */
            if (out) out[n] = cur;
            n++;
            props += cur.count * cur.ops->props_size;
            slot += cur.count * (size_t)cur.nslots;
        }
        if (!el) break;
        cur.ops = ops;
        cur.e0 = e;
        cur.count = 1;
        cur.nnodes = el->nnodes;
        cur.nedof = el->nnodes * ops->ndof_node;
        cur.nslots = ctn_packed_size(cur.nedof);
        cur.props0 = props;
        cur.slot0 = slot;
    }
    return n;
}

static int build_props(ctn_ctx *ctx, ctn_asm *a)
{
    const ctn_asm_block *last = &a->blocks[a->nblocks - 1];
    size_t bytes = last->props0 + last->count * last->ops->props_size;
    a->props = ctn_malloc(ctx, bytes ? bytes : 1, 1);
    if (!a->props) return CTN_ERR_NOMEM;
    for (size_t k = 0; k < a->nblocks; k++) {
        const ctn_asm_block *b = &a->blocks[k];
        for (size_t i = 0; i < b->count; i++) {
            void *p = a->props + b->props0 + i * b->ops->props_size;
            b->ops->setup(a->m, b->e0 + i, p);
            a->kscale = fmax(a->kscale, b->ops->stiffness(p));
        }
    }
    return CTN_OK;
}

/* Each node gets the DOFs the model gave it: the most any family reaching it uses. */
static int build_dofmap(ctn_ctx *ctx, ctn_asm *a)
{
    unsigned char *nd = ctn_malloc(ctx, a->nn ? a->nn : 1, 1);
    if (!nd) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < a->nn; i++) nd[i] = (unsigned char)a->m->nodes.v[i].ndof;
    int rc = ctn_dofmap_build(ctx, a->m, nd, &a->map);
    ctn_free(nd);
    for (size_t k = 0; k < a->nblocks; k++)      /* finite rotations: composed (beam3.h, spin) */
        if (a->blocks[k].ops->flags & CTN_ELEM_FINITE_ROTATION) a->map.rot_update = ctn_rot_update_compose;
    a->ndof = a->map.ndof;
    return rc;
}

int ctn_asm_blocks(ctn_ctx *ctx, ctn_asm *a)
{
    a->nblocks = scan_blocks(a->m, NULL);
    a->blocks = ctn_malloc(ctx, a->nblocks ? a->nblocks : 1, sizeof(ctn_asm_block));
    if (!a->blocks) return CTN_ERR_NOMEM;
    scan_blocks(a->m, a->blocks);
    int maxslots = 0, maxnodes = 0;
    for (size_t k = 0; k < a->nblocks; k++) {
        if (a->blocks[k].nedof > a->maxdof) a->maxdof = a->blocks[k].nedof;
        if (a->blocks[k].nslots > maxslots) maxslots = a->blocks[k].nslots;
        if (a->blocks[k].nnodes > maxnodes) maxnodes = a->blocks[k].nnodes;
    }
    a->work = ctn_malloc(ctx, (size_t)(3 * a->maxdof + 3 * maxnodes + maxslots) + 1, sizeof(double));
    if (!a->work) return CTN_ERR_NOMEM;
    int rc = a->nblocks ? build_props(ctx, a) : CTN_OK;
    return rc ? rc : build_dofmap(ctx, a);
}

const ctn_asm_block *ctn_asm_block_of(const ctn_asm *a, size_t e)
{
    size_t lo = 0, hi = a->nblocks;                 /* last block with e0 <= e */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (a->blocks[mid].e0 <= e) lo = mid;
        else hi = mid;
    }
    return &a->blocks[lo];
}

const void *ctn_asm_props(const ctn_asm *a, size_t e)
{
    const ctn_asm_block *b = ctn_asm_block_of(a, e);
    return a->props + b->props0 + (e - b->e0) * b->ops->props_size;
}

void ctn_asm_set_temperatures(ctn_asm *a, const double *dT)
{
    for (size_t k = 0; k < a->nblocks; k++) {
        const ctn_asm_block *b = &a->blocks[k];
        if (!b->ops->temperature) continue;
        for (size_t i = 0; i < b->count; i++)
            b->ops->temperature(a->props + b->props0 + i * b->ops->props_size, dT[b->e0 + i]);
    }
}

void ctn_asm_setup_element(ctn_asm *a, size_t e, double dT)
{
    const ctn_asm_block *b = ctn_asm_block_of(a, e);
    void *props = a->props + b->props0 + (e - b->e0) * b->ops->props_size;
    b->ops->setup(a->m, e, props);
    if (b->ops->temperature) b->ops->temperature(props, dT);
}

int ctn_asm_sever_element(ctn_asm *a, size_t e)
{
    const ctn_asm_block *b = ctn_asm_block_of(a, e);
    if (!b->ops->sever) return CTN_ERR_INVALID;
    b->ops->sever(a->props + b->props0 + (e - b->e0) * b->ops->props_size);
    return CTN_OK;
}
