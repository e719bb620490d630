/* What a target measures on its cable or catenary element (target.h; docs/format.md,
 * "Cables set by a target"). Forces come from the elements' own kernels at the state,
 * so a catenary element's H and end tensions are those of its inner solution, and its
 * sag is read on its exact curve. */
#include "element/catenary.h"
#include "design/targets/target.h"

#include <math.h>

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void node_pos(const ctn_model *m, const double *u3, size_t i, double x[3])
{
    for (int k = 0; k < 3; k++) x[k] = m->nodes.v[i].X[k] + u3[3 * i + (size_t)k];
}

static void unit_down(const ctn_model *m, double g[3])
{
    double n = sqrt(dot3(m->gravity, m->gravity));
    for (int k = 0; k < 3; k++) g[k] = n > 0 ? m->gravity[k] / n : 0;
}

/* X and u of two-node element e (6 each) from the state u3. */
static void gather(const ctn_model *m, const double *u3, size_t e, double X[6], double u[6])
{
    const int *nd = ctn_elem_nodes(m, e);
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) {
            X[3 * a + k] = m->nodes.v[nd[a]].X[k];
            u[3 * a + k] = u3[3 * (size_t)nd[a] + (size_t)k];
        }
}

/* Internal forces f (6) and state of two-node element e at u3. */
static void eval(const ctn_problem *p, const double *u3, size_t e, double f[6], ctn_elem_state *st)
{
    double X[6], u[6];
    gather(p->m, u3, e, X, u);
    ctn_asm_block_of(p->a, e)->ops->eval(ctn_asm_props(p->a, e), 0, X, u, f, NULL, st);
}

/* Force of record c on its end node `end` (0 or 1): minus the end element's internal
 * force there, plus the half of the element's weight that the node carries. */
static void end_force(const ctn_problem *p, const double *u3, const ctn_cable *c, int end, double F[3])
{
    const ctn_model *m = p->m;
    size_t e = end ? c->first + c->count - 1 : c->first;
    double f[6];
    ctn_elem_state st;
    eval(p, u3, e, f, &st);
    double W = 0.5 * m->sections.v[m->elements.v[e].section].w * m->elements.v[e].l0;
    for (int k = 0; k < 3; k++) F[k] = -f[3 * end + k] + W * m->gravity[k];
}

static double horizontal(const ctn_model *m, const double F[3])
{
    double g[3], h[3];
    unit_down(m, g);
    double v = dot3(F, g);
    for (int k = 0; k < 3; k++) h[k] = F[k] - v * g[k];
    return sqrt(dot3(h, h));
}

/* Largest distance along gravity of a node of the chain below the chord, read at the
 * chord's point with the same horizontal position. */
static double chain_sag(const ctn_model *m, const double *u3, const ctn_cable *c)
{
    double g[3], A[3], B[3], ch[3], h[3], best = 0;
    unit_down(m, g);
    node_pos(m, u3, (size_t)c->node[0], A);
    node_pos(m, u3, (size_t)c->node[1], B);
    for (int k = 0; k < 3; k++) ch[k] = B[k] - A[k];
    double cg = dot3(ch, g);
    for (int k = 0; k < 3; k++) h[k] = ch[k] - cg * g[k];      /* horizontal part of the chord */
    double hh = dot3(h, h);
    if (!(hh > 0)) return NAN;
    for (size_t j = 0; j + 1 < c->count; j++) {
        double P[3], r[3];
        node_pos(m, u3, (size_t)ctn_elem_nodes(m, c->first + j)[1], P);
        for (int k = 0; k < 3; k++) r[k] = P[k] - A[k];
        double s = dot3(r, h) / hh;                            /* chord parameter */
        best = fmax(best, dot3(r, g) - s * cg);
    }
    return best;
}

/* The sag of catenary element e on its exact curve (0 without weight: a straight bar). */
static double catenary_sag(const ctn_problem *p, const double *u3, size_t e)
{
    double X[6], u[6], ex[3];
    ctn_ecat c;
    int bar;
    gather(p->m, u3, e, X, u);
    if (ctn_catenary_state(ctn_asm_props(p->a, e), X, u, &c, ex, &bar)) return NAN;
    if (!bar && !(c.l > 0)) return NAN;
    return bar ? 0 : ctn_ecat_max_sag(&c);
}

double ctn_target_quantity(const ctn_problem *p, const ctn_cable *c, const double *u3)
{
    double F0[3], F1[3];
    switch (c->target) {
    case CTN_TARGET_H:
        end_force(p, u3, c, 0, F0);
        return horizontal(p->m, F0);
    case CTN_TARGET_SAG:
        if (c->count == 1 && ctn_asm_block_of(p->a, c->first)->ops == &ctn_catenary2_ops)
            return catenary_sag(p, u3, c->first);
        return chain_sag(p->m, u3, c);
    default:
        end_force(p, u3, c, 0, F0);
        end_force(p, u3, c, 1, F1);
        return fmax(sqrt(dot3(F0, F0)), sqrt(dot3(F1, F1)));
    }
}

double ctn_target_strain(const ctn_problem *p, const ctn_cable *c, const double *u3)
{
    double eps = -INFINITY, f[6];
    for (size_t e = c->first; e < c->first + c->count; e++) {
        ctn_elem_state st;
        eval(p, u3, e, f, &st);
        eps = fmax(eps, st.strain);
    }
    return eps;
}
