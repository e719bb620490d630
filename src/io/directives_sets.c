/* Selection and generation directives (docs/format.md): `set`, loads on a set or at a
 * point of a cable (`load set=`, `load cable= at=`), `include`. */
#include "io/parse.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* n numbers separated by commas (box=x0,y0,z0,x1,y1,z1). */
static int parse_list(ctn_line *l, const char *key, const char *v, int n, double *out)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", v);
    char *p = buf;
    for (int k = 0; k < n; k++) {
        char *c = strchr(p, ',');
        if ((k < n - 1) != (c != NULL))
            return ctn_parse_error(l, "set: %s= takes %d numbers separated by commas (found '%.60s')", key, n, v);
        if (c) *c = '\0';
        int rc = ctn_parse_num(l, "a coordinate", p, &out[k]);
        if (rc) return rc;
        p = c ? c + 1 : p;
    }
    return CTN_OK;
}

/* The node index j along cable c (0: its first end, count: its last). */
static size_t chain_node(const ctn_model *m, const ctn_cable *c, size_t j)
{
    const ctn_element *el = j ? &m->elements.v[c->first + j - 1] : NULL;
    return j ? (size_t)m->conn.v[el->conn + (size_t)el->nnodes - 1] : (size_t)c->node[0];
}

/* cable=A-B: the generated cable with end node ids A and B, into *c. */
static int cable_key(ctn_line *l, const char *what, const char *v, int *c, int *reversed)
{
    int a = 0, b = 0;
    char buf[64];
    snprintf(buf, sizeof buf, "%s", v);
    char *dash = strchr(buf, '-');
    if (!dash || dash == buf || !dash[1])
        return ctn_parse_error(l, "%s: cable= names a cable by its end nodes, NODE1-NODE2 (found '%.40s')", what, v);
    *dash = '\0';
    int rc = ctn_parse_int(l, "a node id", buf, &a);
    if (!rc) rc = ctn_parse_int(l, "a node id", dash + 1, &b);
    if (rc) return rc;
    *c = ctn_model_find_cable(l->m, what, a, b, reversed);        /* its error at this line */
    return *c < 0 ? CTN_ERR_MODEL : CTN_OK;
}

/* ids=ID,FIRST-LAST,...: the node or element ids, each defined. */
static int ids_key(ctn_line *l, const char *v, int nodes, unsigned char *member)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", v);
    for (char *p = buf, *next; p; p = next) {
        int first = 0, last = 0, rc;
        next = strchr(p, ',');
        if (next) *next++ = '\0';
        char *dash = *p ? strchr(p + 1, '-') : NULL;
        if (dash) *dash = '\0';
        rc = ctn_parse_int(l, nodes ? "a node id" : "an element id", p, &first);
        if (!rc) rc = ctn_parse_int(l, nodes ? "a node id" : "an element id", dash ? dash + 1 : p, &last);
        if (rc) return rc;
        if (last < first) return ctn_parse_error(l, "set: the range %d-%d is empty", first, last);
        if (last - first > 100000000) return ctn_parse_error(l, "set: the range %d-%d is too long", first, last);
        for (long long id = first; id <= last; id++) {
            int i = ctn_idmap_get(nodes ? &l->m->node_ids : &l->m->element_ids, (int)id);
            if (i < 0 && first == last)
                return ctn_parse_error(l, "set: undefined %s %lld", nodes ? "node" : "element", id);
            if (i >= 0) member[i] = 1;
        }
    }
    return CTN_OK;
}

/* box=: the nodes within it (bounds included), or the elements all of whose nodes are. */
static int box_key(ctn_line *l, const char *v, int nodes, unsigned char *member)
{
    double b[6];
    const ctn_model *m = l->m;
    int rc = parse_list(l, "box", v, 6, b);
    if (rc) return rc;
    for (int k = 0; k < 3; k++)
        if (b[k] > b[k + 3]) return ctn_parse_error(l, "set: box= is x0,y0,z0,x1,y1,z1 with x0 <= x1, y0 <= y1, z0 <= z1");
    for (size_t i = 0; i < m->nodes.n; i++) {
        const double *X = m->nodes.v[i].X;
        int in = 1;
        for (int k = 0; k < 3; k++) in &= X[k] >= b[k] && X[k] <= b[k + 3];
        if (nodes) member[i] = (unsigned char)in;
    }
    for (size_t e = 0; !nodes && e < m->elements.n; e++) {
        const ctn_element *el = &m->elements.v[e];
        int in = 1;
        for (int a = 0; a < el->nnodes; a++) {
            const double *X = m->nodes.v[m->conn.v[el->conn + (size_t)a]].X;
            for (int k = 0; k < 3; k++) in &= X[k] >= b[k] && X[k] <= b[k + 3];
        }
        member[e] = (unsigned char)in;
    }
    return CTN_OK;
}

/* set NAME nodes|elements box=x0,y0,z0,x1,y1,z1 | cable=NODE1-NODE2 | ids=ID,FIRST-LAST,... */
int ctn_parse_set(ctn_line *l)
{
    int rc = ctn_parse_positional(l, 2, "set NAME nodes|elements box=X0,Y0,Z0,X1,Y1,Z1|cable=NODE1-NODE2|ids=ID,FIRST-LAST,...");
    if (rc) return rc;
    int nodes = !strcmp(l->tok[2], "nodes");
    if (!nodes && strcmp(l->tok[2], "elements"))
        return ctn_parse_error(l, "set: expected 'nodes' or 'elements' after the name, found '%.40s'", l->tok[2]);
    const char *box = ctn_parse_key(l, 3, "box"), *cab = ctn_parse_key(l, 3, "cable"), *ids = ctn_parse_key(l, 3, "ids");
    if (!!box + !!cab + !!ids != 1) return ctn_parse_error(l, "set %s: give one of box=, cable=, ids=", l->tok[1]);
    if ((rc = ctn_parse_leftovers(l, 3, "set"))) return rc;
    ctn_model *m = l->m;
    size_t n = nodes ? m->nodes.n : m->elements.n;
    unsigned char *member = ctn_calloc(m->ctx, n ? n : 1, 1);
    if (!member) return CTN_ERR_NOMEM;
    if (box) rc = box_key(l, box, nodes, member);
    if (ids) rc = ids_key(l, ids, nodes, member);
    if (cab) {
        int c = -1, rev = 0;
        rc = cable_key(l, "set", cab, &c, &rev);
        for (size_t j = 0; !rc && j <= m->cables.v[c].count; j++) {
            if (nodes) member[chain_node(m, &m->cables.v[c], j)] = 1;
            else if (j < m->cables.v[c].count) member[m->cables.v[c].first + j] = 1;
        }
    }
    if (!rc) rc = ctn_model_add_set(m, l->tok[1], nodes, member, n);
    ctn_free(member);
    return rc;
}

/* fx= fy= fz= of a load by set or cable point: at least one. */
static int force_keys(ctn_line *l, double F[3])
{
    static const char *const keys[3] = { "fx", "fy", "fz" };
    int given = 0, rc = CTN_OK;
    for (int k = 0; k < 3 && !rc; k++) {
        F[k] = 0;
        given |= ctn_parse_key(l, 1, keys[k]) != NULL;
        rc = ctn_parse_key_num(l, 1, keys[k], 0, &F[k]);
    }
    if (!rc && !given) return ctn_parse_missing(l, 1, "load", "fx", " (give at least one of fx=, fy=, fz=)");
    return rc;
}

/* The node of cable c nearest the fraction t of its unstressed length from its end
 * `from` (0 or 1): ties go to the node nearer that end. */
static size_t at_node(const ctn_model *m, const ctn_cable *c, int reversed, double t)
{
    double total = 0, s = 0, best = INFINITY;
    size_t pick = 0;
    for (size_t j = 0; j < c->count; j++) total += m->elements.v[c->first + j].l0;
    double goal = t * total;
    for (size_t j = 0; j <= c->count; j++) {
        size_t jj = reversed ? c->count - j : j;
        double dist = fabs(s - goal);
        if (dist < best) best = dist, pick = jj;
        if (j < c->count) s += m->elements.v[c->first + (reversed ? c->count - 1 - j : j)].l0;
    }
    return chain_node(m, c, pick);
}

/* load set=NAME fx= fy= fz= | load cable=NODE1-NODE2 at=FRACTION fx= fy= fz= */
int ctn_parse_load_sel(ctn_line *l)
{
    double F[3], t = 0;
    const char *set = ctn_parse_key(l, 1, "set"), *cab = ctn_parse_key(l, 1, "cable");
    int rc = force_keys(l, F);
    if (!rc && cab) {
        if (!ctn_parse_key(l, 1, "at")) return ctn_parse_missing(l, 1, "load", "at", " (the fraction 0..1 of the cable's length)");
        rc = ctn_parse_key_num(l, 1, "at", 1, &t);
        if (!rc && !(t >= 0 && t <= 1)) return ctn_parse_error(l, "load: at= is a fraction of the cable's length, from 0 to 1 (found %g)", t);
    }
    if (!rc) rc = ctn_parse_leftovers(l, 1, "load");
    if (rc) return rc;
    ctn_model *m = l->m;
    if (cab) {
        int c = -1, rev = 0;
        if ((rc = cable_key(l, "load", cab, &c, &rev))) return rc;
        return ctn_model_add_load(m, m->nodes.v[at_node(m, &m->cables.v[c], rev, t)].id, F);
    }
    int s = ctn_model_find_set(m, set);
    if (s < 0) return ctn_parse_error(l, "load: unknown set '%.63s'", set);
    if (!m->sets.v[s].nodes) return ctn_parse_error(l, "load: set '%.63s' is an element set; a load needs a node set", set);
    for (size_t i = 0; i < m->sets.v[s].size && !rc; i++)
        if (m->sets.v[s].member[i]) rc = ctn_model_add_load(m, m->nodes.v[i].id, F);
    return rc;
}
