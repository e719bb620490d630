/* What a modal analysis stores of each mode: the kind, frequencies, the shape per node
 * (mass-normalized, the largest component positive), participation and effective mass,
 * the nodes that move, and the residual |K phi - omega^2 M phi| / |K phi|. */
#include "core/threads.h"
#include "analysis/modal/modal.h"

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

/* A share of the modes, with its own scratch (Mphi, Kphi: ndof; state: ns). */
typedef struct fill_job {
    ctn_modal *md;
    double *V;
    ctn_modes *res;
    int k0, k1;
    double *Mphi, *Kphi, *state;
    double max_residual, worst;
    int zero, unstable, failed;
} fill_job;

/* One mode from phi (ndof, changed in sign only); its shape (3 per node) into shape, its
 * rotations into rshape (unless NULL). */
static void describe(fill_job *j, double *phi, double lam, ctn_mode *out, double *shape, double *rshape)
{
    ctn_modal *md = j->md;
    ctn_problem *p = md->p;
    double *Mphi = j->Mphi, *Kphi = j->Kphi, *state = j->state;
    size_t n = p->ndof;
    fix_sign(phi, n);
    frequencies(md, lam, out);
    memset(state, 0, p->ns * sizeof(double));
    ctn_problem_axpy(p, state, 1.0, phi);
    ctn_dofmap_to3(&p->a->map, state, shape);
    if (rshape) ctn_dofmap_rot_to3(&p->a->map, state, rshape);
    ctn_modal_mass(md, phi, Mphi);
    ctn_problem_symv(p, p->Kx, phi, Kphi);
    for (size_t q = 0; q < n; q++) {
        int dir = p->a->map.dof_dir[q];
        if (dir < 3) out->participation[dir] += Mphi[q];          /* Gamma = phi^T M r */
    }
    for (int k = 0; k < 3; k++) {
        out->participation[k] = ctn_layout_sum(&p->eq, out->participation[k]);
        out->effective_mass[k] = out->participation[k] * out->participation[k];
    }
    moving_nodes(p->m, out->shape, out);
    if (out->kind == CTN_MODE_ZERO) return;
    double rr = 0;
    for (size_t q = 0; q < n; q++) rr += (Kphi[q] - lam * Mphi[q]) * (Kphi[q] - lam * Mphi[q]);
    rr = ctn_layout_sum(&p->eq, rr);
    double kn = ctn_layout_norm(&p->eq, Kphi), scale = kn + fabs(lam) * ctn_layout_norm(&p->eq, Mphi);
    if (kn > 0) j->max_residual = fmax(j->max_residual, sqrt(rr) / kn);
    double rel = scale > 0 ? sqrt(rr) / scale : sqrt(rr);
    if (!(rel <= CTN_MODE_RESIDUAL_MAX)) j->failed++;
    if (!(rel <= j->worst)) j->worst = rel;          /* a NaN too */
}

static void fill_run(void *arg)
{
    fill_job *j = arg;
    const ctn_modal *md = j->md;
    size_t n = md->p->ndof, nn = md->p->m->nodes.n;
    for (int k = j->k0; k < j->k1; k++) {
        describe(j, j->V + n * (size_t)k, md->lambda[k], &j->res->mode[k], j->res->shapes + 3 * nn * (size_t)k,
                 j->res->rshapes ? j->res->rshapes + 3 * nn * (size_t)k : NULL);
        j->zero += j->res->mode[k].kind == CTN_MODE_ZERO;
        j->unstable += j->res->mode[k].kind == CTN_MODE_UNSTABLE;
    }
}

/* Where the thread policy allows it (CTN_THR_MODES), the second half of the modes on
 * the context's helper with scratch of its own (each mode reads K and M once: the 20
 * modes of the K = 400 net took 0.19 s on one). */
void ctn_modes_fill(ctn_modal *md, double *V, ctn_modes *res)
{
    ctn_problem *p = md->p;
    const int count = md->opt->count;
    fill_job job[2] = { { md, V, res, 0, count, md->w0, md->w1, md->d, 0, 0, 0, 0, 0 } };
    job[1] = job[0];
    job[1].k0 = job[1].k1 = count;
    int two = count >= 2 && ctn_thr_allows(p->ctx, p->opt.threads, CTN_THR_MODES, (double)p->ndof);
    double *mine = two ? ctn_malloc(p->ctx, 2 * p->ndof + p->ns, sizeof(double)) : NULL;
    if (mine) {
        job[0].k1 = job[1].k0 = count / 2;
        job[1].Mphi = mine;
        job[1].Kphi = mine + p->ndof;
        job[1].state = mine + 2 * p->ndof;
    }
    if (mine) ctn_thr_both(p->ctx, p->opt.threads, CTN_THR_MODES, (double)p->ndof, fill_run, &job[0], &job[1]);
    else fill_run(&job[0]);
    ctn_free(mine);
    if (two && !mine) ctn_ctx_clear(p->ctx);            /* no scratch: one thread did it all */
    for (int i = 0; i < 2; i++) {
        md->sum.max_residual = fmax(md->sum.max_residual, job[i].max_residual);
        md->sum.zero_modes += job[i].zero;
        md->sum.unstable_modes += job[i].unstable;
        md->failed += job[i].failed;
        if (!(job[i].worst <= md->worst)) md->worst = job[i].worst;
    }
}
