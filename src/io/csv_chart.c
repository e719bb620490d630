/* sag_tension.csv: the sag-tension chart (`sagtension`, docs/format.md), one row per
 * chart row and cable (each generated cable, then each catenary element), the values of
 * the JSON's "sag_tension"; numbers as "%.17g", C locale. Written into a result
 * directory only when the model has a chart. */
#include "io/writer.h"

#include <math.h>
#include <string.h>

typedef struct chart_cable {
    int node1, node2;
    double sag, hi, lo, length, l0;
    int has_sag;
} chart_cable;

static int node_id(const ctn_model *m, int index)
{
    ctn_node_info p;
    return ctn_model_node(m, (size_t)index, &p) ? 0 : p.id;
}

static int chart_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    ctn_writer *w = p;
    int rc = ctn_writer_open(w, m, sink);
    if (!rc) ctn_wbuf_puts(&w->out, "name,case,dT,node1,node2,sag,max_tension,min_tension,stretched_length,unstressed_length\n");
    return w->out.err;
}

/* Generated cable i of solution s (a case's: its step 0). */
static int meshed(const ctn_model *m, const ctn_solution *s, size_t i, chart_cable *c)
{
    ctn_cable_info ci;
    ctn_element_info ei;
    ctn_element_state es;
    if (ctn_model_cable(m, i, &ci)) return CTN_ERR_INVALID;
    c->hi = -INFINITY;
    c->lo = INFINITY;
    c->length = c->l0 = 0;
    for (size_t e = ci.first; e < ci.first + ci.count; e++) {
        if (ctn_model_element(m, e, &ei) || ctn_solution_step_element(s, 0, e, &es)) return CTN_ERR_INVALID;
        c->hi = fmax(c->hi, es.force);
        c->lo = fmin(c->lo, es.force);
        c->length += es.length;
        c->l0 += ei.l0;
    }
    c->node1 = node_id(m, ci.node[0]);
    c->node2 = node_id(m, ci.node[1]);
    c->has_sag = !ctn_solution_step_cable_sag(m, s, 0, i, &c->sag);
    return CTN_OK;
}

/* Catenary element e (as the JSON: the smallest tension is H when both supports lift). */
static int catenary(const ctn_model *m, const ctn_solution *s, size_t e, const ctn_element_info *ei, chart_cable *c)
{
    ctn_catenary_result r = { .size = sizeof r };
    if (ctn_solution_catenary(m, s, 0, e, &r)) return CTN_ERR_INVALID;
    c->hi = fmax(r.tension[0], r.tension[1]);
    c->lo = r.V[0] > 0 && r.V[1] > 0 ? r.H : fmin(r.tension[0], r.tension[1]);
    c->node1 = node_id(m, ei->nodes[0]);
    c->node2 = node_id(m, ei->nodes[1]);
    c->sag = r.sag;
    c->has_sag = 1;
    c->length = r.length;
    c->l0 = ei->l0;
    return CTN_OK;
}

static void row(ctn_wbuf *b, const char *name, const char *base, double dT, const chart_cable *c)
{
    const double v[5] = { c->sag, c->hi, c->lo, c->length, c->l0 };
    ctn_wbuf_puts(b, name);
    ctn_wbuf_putc(b, ',');
    if (base) ctn_wbuf_puts(b, base);
    ctn_wbuf_putc(b, ',');
    ctn_wbuf_g17(b, dT);
    ctn_wbuf_putc(b, ',');
    ctn_wbuf_int(b, c->node1);
    ctn_wbuf_putc(b, ',');
    ctn_wbuf_int(b, c->node2);
    for (int k = 0; k < 5; k++) {
        ctn_wbuf_putc(b, ',');
        if (k || c->has_sag) ctn_wbuf_g17(b, v[k]);
    }
    ctn_wbuf_putc(b, '\n');
}

/* The rows of chart row r. */
static int chart_row(ctn_writer *w, const ctn_solution *s, size_t r)
{
    const ctn_model *m = w->m;
    size_t i = 0, nc = ctn_model_cable_count(m), ne = ctn_model_element_count(m);
    double dT = 0;
    const char *base = NULL, *name = NULL;
    const ctn_solution *cs = NULL;
    chart_cable c;
    if (ctn_model_chart_row(m, r, &i, &dT, &base) || ctn_model_case_info(m, i, &name, NULL, NULL) ||
        !(cs = ctn_solution_case(s, i)))
        return ctn_writer_mismatch(w);
    for (size_t k = 0; k < nc; k++) {
        if (meshed(m, cs, k, &c)) return ctn_writer_mismatch(w);
        row(&w->out, name, base, dT, &c);
    }
    for (size_t e = 0; e < ne; e++) {
        ctn_element_info ei;
        if (ctn_model_element(m, e, &ei) || strcmp(ei.type, "catenary")) continue;
        if (catenary(m, cs, e, &ei, &c)) return ctn_writer_mismatch(w);
        row(&w->out, name, base, dT, &c);
    }
    return w->out.err;
}

/* The chart's states are cases: written once, at the last step. */
static int chart_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    if (k + 1 < ctn_solution_step_count(s)) return CTN_OK;
    for (size_t r = 0; r < ctn_model_chart_count(w->m) && !w->out.err; r++) chart_row(w, s, r);
    return w->out.err;
}

static int chart_end(void *p)
{
    ctn_writer *w = p;
    return w->out.err;
}

const ctn_writer_ops ctn_writer_chart_csv = { "sag_tension.csv", sizeof(ctn_writer), chart_begin, chart_step, chart_end };
