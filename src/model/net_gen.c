/* The `net` generator: a rectangular cable net, its supports and its sets (net_gen.h). */
#include "model/net_gen.h"

#include "catena/formfind.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define CTN_NET_MAX 100000      /* bays along one side at most */

static int check(const ctn_model *m, const ctn_net_spec *s)
{
    if (s->nx < 2 || s->ny < 2 || s->nx > CTN_NET_MAX || s->ny > CTN_NET_MAX)
        return ctn_model_error(m, CTN_ERR_MODEL, "net %s: nx and ny must be from 2 to %d (got %d, %d)", s->name, CTN_NET_MAX,
                               s->nx, s->ny);
    if (!(s->lx > 0) || !(s->ly > 0) || !isfinite(s->lx) || !isfinite(s->ly))
        return ctn_model_error(m, CTN_ERR_MODEL, "net %s: lx and ly must be positive (got %g, %g)", s->name, s->lx, s->ly);
    if (!isfinite(s->h)) return ctn_model_error(m, CTN_ERR_MODEL, "net %s: h must be finite", s->name);
    if (!s->section || ctn_model_find_section(m, s->section) < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "net %s: undefined section '%s'", s->name, s->section ? s->section : "");
    double nodes = (double)(s->nx + 1) * (s->ny + 1), members = 2.0 * s->nx * s->ny;
    long lim = ctn_ctx_model_limit(m->ctx);
    if (m->max_node_id + nodes > 0x7fffffff || m->max_element_id + members > 0x7fffffff)
        return ctn_model_error(m, CTN_ERR_MODEL, "net %s: generated ids would overflow", s->name);
    if (lim && (m->nodes.n + nodes > (double)lim || m->elements.n + members > (double)lim))
        return ctn_model_error(m, CTN_ERR_MODEL, "model too large: net %s of %.0f nodes exceeds the caller's limit of %ld",
                               s->name, nodes, lim);
    return CTN_OK;
}

/* The reference position of grid point (i, j). */
static void grid_point(const ctn_net_spec *s, int i, int j, double X[3])
{
    double a = 0.5 * s->lx, b = 0.5 * s->ly;
    double dx = -a + i * (s->lx / s->nx), dy = -b + j * (s->ly / s->ny);
    X[0] = s->origin[0] + dx;
    X[1] = s->origin[1] + dy;
    X[2] = s->origin[2] + (s->shape == CTN_NET_HYPAR ? s->h * (dx * dx / (a * a) - dy * dy / (b * b)) : 0.0);
}

static int on_edge(const ctn_net_spec *s, int i, int j)
{
    return i == 0 || j == 0 || i == s->nx || j == s->ny;
}

static int add_nodes(ctn_model *m, const ctn_net_spec *s, int n0)
{
    int rc = CTN_OK;
    for (int i = 0; i <= s->nx && !rc; i++)
        for (int j = 0; j <= s->ny && !rc; j++) {
            double X[3];
            grid_point(s, i, j, X);
            int corner = (i == 0 || i == s->nx) && (j == 0 || j == s->ny);     /* no member */
            unsigned fix = corner ? CTN_FIX_X | CTN_FIX_Y | CTN_FIX_Z : on_edge(s, i, j) ? s->fix : 0;
            rc = ctn_model_add_node(m, n0 + i * (s->ny + 1) + j, X, fix);
        }
    return rc;
}

static int add_member(ctn_model *m, const ctn_net_spec *s, int id, int a, int b)
{
    ctn_element_spec e;
    int nodes[2] = { a, b };
    ctn_element_spec_init(&e);
    e.id = id;
    e.nnodes = 2;
    e.nodes = nodes;
    e.section = s->section;
    e.l0 = CTN_L0_DEFAULT;
    e.prestress = s->prestress;
    e.prestress_value = s->prestress_value;
    e.group = s->group;
    return ctn_model_add_element_spec(m, &e);
}

/* The members, in the order of net_gen.h; *count of them. */
static int add_members(ctn_model *m, const ctn_net_spec *s, int n0, int e0, int *count)
{
    int rc = CTN_OK, id = e0;
    for (int i = 0; i <= s->nx && !rc; i++)
        for (int j = 0; j <= s->ny && !rc; j++) {
            int a = n0 + i * (s->ny + 1) + j;
            if (i < s->nx && !(j == 0 || j == s->ny)) rc = add_member(m, s, id++, a, a + s->ny + 1);
            if (!rc && j < s->ny && !(i == 0 || i == s->nx)) rc = add_member(m, s, id++, a, a + 1);
        }
    *count = id - e0;
    return rc;
}

/* NAME (members), NAME.edge, NAME.inner (nodes). */
static int add_sets(ctn_model *m, const ctn_net_spec *s, size_t node0, size_t elem0)
{
    size_t nn = m->nodes.n, ne = m->elements.n, n = nn > ne ? nn : ne;
    unsigned char *member = ctn_calloc(m->ctx, n ? n : 1, 1);
    if (!member) return CTN_ERR_NOMEM;
    char name[CTN_NAME_MAX + 8];
    memset(member + elem0, 1, ne - elem0);
    int rc = ctn_model_add_set(m, s->name, 0, member, ne);
    for (int pass = 0; pass < 2 && !rc; pass++) {
        memset(member, 0, n);
        for (size_t k = node0; k < nn; k++) {
            int i = (int)((k - node0) / (size_t)(s->ny + 1)), j = (int)((k - node0) % (size_t)(s->ny + 1));
            member[k] = on_edge(s, i, j) == (pass == 0);
        }
        snprintf(name, sizeof name, "%s.%s", s->name, pass ? "inner" : "edge");
        rc = ctn_model_add_set(m, name, 1, member, nn);
    }
    ctn_free(member);
    return rc;
}

int ctn_model_add_net(ctn_model *m, const ctn_net_spec *s, int *first_node, int *first_element)
{
    if (!m || !s || !s->name) return CTN_ERR_INVALID;
    int rc = check(m, s), count = 0;
    if (rc) return rc;
    int n0 = m->max_node_id + 1, e0 = m->max_element_id + 1;
    size_t node0 = m->nodes.n, elem0 = m->elements.n;
    if (!rc) rc = add_nodes(m, s, n0);
    if (!rc) rc = add_members(m, s, n0, e0, &count);
    if (!rc && (s->q > 0 || s->force > 0)) rc = ctn_model_set_force_density(m, e0, e0 + count - 1, s->q, s->force);
    if (!rc) rc = add_sets(m, s, node0, elem0);
    if (first_node) *first_node = n0;
    if (first_element) *first_element = e0;
    return rc;
}
