/* The elastic catenary element (Irvine): one element per span, its end forces solved
 * from the chord by the compatibility equations (catenary_solve.c), its tangent the
 * inverse of the flexibility (docs/theory.md, "The catenary element").
 *   f2 = H ex + (Vb - W/2) up = -f1   (the weight W/2 at each node is an external load,
 *                                      lumped by `load`, so that steps ramp it)
 *   K22 = [ex up] F^-1 [ex up]^T + (H / l) ey ey^T,  K = [[K22, -K22], [-K22, K22]]
 * ex the unit horizontal chord, ey = up x ex; with a vertical chord (l = 0) the
 * horizontal stiffness 1 / F_HH in every horizontal direction. Without weight it is the
 * bar N = EA (|chord| - L) / L, slack (no force, no stiffness) when shorter than L. */
#include "element/axial.h"
#include "element/hang_law.h"
#include "element/catenary.h"

#include <math.h>

int ctn_catenary_state(const ctn_catenary_props *p, const double *X, const double *u,
                       ctn_ecat *c, double ex[3], int *bar)
{
    double a[3], h = 0;
    for (int i = 0; i < 3; i++) a[i] = (X[3 + i] - X[i]) + (u[3 + i] - u[i]);
    for (int i = 0; i < 3; i++) h += a[i] * p->up[i];
    for (int i = 0; i < 3; i++) ex[i] = a[i] - h * p->up[i];
    double l = sqrt(ex[0] * ex[0] + ex[1] * ex[1] + ex[2] * ex[2]);
    for (int i = 0; i < 3; i++) ex[i] = l > 0 ? ex[i] / l : 0;
    *c = (ctn_ecat){ .L = p->l0, .EA = p->EA, .W = p->W, .l = l, .h = h };
    *bar = !(p->W > 0);
    if (!(hypot(l, h) > 0) || !isfinite(l + h)) return 1;
    return *bar ? 0 : ctn_ecat_solve(c) != CTN_OK;
}

/* The bar without weight: the axial member's law with a slack side. */
static int bar_eval(const ctn_catenary_props *p, unsigned mode, const double *X, const double *u,
                    double *f, double *K, ctn_elem_state *st)
{
    double e[3];
    if (ctn_axial_chord(X, u, e, &st->l)) return 1;
    st->slack = st->l < p->l0;
    st->strain = st->slack ? 0 : st->l / p->l0 - 1;
    st->N = p->EA * st->strain;
    st->energy = 0.5 * p->EA * p->l0 * st->strain * st->strain;
    st->stress = mode & CTN_EVAL_STRESS ? st->N / p->A : 0;
    ctn_axial_forces(e, st->N, f);
    if (K) ctn_axial_tangent(e, st->l, st->N, st->slack ? 0 : p->EA / p->l0, K);
    return 0;
}

/* K22 (3 x 3) from the inverse flexibility in the (ex, up) plane and H / l across it. */
static void block(const ctn_ecat *c, const double ex[3], const double up[3], double k[3][3])
{
    double det = c->Fhh * c->Fvv - c->Fhv * c->Fhv;
    double kxx = isfinite(c->Fhh) ? c->Fvv / det : 0, kxz = isfinite(c->Fhh) ? -c->Fhv / det : 0;
    double kzz = isfinite(c->Fhh) ? c->Fhh / det : 1 / c->Fvv;
    double kyy = c->l > 0 ? c->H / c->l : kxx;          /* vertical chord: isotropic */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double ey = (i == j) - up[i] * up[j] - ex[i] * ex[j];    /* ey ey^T */
            k[i][j] = kxx * ex[i] * ex[j] + kxz * (ex[i] * up[j] + up[i] * ex[j]) + kzz * up[i] * up[j] + kyy * ey;
        }
}

static void tangent(const double k[3][3], double *K)
{
    int t = 0;
    for (int i = 0; i < 3; i++) {
        for (int j = i; j < 3; j++) K[t++] = k[i][j];
        for (int j = 0; j < 3; j++) K[t++] = -k[i][j];
    }
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) K[t++] = k[i][j];
}

static int catenary_eval(const void *props, unsigned mode, const double *X, const double *u,
                         double *f, double *K, ctn_elem_state *out)
{
    const ctn_catenary_props *p = props;
    ctn_elem_state st = { 0, 0, 0, 0, 0, 0 };
    ctn_ecat c;
    double ex[3], k[3][3];
    int bar;
    if (ctn_catenary_state(p, X, u, &c, ex, &bar)) return 1;
    if (bar) {
        bar_eval(p, mode, X, u, f, K, &st);
        if (out) *out = st;
        return 0;
    }
    st.l = hypot(c.l, c.h);
    st.N = fmax(hypot(c.H, c.Va), hypot(c.H, c.Vb));   /* the larger end tension */
    st.strain = st.N / p->EA;
    st.stress = mode & CTN_EVAL_STRESS ? st.N / p->A : 0;
    st.energy = ctn_ecat_energy(&c);
    for (int i = 0; i < 3; i++) {
        f[3 + i] = c.H * ex[i] + 0.5 * (c.Vb - c.Va) * p->up[i];
        f[i] = -f[3 + i];
    }
    if (K) {
        block(&c, ex, p->up, k);
        tangent(k, K);
    }
    if (out) *out = st;
    return !(isfinite(st.N) && isfinite(st.energy));
}

static int catenary_check(const ctn_model *m, const ctn_element *e)
{
    const ctn_section *sp = &m->sections.v[e->section];
    double EA = m->materials.v[sp->material].E * sp->A;
    if (!isfinite(e->l0) || e->l0 <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "catenary %d: length must be positive and finite (got %g)", e->id, e->l0);
    if (!isfinite(EA / e->l0))
        return ctn_model_error(m, CTN_ERR_MODEL, "catenary %d: axial stiffness E A / length overflows (length = %g)", e->id, e->l0);
    double g = hypot(hypot(m->gravity[0], m->gravity[1]), m->gravity[2]);
    if (!isfinite(sp->w * e->l0 * g))
        return ctn_model_error(m, CTN_ERR_MODEL, "catenary %d: its weight w length |g| = %g * %g * %g overflows", e->id,
                               sp->w, e->l0, g);
    return CTN_OK;
}

static void catenary_setup(const ctn_model *m, size_t e, void *props)
{
    const ctn_element *el = &m->elements.v[e];
    const ctn_section *s = &m->sections.v[el->section];
    ctn_catenary_props *p = props;
    double g = hypot(hypot(m->gravity[0], m->gravity[1]), m->gravity[2]);
    p->EA = m->materials.v[s->material].E * s->A;
    p->l0 = p->l0_ref = el->l0;
    p->A = s->A;
    p->W = s->w * el->l0 * g;
    p->alpha = m->materials.v[s->material].alpha;
    p->mass = ctn_model_section_mass(m, el->section) * el->l0;
    for (int i = 0; i < 3; i++) p->up[i] = p->W > 0 ? -m->gravity[i] / g : 0;
}

/* The weight W/2 at each node, as a cable element's (the element's own forces carry the
 * rest of it). */
static void catenary_load(const ctn_model *m, size_t e, double *f) { ctn_cable2_ops.load(m, e, f); }

static double catenary_rest_length(const void *props) { return ((const ctn_catenary_props *)props)->l0; }

static double catenary_hang(const void *props, const double S[3], double v[3], double H[9])
{
    const ctn_catenary_props *p = props;
    return ctn_hang_catenary(p->l0, p->EA, p->W, p->up, S, v, H);
}

static double catenary_stiffness(const void *props)
{
    const ctn_catenary_props *p = props;
    return p->EA / p->l0;
}

/* A temperature change dT from the reference: L = L_ref (1 + alpha dT), the weight
 * stays that of L_ref (its weight per unstressed length scales by 1 / (1 + alpha dT)). */
static void catenary_temperature(void *props, double dT)
{
    ctn_catenary_props *p = props;
    p->l0 = p->l0_ref * (1 + p->alpha * dT);
}

/* The mass of a cable element of the same unstressed length: the two nodes carry the
 * span's mass (half each, lumped) or its linear interpolation along the chord
 * (consistent). The span's own vibration between its nodes is not represented: modes of
 * a span come from meshing it with cable elements. */
static void catenary_mass(const void *props, const double *X, int lumped, double *M)
{
    (void)X;
    ctn_axial_mass(((const ctn_catenary_props *)props)->mass, lumped, M);
}

const ctn_element_ops ctn_catenary2_ops = {
    .name = "catenary", .nnodes = 2, .ndof_node = 3, .props_size = sizeof(ctn_catenary_props),
    .flags = CTN_ELEM_SECTION | CTN_ELEM_TENSION_ONLY,
    .check = catenary_check, .setup = catenary_setup, .eval = catenary_eval, .load = catenary_load,
    .stiffness = catenary_stiffness, .rest_length = catenary_rest_length, .hang = catenary_hang,
    .temperature = catenary_temperature, .prestress_l0 = ctn_catenary_prestress_l0,
    .mass = catenary_mass,
};
