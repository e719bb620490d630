/* The linear equilibrium of the free nodes for fixed force densities, one system per
 * set of free nodes (one for every coordinate in the common case of nodes either fully
 * fixed or free; three at most):
 *   D_ff x_f = p_f - D_fx x_x,   D = C' Q C: D_ii = sum of q at node i, D_ij = -q_ij,
 * assembled in compressed columns (upper triangle) and factored by CHOLMOD LL' once per
 * density set; each coordinate it serves is one right-hand side. */
#include "design/formfind/ff.h"

#include <stdlib.h>
#include <string.h>

static int cmp_int(const void *x, const void *y)
{
    int p = *(const int *)x, r = *(const int *)y;
    return (p > r) - (p < r);
}

/* Equations of the nodes free in coordinate k; the count in *n. */
static int number_free(ctn_ff *f, int k, int **eq, size_t *n)
{
    *eq = ctn_malloc(f->ctx, f->nn ? f->nn : 1, sizeof(int));
    if (!*eq) return CTN_ERR_NOMEM;
    *n = 0;
    for (size_t i = 0; i < f->nn; i++)
        (*eq)[i] = f->m->nodes.v[i].fix & (1u << k) ? -1 : (int)(*n)++;
    return CTN_OK;
}

/* Rows of column c (count pass: rows == NULL) from the members between free nodes. */
static void each_entry(const ctn_ff *f, const int *eq, int *cnt, int *fill, int *rows)
{
    for (size_t e = 0; e < f->ne; e++) {
        const int *nd = ctn_elem_nodes(f->m, e);
        int a = eq[nd[0]], b = eq[nd[1]];
        if (a < 0 || b < 0) continue;
        int r = a < b ? a : b, c = a < b ? b : a;
        if (rows) rows[fill[c]++] = r;
        else cnt[c + 1]++;
    }
}

/* The pattern: every column's rows sorted and unique, the diagonal last. */
static int build_pattern(ctn_ff *f, ctn_ff_system *s)
{
    size_t n = s->n;
    int *ptr = ctn_calloc(f->ctx, n + 1, sizeof(int)), *fill = ctn_malloc(f->ctx, n ? n : 1, sizeof(int));
    int rc = ptr && fill ? CTN_OK : CTN_ERR_NOMEM;
    if (!rc) {
        each_entry(f, s->eq, ptr, NULL, NULL);
        for (size_t c = 0; c < n; c++) ptr[c + 1] += ptr[c] + 1;        /* + the diagonal */
        s->rowind = ctn_malloc(f->ctx, (size_t)ptr[n] ? (size_t)ptr[n] : 1, sizeof(int));
        rc = s->rowind ? CTN_OK : CTN_ERR_NOMEM;
    }
    if (!rc) {
        for (size_t c = 0; c < n; c++) fill[c] = ptr[c];
        each_entry(f, s->eq, NULL, fill, s->rowind);
        int w = 0;
        for (size_t c = 0; c < n; c++) {
            int start = ptr[c], end = fill[c], last = -1;
            qsort(s->rowind + start, (size_t)(end - start), sizeof(int), cmp_int);
            ptr[c] = w;
            for (int k = start; k < end; k++)
                if (s->rowind[k] != last) last = s->rowind[w++] = s->rowind[k];
            s->rowind[w++] = (int)c;
            /* the next column's entries start at the old ptr[c + 1], untouched yet */
        }
        ptr[n] = w;
        s->colptr = ptr;
        ptr = NULL;
    }
    ctn_free(ptr);
    ctn_free(fill);
    return rc;
}

/* Position of entry (r, c), r <= c, in the pattern. */
static int position(const ctn_ff_system *s, int r, int c)
{
    const int *lo = s->rowind + s->colptr[c], *hi = s->rowind + s->colptr[c + 1];
    const int *at = bsearch(&r, lo, (size_t)(hi - lo), sizeof(int), cmp_int);
    return (int)(at - s->rowind);
}

static int build_slots(ctn_ff *f, ctn_ff_system *s)
{
    s->slot = ctn_malloc(f->ctx, 3 * (f->ne ? f->ne : 1), sizeof(int));
    s->Dx = ctn_malloc(f->ctx, (size_t)s->colptr[s->n] ? (size_t)s->colptr[s->n] : 1, sizeof(double));
    if (!s->slot || !s->Dx) return CTN_ERR_NOMEM;
    for (size_t e = 0; e < f->ne; e++) {
        const int *nd = ctn_elem_nodes(f->m, e);
        int a = s->eq[nd[0]], b = s->eq[nd[1]];
        s->slot[3 * e] = a < 0 ? -1 : position(s, a, a);
        s->slot[3 * e + 1] = b < 0 ? -1 : position(s, b, b);
        s->slot[3 * e + 2] = a < 0 || b < 0 ? -1 : position(s, a < b ? a : b, a < b ? b : a);
    }
    return CTN_OK;
}

static int system_create(ctn_ff *f, int k, ctn_ff_system *s)
{
    int rc = number_free(f, k, &s->eq, &s->n);
    if (rc || !s->n) return rc;
    if ((rc = build_pattern(f, s)) || (rc = build_slots(f, s))) return rc;
    ctn_pattern p = { s->n, s->colptr, s->rowind };
    return ctn_linsolve_create(f->ctx, "cholmod", &p, f->order, &s->ls);
}

/* 1 if coordinates j and k have the same free nodes. */
static int same_free(const ctn_ff *f, int j, int k)
{
    for (size_t i = 0; i < f->nn; i++) {
        unsigned fix = f->m->nodes.v[i].fix;
        if (!(fix & (1u << j)) != !(fix & (1u << k))) return 0;
    }
    return 1;
}

int ctn_ff_systems_create(ctn_ff *f)
{
    int rc = CTN_OK;
    for (int k = 0; k < 3 && !rc; k++) {
        f->which[k] = k;
        for (int j = 0; j < k && f->which[k] == k; j++)
            if (f->which[j] == j && same_free(f, j, k)) f->which[k] = j;
        if (f->which[k] == k) rc = system_create(f, k, &f->sys[k]);
    }
    return rc;
}

void ctn_ff_systems_destroy(ctn_ff *f)
{
    for (int k = 0; k < 3; k++) {
        ctn_ff_system *s = &f->sys[k];
        ctn_linsolve_destroy(&s->ls);
        ctn_free(s->eq);
        ctn_free(s->colptr);
        ctn_free(s->rowind);
        ctn_free(s->slot);
        ctn_free(s->Dx);
        memset(s, 0, sizeof *s);
    }
}

/* D_ff from the densities, factored. */
static int factor(ctn_ff *f, ctn_ff_system *s)
{
    memset(s->Dx, 0, (size_t)s->colptr[s->n] * sizeof(double));
    for (size_t e = 0; e < f->ne; e++) {
        const int *sl = s->slot + 3 * e;
        if (sl[0] >= 0) s->Dx[sl[0]] += f->q[e];
        if (sl[1] >= 0) s->Dx[sl[1]] += f->q[e];
        if (sl[2] >= 0) s->Dx[sl[2]] -= f->q[e];
    }
    ctn_factor_info info;
    int rc = ctn_linsolve_factor(s->ls, s->Dx, 0, &info);
    if (!rc && !info.ok)
        return ctn_error(f->ctx, CTN_ERR_LINALG, "form finding: the force density matrix is not positive definite "
                         "(column %ld)", info.fail_col);
    return rc;
}

/* Coordinate k of node i in the shape (f->x or the model's). */
static double coordinate(const ctn_ff *f, int i, int k)
{
    return f->x ? f->x[3 * (size_t)i + (size_t)k] : f->m->nodes.v[i].X[k];
}

/* Coordinate k: b = p_f + sum over members to a node fixed in k of q x_fixed; solve. */
static int solve_coordinate(ctn_ff *f, const ctn_ff_system *s, int k)
{
    ctn_node *nodes = f->m->nodes.v;
    for (size_t i = 0; i < f->nn; i++)
        if (s->eq[i] >= 0) f->b[s->eq[i]] = f->p[3 * i + (size_t)k];
    for (size_t e = 0; e < f->ne; e++) {
        const int *nd = ctn_elem_nodes(f->m, e);
        int a = s->eq[nd[0]], b = s->eq[nd[1]];
        if (a >= 0 && b < 0) f->b[a] += f->q[e] * coordinate(f, nd[1], k);    /* -D_fx x_x */
        if (b >= 0 && a < 0) f->b[b] += f->q[e] * coordinate(f, nd[0], k);
    }
    int rc = ctn_linsolve_solve(s->ls, f->b, f->b);
    for (size_t i = 0; !rc && i < f->nn; i++)
        if (s->eq[i] >= 0) *(f->x ? &f->x[3 * i + (size_t)k] : &nodes[i].X[k]) = f->b[s->eq[i]];
    return rc;
}

int ctn_ff_solve_shape(ctn_ff *f, int *factorizations)
{
    int rc = CTN_OK;
    for (int k = 0; k < 3 && !rc && !f->factored; k++)
        if (f->which[k] == k && f->sys[k].n) {
            rc = factor(f, &f->sys[k]);
            ++*factorizations;
        }
    if (!rc) f->factored = 1;
    for (int k = 0; k < 3 && !rc; k++)
        if (f->sys[f->which[k]].n) rc = solve_coordinate(f, &f->sys[f->which[k]], k);
    return rc;
}
