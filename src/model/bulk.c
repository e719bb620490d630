/* Nodes and elements from arrays (ctn_model_add_nodes, ctn_model_add_elements): a row
 * at a time through the one-at-a-time calls (a beam through ctn_model_add_beam, as the
 * reader adds one), so that every row is checked as they check it, with their messages;
 * the storage reserved once for all rows. */
#include "model/model.h"
#include "model/idmap.h"

#include <limits.h>
#include <string.h>

void ctn_element_rows_init(ctn_element_rows *r)
{
    if (!r) return;
    memset(r, 0, sizeof *r);
    r->size = sizeof *r;
}

/* Row i is line origin + i of the model's file (origin 0: rows of no file). */
static int row_lines(ctn_model *m, size_t n)
{
    if (m->line > 0 && n > (size_t)(INT_MAX - m->line))
        return ctn_model_error(m, CTN_ERR_MODEL, "too many rows after line %d", m->line);
    return CTN_OK;
}

int ctn_model_add_nodes(ctn_model *m, size_t n, const int *ids, const double *X, const unsigned *fix)
{
    if (!m || (n && (!ids || !X))) return CTN_ERR_INVALID;
    int origin = m->line, rc = row_lines(m, n);
    if (!rc && n) rc = CTN_ARRAY_RESERVE(m->ctx, m->nodes, n);
    if (!rc && n) rc = ctn_idmap_reserve(m->ctx, &m->node_ids, n);
    for (size_t i = 0; i < n && !rc; i++) {
        if (origin > 0) m->line = origin + (int)i;
        rc = ctn_model_add_node(m, ids[i], X + 3 * i, fix ? fix[i] : 0u);
    }
    m->line = origin;
    return rc;
}

/* The spec of row i: the common spec with the row's id, nodes and given columns. */
static void row_spec(const ctn_element_rows *r, size_t i, ctn_element_spec *s)
{
    s->id = r->ids[i];
    s->nodes = r->nodes + i * (size_t)s->nnodes;
    if (r->l0) s->l0 = r->l0[i];
    if (r->prestress_value) s->prestress_value = r->prestress_value[i];
    if (r->k) s->k = r->k[i];
    if (r->q) s->q = r->q[i];
    if (r->force) s->force = r->force[i];
    if (r->target_value) s->target_value = r->target_value[i];
    if (r->orient) memcpy(s->orient, r->orient + 3 * i, sizeof s->orient);
    if (r->release) s->release = r->release[i];
}

int ctn_model_add_elements(ctn_model *m, const ctn_element_spec *spec, const ctn_element_rows *rows)
{
    if (!m || !spec || !rows || spec->size < sizeof(size_t) || rows->size < sizeof(size_t)) return CTN_ERR_INVALID;
    ctn_element_rows r;
    ctn_element_spec s;
    ctn_element_rows_init(&r);
    ctn_spec_copy(&r, sizeof r, rows);
    ctn_element_spec_init(&s);
    ctn_spec_copy(&s, sizeof s, spec);
    if (r.n && (!r.ids || !r.nodes || s.nnodes < 1)) return CTN_ERR_INVALID;
    int origin = m->line, rc = row_lines(m, r.n), beam = s.type && !strcmp(s.type, "beam");
    if (!rc && r.n) rc = CTN_ARRAY_RESERVE(m->ctx, m->elements, r.n);
    if (!rc && r.n) rc = CTN_ARRAY_RESERVE(m->ctx, m->conn, r.n * (size_t)s.nnodes);
    if (!rc && r.n) rc = ctn_idmap_reserve(m->ctx, &m->element_ids, r.n);
    for (size_t i = 0; i < r.n && !rc; i++) {
        if (origin > 0) m->line = origin + (int)i;
        row_spec(&r, i, &s);
        rc = beam ? ctn_model_add_beam(m, &s, r.segments ? r.segments[i] : 1) : ctn_model_add_element_spec(m, &s);
    }
    m->line = origin;
    return rc;
}
