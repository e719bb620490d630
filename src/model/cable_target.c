/* Cables set by a target: checks and the first length of the root find. The first length
 * comes from the shallow parabola through the chord with the weight w per unit length
 * across it (docs/theory.md, "Cables set by a target"): sag d = w_n c^2 / (8 H),
 * length = c + 8 d^2 / (3 c) - H c / EA, c the chord, w_n the weight's part normal to it. */
#include "model/cable_target.h"

#include <math.h>
#include <string.h>

static const char *const names[] = { "length", "H", "sag", "tension" };

/* Weight per unit length normal to the chord AB, and |g|. */
static double normal_weight(const ctn_model *m, double w, const double A[3], const double B[3], double chord)
{
    double g2 = 0, gc = 0;
    for (int k = 0; k < 3; k++) {
        g2 += m->gravity[k] * m->gravity[k];
        gc += m->gravity[k] * (B[k] - A[k]) / chord;
    }
    double gn2 = g2 - gc * gc;
    return w * sqrt(gn2 > 0 ? gn2 : 0);
}

int ctn_cable_target_check(const ctn_model *m, const char *what, const ctn_cable_spec *s, const char *section,
                           const double A[3], const double B[3], double chord, double *length)
{
    if (s->target == CTN_TARGET_NONE) return CTN_OK;
    if (s->target < CTN_TARGET_NONE || s->target > CTN_TARGET_TENSION)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: unknown target", what);
    const char *key = names[s->target];
    double v = s->target_value;
    if (!isfinite(v) || v <= 0) return ctn_model_error(m, CTN_ERR_MODEL, "%s: %s= must be positive and finite (got %g)", what, key, v);
    if (s->prestress != CTN_PRESTRESS_NONE)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: a target (%s=) sets the length: give no prestress with it", what, key);
    double g2 = m->gravity[0] * m->gravity[0] + m->gravity[1] * m->gravity[1] + m->gravity[2] * m->gravity[2];
    if (s->target != CTN_TARGET_TENSION && !(g2 > 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: %s= is measured against gravity, and there is none (set gravity before the %.*s)", what, key,
                               (int)strcspn(what, " "), what);
    double gc = 0;
    for (int k = 0; k < 3; k++) gc += m->gravity[k] * (B[k] - A[k]) / chord;
    if (s->target != CTN_TARGET_TENSION && !(g2 - gc * gc > 1e-18 * g2))
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: %s= is measured across the chord, and this chord is vertical "
                               "(use tension=)", what, key);
    int si = ctn_model_find_section(m, section);
    if (si < 0) return ctn_model_error(m, CTN_ERR_MODEL, "%s: undefined section '%s'", what, section);
    const ctn_section *sec = &m->sections.v[si];
    double EA = m->materials.v[sec->material].E * sec->A, wn = normal_weight(m, sec->w, A, B, chord);
    double H, d;
    if (s->target == CTN_TARGET_SAG) {
        d = v;
        H = wn > 0 ? wn * chord * chord / (8 * d) : 0;
    } else {
        H = v;
        d = wn > 0 ? wn * chord * chord / (8 * H) : 0;
    }
    double L = chord + 8 * d * d / (3 * chord) - H * chord / EA;
    /* on an arc the nodes need a length above the chord: the root find goes below it if
     * the target asks for a cable shorter than its span */
    double floor = s->shape == CTN_SHAPE_ARC ? 1.001 * chord : 0.5 * chord;
    *length = isfinite(L) && L > floor ? L : floor;
    return CTN_OK;
}

int ctn_model_targets_found(ctn_ctx *ctx, const ctn_model *m)
{
    for (size_t i = 0; i < m->cables.n; i++) {
        const ctn_cable *c = &m->cables.v[i];
        if (c->target != CTN_TARGET_NONE && !c->resolved)
            return ctn_error_at(ctx, CTN_ERR_INVALID, m->file, c->line,
                                "cable %d-%d is set by a target: find its length first (ctn_model_resolve_targets)",
                                m->nodes.v[c->node[0]].id, m->nodes.v[c->node[1]].id);
    }
    for (size_t i = 0; i < m->etargets.n; i++) {
        const ctn_cable *c = &m->etargets.v[i];
        if (!c->resolved)
            return ctn_error_at(ctx, CTN_ERR_INVALID, m->file, c->line,
                                "catenary %d is set by a target: find its length first (ctn_model_resolve_targets)",
                                m->elements.v[c->first].id);
    }
    return CTN_OK;
}
