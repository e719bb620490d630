/* Finite rotations in a dynamics analysis (beams): each node with free rotations carries
 * its rotary inertia J (3 x 3, in the node's material frame: half of each element's
 * rho I L0 at each of its nodes, from the family's lumped mass op; the translations keep
 * the consistent or lumped mass). Its angular velocity W and acceleration A are material
 * (body-frame) vectors, its rotation R = exp(psi) (psi the state's rotation vector, which
 * the Newton iteration turns by spins, R <- exp(dw) R). Newmark's formulas on the
 * material rotation increment of the step, Theta = log(R0^T R1) (Simo and Vu-Quoc 1988;
 * the Lie-group Newmark of Cardona and Geradin):
 *   A1 = (Theta - h W0 - h^2 (1/2 - beta) A0) / (beta h^2),
 *   W1 = W0 + h ((1 - gamma) A0 + gamma A1),
 * and the inertia moment in the spatial frame, I = R (J A + W x J W) (the gyroscopic
 * term included), weighted as the translations' inertia: (1 - am) I1 + am I0. Its
 * tangent in the spin of R1, c1 R1 J R1^T (symmetric), leaves out the gyroscopic and
 * the frame-rotation terms (of order h |W| beside it: Newton converges linearly in
 * them). Exact for any rigid rotation about a fixed axis; second order in h. A node
 * with some rotations fixed (a plane model) takes the same formulas (exact when one
 * rotation is free, about a fixed axis). docs/theory.md "Dynamics". */
#include "analysis/dynamics/dyn_rot.h"

#include <string.h>

/* The rotary inertia of the lumped mass op: each element's node blocks of rotations. */
static void inertia_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    struct ctn_dyn_rot *rt = data;
    const ctn_asm_block *b = el->b;
    double *Me = rt->work, *X = rt->work + b->nslots;
    if (!b->ops->mass || b->ops->ndof_node != 6) return;
    for (int i = 0; i < b->nnodes; i++) memcpy(X + 3 * i, a->m->nodes.v[el->nodes[i]].X, 3 * sizeof(double));
    b->ops->mass(el->props, X, 1, Me);
    for (int i = 0; i < b->nnodes; i++) {
        long k = rt->at[el->nodes[i]];
        double *J = k >= 0 ? rt->J + 9 * k : NULL;
        for (int r = 0; r < 3 && J; r++)
            for (int c = 0; c < 3; c++) {
                int u = 6 * i + 3 + r, v = 6 * i + 3 + c;
                J[3 * r + c] += Me[u <= v ? ctn_packed_index(b->nedof, u, v) : ctn_packed_index(b->nedof, v, u)];
            }
    }
}

/* The value index of (row i, column j), i <= j, in the tangent's upper pattern, or -1. */
static int find_slot(const ctn_asm *a, int i, int j)
{
    for (int k = a->colptr[j]; k < a->colptr[j + 1]; k++)
        if (a->rowind[k] == i) return k;
    return -1;
}

static int rot_alloc(ctn_dyn *dy, size_t n)
{
    ctn_ctx *ctx = dy->p->ctx;
    struct ctn_dyn_rot *r = dy->rot = ctn_calloc(ctx, 1, sizeof *r);
    if (!r) return CTN_ERR_NOMEM;
    r->n = n;
    r->node = ctn_calloc(ctx, n, sizeof(size_t));
    r->st = ctn_calloc(ctx, n, sizeof(size_t));
    r->eq = ctn_calloc(ctx, 3 * n, sizeof(int));
    r->slot = ctn_calloc(ctx, 9 * n, sizeof(int));
    size_t md = (size_t)dy->p->a->maxdof, nn = dy->p->a->nn;
    r->at = ctn_malloc(ctx, nn ? nn : 1, sizeof(long));
    r->work = ctn_calloc(ctx, md * (md + 1) / 2 + 3 * md, sizeof(double));
    if (!r->at || !r->work) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < nn; i++) r->at[i] = -1;
    double **v[] = { &r->J, &r->W0, &r->A0, &r->W1, &r->A1, &r->I0, &r->I1 };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++)
        if (!(*v[i] = ctn_calloc(ctx, (i ? 3 : 9) * n, sizeof(double)))) return CTN_ERR_NOMEM;
    return r->node && r->st && r->eq && r->slot ? CTN_OK : CTN_ERR_NOMEM;
}

void ctn_dyn_rot_free(ctn_dyn *dy)
{
    struct ctn_dyn_rot *r = dy->rot;
    if (!r) return;
    ctn_dyn_exact_free(r);
    void *v[] = { r->node, r->st, r->eq, r->slot, r->at, r->work, r->J, r->W0, r->A0, r->W1, r->A1, r->I0, r->I1 };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
    ctn_free(r);
    dy->rot = NULL;
}

int ctn_dyn_rot_setup(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    const ctn_asm *a = p->a;
    const ctn_dofmap *map = &a->map;
    size_t n = 0;
    if (!map->rot) return CTN_OK;
    for (int pass = 0; pass < 2; pass++) {
        n = 0;
        for (size_t i = 0; i < map->nn; i++) {
            size_t k0 = ctn_dofmap_node(map, i) + 3;
            if (ctn_dofmap_count(map, i) != 6 || (map->eq[k0] < 0 && map->eq[k0 + 1] < 0 && map->eq[k0 + 2] < 0))
                continue;
            if (pass) {
                dy->rot->node[n] = i;
                dy->rot->at[i] = (long)n;
                dy->rot->st[n] = k0;
                for (int c = 0; c < 3; c++) dy->rot->eq[3 * n + (size_t)c] = map->eq[k0 + (size_t)c];
            }
            n++;
        }
        if (!n) return CTN_OK;                        /* every rotation fixed */
        int rc = pass ? CTN_OK : rot_alloc(dy, n);
        if (rc) return rc;
    }
    struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; k < n; k++)
        for (int u = 0; u < 9; u++) {
            int qa = r->eq[3 * k + (size_t)(u / 3)], qb = r->eq[3 * k + (size_t)(u % 3)];
            r->slot[9 * k + (size_t)u] = qa >= 0 && qb >= 0 && qa <= qb ? find_slot(a, qa, qb) : -1;
        }
    ctn_asm_loop(a, NULL, 0, 0, inertia_visit, r, NULL);
    for (size_t j = 0; j < a->ndof; j++)                 /* the translations' mass alone */
        for (int k = a->colptr[j]; k < a->colptr[j + 1]; k++)
            if (map->dof_dir[j] >= 3 || map->dof_dir[a->rowind[k]] >= 3) dy->Mx[k] = 0.0;
    return CTN_OK;
}

/* The inertia moment I = R (J A + W x J W) of node k at rotation vector psi. */
static void inertia(const struct ctn_dyn_rot *r, size_t k, const double *psi, const double W[3], const double A[3],
                    double I[3])
{
    const double *J = r->J + 9 * k;
    double q[4], R[9], JW[3], JA[3], m[3];
    dr_quat(psi, q);
    dr_rmat(q, R);
    dr_mv(J, W, JW);
    dr_mv(J, A, JA);
    for (int c = 0; c < 3; c++) m[c] = JA[c] + W[(c + 1) % 3] * JW[(c + 2) % 3] - W[(c + 2) % 3] * JW[(c + 1) % 3];
    dr_mv(R, m, I);
}

void ctn_dyn_rot_kinematics(ctn_dyn *dy, double h)
{
    struct ctn_dyn_rot *r = dy->rot;
    double b = dy->beta, g = dy->gamma;
    for (size_t k = 0; r && k < r->n; k++) {
        double q0[4], q1[4], th[3];
        dr_quat(dy->d0 + r->st[k], q0);
        dr_quat(dy->d1 + r->st[k], q1);
        dr_log_rel(q0, q1, th);
        double *W0 = r->W0 + 3 * k, *A0 = r->A0 + 3 * k, *W1 = r->W1 + 3 * k, *A1 = r->A1 + 3 * k;
        for (int c = 0; c < 3; c++) {
            A1[c] = (th[c] - h * W0[c] - h * h * (0.5 - b) * A0[c]) / (b * h * h);
            W1[c] = W0[c] + h * ((1 - g) * A0[c] + g * A1[c]);
            int q = r->eq[3 * k + (size_t)c];
            if (q >= 0) {
                dy->a1[q] = A1[c];
                dy->v1[q] = W1[c];
            }
        }
        inertia(r, k, dy->d1 + r->st[k], W1, A1, r->I1 + 3 * k);
    }
}

double ctn_dyn_rot_residual(const ctn_dyn *dy, double *y)
{
    const struct ctn_dyn_rot *r = dy->rot;
    double ss = 0;
    for (size_t k = 0; r && k < r->n; k++)
        for (int c = 0; c < 3; c++) {
            int q = r->eq[3 * k + (size_t)c];
            if (q < 0) continue;
            double f = (1 - dy->am) * r->I1[3 * k + (size_t)c] + dy->am * r->I0[3 * k + (size_t)c];
            y[q] -= f;
            ss += f * f;
        }
    return ss;
}

void ctn_dyn_rot_tangent(ctn_dyn *dy, double c1)
{
    const struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; r && k < r->n; k++) {
        double q[4], R[9], RJ[9];
        const double *J = r->J + 9 * k;
        dr_quat(dy->d1 + r->st[k], q);
        dr_rmat(q, R);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) RJ[3 * i + j] = R[3 * i] * J[j] + R[3 * i + 1] * J[3 + j] + R[3 * i + 2] * J[6 + j];
        for (int u = 0; u < 9; u++) {
            int s = r->slot[9 * k + (size_t)u], i = u / 3, j = u % 3;
            if (s >= 0)
                dy->p->Kx[s] += c1 * (RJ[3 * i] * R[3 * j] + RJ[3 * i + 1] * R[3 * j + 1] + RJ[3 * i + 2] * R[3 * j + 2]);
        }
    }
}

double ctn_dyn_rot_accept(ctn_dyn *dy)
{
    struct ctn_dyn_rot *r = dy->rot;
    double ek = 0;
    if (!r) return 0.0;
    for (size_t k = 0; k < r->n; k++) {
        double JW[3];
        dr_mv(r->J + 9 * k, r->W1 + 3 * k, JW);
        for (int c = 0; c < 3; c++) ek += 0.5 * r->W1[3 * k + (size_t)c] * JW[c];
    }
    memcpy(r->W0, r->W1, 3 * r->n * sizeof(double));
    memcpy(r->A0, r->A1, 3 * r->n * sizeof(double));
    memcpy(r->I0, r->I1, 3 * r->n * sizeof(double));
    return ek;
}

double ctn_dyn_rot_work(const ctn_dyn *dy, const double *f0, const double *f1)
{
    const struct ctn_dyn_rot *r = dy->rot;
    double w = 0;
    for (size_t k = 0; r && k < r->n; k++) {
        double q0[4], q1[4], th[3], ts[3], R[9];
        dr_quat(dy->d0 + r->st[k], q0);
        dr_quat(dy->d1 + r->st[k], q1);
        dr_log_rel(q0, q1, th);
        dr_rmat(q0, R);
        dr_mv(R, th, ts);                                   /* the spatial increment R0 Theta */
        for (int c = 0; c < 3; c++)
            if (r->eq[3 * k + (size_t)c] >= 0) {
                size_t i = r->st[k] + (size_t)c;
                w += 0.5 * (f0[i] + f1[i]) * ts[c];
            }
    }
    return w;
}

void ctn_dyn_rot_mass_add(ctn_dyn *dy, double scale)
{
    double *keep = dy->p->Kx;
    dy->p->Kx = dy->Mx;                                  /* the blocks R0 J R0^T into M */
    memcpy(dy->d1, dy->d0, dy->p->ns * sizeof(double));
    ctn_dyn_rot_tangent(dy, scale);
    dy->p->Kx = keep;
}

void ctn_dyn_rot_start(ctn_dyn *dy, double *a)
{
    struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; r && k < r->n; k++) {
        double al[3] = { 0, 0, 0 }, q[4], R[9], W[3] = { 0, 0, 0 };
        for (int c = 0; c < 3; c++) {
            int e = r->eq[3 * k + (size_t)c];
            if (e >= 0) al[c] = a[e];
        }
        dr_quat(dy->d0 + r->st[k], q);
        dr_rmat(q, R);
        dr_mtv(R, al, r->A0 + 3 * k);                       /* A0 = R0^T alpha (W0 = 0) */
        memset(r->W0 + 3 * k, 0, 3 * sizeof(double));
        for (int c = 0; c < 3; c++) {
            int e = r->eq[3 * k + (size_t)c];
            if (e >= 0) a[e] = r->A0[3 * k + (size_t)c];
        }
        inertia(r, k, dy->d0 + r->st[k], W, r->A0 + 3 * k, r->I0 + 3 * k);
    }
}

void ctn_dyn_rot_reactions(const ctn_dyn *dy, double *react)
{
    const struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; r && k < r->n; k++) {
        double I[3], q[4], R[9], JW[3], m[3];
        const double *W = r->W0 + 3 * k;
        inertia(r, k, dy->d0 + r->st[k], W, r->A0 + 3 * k, I);   /* R (J A + W x J W) */
        dr_quat(dy->d0 + r->st[k], q);
        dr_rmat(q, R);
        dr_mv(r->J + 9 * k, W, JW);
        dr_mv(R, JW, m);                                          /* R J W */
        for (int c = 0; c < 3; c++)
            if (r->eq[3 * k + (size_t)c] < 0) react[r->st[k] + (size_t)c] += I[c] + dy->o->damping_alpha * m[c];
    }
}
