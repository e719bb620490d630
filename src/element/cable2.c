/* Two-node cable element, total Lagrangian (docs/theory.md); its kernel, eval_axial, is
 * in cable2.h. */
#include "element/cable2.h"
#include "element/hang_law.h"

#include <float.h>
#include <math.h>

static int cable_eval(const void *props, unsigned mode, const double *X, const double *u,
                      double *f, double *K, ctn_elem_state *out)
{
    return ctn_axial_eval(ctn_cable_axial, props, mode, X, u, f, K, out);
}

static int cable_check(const ctn_model *m, const ctn_element *e)
{
    const ctn_section *sp = &m->sections.v[e->section];
    if (!isfinite(e->l0) || e->l0 <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d: l0 must be positive and finite (got %g)", e->id, e->l0);
    if (!isfinite(m->materials.v[sp->material].E * sp->A / e->l0))
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d: axial stiffness E A / l0 overflows (l0 = %g)", e->id, e->l0);
    return CTN_OK;
}

static void cable_setup(const ctn_model *m, size_t e, void *props)
{
    const ctn_element *el = &m->elements.v[e];
    const ctn_section *s = &m->sections.v[el->section];
    const ctn_material *mat = &m->materials.v[s->material];
    ctn_cable_props *p = props;
    p->EA = mat->E * s->A;
    p->l0 = el->l0;
    p->A = s->A;
    p->strain = (int)mat->strain;
    p->tension_only = mat->tension_only;
    p->l0_ref = el->l0;
    p->alpha = mat->alpha;
    p->mass = ctn_model_section_mass(m, el->section) * el->l0;   /* m' l0 */
}

static void cable_temperature(void *props, double dT)
{
    ctn_cable_props *p = props;
    p->l0 = p->l0_ref * (1 + p->alpha * dT);
}

/* Self-weight: w l0 g, half to each node (a dead load). */
static void cable_load(const ctn_model *m, size_t e, double *f)
{
    const ctn_element *el = &m->elements.v[e];
    const int *nd = ctn_elem_nodes(m, e);
    double W = 0.5 * m->sections.v[el->section].w * el->l0;
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) f[3 * (size_t)nd[a] + (size_t)k] += W * m->gravity[k];
}

static double cable_stiffness(const void *props)
{
    const ctn_cable_props *p = props;
    return p->EA / p->l0;
}

static void cable_sever(void *props) { ((ctn_cable_props *)props)->EA = 0; }

static void cable_mass(const void *props, const double *X, int lumped, double *M)
{
    (void)X;
    ctn_axial_mass(((const ctn_cable_props *)props)->mass, lumped, M);
}

static double cable_rest_length(const void *props) { return ((const ctn_cable_props *)props)->l0; }

static double cable_hang(const void *props, const double S[3], double v[3], double H[9])
{
    const ctn_cable_props *p = props;
    return ctn_hang_bar(p->l0, p->EA, S, v, H);
}

/* Stretch lambda = l / l0 at which the material's law gives force N (tension positive);
 * Green-Lagrange: N = EA (lambda^2 - 1) lambda / 2, increasing for lambda > 1/sqrt(3),
 * solved by safeguarded Newton on [1/sqrt(3), hi]. 0 if no stretch gives it. */
static double stretch_for(const ctn_material *mat, double EA, double N)
{
    if (mat->strain == CTN_STRAIN_ENGINEERING) return 1 + N / EA;
    double n = N / EA, lo = 1 / sqrt(3.0), hi = 1;
    if (n <= (lo * lo - 1) * lo / 2) return 0;               /* below the law's minimum */
    while ((hi * hi - 1) * hi / 2 < n) hi *= 2;
    double x = n > 0 ? hi : 1;
    for (int it = 0; it < 200; it++) {
        double f = (x * x - 1) * x / 2 - n, df = (3 * x * x - 1) / 2;
        if (f > 0) hi = x; else lo = x;
        double next = x - f / df;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (next == x || hi - lo <= 4 * DBL_EPSILON * hi) break;
        x = next;
    }
    return x;
}

static int cable_prestress_l0(const ctn_model *m, const ctn_element *e, int kind, double v, double l, double *l0)
{
    const ctn_section *sp = &m->sections.v[e->section];
    const ctn_material *mat = &m->materials.v[sp->material];
    double EA = mat->E * sp->A, lam = 0;
    if (!isfinite(v)) return ctn_model_error(m, CTN_ERR_MODEL, "element %d: the prestress must be finite", e->id);
    if (kind == CTN_PRESTRESS_STRAIN) {
        double q = 1 + 2 * v;                                /* lambda^2 for Green-Lagrange */
        lam = mat->strain == CTN_STRAIN_ENGINEERING ? 1 + v : q > 0 ? sqrt(q) : 0;
    } else {
        double N = kind == CTN_PRESTRESS_STRESS ? v * sp->A : v;
        if (mat->tension_only && N < 0)
            return ctn_model_error(m, CTN_ERR_MODEL, "element %d: a tension-only member cannot be prestressed in "
                                   "compression (N0 = %g)", e->id, N);
        lam = stretch_for(mat, EA, N);
    }
    if (!(lam > 0) || !isfinite(l / lam))
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d: no unstressed length gives that prestress (%g) "
                               "with this material's law", e->id, v);
    *l0 = l / lam;
    return CTN_OK;
}

const ctn_element_ops ctn_cable2_ops = {
    .name = "cable", .nnodes = 2, .ndof_node = 3, .props_size = sizeof(ctn_cable_props),
    .flags = CTN_ELEM_FLEXIBLE | CTN_ELEM_SECTION,
    .check = cable_check, .setup = cable_setup, .eval = cable_eval, .load = cable_load,
    .stiffness = cable_stiffness, .rest_length = cable_rest_length, .hang = cable_hang, .prestress_l0 = cable_prestress_l0,
    .temperature = cable_temperature,
    .mass = cable_mass, .eval_axial = ctn_cable_axial, .sever = cable_sever,
};
