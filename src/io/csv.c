/* nodes.csv and elements.csv: the state at the end of the last step, one row per node
 * or element, numbers as "%.17g" (round-trip) and ids as "%d", C locale. */
#include "io/writer.h"

#include <string.h>

static int csv_begin(ctn_writer *w, const ctn_model *m, ctn_sink *sink, const char *header)
{
    int rc = ctn_writer_open(w, m, sink);
    if (!rc) ctn_wbuf_puts(&w->out, header);
    return w->out.err;
}

/* value, then ',' */
static void field(ctn_wbuf *b, double v)
{
    ctn_wbuf_g17(b, v);
    ctn_wbuf_putc(b, ',');
}

/* In a model with rotations, the rows go on with the rotations and reaction moments. */
static int nodes_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    return csv_begin(p, m, sink, ctn_model_has_rotations(m) ? "id,x,y,z,ux,uy,uz,fix,rx,ry,rz,thx,thy,thz,mx,my,mz\n"
                                                           : "id,x,y,z,ux,uy,uz,fix,rx,ry,rz\n");
}

/* ',' then each of the three values, comma-separated. */
static void fields3(ctn_wbuf *b, const double *v)
{
    for (int k = 0; k < 3; k++) {
        ctn_wbuf_putc(b, ',');
        ctn_wbuf_g17(b, v[k]);
    }
}

/* id,x,y,z,ux,uy,uz,fix,rx,ry,rz[,thx,thy,thz,mx,my,mz]; fix spelled with the letters of
 * the fixed DOFs (rx, ry, rz for the rotations); rx, ry, rz the reaction forces, thx,
 * thy, thz the rotations and mx, my, mz the reaction moments (th, m NULL: none). */
static void node_row(ctn_wbuf *b, const ctn_node_info *p, const double *d, const double *r, const double *th,
                     const double *m)
{
    static const char *const fix[6] = { "x", "y", "z", "rx", "ry", "rz" };
    ctn_wbuf_int(b, p->id);
    ctn_wbuf_putc(b, ',');
    for (int k = 0; k < 3; k++) field(b, p->X[k]);
    for (int k = 0; k < 3; k++) field(b, d[k]);
    for (int k = 0; k < 6; k++)
        if (p->fix & (1u << k)) ctn_wbuf_puts(b, fix[k]);
    fields3(b, r);
    if (th) fields3(b, th);
    if (m) fields3(b, m);
    ctn_wbuf_putc(b, '\n');
}

static int nodes_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    if (k + 1 < ctn_solution_step_count(s)) return CTN_OK;
    size_t nn = ctn_model_node_count(w->m);
    ctn_node_piece pc;
    for (size_t lo = 0; lo < nn && !w->out.err; lo = pc.hi) {
        if (w->pieces->nodes(w->pieces->ud, s, k, lo, nn, &pc)) return ctn_writer_mismatch(w);
        if (!pc.rot != !ctn_model_has_rotations(w->m)) return ctn_writer_mismatch(w);
        for (size_t i = pc.lo; i < pc.hi && !w->out.err; i++) {
            ctn_node_info n;
            if (ctn_model_node(w->m, i, &n)) return ctn_writer_mismatch(w);
            node_row(&w->out, &n, ctn_piece_d(&pc, i), ctn_piece_react(&pc, i), ctn_piece_rot(&pc, i),
                     ctn_piece_mom(&pc, i));
        }
    }
    return w->out.err;
}

/* Whether the model has a beam: its elements' rows then go on with the end forces. */
static int has_beams(const ctn_model *m)
{
    ctn_element_info e;
    for (size_t i = 0; i < ctn_model_element_count(m); i++)
        if (!ctn_model_element(m, i, &e) && !strcmp(e.type, "beam")) return 1;
    return 0;
}

/* Whether an element has more than two nodes (a pulley): elements.csv then ends with a
 * column `nodes`, every node id of the element in order, separated by spaces. */
static int has_chains(const ctn_model *m)
{
    ctn_element_info e;
    for (size_t i = 0; i < ctn_model_element_count(m); i++)
        if (!ctn_model_element(m, i, &e) && e.nnodes > 2) return 1;
    return 0;
}

static int elements_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    int rc = csv_begin(p, m, sink, has_beams(m) ? "id,node1,node2,l0,length,strain,force,stress,slack,utilisation,group,"
                                                  "fx1,fy1,fz1,mx1,my1,mz1,fx2,fy2,fz2,mx2,my2,mz2"
                                                : "id,node1,node2,l0,length,strain,force,stress,slack,utilisation,group");
    ctn_writer *w = p;
    if (!rc) ctn_wbuf_puts(&w->out, has_chains(m) ? ",nodes\n" : "\n");
    return rc ? rc : w->out.err;
}

/* The `nodes` field: the element's node ids in order, after a comma. */
static int nodes_field(ctn_writer *w, const ctn_element_info *e)
{
    ctn_wbuf_putc(&w->out, ',');
    for (int j = 0; j < e->nnodes; j++) {
        ctn_node_info n;
        if (ctn_model_node(w->m, (size_t)e->nodes[j], &n)) return ctn_writer_mismatch(w);
        if (j) ctn_wbuf_putc(&w->out, ' ');
        ctn_wbuf_int(&w->out, n.id);
    }
    return CTN_OK;
}

/* A beam's end forces in its local axes (ctn_solution_beam), 12 fields after a comma;
 * empty for the other elements. */
static void beam_fields(ctn_writer *w, const ctn_solution *s, size_t k, size_t i)
{
    ctn_beam_result b = { .size = sizeof b };
    int ok = !ctn_solution_beam(w->m, s, k, i, &b);
    for (int a = 0; a < 12; a++) {
        ctn_wbuf_putc(&w->out, ',');
        if (ok) ctn_wbuf_g17(&w->out, b.end[a / 6][a % 6]);
    }
}

/* A beam's utilisation (ctn_solution_beam) when its material has fy, else -1. */
static double beam_utilisation(ctn_writer *w, const ctn_solution *s, size_t k, size_t i)
{
    ctn_beam_result b = { .size = sizeof b };
    return !ctn_solution_beam(w->m, s, k, i, &b) && b.fy > 0 ? b.utilisation : -1;
}

/* id,node1,node2,l0,length,strain,force,stress,slack,utilisation,group (utilisation and
 * group empty when the section has no mbl / the element no group; a beam's utilisation,
 * beam_util >= 0, when its material has fy), without the line's end */
static int element_row(ctn_writer *w, const ctn_element_info *e, const ctn_element_state *es, double beam_util)
{
    ctn_node_info a, b;
    if (ctn_model_node(w->m, (size_t)e->node[0], &a) || ctn_model_node(w->m, (size_t)e->node[1], &b))
        return ctn_writer_mismatch(w);
    int ids[3] = { e->id, a.id, b.id };
    for (int k = 0; k < 3; k++) {
        ctn_wbuf_int(&w->out, ids[k]);
        ctn_wbuf_putc(&w->out, ',');
    }
    double v[5] = { e->l0, es->length, es->strain, es->force, es->stress };
    for (int k = 0; k < 5; k++) field(&w->out, v[k]);
    ctn_wbuf_int(&w->out, es->slack);
    ctn_wbuf_putc(&w->out, ',');
    if (e->capacity > 0) ctn_wbuf_g17(&w->out, ctn_utilisation(e, es));
    else if (beam_util >= 0) ctn_wbuf_g17(&w->out, beam_util);
    ctn_wbuf_putc(&w->out, ',');
    if (e->group) ctn_wbuf_puts(&w->out, e->group);
    return CTN_OK;
}

static int elements_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    if (k + 1 < ctn_solution_step_count(s)) return CTN_OK;
    int beams = has_beams(w->m), chains = has_chains(w->m);
    for (size_t i = 0; i < ctn_model_element_count(w->m) && !w->out.err; i++) {
        ctn_element_info e;
        ctn_element_state es;
        if (ctn_model_element(w->m, i, &e) || ctn_solution_step_element(s, k, i, &es) ||
            element_row(w, &e, &es, beams ? beam_utilisation(w, s, k, i) : -1)) return ctn_writer_mismatch(w);
        if (beams) beam_fields(w, s, k, i);
        if (chains && nodes_field(w, &e)) return ctn_writer_mismatch(w);
        ctn_wbuf_putc(&w->out, '\n');
    }
    return w->out.err;
}

static int csv_end(void *p)
{
    ctn_writer *w = p;
    return w->out.err;
}

const ctn_writer_ops ctn_writer_nodes_csv = { "nodes.csv", sizeof(ctn_writer), nodes_begin,
                                              nodes_step, csv_end };
const ctn_writer_ops ctn_writer_elements_csv = { "elements.csv", sizeof(ctn_writer),
                                                 elements_begin, elements_step, csv_end };
