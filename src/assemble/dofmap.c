/* Equation numbering of the free DOFs, in node order x, y, z, and element properties. */
#include "assemble/asm.h"

int ctn_asm_number_dofs(ctn_ctx *ctx, ctn_asm *a)
{
    const ctn_model *m = a->m;
    a->eq = ctn_malloc(ctx, 3 * a->nn, sizeof(int));
    if (!a->eq) return CTN_ERR_NOMEM;
    size_t n = 0;
    for (size_t i = 0; i < a->nn; i++)
        for (int k = 0; k < 3; k++)
            a->eq[3 * i + k] = (m->nodes.v[i].fix >> k) & 1u ? -1 : (int)n++;
    a->ndof = n;
    a->dof_node = ctn_malloc(ctx, n ? n : 1, sizeof(int));
    a->dof_dir = ctn_malloc(ctx, n ? n : 1, sizeof(int));
    if (!a->dof_node || !a->dof_dir) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < 3 * a->nn; i++)
        if (a->eq[i] >= 0) {
            a->dof_node[a->eq[i]] = (int)(i / 3);
            a->dof_dir[a->eq[i]] = (int)(i % 3);
        }
    return CTN_OK;
}

int ctn_asm_element_props(ctn_ctx *ctx, ctn_asm *a)
{
    const ctn_model *m = a->m;
    a->props = ctn_malloc(ctx, a->ne, sizeof(ctn_cable_props));
    a->tension_only = ctn_malloc(ctx, a->ne, 1);
    if (!a->props || !a->tension_only) return CTN_ERR_NOMEM;
    for (size_t e = 0; e < a->ne; e++) {
        const ctn_section *s = &m->sections.v[m->elements.v[e].section];
        const ctn_material *mat = &m->materials.v[s->material];
        a->props[e].EA = mat->E * s->A;
        a->props[e].l0 = m->elements.v[e].l0;
        a->props[e].strain = mat->strain;
        a->props[e].tension_only = mat->tension_only;
        a->tension_only[e] = (unsigned char)mat->tension_only;
    }
    a->ops = &ctn_cable2_ops;
    return CTN_OK;
}
