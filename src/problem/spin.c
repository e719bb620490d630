/* Moments on nodes whose rotations are composed (a family of finite rotations, the
 * beam: beam3.h, spin; assemble/rot_compose.c). The elements' rotation forces there are
 * the gradient of the energy in the spin w of R = exp(w) R at w = 0, i.e. the true
 * (spatial) moments, and a `load`/`moment` is a fixed spatial moment m. Their tangent is
 * the energy's Hessian H in w, symmetric; but the residual at the next state is taken
 * in the spin of that state, and the change of spin variables adds, at a node of
 * internal moment g, the term (1/2) dw x g (the left Jacobian of exp, J^-T = I +
 * [dw]x / 2 + ...): the consistent tangent is H - [g]x / 2, not symmetric where g does
 * not vanish, i.e. at a node that carries an applied moment (a fixed moment is not
 * conservative in 3D). Without the term Newton converges linearly there (by about
 * |m| / 2 over the node's rotational stiffness per iteration: a cantilever turned into a
 * helix by an end moment does not converge). With it each step solves
 * (K + shift I - [g]x / 2) dd = r by GMRES preconditioned by the factorization of
 * K + shift I, as the follower loads do (follow.c), and the globalized corrector takes
 * the residual's merit (no potential). Only the nodes that carry a `load`/`moment`
 * moment with all three rotations free get the term. */
#include "problem/problem.h"

#include <math.h>
#include <string.h>

#define CTN_SPIN_M 30             /* Krylov vectors per cycle */
#define CTN_SPIN_CYCLES 4
#define CTN_SPIN_RTOL 1e-13

struct ctn_spin {
    size_t n;                     /* nodes with the term */
    size_t *st;                   /* per node: the state index of its rotation x */
    int *eq;                      /* 3 per node: the equations of its rotations */
    ctn_gmres gm;
    double *work;
};

/* The nodes: a moment in the model, three free rotations, composed (count if s NULL). */
static size_t scan(const ctn_problem *p, ctn_spin *s)
{
    const ctn_dofmap *map = &p->a->map;
    const ctn_model *m = p->m;
    size_t n = 0;
    unsigned char *seen = s ? (unsigned char *)s->work : NULL;   /* nn bytes of scratch */
    if (seen) memset(seen, 0, map->nn);
    for (size_t i = 0; i < m->mloads.n; i++) {
        size_t nd = (size_t)m->mloads.v[i].node, k0 = ctn_dofmap_node(map, nd) + 3;
        if (ctn_dofmap_count(map, nd) != 6 || map->eq[k0] < 0 || map->eq[k0 + 1] < 0 || map->eq[k0 + 2] < 0) continue;
        if (s) {
            if (seen[nd]) continue;
            seen[nd] = 1;
            s->st[n] = k0;
            for (int k = 0; k < 3; k++) s->eq[3 * n + (size_t)k] = map->eq[k0 + (size_t)k];
        }
        n++;
    }
    return n;
}

/* y = (K + shift I) x - [g]x x / 2 = (K + shift I) x + (x x g) / 2 at the nodes. */
static int apply(void *data, const double *x, double *y)
{
    ctn_problem *p = data;
    const ctn_spin *s = p->sp;
    if (p->fl) {                                   /* (K + shift I - L) x */
        int rc = ctn_follow_apply(p, x, y);
        if (rc) return rc;
    } else {
        ctn_problem_symv(p, p->Kx, x, y);
        for (size_t c = 0; c < p->ndof; c++) y[c] += p->shift * x[c];
    }
    for (size_t i = 0; i < s->n; i++) {
        const int *q = s->eq + 3 * i;
        const double *g = p->fint + s->st[i];
        for (int k = 0; k < 3; k++) {
            int a = (k + 1) % 3, b = (k + 2) % 3;
            y[q[k]] += 0.5 * (x[q[a]] * g[b] - x[q[b]] * g[a]);
        }
    }
    return CTN_OK;
}

static int precond(void *data, const double *x, double *y)
{
    ctn_problem *p = data;
    return ctn_linsolve_solve(p->ls, x, y);
}

int ctn_spin_wanted(const ctn_problem *p)
{
    return p->a->map.rot_update == ctn_rot_update_compose && scan(p, NULL) > 0;
}

int ctn_spin_create(ctn_problem *p)
{
    if (p->a->map.rot_update != ctn_rot_update_compose || !p->ls) return CTN_OK;
    size_t n = scan(p, NULL);
    if (!n) return CTN_OK;
    ctn_spin *s = ctn_calloc(p->ctx, 1, sizeof *s);
    if (!s) return CTN_ERR_NOMEM;
    p->sp = s;
    size_t ws = ctn_gmres_work_size(p->ndof, CTN_SPIN_M), nn = p->a->map.nn;
    s->st = ctn_calloc(p->ctx, n, sizeof(size_t));
    s->eq = ctn_calloc(p->ctx, 3 * n, sizeof(int));
    s->work = ctn_calloc(p->ctx, ws > nn / sizeof(double) + 1 ? ws : nn / sizeof(double) + 1, sizeof(double));
    if (!s->st || !s->eq || !s->work) return CTN_ERR_NOMEM;
    s->n = scan(p, s);
    ctn_gmres_init(&s->gm, p->ndof, CTN_SPIN_M, s->work);
    s->gm.apply = apply;
    s->gm.precond = precond;
    s->gm.data = p;
    s->gm.dot = ctn_problem_dot;
    return CTN_OK;
}

void ctn_spin_destroy(ctn_spin **ps)
{
    if (!ps || !*ps) return;
    ctn_free((*ps)->st);
    ctn_free((*ps)->eq);
    ctn_free((*ps)->work);
    ctn_free(*ps);
    *ps = NULL;
}

int ctn_spin_solve(ctn_problem *p, const double *b, double *x)
{
    double rel;
    int iters;
    int rc = ctn_gmres_solve(&p->sp->gm, b, x, CTN_SPIN_RTOL, CTN_SPIN_CYCLES, &rel, &iters);
    p->sum->solves += iters + 1;
    return rc;
}

/* The sign of the determinant of the n x n matrix A (column-major, overwritten): LU with
 * partial pivoting; 0 when a pivot vanishes. */
static int det_sign(double *A, size_t n)
{
    int sign = 1;
    for (size_t k = 0; k < n; k++) {
        size_t piv = k;
        for (size_t i = k + 1; i < n; i++)
            if (fabs(A[k * n + i]) > fabs(A[k * n + piv])) piv = i;
        if (!(A[k * n + piv] != 0)) return 0;
        if (piv != k) {
            sign = -sign;
            for (size_t j = 0; j < n; j++) {
                double t = A[j * n + k];
                A[j * n + k] = A[j * n + piv];
                A[j * n + piv] = t;
            }
        }
        if (A[k * n + k] < 0) sign = -sign;
        for (size_t i = k + 1; i < n; i++) {
            double l = A[k * n + i] / A[k * n + k];
            for (size_t j = k + 1; j < n; j++) A[j * n + i] -= l * A[j * n + k];
        }
    }
    return sign;
}

int ctn_spin_det_sign(ctn_problem *p, ctn_linsolve *f, long neg, int *sign)
{
    const ctn_spin *s = p->sp;
    size_t m = 3 * s->n;
    double *W = ctn_calloc(p->ctx, m * m + p->ndof, sizeof(double)), *x = W + m * m;
    if (!W) return CTN_ERR_NOMEM;
    int rc = CTN_OK;
    for (size_t c = 0; c < m && !rc; c++) {      /* W = I + S E^T K^-1 E, column c */
        memset(x, 0, p->ndof * sizeof(double));
        x[s->eq[c]] = 1;
        if ((rc = ctn_linsolve_solve(f, x, x))) break;
        for (size_t i = 0; i < s->n; i++) {       /* S_i y = -[g_i]x y / 2 = (y x g_i) / 2 */
            const int *q = s->eq + 3 * i;
            const double *g = p->fint + s->st[i];
            for (int k = 0; k < 3; k++) {
                int a = (k + 1) % 3, b = (k + 2) % 3;
                W[c * m + 3 * i + (size_t)k] = 0.5 * (x[q[a]] * g[b] - x[q[b]] * g[a]) + (c == 3 * i + (size_t)k);
            }
        }
    }
    if (!rc) *sign = (neg % 2 ? -1 : 1) * det_sign(W, m);
    ctn_free(W);
    return rc;
}

double ctn_spin_moment_max(const ctn_problem *p)
{
    const ctn_spin *s = p->sp;
    double m = 0;
    for (size_t i = 0; i < s->n; i++) {
        const double *g = p->fint + s->st[i];
        m = fmax(m, sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
    }
    return m;
}
