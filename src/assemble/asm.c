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

/* Add (or, for an entry's first element, assign) an element's packed upper triangle. */
static void scatter_K(const int *slot, const double *Ke, double *Kx)
{
    for (int t = 0; t < CTN_ESLOTS; t++) {
        int s = slot[t];
        if (s >= 0) Kx[s] += Ke[t];
        else if (s <= -2) Kx[-(s + 2)] = Ke[t];
    }
}

void ctn_asm_gather(const ctn_asm *a, size_t e, const double *d, double *X, double *u)
{
    const int *nd = a->m->elements.v[e].node;
    const double *X0 = a->m->nodes.v[nd[0]].X, *X1 = a->m->nodes.v[nd[1]].X;
    const double *u0 = d + 3 * (size_t)nd[0], *u1 = d + 3 * (size_t)nd[1];
    for (int k = 0; k < 3; k++) {
        X[k] = X0[k];
        X[3 + k] = X1[k];
        u[k] = u0[k];
        u[3 + k] = u1[k];
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
        double X[CTN_EDOF], u[CTN_EDOF], fe[CTN_EDOF], Ke[CTN_ESLOTS];
        ctn_asm_gather(a, e, d, X, u);
        if (a->ops->eval(&a->props[e], X, u, fe, Kx ? Ke : NULL, U ? &st : NULL)) {
            if (bad) *bad = e;
            return CTN_ERR_DOMAIN;
        }
        if (U) energy += st.energy;
        double *f0 = f + 3 * (size_t)nd[0], *f1 = f + 3 * (size_t)nd[1];
        for (int k = 0; k < 3; k++) {
            f0[k] += fe[k];
            f1[k] += fe[3 + k];
        }
        if (Kx) scatter_K(a->slot + e * CTN_ESLOTS, Ke, Kx);
    }
    if (U) *U = energy;
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
