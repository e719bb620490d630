/* The histories of a dynamics analysis: a row per time step (t = 0 first) of the
 * model's records (nodes' displacements from the start geometry, supports' reactions,
 * elements' axial forces) and of the energy balance; the solution's accessors of them. */
#include "analysis/dynamics/dynamics.h"

#include <stdio.h>
#include <string.h>

void ctn_dyn_result_destroy(ctn_dyn_result **r)
{
    if (!r || !*r) return;
    ctn_free((*r)->names);
    ctn_free((*r)->rows);
    ctn_free((*r)->energy);
    ctn_free((*r)->frames);
    ctn_free(*r);
    *r = NULL;
}

unsigned ctn_dyn_record_dofs(const ctn_model *m, const ctn_record *r)
{
    unsigned all = ctn_model_node_dofs(m, (size_t)r->node) == 6 ? CTN_FIX_ALL6 : CTN_FIX_ALL;
    return r->reaction && !r->dofs ? m->nodes.v[r->node].fix & all : r->dofs;
}

static size_t column_count(const ctn_model *m)
{
    size_t n = 0;
    for (size_t i = 0; i < m->records.n; i++) {
        const ctn_record *r = &m->records.v[i];
        unsigned b = r->element >= 0 ? 1 : ctn_dyn_record_dofs(m, r);
        for (int k = 0; k < 6; k++) n += b >> k & 1;
    }
    return n;
}

int ctn_dyn_record_begin(ctn_dyn *dy)
{
    const ctn_model *m = dy->p->m;
    ctn_dyn_result *res = ctn_calloc(dy->p->ctx, 1, sizeof *res);
    if (!res) return CTN_ERR_NOMEM;
    ctn_dyn_result_destroy(&dy->s->dyn);
    dy->s->dyn = res;
    res->ncol = column_count(m);
    if (res->ncol && !(res->names = ctn_calloc(dy->p->ctx, res->ncol, sizeof *res->names))) return CTN_ERR_NOMEM;
    static const char *const u[2][6] = { { "ux", "uy", "uz", "rx", "ry", "rz" }, { "fx", "fy", "fz", "mx", "my", "mz" } };
    size_t c = 0;
    res->nn = m->nodes.n;
    res->ne = m->elements.n;
    for (size_t i = 0; i < m->records.n; i++) {
        const ctn_record *r = &m->records.v[i];
        if (r->element >= 0) snprintf(res->names[c++], CTN_DYN_NAME_MAX, "%d.force", m->elements.v[r->element].id);
        for (int k = 0; k < 6 && r->element < 0; k++)
            if (ctn_dyn_record_dofs(m, r) >> k & 1)
                snprintf(res->names[c++], CTN_DYN_NAME_MAX, "%d.%s", m->nodes.v[r->node].id, u[r->reaction != 0][k]);
    }
    return ctn_dyn_record_row(dy, 0.0);
}

/* The axial force of element e at the state d (0 if it cannot be evaluated). */
static double element_force(ctn_dyn *dy, size_t e, const double *d)
{
    const ctn_asm *a = dy->p->a;
    const ctn_asm_block *b = ctn_asm_block_of(a, e);
    const int *nodes = ctn_elem_nodes(a->m, e);
    int nn = a->m->elements.v[e].nnodes, nd = b->ops->ndof_node;
    double *X = dy->ework, *u = X + 3 * (size_t)nn, *f = u + (size_t)(nn * nd);
    for (int k = 0; k < nn; k++) {
        memcpy(X + 3 * k, a->m->nodes.v[nodes[k]].X, 3 * sizeof(double));
        memcpy(u + nd * k, d + ctn_dofmap_node(&a->map, (size_t)nodes[k]), (size_t)nd * sizeof(double));
    }
    ctn_elem_state st;
    memset(&st, 0, sizeof st);
    return b->ops->eval(ctn_asm_props(a, e), 0, X, u, f, NULL, &st) ? 0.0 : st.N;
}

int ctn_dyn_record_row(ctn_dyn *dy, double t)
{
    ctn_dyn_result *res = dy->s->dyn;
    const ctn_model *m = dy->p->m;
    size_t w = 1 + res->ncol;
    if (res->nrow == res->cap) {
        size_t cap = res->cap ? 2 * res->cap : 64, c1 = res->cap * w, c2 = res->cap * 4;
        int rc = ctn_array_reserve(dy->p->ctx, (void **)&res->rows, &c1, cap * w, sizeof(double));
        if (!rc) rc = ctn_array_reserve(dy->p->ctx, (void **)&res->energy, &c2, cap * 4, sizeof(double));
        if (rc) return rc;
        res->cap = cap;
    }
    if (dy->o->frames) {
        int rc = ctn_dyn_keep_frame(dy, t);                   /* the reactions at t too */
        if (rc) return rc;
    } else if (dy->react) {
        int rc = ctn_dyn_reactions(dy, t, NULL);
        if (rc) return rc;
    }
    double *row = res->rows + res->nrow * w, *en = res->energy + res->nrow * 4;
    size_t c = 1;
    row[0] = t;
    for (size_t i = 0; i < m->records.n; i++) {
        const ctn_record *r = &m->records.v[i];
        const double *from = r->reaction ? dy->react : dy->d0;
        if (r->element >= 0) row[c++] = element_force(dy, (size_t)r->element, dy->d0);
        for (int k = 0; k < 6 && r->element < 0; k++)
            if (ctn_dyn_record_dofs(m, r) >> k & 1) row[c++] = from[ctn_dofmap_node(&dy->p->a->map, (size_t)r->node) + (size_t)k];
    }
    en[0] = dy->ek;
    en[1] = dy->U;
    en[2] = dy->W;
    en[3] = dy->D;
    res->nrow++;
    return CTN_OK;
}

int ctn_solution_dynamics_summary(const ctn_solution *s, ctn_dynamics_summary *out)
{
    if (!s || !out || !s->dyn) return CTN_ERR_INVALID;
    *out = s->dyn->sum;
    return CTN_OK;
}

const double *ctn_solution_history(const ctn_solution *s, size_t *rows, size_t *columns)
{
    if (rows) *rows = s && s->dyn ? s->dyn->nrow : 0;
    if (columns) *columns = s && s->dyn ? s->dyn->ncol : 0;
    return s && s->dyn ? s->dyn->rows : NULL;
}

const char *ctn_solution_history_name(const ctn_solution *s, size_t j)
{
    return s && s->dyn && j < s->dyn->ncol ? s->dyn->names[j] : NULL;
}

const double *ctn_solution_energy(const ctn_solution *s, size_t *rows)
{
    if (rows) *rows = s && s->dyn ? s->dyn->nrow : 0;
    return s && s->dyn ? s->dyn->energy : NULL;
}
