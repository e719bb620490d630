/* A cable over frictionless pulleys: nodes x_0 (end), x_1 .. x_{n-2} (pulleys), x_{n-1}
 * (end); straight segments a_j = x_{j+1} - x_j, l_j = |a_j|, e_j = a_j / l_j. One
 * unstressed length l0 for the whole cable, so one tension N(lambda), lambda = S / l0,
 * S = sum l_j, by the material's law (that of the cable element, tension-only):
 *   f_i = N g_i,  g_i = dS/dx_i = e_{i-1} - e_i  (e_{-1} = e_{n-1} = 0)
 *   K = dN/dS g g^T + sum_j N / l_j (I - e_j e_j^T) on nodes (j, j+1) as a bar's block.
 * A pulley node is loaded by the resultant N (e_{i-1} - e_i) of the tension on its two
 * sides; the pulley's radius is not modelled (the cable passes through the node). */
#include "element/pulley.h"

#include <math.h>
#include <string.h>

/* Tension, its derivative dN/dS and energy of the whole cable at current length S: the
 * cable element's law, evaluated on a straight chord of length S. */
static void law(const ctn_pulley_props *p, unsigned mode, double S, ctn_elem_state *st, double *dNdS)
{
    double X[6] = { 0, 0, 0, S, 0, 0 }, u[6] = { 0 }, f[6], K[21];
    ctn_cable2_ops.eval(&p->cable, mode, X, u, f, K, st);
    *dNdS = K[0];                                      /* k_xx = dN/dl on an x chord */
}

/* Packed tangent: dN/dS g g^T + sum_j N / l_j (I - e_j e_j^T) on nodes (j, j + 1). */
static void pulley_tangent(int n, const double *g, double e[][3], const double *l, double N, double dNdS, double *K)
{
    int nd = 3 * n;
    for (int a = 0; a < nd; a++)
        for (int b = a; b < nd; b++) K[ctn_packed_index(nd, a, b)] = dNdS * g[a] * g[b];
    for (int j = 0; j + 1 < n && N != 0; j++)
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) {
                double k = N / l[j] * ((r == c) - e[j][r] * e[j][c]);
                if (r <= c) {
                    K[ctn_packed_index(nd, 3 * j + r, 3 * j + c)] += k;
                    K[ctn_packed_index(nd, 3 * j + 3 + r, 3 * j + 3 + c)] += k;
                }
                K[ctn_packed_index(nd, 3 * j + r, 3 * j + 3 + c)] -= k;
            }
}

static int pulley_eval(const void *props, unsigned mode, const double *X, const double *u,
                       double *f, double *K, ctn_elem_state *out)
{
    const ctn_pulley_props *p = props;
    int n = p->nnodes;
    double e[CTN_ELEM_MAX_NODES - 1][3], l[CTN_ELEM_MAX_NODES - 1], g[3 * CTN_ELEM_MAX_NODES], S = 0, dNdS;
    ctn_elem_state st;
    for (int j = 0; j + 1 < n; j++) {
        if (ctn_axial_chord(X + 3 * j, u + 3 * j, e[j], &l[j])) return 1;
        S += l[j];
    }
    law(p, mode, S, &st, &dNdS);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            g[3 * i + k] = (i > 0 ? e[i - 1][k] : 0) - (i + 1 < n ? e[i][k] : 0);
            f[3 * i + k] = st.N * g[3 * i + k];
        }
    if (K) pulley_tangent(n, g, e, l, st.N, dNdS, K);
    st.l = S;
    if (out) *out = st;
    return 0;
}

static int pulley_check(const ctn_model *m, const ctn_element *e)
{
    if (e->nnodes < 3)
        return ctn_model_error(m, CTN_ERR_MODEL, "pulley %d: give the two ends and at least one pulley node "
                               "(%d nodes given)", e->id, e->nnodes);
    if (!isfinite(e->l0) || e->l0 <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "pulley %d: length must be positive and finite (got %g)", e->id, e->l0);
    const ctn_section *sp = &m->sections.v[e->section];
    if (!isfinite(m->materials.v[sp->material].E * sp->A / e->l0))
        return ctn_model_error(m, CTN_ERR_MODEL, "pulley %d: axial stiffness E A / length overflows (length = %g)", e->id, e->l0);
    return CTN_OK;
}

static void pulley_setup(const ctn_model *m, size_t e, void *props)
{
    const ctn_element *el = &m->elements.v[e];
    ctn_pulley_props *p = props;
    memset(p, 0, sizeof *p);
    ctn_cable2_ops.setup(m, e, &p->cable);
    p->cable.tension_only = 1;
    p->nnodes = el->nnodes;
    p->l0_ref = el->l0;
    p->alpha = m->materials.v[m->sections.v[el->section].material].alpha;
}

static double seg_len(const double *a, const double *b)
{
    return hypot(hypot(b[0] - a[0], b[1] - a[1]), b[2] - a[2]);
}

/* Self-weight w l0 g, shared by the segments in proportion to their reference lengths,
 * half of each segment's share to each of its ends (the segments stay straight). */
static void pulley_load(const ctn_model *m, size_t e, double *f)
{
    const ctn_element *el = &m->elements.v[e];
    const int *nd = ctn_elem_nodes(m, e);
    double S = 0, w = m->sections.v[el->section].w * el->l0;
    if (w == 0) return;
    for (int j = 0; j + 1 < el->nnodes; j++) {
        S += seg_len(m->nodes.v[nd[j]].X, m->nodes.v[nd[j + 1]].X);
    }
    for (int j = 0; j + 1 < el->nnodes; j++) {
        double W = 0.5 * w * seg_len(m->nodes.v[nd[j]].X, m->nodes.v[nd[j + 1]].X) / S;
        for (int k = 0; k < 3; k++) {
            f[3 * (size_t)nd[j] + (size_t)k] += W * m->gravity[k];
            f[3 * (size_t)nd[j + 1] + (size_t)k] += W * m->gravity[k];
        }
    }
}

static double pulley_stiffness(const void *props)
{
    const ctn_pulley_props *p = props;
    return p->cable.EA / p->cable.l0;
}

static int pulley_prestress_l0(const ctn_model *m, const ctn_element *e, int kind, double v, double l, double *l0)
{
    return ctn_cable2_ops.prestress_l0(m, e, kind, v, l, l0);
}

static void pulley_temperature(void *props, double dT)
{
    ctn_pulley_props *p = props;
    p->cable.l0 = p->l0_ref * (1 + p->alpha * dT);
}

/* The rope's mass m' l0 shared by the segments as its weight is (in proportion to their
 * input lengths), each segment's share a two-node member's mass matrix on its ends. */
static void pulley_mass(const void *props, const double *X, int lumped, double *M)
{
    const ctn_pulley_props *p = props;
    const int n = 3 * p->nnodes;
    double S = 0, seg[21];
    for (int t = 0; t < ctn_packed_size(n); t++) M[t] = 0;
    for (int j = 0; j + 1 < p->nnodes; j++) S += seg_len(X + 3 * j, X + 3 * j + 3);
    for (int j = 0; j + 1 < p->nnodes; j++) {
        double share = S > 0 ? seg_len(X + 3 * j, X + 3 * j + 3) / S : 1.0 / (p->nnodes - 1);
        ctn_axial_mass(p->cable.mass * share, lumped, seg);
        for (int a = 0; a < 6; a++)
            for (int b = a; b < 6; b++) M[ctn_packed_index(n, 3 * j + a, 3 * j + b)] += seg[ctn_packed_index(6, a, b)];
    }
}

const ctn_element_ops ctn_pulley_ops = {
    .name = "pulley", .nnodes = 0, .ndof_node = 3, .props_size = sizeof(ctn_pulley_props),
    .flags = CTN_ELEM_SECTION | CTN_ELEM_TENSION_ONLY,
    .check = pulley_check, .setup = pulley_setup, .eval = pulley_eval, .load = pulley_load,
    .stiffness = pulley_stiffness, .prestress_l0 = pulley_prestress_l0, .temperature = pulley_temperature,
    .mass = pulley_mass,
};
