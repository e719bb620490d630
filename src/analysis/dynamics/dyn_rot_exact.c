/* The consistent tangent of the rotations' inertia and damping (implicit methods): at a
 * node whose three rotations are composed (R1 <- exp(dw) R1), with Theta = log(R0^T R1),
 * dTheta = Jr^-1(Theta) R1^T dw (Jr the right Jacobian of SO(3)), dA1 = dTheta / (beta
 * h^2), dW1 = c2 dTheta (c2 = gamma / (beta h)):
 *   dI1/dw = -[I1]x + R1 (J / (beta h^2) + c2 ([W1]x J - [J W1]x)) Jr^-1 R1^T,
 *   d(R1 W1)/dw = -[R1 W1]x + c2 R1 Jr^-1 R1^T,   d(R1 J W1)/dw = -[R1 J W1]x + c2 R1 J Jr^-1 R1^T
 * (I1 = R1 (J A1 + W1 x J W1), the damping's velocity R1 W1, alpha's moment R1 J W1).
 * The factored effective tangent A holds their leading parts (c1 R1 J R1^T, c2 C,
 * alpha c2 R1 J R1^T: symmetric); the rest, B (node blocks, and C's columns times
 * d(R1 W1)/dw - c2 I), is not symmetric and of order h |W| beside A: (A + B) x = b is
 * solved by GMRES on (I + B A^-1) y = b, x = A^-1 y, each product one solve with A's
 * factorization (a few per Newton iteration), so Newton converges quadratically in the
 * gyroscopic and frame terms too. The stiffness's own term of the spin variables, -[g]x / 2
 * (g the node's internal moment: problem/spin.c), joins B where spin.c does not take it
 * (a node without an applied moment: in time its g balances the inertia). Checked against
 * central differences of the step's residual in the spins (eps = 1e-6, the 3D pendulum
 * with damping): B's part of the derivative, 30 to 2000, is matched to 1e-4 to 1e-3 (the
 * differences' own error; 0.1 to 0.3 without the -[g]x / 2 term). Nodes with some rotations fixed keep the leading part
 * (exact for one free rotation about a principal axis). docs/theory.md "Dynamics". */
#include "analysis/dynamics/dyn_rot.h"
#include "linalg/gmres.h"

#include <string.h>

#define CTN_DYN_EXACT_M 20          /* Krylov vectors per cycle */
#define CTN_DYN_EXACT_CYCLES 4
#define CTN_DYN_EXACT_RTOL 1e-13

struct ctn_dyn_exact {
    double *B, *D;                  /* 9 per node: the blocks of B, d(R1 W1)/dw - c2 I */
    double *x, *z, *y, *s;          /* ndof scratch; s: GMRES's y */
    double *work;                   /* GMRES */
    ctn_gmres gm;
    unsigned char *spun;            /* per node: its moment's term is problem/spin.c's */
    int damped;                     /* D in use */
};

static void skew(const double v[3], double S[9])
{
    S[0] = 0, S[1] = -v[2], S[2] = v[1], S[3] = v[2], S[4] = 0, S[5] = -v[0], S[6] = -v[1], S[7] = v[0], S[8] = 0;
}

static void mm(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

/* Jr^-1(th) = I + [th]x / 2 + (1 / t^2 - (1 + cos t) / (2 t sin t)) [th]x^2. */
static void jr_inv(const double th[3], double Ji[9])
{
    double t = sqrt(th[0] * th[0] + th[1] * th[1] + th[2] * th[2]), S[9], S2[9];
    double c = t > 1e-4 ? 1 / (t * t) - (1 + cos(t)) / (2 * t * sin(t)) : 1.0 / 12 + t * t / 720;
    skew(th, S);
    mm(S, S, S2);
    for (int i = 0; i < 9; i++) Ji[i] = (i % 4 == 0) + 0.5 * S[i] + c * S2[i];
}

/* Whether node k's three rotations are free (composed). */
static int composed(const struct ctn_dyn_rot *r, size_t k)
{
    return r->eq[3 * k] >= 0 && r->eq[3 * k + 1] >= 0 && r->eq[3 * k + 2] >= 0;
}

/* y = x + B A^-1 x (the right-preconditioned operator). */
static int apply(void *data, const double *x, double *y);

static double dot(void *data, const double *a, const double *b)
{
    const ctn_dyn *dy = data;
    return ctn_problem_dot(dy->p, a, b);
}

static int identity(void *data, const double *x, double *y)
{
    const ctn_dyn *dy = data;
    if (y != x) memcpy(y, x, dy->p->ndof * sizeof(double));
    return CTN_OK;
}

int ctn_dyn_exact_setup(ctn_dyn *dy)
{
    struct ctn_dyn_rot *r = dy->rot;
    ctn_ctx *ctx = dy->p->ctx;
    size_t nc = 0, n = dy->p->ndof;
    for (size_t k = 0; r && k < r->n; k++) nc += composed(r, k) != 0;
    if (!nc || dy->o->method == CTN_DYN_CENTRAL || dy->p->a->map.rot_update != ctn_rot_update_compose) return CTN_OK;
    struct ctn_dyn_exact *e = r->exact = ctn_calloc(ctx, 1, sizeof *e);
    if (!e) return CTN_ERR_NOMEM;
    e->B = ctn_calloc(ctx, 9 * r->n, sizeof(double));
    e->D = ctn_calloc(ctx, 9 * r->n, sizeof(double));
    e->x = ctn_calloc(ctx, n, sizeof(double));
    e->z = ctn_calloc(ctx, n, sizeof(double));
    e->y = ctn_calloc(ctx, n, sizeof(double));
    e->s = ctn_calloc(ctx, n, sizeof(double));
    e->work = ctn_calloc(ctx, ctn_gmres_work_size(n, CTN_DYN_EXACT_M), sizeof(double));
    e->spun = ctn_calloc(ctx, r->n, 1);
    if (!e->B || !e->D || !e->x || !e->z || !e->y || !e->s || !e->work || !e->spun) return CTN_ERR_NOMEM;
    for (size_t i = 0; dy->p->sp && i < dy->p->m->mloads.n; i++) {
        long at = r->at[dy->p->m->mloads.v[i].node];
        if (at >= 0) e->spun[at] = 1;
    }
    ctn_gmres_init(&e->gm, n, CTN_DYN_EXACT_M, e->work);
    e->gm.apply = apply;
    e->gm.precond = identity;
    e->gm.data = dy;
    e->gm.dot = dot;
    e->damped = ctn_dyn_damped(dy);
    return CTN_OK;
}

void ctn_dyn_exact_free(struct ctn_dyn_rot *r)
{
    struct ctn_dyn_exact *e = r->exact;
    if (!e) return;
    void *v[] = { e->B, e->D, e->x, e->z, e->y, e->s, e->work, e->spun };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
    ctn_free(e);
    r->exact = NULL;
}

void ctn_dyn_exact_blocks(ctn_dyn *dy, double h)
{
    struct ctn_dyn_rot *r = dy->rot;
    struct ctn_dyn_exact *e = r ? r->exact : NULL;
    double b = dy->beta, c2 = dy->gamma / (b * h), cf = (1 - dy->am) / (1 - dy->af), al = dy->o->damping_alpha;
    for (size_t k = 0; e && k < r->n; k++) {
        double *B = e->B + 9 * k, *D = e->D + 9 * k, q0[4], q1[4], th[3], R[9], Rt[9], Ji[9], G[9], T[9], M[9];
        double JW[3], w[3], S[9], SJ[9], JSW[9];
        memset(B, 0, 9 * sizeof(double));
        memset(D, 0, 9 * sizeof(double));
        if (!composed(r, k)) continue;
        const double *J = r->J + 9 * k, *W = r->W1 + 3 * k;
        dr_quat(dy->d0 + r->st[k], q0);
        dr_quat(dy->d1 + r->st[k], q1);
        dr_log_rel(q0, q1, th);
        dr_rmat(q1, R);
        for (int i = 0; i < 9; i++) Rt[i] = R[3 * (i % 3) + i / 3];
        jr_inv(th, Ji);
        mm(Ji, Rt, G);                                          /* dTheta/dw */
        dr_mv(J, W, JW);
        skew(W, S);
        mm(S, J, SJ);                                           /* [W]x J */
        skew(JW, JSW);                                          /* [J W]x */
        for (int i = 0; i < 9; i++) M[i] = J[i] / (b * h * h) + c2 * (SJ[i] - JSW[i]) + al * c2 * J[i] / cf;
        mm(M, G, T);
        mm(R, T, M);                                            /* R (..) Jr^-1 R^T */
        double I[3], mom[3];
        for (int c = 0; c < 3; c++) I[c] = cf * r->I1[3 * k + (size_t)c];
        dr_mv(R, JW, mom);                                      /* R J W */
        for (int c = 0; c < 3; c++) I[c] += al * mom[c];
        skew(I, S);
        mm(R, J, T);
        mm(T, Rt, SJ);                                          /* R J R^T */
        for (int i = 0; i < 9; i++) B[i] = cf * M[i] - S[i] - (cf / (b * h * h) + c2 * al) * SJ[i];
        if (!e->spun[k]) {                                      /* the spin variables' change: */
            skew(dy->p->fint + r->st[k], S);                    /* -[g]x / 2 (problem/spin.c) */
            for (int i = 0; i < 9; i++) B[i] -= 0.5 * S[i];
        }
        if (!e->damped) continue;
        dr_mv(R, W, w);                                         /* R W: the spatial velocity */
        skew(w, S);
        mm(R, G, T);
        for (int i = 0; i < 9; i++) D[i] = c2 * T[i] - S[i] - c2 * (i % 4 == 0);
    }
}

/* y += B x: the node blocks, and C (D x) on the rotations' velocities. */
static void add_b(const ctn_dyn *dy, const double *x, double *y)
{
    const struct ctn_dyn_rot *r = dy->rot;
    struct ctn_dyn_exact *e = r->exact;
    if (e->damped) memset(e->z, 0, dy->p->ndof * sizeof(double));
    for (size_t k = 0; k < r->n; k++) {
        const int *q = r->eq + 3 * k;
        if (!composed(r, k)) continue;
        double xk[3] = { x[q[0]], x[q[1]], x[q[2]] }, bx[3], dx[3];
        dr_mv(e->B + 9 * k, xk, bx);
        dr_mv(e->D + 9 * k, xk, dx);
        for (int c = 0; c < 3; c++) {
            y[q[c]] += bx[c];
            if (e->damped) e->z[q[c]] = dx[c];
        }
    }
    if (!e->damped) return;
    ctn_dyn_damp(dy, e->z, e->y);
    for (size_t i = 0; i < dy->p->ndof; i++) y[i] += e->y[i];
}

/* x = A^-1 b: the factored effective tangent (and its modal and spin parts). */
static int solve_a(ctn_dyn *dy, const double *b, double *x)
{
    int rc = ctn_problem_linsolve(dy->p, b, x);
    if (!rc) ctn_dyn_modal_correct(dy, x);
    return rc;
}

static int apply(void *data, const double *x, double *y)
{
    ctn_dyn *dy = data;
    struct ctn_dyn_exact *e = dy->rot->exact;
    int rc = solve_a(dy, x, e->x);
    if (rc) return rc;
    if (y != x) memcpy(y, x, dy->p->ndof * sizeof(double));
    add_b(dy, e->x, y);
    return CTN_OK;
}

int ctn_dyn_exact_solve(ctn_dyn *dy, const double *b, double *x)
{
    struct ctn_dyn_exact *e = dy->rot ? dy->rot->exact : NULL;
    if (!e) return solve_a(dy, b, x);
    double rel;
    int iters, rc = ctn_gmres_solve(&e->gm, b, e->s, CTN_DYN_EXACT_RTOL, CTN_DYN_EXACT_CYCLES, &rel, &iters);
    dy->p->sum->solves += iters;
    if (!rc) rc = solve_a(dy, e->s, x);
    return rc;
}
