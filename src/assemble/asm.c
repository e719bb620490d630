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
    int rc = ctn_asm_number_dofs(ctx, a);
    if (!rc) rc = ctn_asm_element_props(ctx, a);
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
    ctn_free(p->eq);
    ctn_free(p->dof_node);
    ctn_free(p->dof_dir);
    ctn_free(p->colptr);
    ctn_free(p->rowind);
    ctn_free(p->slot);
    ctn_free(p->props);
    ctn_free(p->tension_only);
    ctn_free(p);
    *a = NULL;
}

/* Add (or, for an entry's first element, assign) an element's upper-triangle entries. */
static void scatter_K(const int *slot, const double *Ke, double *Kx)
{
    for (int i = 0; i < CTN_EDOF; i++)
        for (int j = i; j < CTN_EDOF; j++) {
            int s = slot[ctn_asm_local_slot(i, j)];
            if (s >= 0) Kx[s] += Ke[CTN_EDOF * i + j];
            else if (s <= -2) Kx[-(s + 2)] = Ke[CTN_EDOF * i + j];
        }
}

void ctn_asm_gather(const ctn_asm *a, size_t e, const double *d, double *X, double *u)
{
    const int *nd = a->m->elements.v[e].node;
    for (int k = 0; k < CTN_EDOF; k++) {
        X[k] = a->m->nodes.v[nd[k / 3]].X[k % 3];
        u[k] = d[3 * (size_t)nd[k / 3] + (size_t)(k % 3)];
    }
}

int ctn_asm_eval(const ctn_asm *a, const double *d, double *f, double *Kx, size_t *bad)
{
    return ctn_asm_eval_energy(a, d, f, Kx, NULL, bad);
}

int ctn_asm_eval_energy(const ctn_asm *a, const double *d, double *f, double *Kx, double *U,
                        size_t *bad)
{
    double energy = 0;
    ctn_elem_state st;
    memset(f, 0, 3 * a->nn * sizeof(double));
    for (size_t e = 0; e < a->ne; e++) {
        const int *nd = a->m->elements.v[e].node;
        double X[CTN_EDOF], u[CTN_EDOF], fe[CTN_EDOF], Ke[CTN_EDOF * CTN_EDOF];
        ctn_asm_gather(a, e, d, X, u);
        if (a->ops->eval(&a->props[e], X, u, fe, Kx ? Ke : NULL, U ? &st : NULL)) {
            if (bad) *bad = e;
            return CTN_ERR_DOMAIN;
        }
        if (U) energy += st.energy;
        for (int k = 0; k < CTN_EDOF; k++) f[3 * (size_t)nd[k / 3] + (size_t)(k % 3)] += fe[k];
        if (Kx) scatter_K(a->slot + e * CTN_ESLOTS, Ke, Kx);
    }
    if (U) *U = energy;
    return CTN_OK;
}

int ctn_asm_energy(const ctn_asm *a, const double *d, double *U)
{
    double sum = 0;
    for (size_t e = 0; e < a->ne; e++) {
        double X[CTN_EDOF], u[CTN_EDOF], fe[CTN_EDOF];
        ctn_elem_state st;
        ctn_asm_gather(a, e, d, X, u);
        if (a->ops->eval(&a->props[e], X, u, fe, NULL, &st)) return CTN_ERR_DOMAIN;
        sum += st.energy;
    }
    *U = sum;
    return CTN_OK;
}

size_t ctn_asm_count_compressed(const ctn_asm *a, const double *d)
{
    size_t n = 0;
    for (size_t e = 0; e < a->ne; e++) {
        double X[CTN_EDOF], u[CTN_EDOF], fe[CTN_EDOF];
        ctn_elem_state st;
        ctn_cable_props p = a->props[e];
        p.tension_only = 0;
        ctn_asm_gather(a, e, d, X, u);
        if (a->ops->eval(&p, X, u, fe, NULL, &st)) return 0;
        n += st.N < 0 && !a->tension_only[e];
    }
    return n;
}

void ctn_asm_cut_compression(ctn_asm *a, int on)
{
    for (size_t e = 0; e < a->ne; e++) a->props[e].tension_only = on ? 1 : a->tension_only[e];
}
