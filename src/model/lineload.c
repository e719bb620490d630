/* Loads per unit unstressed length in a fixed direction (`lineload`): wind, ice, any
 * distributed load of a cable element, lumped consistently: an element of unstressed
 * length l0 under q carries q l0, half at each end (exact for a straight two-node
 * element with linear shape functions). A beam takes the same forces and its fixed-end
 * moments (its family's line_load), as it takes its weight. Other families are refused
 * where the lumping would not be exact: a catenary element's curve, a pulley's sliding
 * segments. */
#include "element/element.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int is_cable(const ctn_model *m, size_t e)
{
    return !strcmp(ctn_element_family(m->elements.v[e].type)->name, "cable");
}

/* A lineload's families: cables (q l0 / 2 at each end) and the families with their own
 * consistent loads (line_load: beams, with the fixed-end moments). */
static int takes_lineload(const ctn_model *m, size_t e)
{
    return is_cable(m, e) || ctn_element_family(m->elements.v[e].type)->line_load;
}

int ctn_lload_on(const ctn_model *m, const ctn_lload *l, size_t e)
{
    const ctn_element *el = &m->elements.v[e];
    if (el->section < 0) return 0;                   /* springs: sets pass over them */
    return ctn_model_target_has(m, l->kind, l->target, e);
}

/* TARGET: all, an element id (a cable element) or a defined group. */
static int resolve(ctn_model *m, const char *target, ctn_lload *l)
{
    if (!l->drag)
        return ctn_model_load_target(m, "lineload", target, takes_lineload,
                                     "; a load per length is lumped exactly on cable elements only, or taken by beams "
                                     "(mesh the span with cable)", &l->kind, &l->target);
    return ctn_model_load_target(m, "wind", target, is_cable,
                                 "; a load per length is lumped exactly on cable elements only (mesh the span with "
                                 "cable)", &l->kind, &l->target);
}

static int push(ctn_model *m, const char *target, ctn_lload *l)
{
    int rc = resolve(m, target, l);
    if (!rc) rc = CTN_ARRAY_RESERVE(m->ctx, m->lloads, 1);
    if (rc) return rc;
    m->lloads.v[m->lloads.n++] = *l;
    return CTN_OK;
}

int ctn_model_add_lineload(ctn_model *m, const char *target, const double q[3])
{
    return ctn_model_add_ice(m, target, q, 0);
}

int ctn_model_add_ice(ctn_model *m, const char *target, const double q[3], double t)
{
    if (!m || !target || !q) return CTN_ERR_INVALID;
    for (int k = 0; k < 3; k++)
        if (!isfinite(q[k])) return ctn_model_error(m, CTN_ERR_MODEL, "lineload: q must be finite");
    if (!(t >= 0) || !isfinite(t)) return ctn_model_error(m, CTN_ERR_MODEL, "ice: the thickness must be >= 0 and finite");
    ctn_lload l = { CTN_TARGET_ALL, -1, { q[0], q[1], q[2] }, ctn_model_load_tag(m), m->line, 0, { 0, 0, 0 }, 0, 0, t, NAN, 0, 0 };
    return push(m, target, &l);
}

int ctn_model_add_wind(ctn_model *m, const char *target, const double dir[3], double cdp, double d)
{
    if (!m || !target || !dir) return CTN_ERR_INVALID;
    double n = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]), q = cdp * d;
    if (!isfinite(q) || !(n > 0) || !isfinite(n))
        return ctn_model_error(m, CTN_ERR_MODEL, "wind: the direction must be a finite non-zero vector and the load finite");
    ctn_lload l = { CTN_TARGET_ALL, -1, { q * dir[0] / n, q * dir[1] / n, q * dir[2] / n }, ctn_model_load_tag(m),
                    m->line, 1, { dir[0] / n, dir[1] / n, dir[2] / n }, cdp, d, 0, NAN, 0, 0 };
    return push(m, target, &l);
}

int ctn_model_wind_air(ctn_model *m, double rho, double speed, double cd)
{
    if (!m || !m->lloads.n || !m->lloads.v[m->lloads.n - 1].drag) return CTN_ERR_INVALID;
    ctn_lload *l = &m->lloads.v[m->lloads.n - 1];
    l->rho = rho;
    l->speed = speed;
    l->cd = cd;
    return CTN_OK;
}

void ctn_lload_dir(const ctn_lload *l, double u[3])
{
    double qn = sqrt(l->q[0] * l->q[0] + l->q[1] * l->q[1] + l->q[2] * l->q[2]);
    for (int k = 0; k < 3; k++) u[k] = qn > 0 ? l->q[k] / qn : l->dir[k];
}

/* The thickest ice of a selection (positive weight) on element e; 0 if none. */
static double ice_on(const ctn_model *m, const ctn_loadsel *sel, size_t e)
{
    double t = 0;
    for (size_t j = 0; j < m->lloads.n; j++) {
        const ctn_lload *l = &m->lloads.v[j];
        if (l->t > t && ctn_loadsel_weight(sel, l->step) > 0 && ctn_lload_on(m, l, e)) t = l->t;
    }
    return t;
}

double ctn_model_drag_q(const ctn_model *m, const ctn_lload *l, const ctn_loadsel *sel, size_t e)
{
    double t = ice_on(m, sel, e);
    if (t > 0) return l->cdp * (l->d + 2 * t);                       /* the iced diameter */
    return sqrt(l->q[0] * l->q[0] + l->q[1] * l->q[1] + l->q[2] * l->q[2]);
}

/* The drag of wind l on element e (chord a-b) at the reference geometry, added at both
 * ends. */
static void add_reference_drag(const ctn_model *m, const ctn_lload *l, const ctn_loadsel *sel, double w, size_t e,
                               double *f)
{
    const int *nd = ctn_elem_nodes(m, e);
    double qn = ctn_model_drag_q(m, l, sel, e), h[3], u[3], along = 0, hn = 0;
    if (!(qn > 0)) return;
    ctn_lload_dir(l, u);
    for (int k = 0; k < 3; k++) {
        h[k] = m->nodes.v[nd[1]].X[k] - m->nodes.v[nd[0]].X[k];
        along += h[k] * u[k];
    }
    for (int k = 0; k < 3; k++) hn += (h[k] - along * u[k]) * (h[k] - along * u[k]);
    double P = 0.5 * w * qn * sqrt(hn);
    for (int k = 0; k < 3; k++) {
        f[3 * (size_t)nd[0] + (size_t)k] += P * u[k];
        f[3 * (size_t)nd[1] + (size_t)k] += P * u[k];
    }
}

void ctn_model_add_lineloads(const ctn_model *m, const ctn_loadsel *sel, int dead_only, double *f)
{
    for (size_t j = 0; j < m->lloads.n; j++) {
        const ctn_lload *l = &m->lloads.v[j];
        double w = ctn_loadsel_weight(sel, l->step);
        if (w == 0 || (l->drag && dead_only)) continue;
        for (size_t e = 0; e < m->elements.n; e++) {
            if (!ctn_lload_on(m, l, e)) continue;
            if (l->drag) {
                add_reference_drag(m, l, sel, w, e, f);
                continue;
            }
            const ctn_element_ops *ops = ctn_element_family(m->elements.v[e].type);
            if (ops->line_load) {                                  /* beams: their own */
                const double q[3] = { w * l->q[0], w * l->q[1], w * l->q[2] };
                ops->line_load(m, e, q, f, NULL);
                continue;
            }
            const int *nd = ctn_elem_nodes(m, e);
            double half = 0.5 * w * m->elements.v[e].l0;          /* q l0 / 2 at each end */
            for (int k = 0; k < 3; k++) {
                f[3 * (size_t)nd[0] + (size_t)k] += half * l->q[k];
                f[3 * (size_t)nd[1] + (size_t)k] += half * l->q[k];
            }
        }
    }
}

int ctn_model_check_lineloads(const ctn_model *m)
{
    for (size_t j = 0; j < m->lloads.n; j++) {
        const ctn_lload *l = &m->lloads.v[j];
        int hit = 0;
        for (size_t e = 0; e < m->elements.n; e++) {
            if (!ctn_lload_on(m, l, e)) continue;
            if (!(l->drag ? is_cable(m, e) : takes_lineload(m, e)))
                return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, l->line,
                                    "%s: element %d is a %s; a load per length is lumped exactly on cable elements "
                                    "only%s (mesh the span with cable, or leave it out of the target)",
                                    l->drag ? "wind" : "lineload", m->elements.v[e].id,
                                    ctn_element_family(m->elements.v[e].type)->name,
                                    l->drag ? "" : ", or taken by beams");
            hit = 1;
        }
        if (!hit && l->kind == CTN_TARGET_GROUP)
            return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, l->line, "%s: group '%s' has no cable element",
                                l->drag ? "wind" : "lineload", m->groups.v[l->target].name);
        if (!hit)
            return ctn_error_at(m->ctx, CTN_ERR_MODEL, m->file, l->line, "%s: no cable element to load",
                                l->drag ? "wind" : "lineload");
    }
    return CTN_OK;
}

/* The moments of a selection's lineloads on the families that take them with moments
 * (line_load: beams' fixed-end moments), added to M (3 per node). */
static void add_lineload_moments(const ctn_model *m, const ctn_loadsel *sel, double *M)
{
    for (size_t j = 0; j < m->lloads.n; j++) {
        const ctn_lload *l = &m->lloads.v[j];
        double w = ctn_loadsel_weight(sel, l->step);
        if (w == 0 || l->drag) continue;
        const double q[3] = { w * l->q[0], w * l->q[1], w * l->q[2] };
        for (size_t e = 0; e < m->elements.n; e++) {
            const ctn_element_ops *ops = ctn_element_family(m->elements.v[e].type);
            if (ops->line_load && ctn_lload_on(m, l, e)) ops->line_load(m, e, q, NULL, M);
        }
    }
}

/* Self-weight w g per unstressed length of a family with line_load, its section's w. */
static int weight_line(const ctn_model *m, size_t e, double q[3])
{
    const ctn_element *el = &m->elements.v[e];
    if (!ctn_element_family(el->type)->line_load || el->section < 0) return 0;
    double w = m->sections.v[el->section].w;
    for (int k = 0; k < 3; k++) q[k] = w * m->gravity[k];
    return w > 0 && (q[0] != 0 || q[1] != 0 || q[2] != 0);
}

void ctn_model_add_line_moments(const ctn_model *m, const ctn_loadsel *sel, double *M)
{
    double q[3];
    for (size_t e = 0; e < m->elements.n; e++)             /* the weight's, always on */
        if (weight_line(m, e, q)) ctn_element_family(m->elements.v[e].type)->line_load(m, e, q, NULL, M);
    add_lineload_moments(m, sel, M);
}

void ctn_model_element_line(const ctn_model *m, const ctn_loadsel *sel, size_t e, double q[3])
{
    double wq[3];
    q[0] = q[1] = q[2] = 0;
    if (!ctn_element_family(m->elements.v[e].type)->line_load) return;
    if (weight_line(m, e, wq))
        for (int k = 0; k < 3; k++) q[k] += wq[k];
    for (size_t j = 0; j < m->lloads.n; j++) {
        const ctn_lload *l = &m->lloads.v[j];
        double w = ctn_loadsel_weight(sel, l->step);
        if (w == 0 || l->drag || !ctn_lload_on(m, l, e)) continue;
        for (int k = 0; k < 3; k++) q[k] += w * l->q[k];
    }
}
