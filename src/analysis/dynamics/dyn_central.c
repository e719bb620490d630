/* Explicit central differences on the lumped mass, in the velocity form:
 *   v(n+1/2) = v_n + h/2 a_n,  d1 = d0 + h v(n+1/2),
 *   a1 = M_L^-1 (f_ext - f_int(d1) - C v(n+1/2)),  v1 = v(n+1/2) + h/2 a1,
 * stable for h <= 2 / omega_max (sqrt(1 + zeta^2) - zeta); omega_max^2 is bounded by
 * Gershgorin's theorem on M_L^-1 K_T at the start: max_q sum_j |K_qj| / M_qq (for a
 * uniform taut string that is exactly the largest eigenvalue: h <= l / c). A member slack
 * at the start (a chain released from a shorter chord) adds nothing to K_T there but its
 * elastic stiffness k e e^T once taut: its rows are added to the bound. */
#include "analysis/dynamics/dynamics.h"

#include <math.h>
#include <string.h>

/* The rows of |k e e^T| (on the free DOFs, e the chord at the start) of the members
 * slack at the start, added into row (ndof). */
typedef struct slack_rows {
    const ctn_problem *p;
    const double *d;
    double *row;
} slack_rows;

static void slack_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    slack_rows *sr = data;
    if (!el->st->slack || el->b->nnodes != 2 || el->b->ops->ndof_node != 3) return;
    double e[3], len = 0, k = el->b->ops->stiffness(el->props), abs_e[2] = { 0, 0 };
    int q[2][3];
    for (int c = 0; c < 3; c++) {
        size_t i0 = ctn_dofmap_node(&a->map, (size_t)el->nodes[0]), i1 = ctn_dofmap_node(&a->map, (size_t)el->nodes[1]);
        e[c] = a->m->nodes.v[el->nodes[1]].X[c] + sr->d[i1 + (size_t)c] - a->m->nodes.v[el->nodes[0]].X[c] - sr->d[i0 + (size_t)c];
        len += e[c] * e[c];
        q[0][c] = a->map.eq[i0 + (size_t)c];
        q[1][c] = a->map.eq[i1 + (size_t)c];
    }
    len = sqrt(len);
    if (!(len > 0)) return;
    for (int n = 0; n < 2; n++)
        for (int c = 0; c < 3; c++) abs_e[n] += q[n][c] >= 0 ? fabs(e[c]) / len : 0.0;
    for (int n = 0; n < 2; n++)
        for (int c = 0; c < 3; c++)
            if (q[n][c] >= 0) sr->row[q[n][c]] += k * fabs(e[c]) / len * (abs_e[0] + abs_e[1]);
}

int ctn_dyn_stable_step(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    size_t n = p->ndof;
    int valid = 0;
    int rc = ctn_dyn_residual(dy, dy->d0, 1, dy->r1, &valid);
    if (rc) return rc;
    if (!valid) return ctn_error(p->ctx, CTN_ERR_MODEL, "dynamics: the start state cannot be evaluated");
    double *row = dy->w, wmax2 = 0;
    memset(row, 0, n * sizeof(double));
    for (size_t j = 0; j < n; j++)
        for (int k = p->a->colptr[j]; k < p->a->colptr[j + 1]; k++) {
            size_t i = (size_t)p->a->rowind[k];
            row[j] += fabs(p->Kx[k]);
            if (i != j) row[i] += fabs(p->Kx[k]);
        }
    slack_rows sr = { p, dy->d0, row };
    ctn_asm_loop(p->a, dy->d0, 0, 0, slack_visit, &sr, NULL);
    for (size_t q = 0; q < n; q++) wmax2 = fmax(wmax2, row[q] / dy->diag[q]);
    double w = sqrt(wmax2), zeta = w > 0 ? 0.5 * (dy->o->damping_alpha / w + dy->o->damping_beta * w) : 0;
    dy->sum.dt_stable = w > 0 ? 2.0 / w * (sqrt(1 + zeta * zeta) - zeta) : dy->o->t_end;   /* no stiffness: no limit */
    return CTN_OK;
}

int ctn_dyn_central_step(ctn_dyn *dy, double h, int *ok)
{
    ctn_problem *p = dy->p;
    const int *eq = p->a->map.eq;
    size_t n = p->ndof;
    int valid = 0;
    double *vh = dy->w;
    *ok = 0;
    for (size_t q = 0; q < n; q++) vh[q] = dy->v0[q] + 0.5 * h * dy->a0[q];
    for (size_t i = 0; !dy->rot && i < p->ns; i++) {
        int q = eq[i];
        if (q >= 0) dy->d1[i] = dy->d0[i] + h * vh[q];      /* fixed DOFs: at t_n+1 already */
    }
    if (dy->rot) {                                          /* the rotations turned by spins */
        for (size_t i = 0; i < p->ns; i++)
            if (eq[i] >= 0) dy->d1[i] = dy->d0[i];
        for (size_t q = 0; q < n; q++) dy->R[q] = h * vh[q];
        ctn_dyn_rot_central_turn(dy, h, dy->R);
        ctn_problem_update(p, dy->d1, 1.0, dy->R);
    }
    int rc = ctn_dyn_residual(dy, dy->d1, 0, dy->r1, &valid);
    if (rc || !valid) return rc;
    ctn_dyn_wind(dy, dy->d1, vh, dy->t1, dy->r1);          /* on v(n+1/2) */
    ctn_dyn_damp_at(dy, dy->d1, vh, dy->R, dy->w2);
    for (size_t q = 0; q < n; q++) {
        dy->R[q] = dy->r1[q] - dy->w2[q] - (dy->fsup ? dy->fsup[q] : 0.0);
        dy->a1[q] = dy->R[q] / dy->diag[q];
        dy->v1[q] = vh[q] + 0.5 * h * dy->a1[q];
    }
    if (dy->rot && !ctn_dyn_rot_central_rates(dy, h, dy->R)) return CTN_OK;
    for (size_t q = 0; q < n; q++)
        if (!isfinite(dy->v1[q])) return CTN_OK;
    dy->sum.iterations++;
    *ok = 1;
    return ctn_interrupted(p->ctx);
}
