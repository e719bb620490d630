/* The `cable` generator: n elements and n-1 interior nodes between two nodes, placed on
 * a circular arc of the cable's length (or on the chord), with the paper's Newton start:
 * the concentric arc of slightly larger radius. */
#include "model/model.h"

#include <math.h>
#include <string.h>

#define CTN_CABLE_MAX_N 50000000

/* sin(a)/a - 1, accurate for small a. */
static double sinc_m1(double a)
{
    if (fabs(a) > 1e-2) return sin(a) / a - 1.0;
    double a2 = a * a;
    return a2 * (-1.0 / 6 + a2 * (1.0 / 120 - a2 / 5040));
}

/* Half-angle alpha in (0, pi) of the arc with chord c and length S > c:
 * sin(alpha)/alpha = c/S, solved by bisection on the monotone function. */
static double arc_half_angle(double c, double S)
{
    double excess = (S - c) / S;                      /* 1 - c/S, no cancellation */
    double lo = 0.0, hi = 3.14159265358979323846;
    for (int it = 0; it < 200 && hi - lo > 1e-17 * hi; it++) {
        double mid = 0.5 * (lo + hi);
        if (sinc_m1(mid) + excess > 0) lo = mid;      /* sin/a - c/S > 0: angle too small */
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

typedef struct arc_frame {
    double mid[3], u[3], n[3]; /* chord midpoint, unit chord, unit sag direction */
    double chord;
} arc_frame;

static int make_frame(const ctn_model *m, const double A[3], const double B[3], arc_frame *f)
{
    double gn = 0, un = 0, gu = 0;
    for (int k = 0; k < 3; k++) {
        f->mid[k] = 0.5 * (A[k] + B[k]);
        f->u[k] = B[k] - A[k];
        un += f->u[k] * f->u[k];
    }
    f->chord = sqrt(un);
    for (int k = 0; k < 3; k++) {
        f->u[k] /= f->chord;
        gu += m->gravity[k] * f->u[k];
    }
    for (int k = 0; k < 3; k++) {
        f->n[k] = m->gravity[k] - gu * f->u[k];
        gn += f->n[k] * f->n[k];
    }
    double g2 = m->gravity[0] * m->gravity[0] + m->gravity[1] * m->gravity[1] +
                m->gravity[2] * m->gravity[2];
    if (!(gn > 1e-20 * g2) || g2 == 0) return CTN_ERR_DOMAIN;
    for (int k = 0; k < 3; k++) f->n[k] /= sqrt(gn);
    return CTN_OK;
}

static int check_spec(const ctn_model *m, const ctn_cable_spec *s, double chord)
{
    if (s->n < 1 || s->n > CTN_CABLE_MAX_N)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: n must be between 1 and %d (got %d)", CTN_CABLE_MAX_N, s->n);
    if (!isfinite(s->length) || s->length <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: length must be positive and finite (got %g)", s->length);
    if (s->shape == CTN_SHAPE_ARC && s->length < chord)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable shorter than its chord (length %.17g < chord %.17g); use shape=straight for a taut cable", s->length, chord);
    if (!isfinite(s->guess_strain) || s->guess_strain <= 0 || s->guess_strain >= 1)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: guess strain must be in (0, 1) (got %g)", s->guess_strain);
    if (s->shape != CTN_SHAPE_ARC && s->shape != CTN_SHAPE_STRAIGHT)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: unknown shape");
    return CTN_OK;
}

/* Position (and Newton-start displacement) of interior node k of n. */
static void place_node(const arc_frame *f, const ctn_cable_spec *s, double alpha, int k,
                       double X[3], double guess[3])
{
    double t = (double)k / s->n;
    if (s->shape == CTN_SHAPE_STRAIGHT || alpha == 0) {
        for (int j = 0; j < 3; j++) {
            X[j] = f->mid[j] + (t - 0.5) * f->chord * f->u[j];
            guess[j] = 0;
        }
        return;
    }
    double R = f->chord / (2 * sin(alpha));
    double th = alpha * (2 * t - 1);                         /* -alpha .. alpha */
    double drop = 2 * sin(0.5 * (alpha + th)) * sin(0.5 * (alpha - th)); /* cos th - cos alpha */
    double phi = alpha / s->n;                               /* half the element angle */
    double delta = (phi / sin(phi)) * (1 + s->guess_strain) - 1; /* R' = R (1 + delta) */
    for (int j = 0; j < 3; j++) {
        X[j] = f->mid[j] + R * (sin(th) * f->u[j] + drop * f->n[j]);
        guess[j] = delta * R * (sin(th) * f->u[j] + cos(th) * f->n[j]);
    }
}

static int reserve_all(ctn_model *m, size_t n)
{
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->nodes, n - 1);
    if (!rc) rc = CTN_ARRAY_RESERVE(m->ctx, m->loads, 3 * (n - 1));
    if (!rc) rc = CTN_ARRAY_RESERVE(m->ctx, m->elements, n);
    if (!rc) rc = CTN_ARRAY_RESERVE(m->ctx, m->cables, 1);
    if (!rc) rc = ctn_idmap_reserve(m->ctx, &m->node_ids, n - 1);
    if (!rc) rc = ctn_idmap_reserve(m->ctx, &m->element_ids, n);
    return rc;
}

int ctn_model_add_cable(ctn_model *m, int a, int b, const char *section,
                        const ctn_cable_spec *spec, int *first_elem, int *last_elem)
{
    if (!m || !spec) return CTN_ERR_INVALID;
    int ia = ctn_idmap_get(&m->node_ids, a), ib = ctn_idmap_get(&m->node_ids, b);
    if (ia < 0) return ctn_model_error(m, CTN_ERR_MODEL, "undefined node %d", a);
    if (ib < 0) return ctn_model_error(m, CTN_ERR_MODEL, "undefined node %d", b);
    if (ia == ib) return ctn_model_error(m, CTN_ERR_MODEL, "cable from node %d to itself", a);
    if (!section || ctn_model_find_section(m, section) < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: undefined section '%s'", section ? section : "");
    arc_frame f;
    int rc = make_frame(m, m->nodes.v[ia].X, m->nodes.v[ib].X, &f);
    if (!(f.chord > 0)) return ctn_model_error(m, CTN_ERR_MODEL, "cable: nodes %d and %d coincide", a, b);
    if ((rc = check_spec(m, spec, f.chord))) return rc;
    if (spec->shape == CTN_SHAPE_ARC && make_frame(m, m->nodes.v[ia].X, m->nodes.v[ib].X, &f))
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: shape=arc needs a gravity direction not parallel to the chord (set gravity before the cable, or use shape=straight)");
    if (m->max_node_id > 0x7fffffff - spec->n || m->max_element_id > 0x7fffffff - spec->n)
        return ctn_model_error(m, CTN_ERR_MODEL, "cable: generated ids would overflow");
    if ((rc = reserve_all(m, (size_t)spec->n))) return rc;
    double alpha = spec->shape == CTN_SHAPE_ARC && spec->length > f.chord
                   ? arc_half_angle(f.chord, spec->length) : 0;
    int prev = a, first = m->max_element_id + 1;
    size_t e0 = m->elements.n;
    for (int k = 1; k <= spec->n; k++) {
        int next = b;
        if (k < spec->n) {
            double X[3], guess[3];
            place_node(&f, spec, alpha, k, X, guess);
            next = m->max_node_id + 1;
            if ((rc = ctn_model_add_node(m, next, X, 0))) return rc;   /* cannot fail: reserved */
            memcpy(m->nodes.v[m->nodes.n - 1].guess, guess, sizeof guess);
        }
        if ((rc = ctn_model_add_element(m, m->max_element_id + 1, prev, next, section,
                                        spec->length / spec->n))) return rc;
        prev = next;
    }
    ctn_cable *c = &m->cables.v[m->cables.n++];
    c->node[0] = ia;
    c->node[1] = ib;
    c->first = e0;
    c->count = (size_t)spec->n;
    c->length = spec->length;
    if (first_elem) *first_elem = first;
    if (last_elem) *last_elem = m->max_element_id;
    return CTN_OK;
}
