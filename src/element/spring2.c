/* Two-node axial linear spring: N = k (l - l0), two-way, no section and no weight.
 *   U = k (l - l0)^2 / 2,  dN/dl = k;  forces and tangent as any axial member. */
#include "element/spring2.h"
#include "element/axial.h"

#include <math.h>

static int spring_axial(const void *props, unsigned mode, const double *X, const double *u, double *f,
                        double *kk, ctn_elem_state *out)
{
    const ctn_spring_props *p = props;
    double e[3];
    (void)mode;                                        /* a spring is never cut */
    *out = (ctn_elem_state){ 0, 0, 0, 0, 0, 0 };
    if (ctn_axial_chord(X, u, e, &out->l)) return 1;
    double ext = out->l - p->l0;
    out->strain = ext / p->l0;                         /* engineering: (l - l0) / l0 */
    out->N = p->k * ext;
    out->energy = 0.5 * p->k * ext * ext;
    ctn_axial_forces(e, out->N, f);
    if (kk) ctn_axial_k(e, out->l, out->N, p->k, kk);
    return 0;
}

static int spring_eval(const void *props, unsigned mode, const double *X, const double *u,
                       double *f, double *K, ctn_elem_state *out)
{
    return ctn_axial_eval(spring_axial, props, mode, X, u, f, K, out);
}

static int spring_check(const ctn_model *m, const ctn_element *e)
{
    if (!isfinite(e->par[0]) || e->par[0] <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "spring %d: k must be positive and finite (got %g)", e->id, e->par[0]);
    if (!isfinite(e->l0) || e->l0 <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "spring %d: l0 must be positive and finite (got %g)", e->id, e->l0);
    if (!isfinite(e->par[0] * e->l0))
        return ctn_model_error(m, CTN_ERR_MODEL, "spring %d: k l0 = %g * %g overflows", e->id, e->par[0], e->l0);
    return CTN_OK;
}

static void spring_params(const ctn_element_spec *s, double *par) { par[0] = s->k; }

static void spring_setup(const ctn_model *m, size_t e, void *props)
{
    ctn_spring_props *p = props;
    p->k = m->elements.v[e].par[0];
    p->l0 = m->elements.v[e].l0;
}

static void spring_sever(void *props) { ((ctn_spring_props *)props)->k = 0; }

static double spring_stiffness(const void *props) { return ((const ctn_spring_props *)props)->k; }

static int spring_prestress_l0(const ctn_model *m, const ctn_element *e, int kind, double v, double l, double *l0)
{
    if (kind == CTN_PRESTRESS_STRESS)
        return ctn_model_error(m, CTN_ERR_MODEL, "spring %d: a spring has no section: give N0= or eps0=", e->id);
    *l0 = kind == CTN_PRESTRESS_FORCE ? l - v / e->par[0] : l / (1 + v);    /* N0 = k (l - l0) */
    if (!(*l0 > 0) || !isfinite(*l0))
        return ctn_model_error(m, CTN_ERR_MODEL, "spring %d: no positive free length gives that prestress (%g)", e->id, v);
    return CTN_OK;
}

const ctn_element_ops ctn_spring2_ops = {
    .name = "spring", .nnodes = 2, .ndof_node = 3, .props_size = sizeof(ctn_spring_props), .flags = 0,
    .check = spring_check, .params = spring_params, .setup = spring_setup, .eval = spring_eval,
    .stiffness = spring_stiffness, .prestress_l0 = spring_prestress_l0, .eval_axial = spring_axial,
    .sever = spring_sever,
};
