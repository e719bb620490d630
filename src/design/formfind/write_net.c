/* A generated net in the found model (write.c): its `net` line written out as the
 * node, element and set lines it stands for, in the shape found (docs/format.md, "net"
 * and "Form finding"). The net's members and nodes are those of its sets NAME (the
 * members) and NAME.edge, NAME.inner (the nodes), which the generator made. */
#include "design/formfind/ff.h"
#include "io/parse.h"
#include "io/sink.h"

#include <string.h>

/* The set `name` of the model with the given kind (1 nodes, 0 elements), NULL if none. */
static const ctn_set *net_set(const ctn_model *m, const char *name, const char *suffix, int nodes)
{
    char full[CTN_NAME_MAX + 8];
    if (strlen(name) + strlen(suffix) >= sizeof full) return NULL;
    strcpy(full, name);
    strcat(full, suffix);
    int k = ctn_model_find_set(m, full);
    return k >= 0 && m->sets.v[k].nodes == nodes ? &m->sets.v[k] : NULL;
}

static void put_fix(ctn_wbuf *out, unsigned fix)
{
    static const char *const letter[] = { "x", "y", "z", "rx", "ry", "rz" };
    if (!fix) return;
    ctn_wbuf_puts(out, " fix=");
    for (int k = 0; k < 6; k++)
        if (fix & (1u << k)) ctn_wbuf_puts(out, letter[k]);
}

/* `set NAME KIND ids=A-B,C,...`: the members of s as ranges of consecutive ids. */
static void put_set(ctn_wbuf *out, const ctn_model *m, const ctn_set *s)
{
    ctn_wbuf_puts(out, "set ");
    ctn_wbuf_puts(out, s->name);
    ctn_wbuf_puts(out, s->nodes ? " nodes ids=" : " elements ids=");
    int first = 1, lo = 0, hi = 0;
    for (size_t i = 0; i <= s->size; i++) {
        int in = i < s->size && s->member[i];
        int id = in ? (s->nodes ? m->nodes.v[i].id : m->elements.v[i].id) : 0;
        if (in && hi && id == hi + 1) {
            hi = id;
            continue;
        }
        if (hi) {
            if (!first) ctn_wbuf_putc(out, ',');
            first = 0;
            ctn_wbuf_int(out, lo);
            if (hi > lo) {
                ctn_wbuf_putc(out, '-');
                ctn_wbuf_int(out, hi);
            }
        }
        lo = hi = in ? id : 0;
    }
    ctn_wbuf_putc(out, '\n');
}

int ctn_ff_write_net(ctn_ctx *ctx, const ctn_model *m, ctn_wbuf *out, const ctn_line *line, const char *raw)
{
    const char *name = line->ntok > 1 ? line->tok[1] : "";
    const ctn_set *members = net_set(m, name, "", 0), *edge = net_set(m, name, ".edge", 1),
                  *inner = net_set(m, name, ".inner", 1);
    if (!members || !edge || !inner || edge->size > m->nodes.n || inner->size != edge->size ||
        members->size > m->elements.n)
        return ctn_error(ctx, CTN_ERR_INVALID, "ctn_formfind_write: line %d of the text does not match the model",
                         line->line);
    const char *group = NULL;
    for (int t = 2; t < line->ntok; t++)
        if (!strncmp(line->tok[t], "group=", 6)) group = line->tok[t];
    ctn_wbuf_puts(out, "# catena formfind: ");
    ctn_wbuf_puts(out, raw);
    ctn_wbuf_puts(out, "\n# (the net above, written out as its nodes, members and sets in the shape found)\n");
    for (size_t i = 0; i < edge->size; i++) {
        if (!edge->member[i] && !inner->member[i]) continue;
        const ctn_node *p = &m->nodes.v[i];
        ctn_wbuf_puts(out, "node ");
        ctn_wbuf_int(out, p->id);
        for (int k = 0; k < 3; k++) {
            ctn_wbuf_putc(out, ' ');
            ctn_wbuf_g17(out, p->X[k]);
        }
        put_fix(out, p->fix);
        ctn_wbuf_putc(out, '\n');
    }
    for (size_t e = 0; e < members->size; e++) {
        if (!members->member[e]) continue;
        const ctn_element *el = &m->elements.v[e];
        const int *nd = ctn_elem_nodes(m, e);
        ctn_wbuf_puts(out, "element ");
        ctn_wbuf_int(out, el->id);
        ctn_wbuf_putc(out, ' ');
        ctn_wbuf_int(out, m->nodes.v[nd[0]].id);
        ctn_wbuf_putc(out, ' ');
        ctn_wbuf_int(out, m->nodes.v[nd[el->nnodes - 1]].id);
        ctn_wbuf_puts(out, " section=");
        ctn_wbuf_puts(out, m->sections.v[el->section].name);
        ctn_wbuf_puts(out, " l0=");
        ctn_wbuf_g17(out, el->l0);
        if (group) {
            ctn_wbuf_putc(out, ' ');
            ctn_wbuf_puts(out, group);
        }
        ctn_wbuf_putc(out, '\n');
    }
    put_set(out, m, members);
    put_set(out, m, edge);
    put_set(out, m, inner);
    return out->err;
}
