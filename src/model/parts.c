/* Parts of a model: the connected components of its node/element graph, each of which
 * must hold a support (docs/format.md, "Checks made when the model is solved"). */
#include "model/model.h"

#include <stdio.h>
#include <string.h>

#define PARTS_SHOWN 6   /* element ids quoted in the message, at most */

/* Node index k of element e: the one place that knows element storage. */
static size_t elem_node(const ctn_model *m, size_t e, int k) { return (size_t)ctn_elem_nodes(m, e)[k]; }

/* Root of i's set, halving the path on the way (union-find). */
static size_t find_root(size_t *parent, size_t i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

/* Join the sets of a and b, the smaller under the larger. */
static void join(size_t *parent, size_t *size, size_t a, size_t b)
{
    a = find_root(parent, a);
    b = find_root(parent, b);
    if (a == b) return;
    if (size[a] < size[b]) { size_t t = a; a = b; b = t; }
    parent[b] = a;
    size[a] += size[b];
}

/* Append run lo-hi ("7" or "7-9") to buf after k characters, with a ", " before
 * all but the first; returns the new length (capped at size - 1). */
static size_t put_run(char *buf, size_t size, size_t k, int first, int lo, int hi)
{
    int w = snprintf(buf + k, size - k, lo == hi ? "%s%d" : "%s%d-%d", first ? "" : ", ", lo, hi);
    return w < 0 || k + (size_t)w >= size ? size - 1 : k + (size_t)w;
}

/* The ids of the part with root r, in model order, consecutive ids as ranges, at most
 * PARTS_SHOWN ranges then "...": "7-8", "3, 5, 9-11, ...". *count gets their number. */
static void part_ids(const ctn_model *m, size_t *parent, size_t r, char *buf, size_t size, size_t *count)
{
    size_t k = 0, runs = 0;
    int lo = 0, hi = 0;
    *count = 0;
    buf[0] = '\0';
    for (size_t e = 0; e < m->elements.n; e++) {
        if (find_root(parent, elem_node(m, e, 0)) != r) continue;
        int id = m->elements.v[e].id;
        (*count)++;
        if (runs && id - 1 == hi) { hi = id; continue; }
        if (runs && runs <= PARTS_SHOWN) k = put_run(buf, size, k, runs == 1, lo, hi);
        lo = hi = id;
        runs++;
    }
    if (runs <= PARTS_SHOWN) put_run(buf, size, k, runs == 1, lo, hi);
    else snprintf(buf + k, size - k, ", ...");
}

/* The error for the part with root r, located at the line of its first element. */
static int part_error(const ctn_model *m, size_t *parent, size_t r, size_t first)
{
    char ids[160];
    size_t count = 0;
    part_ids(m, parent, r, ids, sizeof ids, &count);
    const char *one = count == 1 ? "" : "s";
    char msg[CTN_MSG_MAX];
    snprintf(msg, sizeof msg, "element%s %s (%zu element%s) form%s a part that no support reaches: fix a "
             "node of it (fix=) or connect it to a supported part", one, ids, count, one, count == 1 ? "s" : "");
    int line = m->elements.v[first].line;
    if (line > 0) return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, line, "%s", msg);
    return ctn_error(m->ctx, CTN_ERR_MODEL, "%s%s%s", m->file, *m->file ? ": " : "", msg);
}

int ctn_model_check_parts(const ctn_model *m)
{
    size_t nn = m->nodes.n;
    size_t *parent = ctn_malloc(m->ctx, nn, sizeof *parent), *size = ctn_malloc(m->ctx, nn, sizeof *size);
    unsigned char *held = ctn_calloc(m->ctx, nn, 1);
    int rc = parent && size && held ? CTN_OK : CTN_ERR_NOMEM;
    for (size_t i = 0; !rc && i < nn; i++) parent[i] = i, size[i] = 1;
    for (size_t e = 0; !rc && e < m->elements.n; e++)
        for (int k = 1; k < m->elements.v[e].nnodes; k++) join(parent, size, elem_node(m, e, 0), elem_node(m, e, k));
    for (size_t i = 0; !rc && i < nn; i++)
        if (m->nodes.v[i].fix) held[find_root(parent, i)] = 1;
    for (size_t e = 0; !rc && e < m->elements.n; e++) {
        size_t r = find_root(parent, elem_node(m, e, 0));
        if (!held[r]) rc = part_error(m, parent, r, e);
    }
    ctn_free(parent);
    ctn_free(size);
    ctn_free(held);
    return rc;
}
