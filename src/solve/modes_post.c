/* What a modal analysis stores of each mode: the kind, frequencies, the shape per node
 * (mass-normalized, the largest component positive), participation and effective mass,
 * the nodes that move, and the residual |K phi - omega^2 M phi| / |K phi|. */
#include "solve/modes.h"

#include <math.h>
#include <string.h>

/* Largest component positive: the sign of an eigenvector is arbitrary, a result's not. */
static void fix_sign(double *phi, size_t n)
{
    size_t imax = 0;
    for (size_t i = 1; i < n; i++)
        if (fabs(phi[i]) > fabs(phi[imax])) imax = i;
    if (phi[imax] >= 0) return;
    for (size_t i = 0; i < n; i++) phi[i] = -phi[i];
}

static void frequencies(const ctn_modal *md, double lam, ctn_mode *m)
{
    m->eigenvalue = lam;
    m->kind = fabs(lam) <= md->ztol ? CTN_MODE_ZERO : lam < 0 ? CTN_MODE_UNSTABLE : CTN_MODE_VIBRATION;
    if (m->kind != CTN_MODE_VIBRATION) return;
    m->angular_frequency = sqrt(lam);
    m->frequency = m->angular_frequency / CTN_TWO_PI;
    m->period = 1.0 / m->frequency;
}

/* The node that moves most and, for a zero mode, those that move (largest first). */
static void moving_nodes(const ctn_model *m, const double *shape, ctn_mode *out)
{
    size_t nn = m->nodes.n, imax = 0;
    double amax = 0;
    for (size_t i = 0; i < nn; i++) {
        const double *u = shape + 3 * i;
        double a = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        if (a > amax) { amax = a; imax = i; }
    }
    out->node = m->nodes.v[imax].id;
    if (out->kind != CTN_MODE_ZERO) return;
    double top[CTN_MODE_MAX_NODES];
    for (size_t i = 0; i < nn; i++) {
        const double *u = shape + 3 * i;
        double a = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        if (!(a >= 1e-3 * amax) || amax == 0) continue;
        int k = out->nnodes < CTN_MODE_MAX_NODES ? out->nnodes : CTN_MODE_MAX_NODES;
        out->nnodes++;
        if (k == CTN_MODE_MAX_NODES && a <= top[k - 1]) continue;
        if (k == CTN_MODE_MAX_NODES) k--;                  /* drop the smallest kept */
        for (; k > 0 && top[k - 1] < a; k--) {             /* insertion, largest first */
            top[k] = top[k - 1];
            out->nodes[k] = out->nodes[k - 1];
        }
        top[k] = a;
        out->nodes[k] = m->nodes.v[i].id;
    }
}

/* One mode from phi (ndof, changed in sign only); its shape (3 per node) into shape. */
static void describe(ctn_modal *md, double *phi, double lam, ctn_mode *out, double *shape)
{
    ctn_problem *p = md->p;
    double *Mphi = md->w0, *Kphi = md->w1, *state = md->d;
    size_t n = p->ndof;
    fix_sign(phi, n);
    frequencies(md, lam, out);
    memset(state, 0, p->ns * sizeof(double));
    ctn_problem_axpy(p, state, 1.0, phi);
    ctn_dofmap_to3(&p->a->map, state, shape);
    ctn_problem_symv(p, md->Mx, phi, Mphi);
    ctn_problem_symv(p, p->Kx, phi, Kphi);
    for (size_t q = 0; q < n; q++) {
        int dir = p->a->map.dof_dir[q];
        if (dir < 3) out->participation[dir] += Mphi[q];          /* Gamma = phi^T M r */
    }
    for (int k = 0; k < 3; k++) out->effective_mass[k] = out->participation[k] * out->participation[k];
    moving_nodes(p->m, out->shape, out);
    if (out->kind == CTN_MODE_ZERO) return;
    double rr = 0;
    for (size_t q = 0; q < n; q++) rr += (Kphi[q] - lam * Mphi[q]) * (Kphi[q] - lam * Mphi[q]);
    double kn = ctn_vec_norm(Kphi, n);
    if (kn > 0) md->sum.max_residual = fmax(md->sum.max_residual, sqrt(rr) / kn);
}

void ctn_modes_fill(ctn_modal *md, double *V, ctn_modes *res)
{
    size_t n = md->p->ndof;
    for (int k = 0; k < md->opt->count; k++) {
        double *phi = V + n * (size_t)k;
        describe(md, phi, md->lambda[k], &res->mode[k], res->shapes + 3 * md->p->m->nodes.n * (size_t)k);
        md->sum.zero_modes += res->mode[k].kind == CTN_MODE_ZERO;
        md->sum.unstable_modes += res->mode[k].kind == CTN_MODE_UNSTABLE;
    }
}
