/* The deck: a model's lines (its includes' in place) gathered whole before any directive
 * runs, then run definitions first so that a definition may follow its use
 * (docs/format.md, "Order of the directives"). The lines are scanned once, in place;
 * each is kept as its first token and the length of its tokens, and rebuilt into tokens
 * when it runs. Phases, each in the file's order:
 *   0 units    1 material, function    2 section
 *   3 the mesh: gravity, node, the element families (and a `group` line names its group
 *     here, so that groups are numbered by their first mention); the node lines above
 *     the first generator (cable, beam, net) or below a mesh line that names them, and
 *     the first gravity below a mesh line, run first
 *   4 group, set    5 everything else (steps, cases and their loads, solve, ...)
 * A file in the order of these phases runs line by line as written. */
#include "io/deck.h"

#include "model/idmap.h"

#include <stdio.h>
#include <string.h>

enum { PH_UNITS, PH_MATERIAL, PH_SECTION, PH_MESH, PH_SETS, PH_REST, PH_COUNT };

typedef struct phase_of {
    const char *name;
    unsigned char phase;
    unsigned char refs;      /* mesh: first positional token that is a node id (0: none) */
    unsigned char nrefs;     /* how many (255: every positional token from refs on) */
} phase_of;

static const phase_of phases[] = {
    { "units", PH_UNITS, 0, 0 },      { "material", PH_MATERIAL, 0, 0 },
    { "function", PH_MATERIAL, 0, 0 }, { "section", PH_SECTION, 0, 0 },
    { "gravity", PH_MESH, 0, 0 },     { "node", PH_MESH, 0, 0 },
    { "element", PH_MESH, 2, 2 },     { "spring", PH_MESH, 2, 2 },
    { "rspring", PH_MESH, 2, 2 },     { "beam", PH_MESH, 2, 2 },
    { "catenary", PH_MESH, 2, 2 },    { "pulley", PH_MESH, 2, 255 },
    { "cable", PH_MESH, 1, 2 },       { "net", PH_MESH, 0, 0 },
    { "group", PH_SETS, 0, 0 },       { "set", PH_SETS, 0, 0 },
};

enum { K_GRAVITY = 4, K_NODE = 5, K_BEAM = 9, K_CABLE = 12, K_NET = 13, K_GROUP = 14, K_NONE = 255 };  /* in phases[] */

static unsigned char lookup(const char *word)
{
    for (size_t i = 0; i < sizeof phases / sizeof *phases; i++)
        if (word[0] == phases[i].name[0] && !strcmp(word, phases[i].name)) return (unsigned char)i;
    return K_NONE;
}

void ctn_deck_free(ctn_deck *d)
{
    if (!d) return;
    for (size_t i = 0; i < d->bufs.n; i++) ctn_free(d->bufs.v[i]);
    for (size_t i = 0; i < d->files.n; i++) ctn_free(d->files.v[i]);
    ctn_free(d->bufs.v);
    ctn_free(d->files.v);
    ctn_free(d->lines.v);
    memset(d, 0, sizeof *d);
}

int ctn_deck_keep(ctn_ctx *ctx, ctn_deck *d, char *buf)
{
    if (CTN_ARRAY_RESERVE(ctx, d->bufs, 1)) {
        ctn_free(buf);
        return CTN_ERR_NOMEM;
    }
    d->bufs.v[d->bufs.n++] = buf;
    return CTN_OK;
}

int ctn_deck_file(ctn_ctx *ctx, ctn_deck *d, const char *path, const char **out)
{
    size_t n = strlen(path) + 1;
    char *p = ctn_malloc(ctx, n, 1);
    if (!p) return CTN_ERR_NOMEM;
    memcpy(p, path, n);
    if (CTN_ARRAY_RESERVE(ctx, d->files, 1)) {
        ctn_free(p);
        return CTN_ERR_NOMEM;
    }
    d->files.v[d->files.n++] = p;
    *out = p;
    return CTN_OK;
}

int ctn_deck_add(ctn_line *l)
{
    ctn_deck *d = l->deck;
    unsigned char kind = lookup(l->tok[0]);
    if (CTN_ARRAY_RESERVE(l->m->ctx, d->lines, 1)) return CTN_ERR_NOMEM;
    const char *last = l->tok[l->ntok - 1];
    ctn_deck_line *x = &d->lines.v[d->lines.n++];
    x->text = l->tok[0];
    x->len = (size_t)(last - l->tok[0]) + strlen(last);
    x->file = l->file;
    x->line = l->line;
    x->phase = kind == K_NONE ? PH_REST : phases[kind].phase;
    x->hoist = 0;
    x->kind = kind;
    return CTN_OK;
}

/* The tokens of deck line x back into l (they are NUL-terminated in place). */
static void rebuild(ctn_line *l, const ctn_deck_line *x)
{
    const char *end = x->text + x->len;
    l->ntok = 0;
    l->used = 0;
    for (char *s = x->text; s < end && l->ntok < CTN_MAX_TOKENS;) {
        if (*s == '\0' || *s == ' ' || *s == '\t' || *s == '\v' || *s == '\f') {
            s++;
            continue;
        }
        l->tok[l->ntok++] = s;
        s += strlen(s);
    }
    l->file = x->file;
    l->line = x->line;
}

/* Run the directive of a line; a failed allocation is located at the line. */
static int run_directive(ctn_line *l)
{
    l->m->line = l->line;                           /* definitions record their line */
    int rc = ctn_parse_directive(l);
    if (rc == CTN_ERR_NOMEM) {
        char msg[CTN_MSG_MAX];
        snprintf(msg, sizeof msg, "%s", ctn_ctx_message(l->m->ctx));
        ctn_error_at(l->m->ctx, rc, l->file, l->line, "%s", msg);
    }
    return rc;
}

static int run_line(ctn_line *l, const ctn_deck_line *x, const char **origin)
{
    rebuild(l, x);
    if (*origin != x->file) {                       /* messages of the model name its file */
        ctn_model_set_origin(l->m, x->file, 0);
        *origin = x->file;
    }
    return run_directive(l);
}

/* A `group` line in the mesh phase: only its name, created where the file names it. */
static int declare_group(ctn_line *l, const ctn_deck_line *x, const char **origin)
{
    rebuild(l, x);
    if (l->ntok < 2 || strchr(l->tok[1], '=')) return CTN_OK;   /* its own run reports it */
    if (*origin != x->file) {
        ctn_model_set_origin(l->m, x->file, 0);
        *origin = x->file;
    }
    l->m->line = l->line;
    if (ctn_model_find_group(l->m, l->tok[1]) >= 0) return CTN_OK;
    int g = 0;
    return ctn_model_group_get(l->m, l->tok[1], &g);
}

/* The node ids a mesh line names (positional tokens), each checked against the line of
 * that node's definition: a node defined below a line that names it is hoisted. */
static void mark_refs(ctn_deck *d, const ctn_idmap *defs, size_t i, const phase_of *p, ctn_line *l)
{
    rebuild(l, &d->lines.v[i]);
    int end = p->nrefs == 255 ? l->ntok : p->refs + p->nrefs;
    for (int k = p->refs; k < end && k < l->ntok && !strchr(l->tok[k], '='); k++) {
        long long id = 0;
        if (!ctn_parse_integral(l->tok[k], &id) || id < 1 || id > 0x7fffffff) continue;
        int j = ctn_idmap_get(defs, (int)id);
        if (j > (int)i) d->lines.v[j].hoist = 1;
    }
}

/* Whether a mesh line numbers nodes of its own after the largest id so far. */
static int generates(unsigned char kind)
{
    return kind == K_CABLE || kind == K_NET || kind == K_BEAM;
}

/* Marked to run first: the node lines above the first generator (cable, beam, net), the
 * node lines a mesh line above them names, and the first gravity when a mesh line stands
 * above it. A node line below a generator that nothing above it names keeps its place,
 * so the generated ids are the file's. */
static int find_hoisted(ctn_deck *d, ctn_line *l)
{
    ctn_idmap defs;
    memset(&defs, 0, sizeof defs);
    int rc = CTN_OK, mesh_seen = 0, gravity_seen = 0, gen_seen = 0, late = 0;
    for (size_t i = 0; i < d->lines.n && !late; i++) {      /* a node line below an element's? */
        const ctn_deck_line *x = &d->lines.v[i];
        if (x->phase != PH_MESH || x->kind == K_GRAVITY) continue;
        if (x->kind != K_NODE) mesh_seen = 1;
        else late = mesh_seen;
    }
    mesh_seen = 0;
    for (size_t i = 0; i < d->lines.n && !rc && late; i++) {
        ctn_deck_line *x = &d->lines.v[i];
        if (x->kind != K_NODE) continue;
        rebuild(l, x);
        long long id = 0;
        if (l->ntok < 2 || !ctn_parse_integral(l->tok[1], &id) || id < 1 || id > 0x7fffffff) continue;
        if (ctn_idmap_get(&defs, (int)id) < 0) rc = ctn_idmap_put(l->m->ctx, &defs, (int)id, (int)i);
    }
    for (size_t i = 0; i < d->lines.n && !rc; i++) {
        ctn_deck_line *x = &d->lines.v[i];
        if (x->phase != PH_MESH) continue;
        const phase_of *p = &phases[x->kind];
        if (x->kind == K_GRAVITY) {
            x->hoist = mesh_seen && !gravity_seen;
            gravity_seen = 1;
        } else if (x->kind == K_NODE) {
            x->hoist |= !gen_seen;
        } else {
            mesh_seen = 1;
            gen_seen |= generates(x->kind);
            if (p->refs && defs.count) mark_refs(d, &defs, i, p, l);
        }
    }
    ctn_idmap_free(&defs);
    return rc;
}

/* Phase 3: the hoisted lines, then the others (group lines name their groups). */
static int run_mesh(ctn_deck *d, ctn_line *l, const char **origin)
{
    int rc = find_hoisted(d, l);
    for (int pass = 0; pass < 2 && !rc; pass++)
        for (size_t i = 0; i < d->lines.n && !rc; i++) {
            const ctn_deck_line *x = &d->lines.v[i];
            if (pass == 1 && x->kind == K_GROUP) rc = declare_group(l, x, origin);
            if (x->phase != PH_MESH || x->hoist != (pass == 0)) continue;
            rc = run_line(l, x, origin);
        }
    return rc;
}

/* A second `units` line must repeat the first: the model has one set of units, which
 * every value with a unit is converted to. */
static int check_units(ctn_deck *d, size_t i, ctn_line *l, int *first)
{
    if (*first < 0) {
        *first = (int)i;
        return CTN_OK;
    }
    const ctn_deck_line *a = &d->lines.v[*first], *b = &d->lines.v[i];
    if (a->len == b->len && !memcmp(a->text, b->text, a->len)) return CTN_OK;
    rebuild(l, b);
    return ctn_parse_error(l, "units: given twice, differently (first on line %d of %s): a model has one set of units",
                           a->line, a->file);
}

int ctn_deck_run(ctn_deck *d, ctn_line *l)
{
    int first_units = -1;
    const char *top = l->file, *origin = NULL;
    int rc = CTN_OK;
    for (int ph = 0; ph < PH_COUNT && !rc; ph++) {
        if (ph == PH_MESH) {
            rc = run_mesh(d, l, &origin);
            continue;
        }
        for (size_t i = 0; i < d->lines.n && !rc; i++) {
            if (d->lines.v[i].phase != ph) continue;
            if (ph == PH_UNITS) rc = check_units(d, i, l, &first_units);
            if (!rc) rc = run_line(l, &d->lines.v[i], &origin);
            if (!rc && (i & 0xffff) == 0) rc = ctn_interrupted(l->m->ctx);
        }
    }
    ctn_model_set_origin(l->m, top, 0);
    l->file = top;
    return rc;
}
