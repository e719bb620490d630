/* The found model as a .cable file: the source text line by line, with the lines form
 * finding changed rewritten (node coordinates, l0= in place of q=/force=, cables and nets
 * expanded into their nodes and elements, a net's sets as id lists) and every other line copied as it is. Atomic. */
#include "design/formfind/ff.h"
#include "io/atomic.h"
#include "io/parse.h"
#include "io/sink.h"

#include <math.h>
#include <string.h>

typedef struct ff_writer {
    ctn_ctx *ctx;
    const ctn_model *m;
    ctn_wbuf *out;
    ctn_line line;          /* the tokens of the line being written */
    const char *comment;    /* its comment ('#' on), "" if none */
    size_t cable;           /* cables met so far */
} ff_writer;

/* Keys that set or imply the unstressed length (element, spring), and those of a cable's
 * generation (its length or a target for it, placement, start, prestress): form finding
 * replaces them. Any other key (group=, ...) carries over to the lines written. */
static const char *const length_keys[] = { "l0", "N0", "s0", "eps0", "q", "force" };
static const char *const cable_keys[] = { "section", "n", "length", "H", "sag", "tension", "shape", "start",
                                          "guess", "N0", "s0", "eps0", "q", "force" };

static int has_key(const char *tok, const char *const *keys, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        size_t kl = strlen(keys[k]);
        if (!strncmp(tok, keys[k], kl) && tok[kl] == '=') return 1;
    }
    return 0;
}

static void put_tokens(ff_writer *w, int from, const char *const *drop, size_t ndrop)
{
    for (int t = from; t < w->line.ntok; t++) {
        if (drop && has_key(w->line.tok[t], drop, ndrop)) continue;
        ctn_wbuf_putc(w->out, ' ');
        ctn_wbuf_puts(w->out, w->line.tok[t]);
    }
}

static void put_node(ff_writer *w, const ctn_node *p)
{
    ctn_wbuf_puts(w->out, "node ");
    ctn_wbuf_int(w->out, p->id);
    for (int k = 0; k < 3; k++) {
        ctn_wbuf_putc(w->out, ' ');
        ctn_wbuf_g17(w->out, p->X[k]);
    }
}

static void put_l0(ff_writer *w, double l0)
{
    ctn_wbuf_puts(w->out, " l0=");
    ctn_wbuf_g17(w->out, l0);
}

static void end_line(ff_writer *w)
{
    if (*w->comment) {
        ctn_wbuf_putc(w->out, ' ');
        ctn_wbuf_puts(w->out, w->comment);
    }
    ctn_wbuf_putc(w->out, '\n');
}

static int not_source(ff_writer *w)
{
    return ctn_error(w->ctx, CTN_ERR_INVALID, "ctn_formfind_write: line %d of the text does not match the model",
                     w->line.line);
}

/* Index of the node or element whose id is token 1, -1 if none. */
static int lookup(const ff_writer *w, const ctn_idmap *ids)
{
    long long id = 0;
    if (w->line.ntok < 2 || !ctn_parse_integral(w->line.tok[1], &id) || id < 1 || id > 0x7fffffff) return -1;
    return ctn_idmap_get(ids, (int)id);
}

static int write_node(ff_writer *w, const char *raw)
{
    int i = lookup(w, &w->m->node_ids);
    if (i < 0) return not_source(w);
    const ctn_node *p = &w->m->nodes.v[i];
    if (p->fix == CTN_FIX_ALL) {                     /* an anchor: as it was */
        ctn_wbuf_puts(w->out, raw);
        ctn_wbuf_putc(w->out, '\n');
        return CTN_OK;
    }
    put_node(w, p);
    put_tokens(w, 5, NULL, 0);
    end_line(w);
    return CTN_OK;
}

static int write_member(ff_writer *w)
{
    int e = lookup(w, &w->m->element_ids);
    if (e < 0 || w->line.ntok < 4) return not_source(w);
    for (int t = 0; t < 4; t++) {
        if (t) ctn_wbuf_putc(w->out, ' ');
        ctn_wbuf_puts(w->out, w->line.tok[t]);
    }
    put_tokens(w, 4, length_keys, sizeof length_keys / sizeof *length_keys);
    put_l0(w, w->m->elements.v[e].l0);
    end_line(w);
    return CTN_OK;
}

/* A generated cable: its interior nodes, then its elements, each with the keys of the
 * cable line that are not the generator's (so keys added later carry over). */
static int write_cable(ff_writer *w, const char *raw)
{
    const ctn_model *m = w->m;
    if (w->cable >= m->cables.n) return not_source(w);
    const ctn_cable *c = &m->cables.v[w->cable++];
    ctn_wbuf_puts(w->out, "# catena formfind: ");
    ctn_wbuf_puts(w->out, raw);
    ctn_wbuf_puts(w->out, "\n# (the cable above, expanded into its nodes and elements in the shape found)\n");
    for (size_t k = 0; k + 1 < c->count; k++) {
        put_node(w, &m->nodes.v[ctn_elem_nodes(m, c->first + k)[1]]);
        ctn_wbuf_putc(w->out, '\n');
    }
    for (size_t k = 0; k < c->count; k++) {
        const ctn_element *el = &m->elements.v[c->first + k];
        const int *nd = ctn_elem_nodes(m, c->first + k);
        ctn_wbuf_puts(w->out, "element ");
        ctn_wbuf_int(w->out, el->id);
        ctn_wbuf_putc(w->out, ' ');
        ctn_wbuf_int(w->out, m->nodes.v[nd[0]].id);
        ctn_wbuf_putc(w->out, ' ');
        ctn_wbuf_int(w->out, m->nodes.v[nd[1]].id);
        ctn_wbuf_puts(w->out, " section=");
        ctn_wbuf_puts(w->out, m->sections.v[el->section].name);
        put_l0(w, el->l0);
        put_tokens(w, 3, cable_keys, sizeof cable_keys / sizeof *cable_keys);
        end_line(w);
    }
    return CTN_OK;
}

/* One source line (raw, NUL-terminated; tokenized in scratch). */
static int write_line(ff_writer *w, const char *raw, char *scratch)
{
    strcpy(scratch, raw);
    const char *hash = strchr(raw, '#');
    w->comment = hash ? hash : "";
    int rc = ctn_read_tokenize(&w->line, scratch);
    if (rc) return rc;
    const char *d = w->line.ntok ? w->line.tok[0] : "";
    if (!strcmp(d, "node")) return write_node(w, raw);
    if (!strcmp(d, "element") || !strcmp(d, "spring")) return write_member(w);
    if (!strcmp(d, "cable")) return write_cable(w, raw);
    if (!strcmp(d, "net")) return ctn_ff_write_net(w->ctx, w->m, w->out, &w->line, raw);
    ctn_wbuf_puts(w->out, raw);
    ctn_wbuf_putc(w->out, '\n');
    return CTN_OK;
}

/* Every line of text, as the reader splits them (a UTF-8 byte order mark dropped). */
static int write_lines(ff_writer *w, const char *text, size_t len)
{
    char *raw = ctn_malloc(w->ctx, 2 * len + 2, 1);
    if (!raw) return CTN_ERR_NOMEM;
    char *scratch = raw + len + 1;
    int rc = CTN_OK;
    size_t start = len >= 3 && !memcmp(text, "\xef\xbb\xbf", 3) ? 3 : 0;
    for (w->line.line = 1; !rc && start < len; w->line.line++) {
        size_t next, end = ctn_read_line_end(text, start, len, &next);
        memcpy(raw, text + start, end - start);
        raw[end - start] = '\0';
        rc = write_line(w, raw, scratch);
        if (!rc) rc = w->out->err;
        start = end == len ? len : next;
    }
    if (!rc && w->cable != w->m->cables.n) rc = not_source(w);
    ctn_free(raw);
    return rc;
}

static int check_finite(ctn_ctx *ctx, const ctn_model *m)
{
    for (size_t i = 0; i < m->nodes.n; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(m->nodes.v[i].X[k])) return ctn_error(ctx, CTN_ERR_INVALID, "the model holds a NaN or Inf; not written");
    for (size_t e = 0; e < m->elements.n; e++)
        if (!isfinite(m->elements.v[e].l0)) return ctn_error(ctx, CTN_ERR_INVALID, "the model holds a NaN or Inf; not written");
    return CTN_OK;
}

int ctn_formfind_write(ctn_ctx *ctx, const ctn_model *m, const char *text, size_t len, const char *path)
{
    if (!m || !path || (!text && len)) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_formfind_write: bad arguments");
    if (memchr(text ? text : "", '\0', len)) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_formfind_write: NUL byte in the text");
    int rc = check_finite(ctx, m);
    if (rc) return rc;
    ctn_atomic_file af;
    if ((rc = ctn_atomic_open(ctx, path, &af))) return rc;
    ctn_sink sink = ctn_atomic_sink(&af);
    ctn_wbuf out;
    ff_writer w;
    memset(&w, 0, sizeof w);
    w.ctx = ctx;
    w.m = m;
    w.out = &out;
    w.line.m = (ctn_model *)m;
    w.line.file = m->file;
    if (!(rc = ctn_wbuf_open(&out, ctx, &sink))) {
        ctn_wbuf_puts(&out, "# catena formfind: the shape found from ");
        ctn_wbuf_puts(&out, *m->file ? m->file : "a model");
        ctn_wbuf_puts(&out, "; `catena solve` of this file stays where it is\n");
        rc = write_lines(&w, text, len);
    }
    int rc2 = ctn_wbuf_close(&out);
    if (!rc) rc = rc2;
    if (!rc) rc = ctn_atomic_close(&af);
    if (rc) {
        ctn_atomic_abort(&af);
        return rc;
    }
    return ctn_atomic_commit(&af);
}
