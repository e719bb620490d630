/* Wind drag on the relative velocity (`dynamics ... relative_wind=1`): on each
 * two-node cable element under a `wind` (speed V along its direction w, air density
 * rho, cd, diameter d, iced d + 2T), per unit current length
 *   q = k |u_n| u_n,  k = rho cd d / 2,  u = V w - (v_a + v_b) / 2,  u_n = (I - t t^T) u,
 * t the current chord's unit vector, half of q l at each node: the cross-flow drag on the
 * velocity of the air relative to the element's mean velocity, so the structure's own
 * motion is damped (aerodynamic damping; in still air, V = 0, the only effect). Its
 * derivative in the velocities, -dq/du_bar = k |u_n| (P + n n^T), P = I - t t^T, n =
 * u_n / |u_n| (symmetric, positive semi-definite), enters the effective tangent times
 * c2 = gamma / (beta h) (each node's velocity a half of u_bar's: a block (l/4) k |u_n|
 * (P + n n^T) for every pair of the element's nodes); its derivative in the positions
 * (through t and l) is left out of the tangent (Newton converges linearly in that part,
 * at a rate of about h^2 k |u| / m). docs/theory.md "Dynamics". */
#include "analysis/dynamics/dynamics.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The elements under a wind in the dynamics' loads: counted, or filled. */
static size_t scan(ctn_dyn *dy, int fill)
{
    const ctn_model *m = dy->p->m;
    ctn_loadsel sel = ctn_loadsel_step(ctn_model_step_count(m) - 1);
    size_t n = 0;
    for (size_t j = 0; j < m->lloads.n; j++) {
        const ctn_lload *l = &m->lloads.v[j];
        if (!l->drag || ctn_loadsel_weight(&sel, l->step) == 0) continue;
        for (size_t e = 0; e < m->elements.n; e++) {
            if (!ctn_lload_on(m, l, e)) continue;
            if (fill) {
                double d = l->cdp > 0 ? ctn_model_drag_q(m, l, &sel, e) / l->cdp : l->d;
                dy->wk[n] = 0.5 * l->rho * l->cd * d * ctn_loadsel_weight(&sel, l->step);
                dy->welem[n] = e;
                for (int k = 0; k < 3; k++) dy->wvel[3 * n + (size_t)k] = l->speed * l->dir[k];
            }
            n++;
        }
    }
    return n;
}

/* The wind a dynamics can take: relative_wind=1, given by speed= and rho=, on two-node
 * elements; CTN_ERR_MODEL at the wind's line. */
int ctn_dyn_wind_check(const ctn_problem *p, const ctn_dynamics_options *o)
{
    const ctn_model *m = p->m;
    for (size_t j = 0; j < m->lloads.n; j++) {
        const ctn_lload *l = &m->lloads.v[j];
        if (!l->drag) continue;
        if (!o->relative_wind)
            return ctn_dyn_error(p, o, "dynamics: a `wind` acts in a dynamics analysis on the velocity relative to the "
                                       "elements: give relative_wind=1 (and the wind as speed= rho=)");
        if (!(l->rho > 0))
            return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, l->line, "wind: relative_wind=1 needs the air's density: "
                                "give speed= and rho= (not pressure=)");
        for (size_t e = 0; e < m->elements.n; e++)
            if (ctn_lload_on(m, l, e) && m->elements.v[e].nnodes != 2)
                return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, l->line, "wind: relative_wind=1 drags two-node "
                                    "elements only (element %d has %d nodes)", m->elements.v[e].id, m->elements.v[e].nnodes);
    }
    return CTN_OK;
}

int ctn_dyn_wind_setup(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    size_t n = scan(dy, 0);
    if (!n) return CTN_OK;
    dy->nwind = n;
    dy->wk = ctn_calloc(p->ctx, n, sizeof(double));
    dy->welem = ctn_calloc(p->ctx, n, sizeof(size_t));
    dy->wvel = ctn_calloc(p->ctx, 3 * n, sizeof(double));
    dy->wD = ctn_calloc(p->ctx, 9 * n, sizeof(double));
    dy->wf = ctn_calloc(p->ctx, p->ns, sizeof(double));
    dy->wf0 = ctn_calloc(p->ctx, p->ns, sizeof(double));
    dy->wv = ctn_calloc(p->ctx, p->ns, sizeof(double));
    if (!dy->wk || !dy->welem || !dy->wvel || !dy->wD || !dy->wf || !dy->wf0 || !dy->wv) return CTN_ERR_NOMEM;
    scan(dy, 1);
    return ctn_asm_need_slots(p->ctx, p->a);
}

/* The drag of element s at positions x (its two nodes, current) and velocity ubar of the
 * air relative to it: the force per node into f[3], the block (l/4) k |u_n| (P + n n^T)
 * into D[9]. */
static void drag(const ctn_dyn *dy, size_t s, const double *xa, const double *xb, const double *u, double *f, double *D)
{
    double t[3], l = 0, ut = 0, un[3], nn = 0, k = dy->wk[s];
    for (int c = 0; c < 3; c++) {
        t[c] = xb[c] - xa[c];
        l += t[c] * t[c];
    }
    l = sqrt(l);
    for (int c = 0; c < 3; c++) t[c] = l > 0 ? t[c] / l : 0.0;
    for (int c = 0; c < 3; c++) ut += u[c] * t[c];
    for (int c = 0; c < 3; c++) {
        un[c] = u[c] - ut * t[c];
        nn += un[c] * un[c];
    }
    nn = sqrt(nn);
    for (int c = 0; c < 3; c++) f[c] = 0.5 * l * k * nn * un[c];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            D[3 * i + j] = 0.25 * l * k * (nn * ((i == j) - t[i] * t[j]) + (nn > 0 ? un[i] * un[j] / nn : 0.0));
}

void ctn_dyn_wind(ctn_dyn *dy, const double *d, const double *v, double t, double *r)
{
    ctn_problem *p = dy->p;
    const ctn_model *m = p->m;
    if (!dy->nwind) return;
    const int *eq = p->a->map.eq;
    ctn_dyn_rates(dy, t, v, NULL, dy->wv, NULL);
    memset(dy->wf, 0, p->ns * sizeof(double));
    for (size_t s = 0; s < dy->nwind; s++) {
        const int *nd = ctn_elem_nodes(m, dy->welem[s]);
        size_t ia = ctn_dofmap_node(&p->a->map, (size_t)nd[0]), ib = ctn_dofmap_node(&p->a->map, (size_t)nd[1]);
        double xa[3], xb[3], u[3], f[3];
        for (int c = 0; c < 3; c++) {
            xa[c] = m->nodes.v[nd[0]].X[c] + d[ia + (size_t)c];
            xb[c] = m->nodes.v[nd[1]].X[c] + d[ib + (size_t)c];
            u[c] = dy->wvel[3 * s + (size_t)c] - 0.5 * (dy->wv[ia + (size_t)c] + dy->wv[ib + (size_t)c]);
        }
        drag(dy, s, xa, xb, u, f, dy->wD + 9 * s);
        for (int c = 0; c < 3; c++) {
            dy->wf[ia + (size_t)c] += f[c];
            dy->wf[ib + (size_t)c] += f[c];
        }
    }
    for (size_t i = 0; i < p->ns; i++)
        if (eq[i] >= 0) r[eq[i]] += dy->wf[i];
}

void ctn_dyn_wind_tangent(ctn_dyn *dy, double c2)
{
    ctn_problem *p = dy->p;
    const ctn_asm *a = p->a;
    for (size_t s = 0; s < dy->nwind; s++) {
        size_t e = dy->welem[s];
        const ctn_asm_block *b = ctn_asm_block_of(a, e);
        const int *slot = a->slot + b->slot0 + (e - b->e0) * (size_t)b->nslots;
        const double *D = dy->wD + 9 * s;
        int n = b->nedof, nd = b->ops->ndof_node;
        for (int i = 0; i < n; i++)
            for (int j = i; j < n; j++) {
                int ci = i % nd, cj = j % nd, sl = slot[ctn_packed_index(n, i, j)];
                if (ci >= 3 || cj >= 3 || sl == -1) continue;
                p->Kx[sl >= 0 ? sl : -(sl + 2)] += c2 * D[3 * ci + cj];
            }
    }
}
