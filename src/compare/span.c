/* Finding a model's single span: two fully fixed end nodes joined by a chain of
 * elements whose interior nodes each join exactly two elements. */
#include "compare/cmp.h"

#include <stdint.h>
#include <string.h>

#define NONE SIZE_MAX

/* The two fully fixed nodes; CTN_ERR_MODEL unless there are exactly two. */
static int find_supports(ctn_compare *c, const ctn_model *m, size_t sup[2])
{
    size_t count = 0;
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info nd;
        ctn_model_node(m, i, &nd);
        if ((nd.fix & CTN_FIX_ALL) != CTN_FIX_ALL) continue;
        if (count < 2) sup[count] = i;
        count++;
    }
    if (count != 2)
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "not a single span: %zu nodes are fixed in x, y and z "
                         "(a span has exactly two supports)", count);
    return CTN_OK;
}

/* Incident elements of each node (at most two kept; deg counts them all). */
static int incidence(ctn_compare *c, const ctn_model *m, size_t *inc, size_t *deg)
{
    size_t nn = ctn_model_node_count(m);
    for (size_t i = 0; i < nn; i++) inc[2 * i] = inc[2 * i + 1] = NONE, deg[i] = 0;
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_info el;
        ctn_model_element(m, e, &el);
        for (int k = 0; k < 2; k++) {
            size_t v = (size_t)el.node[k];
            if (deg[v] < 2) inc[2 * v + deg[v]] = e;
            deg[v]++;
        }
    }
    for (size_t i = 0; i < nn; i++)
        if (deg[i] > 2) {
            ctn_node_info nd;
            ctn_model_node(m, i, &nd);
            return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "not a single span: node %d joins %zu elements",
                             nd.id, deg[i]);
        }
    return CTN_OK;
}

/* Walk from support a along the chain; it must end on support b after every element. */
static int walk(ctn_compare *c, const ctn_model *m, const size_t *inc, const size_t *deg,
                size_t a, size_t b)
{
    size_t ne = ctn_model_element_count(m), cur = a, prev = NONE, k = 0;
    c->node[0] = a;
    while (k < ne) {
        size_t e = inc[2 * cur] != prev ? inc[2 * cur] : inc[2 * cur + 1];
        if (e == NONE || (cur != a && deg[cur] != 2)) break;
        ctn_element_info el;
        ctn_model_element(m, e, &el);
        c->elem[k] = e;
        cur = (size_t)el.node[0] == cur ? (size_t)el.node[1] : (size_t)el.node[0];
        c->node[++k] = cur;
        prev = e;
        if (cur == b || cur == a) break;
    }
    ctn_node_info na, nb;
    ctn_model_node(m, a, &na);
    ctn_model_node(m, b, &nb);
    if (cur != b)
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "not a single span: the chain of elements from "
                         "support %d does not reach support %d", na.id, nb.id);
    if (k != ne || deg[a] != 1 || deg[b] != 1)
        return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "not a single span: %zu of the %zu elements lie on "
                         "the chain from support %d to support %d", k, ne, na.id, nb.id);
    return CTN_OK;
}

/* Section data of the first element; every element must match it. */
static int section_data(ctn_compare *c, const ctn_model *m)
{
    ctn_element_info e0, e;
    ctn_model_element(m, c->elem[0], &e0);
    c->span.L0 = 0;
    for (size_t k = 0; k < c->span.n; k++) {
        ctn_model_element(m, c->elem[k], &e);
        if (e.E != e0.E || e.A != e0.A || e.w != e0.w || e.strain != e0.strain)
            return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "the span's elements differ (element %d and %d "
                             "have different E, A, w or strain measure)", e0.id, e.id);
        c->l0[k] = e.l0;
        c->EA[k] = e.E * e.A;
        c->span.L0 += e.l0;
    }
    c->span.E = e0.E;
    c->span.A = e0.A;
    c->span.EA = e0.E * e0.A;
    c->span.strain = e0.strain;
    return CTN_OK;
}

/* If the model's only cable is the whole span, start the walk at its first node. */
static void generated_order(const ctn_model *m, size_t sup[2], int *generated)
{
    ctn_cable_info cb;
    *generated = 0;
    if (ctn_model_cable_count(m) != 1 || ctn_model_cable(m, 0, &cb)) return;
    if (cb.count != ctn_model_element_count(m)) return;
    *generated = 1;
    if ((size_t)cb.node[0] == sup[1]) {
        size_t t = sup[0];
        sup[0] = sup[1];
        sup[1] = t;
    }
}

static int alloc_arrays(ctn_compare *c, size_t n)
{
    c->node = ctn_malloc(c->ctx, n + 1, sizeof *c->node);
    c->elem = ctn_malloc(c->ctx, n, sizeof *c->elem);
    c->l0 = ctn_malloc(c->ctx, n, sizeof *c->l0);
    c->EA = ctn_malloc(c->ctx, n, sizeof *c->EA);
    c->P = ctn_calloc(c->ctx, 2 * (n + 1), sizeof *c->P);
    c->Xref = ctn_malloc(c->ctx, 3 * (n + 1), sizeof *c->Xref);
    return c->node && c->elem && c->l0 && c->EA && c->P && c->Xref ? CTN_OK : CTN_ERR_NOMEM;
}

int ctn_cmp_find_span(ctn_compare *c, const ctn_model *m)
{
    size_t ne = ctn_model_element_count(m), nn = ctn_model_node_count(m), sup[2];
    if (ne == 0) return ctn_cmp_error(c->ctx, c->file, CTN_ERR_MODEL, "the model has no elements");
    int rc = find_supports(c, m, sup);
    if (rc) return rc;
    generated_order(m, sup, &c->span.generated);
    c->span.n = ne;
    size_t *inc = ctn_malloc(c->ctx, 2 * nn, sizeof *inc), *deg = ctn_malloc(c->ctx, nn, sizeof *deg);
    rc = inc && deg ? alloc_arrays(c, ne) : CTN_ERR_NOMEM;
    if (!rc) rc = incidence(c, m, inc, deg);
    if (!rc) rc = walk(c, m, inc, deg, sup[0], sup[1]);
    if (!rc) rc = section_data(c, m);
    for (size_t j = 0; !rc && j <= ne; j++) {
        ctn_node_info nd;
        ctn_model_node(m, c->node[j], &nd);
        for (int k = 0; k < 3; k++) c->Xref[3 * j + (size_t)k] = nd.X[k];
    }
    for (int k = 0; k < 2 && !rc; k++) {
        ctn_node_info nd;
        ctn_model_node(m, sup[k], &nd);
        c->span.support[k] = nd.id;
    }
    ctn_free(inc);
    ctn_free(deg);
    return rc;
}
