/* External nodal forces and whole-model validation. */
#include "element/element.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Loads that belong to the elements (self-weight), asked of each element's family. */
static void add_element_loads(const ctn_model *m, double *f)
{
    for (size_t i = 0; i < m->elements.n; i++) {
        const ctn_element_ops *ops = ctn_element_family(m->elements.v[i].type);
        if (ops->load) ops->load(m, i, f);
    }
}

static void add_segment_hload(const ctn_model *m, double q, const double u[3], int p, int r, double *f)
{
    const double *a = m->nodes.v[p].X, *b = m->nodes.v[r].X;
    double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    double along = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
    double p2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - along * along;
    double P = 0.5 * q * sqrt(p2 > 0 ? p2 : 0);
    for (int k = 0; k < 3; k++) {
        f[3 * (size_t)p + (size_t)k] += P * u[k];
        f[3 * (size_t)r + (size_t)k] += P * u[k];
    }
}

/* Horizontal loads: q times the reference projection of each segment of an element on
 * the plane normal to gravity, half to each of its nodes, along gravity's direction. */
static void add_hloads(const ctn_model *m, const ctn_loadsel *sel, int dead_only, double *f)
{
    double g = sqrt(m->gravity[0] * m->gravity[0] + m->gravity[1] * m->gravity[1] +
                    m->gravity[2] * m->gravity[2]);
    if (!(g > 0)) return;
    double u[3] = { m->gravity[0] / g, m->gravity[1] / g, m->gravity[2] / g };
    for (size_t h = 0; h < m->hloads.n; h++) {
        const ctn_hload *hl = &m->hloads.v[h];
        double w = ctn_loadsel_weight(sel, hl->step);
        if (w == 0 || (dead_only && !hl->reference)) continue;
        for (size_t i = 0; i < m->elements.n; i++) {
            const ctn_element *e = &m->elements.v[i];
            if (!ctn_hload_on(m, hl, i)) continue;
            const int *nd = ctn_elem_nodes(m, i);
            for (int s = 0; s + 1 < e->nnodes; s++)
                add_segment_hload(m, w * hl->q, u, nd[s], nd[s + 1], f);
        }
    }
}

/* v (3 per node) += the records of a selection (forces or moments). */
static void add_nodal(const ctn_pload *v, size_t n, const ctn_loadsel *sel, double *f)
{
    for (size_t i = 0; i < n; i++) {
        double w = ctn_loadsel_weight(sel, v[i].step);
        if (w == 0) continue;
        for (int j = 0; j < 3; j++) f[3 * (size_t)v[i].node + (size_t)j] += w * v[i].F[j];
    }
}

/* u (3 per node) = the prescribed displacements (rot 0) or rotations (rot 1) of a
 * selection. */
static void add_prescribed(const ctn_model *m, const ctn_loadsel *sel, int rot, double *u)
{
    memset(u, 0, 3 * m->nodes.n * sizeof(double));
    for (size_t i = 0; i < m->pdisps.n; i++) {
        double w = ctn_loadsel_weight(sel, m->pdisps.v[i].step);
        if (w == 0 || m->pdisps.v[i].rot != rot) continue;
        for (int j = 0; j < 3; j++) u[3 * (size_t)m->pdisps.v[i].node + (size_t)j] += w * m->pdisps.v[i].u[j];
    }
}

size_t ctn_model_step_count(const ctn_model *m) { return !m ? 0 : m->steps.n ? m->steps.n : 1; }

const char *ctn_model_step_name(const ctn_model *m, size_t k)
{
    if (!m || k >= m->steps.n) return "";
    return m->steps.v[k].name;
}

int ctn_model_step_loads(const ctn_model *m, size_t k, double *f, double *u)
{
    return ctn_model_step_loads_ex(m, k, 0, f, u);
}

int ctn_model_step_loads_ex(const ctn_model *m, size_t k, int dead_only, double *f, double *u)
{
    if (!m || k >= ctn_model_step_count(m)) return CTN_ERR_INVALID;
    ctn_loadsel sel = ctn_loadsel_step(k);         /* records of steps <= k + 1 (0: base) */
    ctn_model_sel_loads(m, &sel, dead_only, f, u);
    return CTN_OK;
}

void ctn_model_sel_loads(const ctn_model *m, const ctn_loadsel *sel, int dead_only, double *f, double *u)
{
    size_t n3 = 3 * m->nodes.n;
    if (f) {
        memset(f, 0, n3 * sizeof(double));
        add_nodal(m->ploads.v, m->ploads.n, sel, f);
        add_element_loads(m, f);
        add_hloads(m, sel, dead_only, f);
        ctn_model_add_lineloads(m, sel, dead_only, f);
    }
    if (u) add_prescribed(m, sel, 0, u);
}

void ctn_model_sel_moments(const ctn_model *m, const ctn_loadsel *sel, double *M, double *r)
{
    if (M) {
        memset(M, 0, 3 * m->nodes.n * sizeof(double));
        add_nodal(m->mloads.v, m->mloads.n, sel, M);
        ctn_model_add_line_moments(m, sel, M);
    }
    if (r) add_prescribed(m, sel, 1, r);
}

int ctn_model_step_moments(const ctn_model *m, size_t k, double *M, double *r)
{
    if (!m || k >= ctn_model_step_count(m)) return CTN_ERR_INVALID;
    ctn_loadsel sel = ctn_loadsel_step(k);
    ctn_model_sel_moments(m, &sel, M, r);
    return CTN_OK;
}

int ctn_model_external_forces(const ctn_model *m, double *f)
{
    if (!m || !f) return CTN_ERR_INVALID;
    return ctn_model_step_loads(m, ctn_model_step_count(m) - 1, f, NULL);
}

int ctn_model_add_step(ctn_model *m, const char *name, int substeps)
{
    if (!m) return CTN_ERR_INVALID;
    if (!name || !*name || strlen(name) >= CTN_NAME_MAX)
        return ctn_model_error(m, CTN_ERR_MODEL, "step name must have 1 to %d characters", CTN_NAME_MAX - 1);
    for (size_t i = 0; i < m->steps.n; i++)
        if (!strcmp(m->steps.v[i].name, name)) return ctn_model_error(m, CTN_ERR_MODEL, "duplicate step '%s'", name);
    if (substeps < 0 || substeps > CTN_SUBSTEPS_MAX)
        return ctn_model_error(m, CTN_ERR_MODEL, "step '%s': substeps must be between 1 and %d", name, CTN_SUBSTEPS_MAX);
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->steps, 1);
    if (rc) return rc;
    ctn_step *st = &m->steps.v[m->steps.n++];
    snprintf(st->name, sizeof st->name, "%s", name);
    st->substeps = substeps;
    m->in_case = 0;                                /* later loads are the step's */
    return CTN_OK;
}

int ctn_model_step_substeps(const ctn_model *m, size_t k)
{
    return m && k < m->steps.n ? m->steps.v[k].substeps : 0;
}

static int has_weight(const ctn_model *m, int *line)
{
    for (size_t i = 0; i < m->sections.n; i++)
        if (m->sections.v[i].w > 0) {
            *line = m->sections.v[i].line;
            return 1;
        }
    return 0;
}

/* An hload is lumped at the nodes of the members it selects, segment by segment: right
 * for members straight between their nodes (cable elements, pulley segments), not for a
 * catenary element, whose curve between its two nodes would not carry it (its shape and
 * forces would ignore the load, which would go straight into the nodes): refused. A
 * spring takes none: naming one alone is an error, sets pass over it (ctn_hload_on). */
static int check_hload_member(const ctn_model *m, const ctn_hload *hl)
{
    if (hl->group < 0 && hl->first == hl->last) {
        int e = ctn_idmap_get(&m->element_ids, hl->first);
        if (e >= 0 && m->elements.v[e].section < 0)
            return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, hl->line,
                                "hload: element %d is a %s, which takes no load per horizontal length", hl->first,
                                ctn_element_family(m->elements.v[e].type)->name);
    }
    for (size_t i = 0; i < m->elements.n; i++)
        if (ctn_hload_on(m, hl, i) && !strcmp(ctn_element_family(m->elements.v[i].type)->name, "catenary"))
            return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, hl->line,
                                "hload: element %d is a catenary element, which carries its own weight only: a load "
                                "per horizontal length cannot ride on it (mesh the span with cable, or leave it out of "
                                "elements=)", m->elements.v[i].id);
    return CTN_OK;
}

static int check_hload_targets(const ctn_model *m)
{
    for (size_t h = 0; h < m->hloads.n; h++) {
        const ctn_hload *hl = &m->hloads.v[h];
        int hit = 0, rc = check_hload_member(m, hl);
        if (rc) return rc;
        for (size_t i = 0; i < m->elements.n && !hit; i++)
            hit = ctn_hload_on(m, hl, i);
        if (!hit && hl->group >= 0)
            return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, hl->line, "hload: group '%s' has no element",
                                m->groups.v[hl->group].name);
        if (!hit)
            return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, hl->line,
                                "hload: no element with id in %d-%d", hl->first, hl->last);
    }
    return CTN_OK;
}

/* A node no element reaches, with a free DOF, is a mechanism: say which. */
static int check_unconnected(const ctn_model *m)
{
    unsigned char *used = ctn_calloc(m->ctx, m->nodes.n, 1);
    if (!used) return CTN_ERR_NOMEM;
    for (size_t k = 0; k < m->conn.n; k++) used[m->conn.v[k]] = 1;
    int rc = CTN_OK;
    for (size_t i = 0; i < m->nodes.n && !rc; i++) {
        const ctn_node *p = &m->nodes.v[i];
        if (used[i] || (p->fix & CTN_FIX_ALL) == CTN_FIX_ALL) continue;
        rc = ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, p->line,
                          "node %d is connected to no element and is free in %s%s%s: a mechanism (fix it with fix=xyz or remove it)",
                          p->id, p->fix & CTN_FIX_X ? "" : "x", p->fix & CTN_FIX_Y ? "" : "y", p->fix & CTN_FIX_Z ? "" : "z");
    }
    ctn_free(used);
    return rc;
}

/* Rotations exist only on the nodes a 6-DOF family reaches: a fixed rotation or a
 * moment on another node is an error at its line. */
static int check_rotations(const ctn_model *m)
{
    static const char *const axis[3] = { "rx", "ry", "rz" };
    for (size_t i = 0; i < m->nodes.n; i++) {
        const ctn_node *p = &m->nodes.v[i];
        if (p->ndof == 6 || !(p->fix & CTN_FIX_ROT)) continue;
        int k = p->fix & CTN_FIX_RX ? 0 : p->fix & CTN_FIX_RY ? 1 : 2;
        return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, p->line,
                            "node %d: fix=%s fixes a rotation, but the node has none (no element with rotations, "
                            "such as rspring, reaches it)", p->id, axis[k]);
    }
    for (size_t i = 0; i < m->mloads.n; i++) {
        const ctn_pload *q = &m->mloads.v[i];
        if (m->nodes.v[q->node].ndof == 6) continue;
        return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, q->line,
                            "moment on node %d, which has no rotations (no element with rotations, such as rspring, "
                            "reaches it)", m->nodes.v[q->node].id);
    }
    return CTN_OK;
}

int ctn_model_validate(const ctn_model *m)
{
    if (!m) return CTN_ERR_INVALID;
    int line = 0, g0 = m->gravity[0] == 0 && m->gravity[1] == 0 && m->gravity[2] == 0;
    if (m->elements.n == 0) return ctn_error(m->ctx, CTN_ERR_MODEL, "%s%sthe model has no elements", m->file, *m->file ? ": " : "");
    if (g0 && has_weight(m, &line))
        return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, line,
                            "section has weight w > 0 but the gravity vector is zero (no gravity directive, or gravity 0 0 0)");
    if (g0 && m->hloads.n)
        return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, m->hloads.v[0].line,
                            "hload needs a gravity direction (no gravity directive, or gravity 0 0 0)");
    int fixed = 0;
    for (size_t i = 0; i < m->nodes.n && !fixed; i++) fixed = m->nodes.v[i].fix != 0;
    if (!fixed) return ctn_error(m->ctx, CTN_ERR_MODEL, "%s%sthe model has no supports (no node has fix=)", m->file, *m->file ? ": " : "");
    int rc = check_rotations(m);
    if (!rc) rc = check_hload_targets(m);
    if (!rc) rc = ctn_model_check_lineloads(m);
    if (!rc) rc = check_unconnected(m);
    return rc ? rc : ctn_model_check_parts(m);
}
