/* Result files: nodes.csv, elements.csv and result.json in a directory, each written
 * atomically, numbers as %.17g in the C locale. */
#include "io/atomic.h"
#include "io/strbuf.h"
#include "model/model.h"
#include "solve/solution.h"
#include "catena/io.h"

#include <errno.h>
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

static int all_finite(const ctn_solution *s)
{
    for (size_t k = 0; k < s->nsteps; k++) {
        const ctn_step_state *st = &s->steps[k];
        for (size_t i = 0; i < 3 * s->nn; i++)
            if (!isfinite(st->d[i]) || !isfinite(st->react[i])) return 0;
        for (size_t e = 0; e < s->ne; e++)
            if (!isfinite(st->elem[e].force) || !isfinite(st->elem[e].length)) return 0;
    }
    return 1;
}

static void nodes_csv(ctn_strbuf *b, const ctn_model *m, const ctn_solution *s)
{
    ctn_sb_printf(b, "id,x,y,z,ux,uy,uz,fix,rx,ry,rz\n");
    for (size_t i = 0; i < m->nodes.n; i++) {
        const ctn_node *p = &m->nodes.v[i];
        const double *d = ctn_solution_displacements(s) + 3 * i, *r = ctn_solution_reactions(s) + 3 * i;
        ctn_sb_printf(b, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s%s%s,%.17g,%.17g,%.17g\n",
                      p->id, p->X[0], p->X[1], p->X[2], d[0], d[1], d[2],
                      p->fix & CTN_FIX_X ? "x" : "", p->fix & CTN_FIX_Y ? "y" : "",
                      p->fix & CTN_FIX_Z ? "z" : "", r[0], r[1], r[2]);
    }
}

static void elements_csv(ctn_strbuf *b, const ctn_model *m, const ctn_solution *s)
{
    ctn_sb_printf(b, "id,node1,node2,l0,length,strain,force,stress,slack\n");
    for (size_t i = 0; i < m->elements.n; i++) {
        const ctn_element *e = &m->elements.v[i];
        const ctn_element_state *st = &s->steps[s->nsteps - 1].elem[i];
        ctn_sb_printf(b, "%d,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n", e->id,
                      m->nodes.v[ctn_elem_nodes(m, i)[0]].id, m->nodes.v[ctn_elem_nodes(m, i)[e->nnodes - 1]].id, e->l0,
                      st->length, st->strain, st->force, st->stress, st->slack);
    }
}

/* Stage one file of the set: dir/name; its temporary name in *tmp. */
static int stage(ctn_ctx *ctx, const char *dir, const char *name, const char *text, size_t n,
                 char **tmp)
{
    char path[4096];
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, name) >= sizeof path)
        return ctn_error(ctx, CTN_ERR_IO, "%s: path too long", dir);
    return ctn_atomic_stage(ctx, path, text, n, tmp);
}

/* Render the three files into memory. */
static int render(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s, ctn_strbuf *nb,
                  ctn_strbuf *eb, char **json)
{
    int rc = ctn_result_json(ctx, m, s, 1, json);
    if (rc) return rc;
    locale_t c = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    locale_t old = c ? uselocale(c) : (locale_t)0;
    nodes_csv(nb, m, s);
    elements_csv(eb, m, s);
    if (c) {
        uselocale(old);
        freelocale(c);
    }
    rc = nb->err ? nb->err : eb->err;
    return rc ? ctn_error(ctx, rc, "out of memory writing CSV") : CTN_OK;
}

/* A target that exists must be a regular file (checked before anything is renamed). */
static int check_targets(ctn_ctx *ctx, const char *dir, const char *const *names)
{
    for (int i = 0; i < 3; i++) {
        char path[4096];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        if (!stat(path, &st) && !S_ISREG(st.st_mode))
            return ctn_error(ctx, CTN_ERR_IO, "%s: exists and is not a regular file", path);
    }
    return CTN_OK;
}

/* All three files are staged before any replaces an older one, so a failure leaves the
 * previous set (or nothing) in place, never a mix. */
int ctn_write_results(ctn_ctx *ctx, const char *dir, const ctn_model *m,
                      const ctn_solution *s)
{
    static const char *names[3] = { "result.json", "nodes.csv", "elements.csv" };
    if (!dir || !m || !s) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_write_results: bad arguments");
    if (!all_finite(s)) return ctn_error(ctx, CTN_ERR_INVALID, "result holds a NaN or Inf; not written");
    if (mkdir(dir, 0755) && errno != EEXIST)
        return ctn_error(ctx, CTN_ERR_IO, "%s: cannot create directory: %s", dir, strerror(errno));
    ctn_strbuf nb = { ctx, NULL, 0, 0, 0 }, eb = { ctx, NULL, 0, 0, 0 };
    char *json = NULL, *tmp[3] = { NULL, NULL, NULL };
    int rc = check_targets(ctx, dir, names);
    if (!rc) rc = render(ctx, m, s, &nb, &eb, &json);
    const char *text[3] = { json, nb.s, eb.s };
    size_t len[3] = { json ? strlen(json) : 0, nb.n, eb.n };
    for (int i = 0; i < 3 && !rc; i++) rc = stage(ctx, dir, names[i], text[i], len[i], &tmp[i]);
    for (int i = 0; i < 3; i++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        if (!rc) rc = ctn_atomic_commit(ctx, tmp[i], path);
        else ctn_atomic_abort(tmp[i]);
    }
    ctn_json_free(json);
    ctn_sb_free(&nb);
    ctn_sb_free(&eb);
    return rc;
}
