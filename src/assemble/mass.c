/* The mass matrix on the tangent's pattern: the element families' mass ops through the
 * one element loop (no state: mass is per unstressed length), point masses at nodes. */
#include "assemble/asm.h"

#include <math.h>
#include <string.h>

typedef struct mass_pass {
    int lumped;
    double *Mx;          /* pattern values (ctn_asm_mass), or NULL */
    double *diag;        /* ndof lumped diagonal (ctn_asm_mass_diag), or NULL */
    size_t bad;          /* first element whose mass is not finite, or SIZE_MAX */
} mass_pass;

/* Equation of DOF k (a translation, k < 3) of node i, -1 if fixed. */
static int node_eq(const ctn_asm *a, size_t i, int k)
{
    return a->map.eq[ctn_dofmap_node(&a->map, i) + (size_t)k];
}

static void mass_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    mass_pass *mp = data;
    const ctn_asm_block *b = el->b;
    double *Me = a->work, *X = a->work + b->nslots;   /* scratch (no eval runs) */
    if (!b->ops->mass) return;                       /* a massless family */
    for (int i = 0; i < b->nedof / b->ops->ndof_node; i++)
        memcpy(X + 3 * i, a->m->nodes.v[el->nodes[i]].X, 3 * sizeof(double));
    b->ops->mass(el->props, X, mp->lumped, Me);
    for (int t = 0; t < b->nslots; t++) {
        if (!isfinite(Me[t]) && mp->bad == (size_t)-1) mp->bad = el->e;
        int s = mp->Mx ? el->slot[t] : -1;
        if (s != -1) mp->Mx[s >= 0 ? s : -(s + 2)] += Me[t];   /* -1: a fixed DOF */
    }
    if (!mp->diag) return;
    int n = b->nedof, ndn = b->ops->ndof_node;
    for (int i = 0; i < n; i++) {                    /* lumped: the diagonal entries */
        int q = a->map.eq[ctn_dofmap_node(&a->map, (size_t)el->nodes[i / ndn]) + (size_t)(i % ndn)];
        if (q >= 0) mp->diag[q] += Me[ctn_packed_index(n, i, i)];
    }
}

int ctn_asm_mass(ctn_ctx *ctx, ctn_asm *a, int lumped, double *Mx)
{
    mass_pass mp = { lumped, Mx, NULL, (size_t)-1 };
    int rc = ctn_asm_need_slots(ctx, a);
    if (rc) return rc;
    memset(Mx, 0, a->nnz * sizeof(double));
    ctn_asm_loop(a, NULL, 0, 0, mass_visit, &mp, NULL);
    for (size_t i = 0; i < a->nn; i++)               /* point masses on the diagonal */
        for (int k = 0; k < 3; k++) {
            int q = node_eq(a, i, k);
            if (q >= 0) Mx[a->colptr[q + 1] - 1] += a->m->nodes.v[i].mass;
        }
    return CTN_OK;
}

int ctn_asm_mass_diag(const ctn_asm *a, double *diag, double tot[3], size_t *bad)
{
    mass_pass mp = { 1, NULL, diag, (size_t)-1 };
    memset(diag, 0, a->ndof * sizeof(double));
    ctn_asm_loop(a, NULL, 0, 0, mass_visit, &mp, NULL);
    for (size_t i = 0; i < a->nn; i++)
        for (int k = 0; k < 3; k++) {
            int q = node_eq(a, i, k);
            if (q >= 0) diag[q] += a->m->nodes.v[i].mass;
        }
    tot[0] = tot[1] = tot[2] = 0;
    for (size_t q = 0; q < a->ndof; q++)
        if (a->map.dof_dir[q] < 3) tot[a->map.dof_dir[q]] += diag[q];
    *bad = mp.bad;
    return mp.bad != (size_t)-1;
}

void ctn_asm_mass_moving(const ctn_asm *a, const double *Mx, double tot[3])
{
    const int *dir = a->map.dof_dir;
    tot[0] = tot[1] = tot[2] = 0;
    for (size_t j = 0; j < a->ndof; j++)
        for (size_t t = (size_t)a->colptr[j]; t < (size_t)a->colptr[j + 1]; t++) {
            size_t i = (size_t)a->rowind[t];
            if (dir[i] == dir[j] && dir[j] < 3) tot[dir[j]] += i == j ? Mx[t] : 2 * Mx[t];
        }
}
