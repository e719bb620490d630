/* The corotational beam's internal forces in closed form (Battini and Pacoste 2002), for
 * a member whose nodes both take spins (beam3.h, spin: the rotations of a 3D model), and
 * its consistent tangent as their exact Jacobian: the forces are written on first-order
 * duals (dual.h) over the chord x and the two spins w_1, w_2 (nine variables). The
 * kinematics and the energy are beam3.c's (which keeps the energy on second-order jets
 * as the reference: tests/test_beam_cf.c compares the two); here:
 *
 *   the variation of the frame (r1 = x / l, r3 = r1 x q / n, r2 = r3 x r1, q the mean of
 *   the two triads' y axes q_a, n = |r1 x q| = q . r2) is the spin
 *     omega = omega1 r1 + (r1 x dx) / l,
 *     omega1 = (sum_a dw_a . (q_a x r3) / 2 - (q . r1) (r3 . dx) / l) / n;
 *   the local rotation Q_a = Rr^T T_a varies by dQ = [phi]x Q with
 *   phi = Rr^T (dw_a - omega), so its skew vector w_a (th_a = h(|w_a|^2) w_a, h = asin(s)/s)
 *   by dw = B phi, B = (tr Q I - Q) / 2, and th_a by D dw, D = h I + 2 h' w w^T;
 *   with m_a = dU/dth_a (the releases' condensation transposed) and
 *   s_a = Rr B_a^T D_a m_a, S = s_1 + s_2:
 *     dU = dx . (N r1 + (S . r1) (q . r1) / (n l) r3 - S x r1 / l)
 *        + sum_b dw_b . (s_b - (S . r1) / (2 n) q_b x r3).
 *
 * The Jacobian of these spin moments in the spins is the Hessian less the skew term
 * [f_w]x / 2 of the exponential's second order (exp(w) = I + [w]x + [w]x^2 / 2): its
 * symmetric part is the Hessian (the jets' tangent), which the kernel takes. */
#include "element/beam3.h"
#include "element/dual.h"

#include <math.h>

/* The kinematics on duals: the chord length, the frame rows r[i], the triads' columns
 * t[a][j] (t = T + w x T to first order at w = 0), and each end's local Q, skew vector w,
 * h and h' of |w|^2 and local rotation th. 1 if they cannot be formed (beam3.c's). */
typedef struct cf_kin {
    ctn_dual l, r[3][3], t[2][3][3], q[3], n;
    ctn_dual Q[2][3][3], w[2][3], h[2], hp[2], th[2][3];
} cf_kin;

static void triad(const ctn_beam_props *p, const double *X, const double *psi, int a, ctn_dual t[3][3])
{
    double E0[3][3], E[3][3], L = 0;
    for (int k = 0; k < 3; k++) {
        E0[0][k] = X[3 + k] - X[k];
        L += E0[0][k] * E0[0][k];
        E0[1][k] = p->e2[k];
        E0[2][k] = p->e3[k];
    }
    L = sqrt(L);
    for (int k = 0; k < 3; k++) E0[0][k] /= L;
    ctn_beam_rotate_n(psi, 3, (const double(*)[3])E0, E);
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++) {                  /* (w x E)_k = w_i E_m - w_m E_i */
            int i = (k + 1) % 3, m = (k + 2) % 3;
            t[j][k] = ctn_dual_const(E[j][k]);
            t[j][k].g[3 + 3 * a + i] = E[j][m];
            t[j][k].g[3 + 3 * a + m] = -E[j][i];
        }
}

static int frame(const double *X, const double *u, cf_kin *s)
{
    ctn_dual x[3], p[3];
    for (int k = 0; k < 3; k++) x[k] = ctn_dual_var((X[3 + k] - X[k]) + (u[6 + k] - u[k]), k);
    ctn_dual xx = ctn_dual_dot(x, x);
    double l = sqrt(xx.v);
    if (!(l > 0)) return 1;
    s->l = ctn_dual_fn(xx, l, 0.5 / l);
    ctn_dual il = ctn_dual_fn(s->l, 1 / l, -1 / (l * l));
    for (int k = 0; k < 3; k++) {
        s->r[0][k] = ctn_dual_mul(x[k], il);
        s->q[k] = ctn_dual_lin(0.5, s->t[0][1][k], 0.5, s->t[1][1][k]);
    }
    ctn_dual_cross(p, s->r[0], s->q);
    ctn_dual pp = ctn_dual_dot(p, p);
    double n = sqrt(pp.v);
    if (!(n > 1e-12)) return 1;
    s->n = ctn_dual_fn(pp, n, 0.5 / n);
    ctn_dual in = ctn_dual_fn(s->n, 1 / n, -1 / (n * n));
    for (int k = 0; k < 3; k++) s->r[2][k] = ctn_dual_mul(p[k], in);
    ctn_dual_cross(s->r[1], s->r[2], s->r[0]);
    return 0;
}

static int local(cf_kin *s, int a)
{
    double tr = 0, fh[3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) s->Q[a][i][j] = ctn_dual_dot(s->r[i], s->t[a][j]);
    for (int i = 0; i < 3; i++) tr += s->Q[a][i][i].v;
    if (!(tr > 1)) return 1;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        s->w[a][k] = ctn_dual_lin(0.5, s->Q[a][j][i], -0.5, s->Q[a][i][j]);
    }
    ctn_dual y = ctn_dual_dot(s->w[a], s->w[a]);
    if (!(y.v < 1)) return 1;
    ctn_beam_log_h(y.v, fh);
    s->h[a] = ctn_dual_fn(y, fh[0], fh[1]);
    s->hp[a] = ctn_dual_fn(y, fh[1], fh[2]);
    for (int k = 0; k < 3; k++) s->th[a][k] = ctn_dual_mul(s->h[a], s->w[a][k]);
    return 0;
}

/* Released end rotations (beam3_release.c's rule): t[a][k] = sum of c * th[b][k]; code
 * 0: th[a][k] itself, 1: zero, 2: -rho th[1 - a][k]. */
static int release_code(const ctn_beam_props *p, int a, int k)
{
    int here = (p->rel >> (3 * a + k)) & 1, there = (p->rel >> (3 * (1 - a) + k)) & 1;
    return k == 0 || !here ? 0 : there ? 1 : 2;
}

static double rho(const ctn_beam_props *p, int k)
{
    return k == 1 ? p->cy1 / (2 * p->cy0) : p->cz1 / (2 * p->cz0);
}

/* The condensed rotations t, the axial force N, and m = dU/dth (on duals). */
static void energy_gradient(const ctn_beam_props *p, const cf_kin *s, ctn_dual t[2][3], ctn_dual *N, ctn_dual m[2][3])
{
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) {
            int c = release_code(p, a, k);
            t[a][k] = c == 0 ? s->th[a][k] : c == 1 ? ctn_dual_const(0) : ctn_dual_scale(-rho(p, k), s->th[1 - a][k]);
            m[a][k] = ctn_dual_const(0);
        }
    ctn_dual st = ctn_dual_sub(s->l, ctn_dual_const(p->L0));   /* l - L0 + the bowing */
    for (int k = 1; k < 3; k++) {
        ctn_dual b = ctn_dual_lin(2, ctn_dual_mul(t[0][k], t[0][k]), 2, ctn_dual_mul(t[1][k], t[1][k]));
        b = ctn_dual_sub(b, ctn_dual_mul(t[0][k], t[1][k]));
        st = ctn_dual_lin(1, st, p->L0 / 30, b);
    }
    *N = ctn_dual_scale(p->EA / p->L0, st);
    ctn_dual nb = ctn_dual_scale(p->L0 / 30, *N), Ut[2][3];
    const double c0[3] = { 0, p->cy0, p->cz0 }, c1[3] = { 0, p->cy1, p->cz1 };
    for (int a = 0; a < 2; a++) {
        ctn_dual tw = ctn_dual_scale(p->kt, ctn_dual_sub(t[1][0], t[0][0]));
        Ut[a][0] = a ? tw : ctn_dual_scale(-1, tw);
        for (int k = 1; k < 3; k++) {                  /* N L0/30 (4 t_a - t_b) + 2 c0 t_a + c1 t_b */
            ctn_dual ta = t[a][k], tb = t[1 - a][k];
            Ut[a][k] = ctn_dual_add(ctn_dual_mul(nb, ctn_dual_lin(4, ta, -1, tb)), ctn_dual_lin(2 * c0[k], ta, c1[k], tb));
        }
    }
    for (int a = 0; a < 2; a++)                        /* m = C^T U_t */
        for (int k = 0; k < 3; k++) {
            int c = release_code(p, a, k);
            if (c == 0) m[a][k] = ctn_dual_add(m[a][k], Ut[a][k]);
            else if (c == 2) m[1 - a][k] = ctn_dual_lin(1, m[1 - a][k], -rho(p, k), Ut[a][k]);
        }
}

/* s_a = Rr B^T D m (global): the spin moment of end a's local rotation. */
static void end_moment(const cf_kin *k, int a, const ctn_dual m[3], ctn_dual s[3])
{
    ctn_dual wm = ctn_dual_dot(k->w[a], m), Dm[3], v[3], tr = ctn_dual_const(0);
    ctn_dual c = ctn_dual_scale(2, ctn_dual_mul(k->hp[a], wm));
    for (int i = 0; i < 3; i++) {
        Dm[i] = ctn_dual_add(ctn_dual_mul(k->h[a], m[i]), ctn_dual_mul(c, k->w[a][i]));
        tr = ctn_dual_add(tr, k->Q[a][i][i]);
    }
    for (int j = 0; j < 3; j++) {                      /* (tr Dm - Q^T Dm) / 2 */
        ctn_dual qd = ctn_dual_const(0);
        for (int i = 0; i < 3; i++) qd = ctn_dual_add(qd, ctn_dual_mul(k->Q[a][i][j], Dm[i]));
        v[j] = ctn_dual_lin(0.5, ctn_dual_mul(tr, Dm[j]), -0.5, qd);
    }
    for (int i = 0; i < 3; i++)
        s[i] = ctn_dual_add(ctn_dual_add(ctn_dual_mul(k->r[0][i], v[0]), ctn_dual_mul(k->r[1][i], v[1])),
                            ctn_dual_mul(k->r[2][i], v[2]));
}

/* The forces on the nine variables: fv[0..2] on the chord, fv[3 + 3 a ..] the spin
 * moments at end a (the header's dU). */
static void forces(const cf_kin *k, ctn_dual N, const ctn_dual m[2][3], ctn_dual fv[9])
{
    ctn_dual s[2][3], S[3], Sx[3], qb[3];
    end_moment(k, 0, m[0], s[0]);
    end_moment(k, 1, m[1], s[1]);
    for (int i = 0; i < 3; i++) S[i] = ctn_dual_add(s[0][i], s[1][i]);
    ctn_dual Sr = ctn_dual_dot(S, k->r[0]), qr = ctn_dual_dot(k->q, k->r[0]);
    ctn_dual ia = ctn_dual_fn(k->l, 1 / k->l.v, -1 / (k->l.v * k->l.v));
    ctn_dual in = ctn_dual_fn(k->n, 1 / k->n.v, -1 / (k->n.v * k->n.v));
    ctn_dual c3 = ctn_dual_mul(ctn_dual_mul(Sr, qr), ctn_dual_mul(in, ia)), cq = ctn_dual_scale(-0.5, ctn_dual_mul(Sr, in));
    ctn_dual_cross(Sx, S, k->r[0]);
    for (int i = 0; i < 3; i++)
        fv[i] = ctn_dual_sub(ctn_dual_add(ctn_dual_mul(N, k->r[0][i]), ctn_dual_mul(c3, k->r[2][i])),
                             ctn_dual_mul(Sx[i], ia));
    for (int b = 0; b < 2; b++) {
        ctn_dual qa[3] = { k->t[b][1][0], k->t[b][1][1], k->t[b][1][2] };
        ctn_dual_cross(qb, qa, k->r[2]);
        for (int i = 0; i < 3; i++) fv[3 + 3 * b + i] = ctn_dual_add(s[b][i], ctn_dual_mul(cq, qb[i]));
    }
}

/* The energy's value (beam3.c's ctn_beam_energy) of the condensed rotations t. */
static double energy(const ctn_beam_props *p, double N, const ctn_dual t[2][3])
{
    double U = 0.5 * N * N * p->L0 / p->EA, d = t[1][0].v - t[0][0].v;
    const double c0[3] = { 0, p->cy0, p->cz0 }, c1[3] = { 0, p->cy1, p->cz1 };
    for (int k = 1; k < 3; k++)
        U += c0[k] * (t[0][k].v * t[0][k].v + t[1][k].v * t[1][k].v) + c1[k] * t[0][k].v * t[1][k].v;
    return U + 0.5 * p->kt * d * d;
}

int ctn_beam_eval_cf(const ctn_beam_props *p, unsigned mode, const double *X, const double *u, double *f, double *K,
                     ctn_elem_state *out)
{
    cf_kin k;
    ctn_dual t[2][3], N, m[2][3], fv[9];
    for (int a = 0; a < 2; a++) triad(p, X, u + 6 * a + 3, a, k.t[a]);
    if (frame(X, u, &k) || local(&k, 0) || local(&k, 1)) return 1;
    energy_gradient(p, &k, t, &N, m);
    forces(&k, N, m, fv);
    const int *v = ctn_beam_dof_var;
    const double *sg = ctn_beam_dof_sign;
    for (int i = 0; i < 12; i++) f[i] = sg[i] * fv[v[i]].v;
    for (int i = 0; K && i < 12; i++)                  /* the Jacobian's symmetric part */
        for (int j = i; j < 12; j++)
            K[ctn_packed_index(12, i, j)] = sg[i] * sg[j] * 0.5 * (fv[v[i]].g[v[j]] + fv[v[j]].g[v[i]]);
    if (out) {
        double eps = N.v / p->EA;
        *out = (ctn_elem_state){ k.l.v, eps, N.v, (mode & CTN_EVAL_STRESS) ? N.v / p->A : 0, energy(p, N.v, t), 0 };
    }
    return 0;
}
