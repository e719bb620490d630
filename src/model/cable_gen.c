/* The `cable` generator: n elements and n-1 interior nodes between two nodes, placed on
 * a circular arc of the cable's length (or on the chord), with the Newton start on the
 * stretched arc through the same ends (docs/theory.md). */
#include "model/arc.h"
#include "model/cable_start.h"
#include "model/cable_target.h"
#include "model/model.h"

#include <math.h>
#include <string.h>



static int check_spec(const ctn_model *m, const ctn_cable_spec *s, double chord)
{
    if (s->n < 1 || s->n > CTN_CABLE_MAX_N)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: n must be between 1 and %d (got %d)", CTN_CABLE_MAX_N, s->n);
    if (!isfinite(s->length) || s->length <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: length must be positive and finite (got %g)", s->length);
    if (s->shape == CTN_SHAPE_ARC && chord < 1e-12 * s->length)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: length %g is more than 1e12 times its chord %g: no arc can be placed in double precision", s->length, chord);
    if (s->shape == CTN_SHAPE_ARC && s->length < chord)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable shorter than its chord (length %.17g < chord %.17g); use shape=straight for a taut cable", s->length, chord);
    if (!isfinite(s->guess_strain) || s->guess_strain < 0 || s->guess_strain >= 1)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: guess strain must be in [0, 1) (got %g)", s->guess_strain);
    if (s->shape != CTN_SHAPE_ARC && s->shape != CTN_SHAPE_STRAIGHT)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: unknown shape");
    if (s->start != CTN_START_ARC && s->start != CTN_START_CATENARY && s->start != CTN_START_AUTO)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: unknown start");
    if (s->prestress < CTN_PRESTRESS_NONE || s->prestress > CTN_PRESTRESS_STRAIN)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: unknown prestress");
    return CTN_OK;
}

/* Element prev-next of the cable: l0 = length / n, or from the prestress in its chord. */
static int add_element(ctn_model *m, const ctn_cable_spec *spec, int prev, int next, const char *section)
{
    ctn_element_spec e;
    int nodes[2] = { prev, next };
    ctn_element_spec_init(&e);
    e.id = m->max_element_id + 1;
    e.nnodes = 2;
    e.nodes = nodes;
    e.section = section;
    e.l0 = spec->prestress == CTN_PRESTRESS_NONE ? spec->length / spec->n : CTN_L0_DEFAULT;
    e.prestress = spec->prestress;
    e.prestress_value = spec->prestress_value;
    e.group = spec->group;
    return ctn_model_add_element_spec(m, &e);
}

static int reserve_all(ctn_model *m, size_t n)
{
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->nodes, n - 1);
    if (!rc) rc = CTN_ARRAY_RESERVE(m->ctx, m->elements, n);
    if (!rc) rc = CTN_ARRAY_RESERVE(m->ctx, m->cables, 1);
    if (!rc) rc = ctn_idmap_reserve(m->ctx, &m->node_ids, n - 1);
    if (!rc) rc = ctn_idmap_reserve(m->ctx, &m->element_ids, n);
    return rc;
}

void ctn_cable_spec_init(ctn_cable_spec *s)
{
    if (!s) return;
    memset(s, 0, sizeof *s);
    s->shape = CTN_SHAPE_ARC;
    s->guess_strain = 1e-3;
    s->start = CTN_START_AUTO;
    s->prestress = CTN_PRESTRESS_NONE;
    s->target = CTN_TARGET_NONE;
}

int ctn_model_add_cable(ctn_model *m, int a, int b, const char *section,
                        const ctn_cable_spec *spec, int *first_elem, int *last_elem)
{
    if (!m || !spec) return CTN_ERR_INVALID;
    if (m->steps.n) return ctn_model_error(m, CTN_ERR_MODEL, "cables must be defined before the first step");
    int ia = ctn_idmap_get(&m->node_ids, a), ib = ctn_idmap_get(&m->node_ids, b);
    if (ia < 0) return ctn_model_error(m, CTN_ERR_MODEL, "undefined node %d", a);
    if (ib < 0) return ctn_model_error(m, CTN_ERR_MODEL, "undefined node %d", b);
    if (ia == ib) return ctn_model_error(m, CTN_ERR_MODEL, "cable from node %d to itself", a);
    if (!section || ctn_model_find_section(m, section) < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: undefined section '%s'", section ? section : "");
    ctn_arc f;
    double A[3], B[3];                      /* copies: reserve_all() moves the nodes */
    memcpy(A, m->nodes.v[ia].X, sizeof A);
    memcpy(B, m->nodes.v[ib].X, sizeof B);
    double chord = sqrt((B[0] - A[0]) * (B[0] - A[0]) + (B[1] - A[1]) * (B[1] - A[1]) + (B[2] - A[2]) * (B[2] - A[2]));
    if (!(chord > 0)) return ctn_model_error(m, CTN_ERR_MODEL, "cable: nodes %d and %d coincide", a, b);
    ctn_cable_spec given = *spec;
    int rc = ctn_cable_target_check(m, "cable", spec, section, A, B, chord, &given.length);
    if (rc) return rc;
    /* An end not held in all three directions is free to move: its place is a guess,
     * and a cable shorter than the chord to it (a pendant rope whose free end the user
     * put beyond its reach) is laid on the chord instead of refused; the solve finds
     * where it hangs (a dangling chain starts on its funicular). */
    if (given.shape == CTN_SHAPE_ARC && given.length < chord &&
        ((m->nodes.v[ia].fix & 7u) != 7u || (m->nodes.v[ib].fix & 7u) != 7u))
        given.shape = CTN_SHAPE_STRAIGHT;
    spec = &given;
    if ((rc = check_spec(m, spec, chord))) return rc;
    if (ctn_arc_make(A, B, m->gravity, spec->shape == CTN_SHAPE_ARC ? spec->length : chord, &f))
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: shape=arc needs a gravity direction not parallel to the chord (give a gravity line, or use shape=straight)");
    if (m->max_node_id > 0x7fffffff - spec->n || m->max_element_id > 0x7fffffff - spec->n)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: generated ids would overflow");
    long lim = ctn_ctx_model_limit(m->ctx);
    if (lim && (m->nodes.n + (size_t)spec->n > (size_t)lim || m->elements.n + (size_t)spec->n > (size_t)lim))
        return ctn_model_error(m, CTN_ERR_MODEL, "model too large: cable of %d elements exceeds the caller's limit of %ld", spec->n, lim);
    if ((rc = reserve_all(m, (size_t)spec->n))) return rc;
    ctn_arc start = f;                                   /* the Newton start */
    if (spec->shape == CTN_SHAPE_ARC && spec->guess_strain > 0 &&
        ctn_arc_stretched(&f, A, B, m->gravity, spec->length, 1.0 / spec->n, spec->guess_strain, &start))
        start = f;
    ctn_catenary_place cat;
    const ctn_section *sec = &m->sections.v[ctn_model_find_section(m, section)];
    int on_catenary = spec->shape == CTN_SHAPE_ARC && spec->start == CTN_START_CATENARY &&
                      !ctn_catenary_start(m->ctx, A, B, m->gravity, sec->w, m->materials.v[sec->material].E * sec->A,
                                          spec->length, spec->n, 1e-4, &cat);
    int prev = a, first = m->max_element_id + 1;
    size_t e0 = m->elements.n;
    for (int k = 1; k <= spec->n; k++) {
        int next = b;
        if (k < spec->n) {
            double X[3], guess[3];
            ctn_arc_point(&f, (double)k / spec->n, X);
            if (on_catenary) ctn_catenary_start_point(&cat, k, guess);
            else ctn_arc_point(&start, (double)k / spec->n, guess);
            for (int j = 0; j < 3; j++) guess[j] -= X[j];
            next = m->max_node_id + 1;
            if ((rc = ctn_model_add_node(m, next, X, 0))) return rc;   /* cannot fail: reserved */
            memcpy(m->nodes.v[m->nodes.n - 1].guess, guess, sizeof guess);
        }
        if ((rc = add_element(m, spec, prev, next, section))) return rc;
        prev = next;
    }
    ctn_cable *c = &m->cables.v[m->cables.n++];
    memset(c, 0, sizeof *c);
    c->node[0] = ia;
    c->node[1] = ib;
    c->first = e0;
    c->count = (size_t)spec->n;
    c->length = spec->length;
    c->start = (int)spec->start;
    c->shape = (int)spec->shape;
    c->target = (int)spec->target;
    c->target_value = spec->target_value;
    c->line = m->line;
    if (first_elem) *first_elem = first;
    if (last_elem) *last_elem = m->max_element_id;
    return CTN_OK;
}
