/* Two-node 3D beam, corotational (Battini and Pacoste 2002), 6 DOFs per node: x, y, z
 * and the node's total rotation vector psi (R = exp(psi)). At a node whose rotations the
 * DOF map composes (all free or all fixed, beam3.h spin) the rotation variables are the
 * spin w of exp(w) exp(psi) at w = 0: the forces are the true moments and the tangent
 * the Hessian in w; at a node of a plane model (some rotations fixed) they are psi's
 * components, added.
 *
 * Kinematics, exact for any rigid motion: the nodal triads T_a = R(psi_a) E0 (E0 the
 * reference local axes: e1 along the member, e3 in the plane of e1 and orient=); the
 * corotated frame r1 = chord / l, r3 = r1 x q / |r1 x q| with q the mean of the two
 * triads' y axes, r2 = r3 x r1; the local rotations theta_a = log(Rr^T T_a), small in
 * a well-meshed member. Energy (Euler-Bernoulli, or Timoshenko with shear areas):
 *   U = EA (l - L0 + b_y + b_z)^2 / (2 L0)
 *     + sum over y, z: c0 (theta_1^2 + theta_2^2) + c1 theta_1 theta_2
 *     + G J (theta_2x - theta_1x)^2 / (2 L0),
 * b = L0 (2 theta_1^2 - theta_1 theta_2 + 2 theta_2^2) / 30 the bowing about y and z
 * (the integral of w'^2 / 2 of the cubic deflection: the local axial strain of a
 * shallow arch, which gives the consistent geometric stiffness, so Euler's load
 * converges at O(h^4)),
 * c0 = EI (4 + phi) / (2 L0 (1 + phi)), c1 = EI (2 - phi) / (L0 (1 + phi)),
 * phi = 12 EI / (G As L0^2) (0 without shear areas). The forces are its gradient and
 * the tangent its Hessian in the DOFs, both exact: the energy is evaluated on
 * second-order jets (jet.h) over the chord and the two rotation vectors. */
#include "element/beam3.h"
#include "element/jet.h"

#include <math.h>
#include <string.h>

/* x = R(psi) e for a constant e: (1 - b y) e + a psi x e + b (psi . e) psi. */
static void rotate(ctn_jet x[3], const ctn_jet psi[3], const ctn_jet c[3], const double e[3])
{
    ctn_jet pe, t;                                     /* c = (1 - b y, a, b) */
    ctn_jet_lin(&pe, e[0], &psi[0], e[1], &psi[1]);
    ctn_jet_lin(&pe, 1, &pe, e[2], &psi[2]);
    ctn_jet_mul(&pe, &pe, &c[2]);
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        ctn_jet_lin(&t, e[j], &psi[i], -e[i], &psi[j]);   /* (psi x e)_k */
        ctn_jet_mul(&t, &t, &c[1]);
        ctn_jet_mul(&x[k], &pe, &psi[k]);
        ctn_jet_lin(&x[k], 1, &x[k], 1, &t);
        ctn_jet_lin(&x[k], 1, &x[k], e[k], &c[0]);
    }
}

void ctn_beam_rotate_n(const double psi[3], int n, const double (*e)[3], double (*x)[3])
{
    double y = psi[0] * psi[0] + psi[1] * psi[1] + psi[2] * psi[2], fa[3], fb[3];
    ctn_beam_rod_a(y, fa);
    ctn_beam_rod_b(y, fb);
    for (int v = 0; v < n; v++) {
        double pe = psi[0] * e[v][0] + psi[1] * e[v][1] + psi[2] * e[v][2];
        for (int k = 0; k < 3; k++) {
            int i = (k + 1) % 3, j = (k + 2) % 3;
            x[v][k] = (1 - fb[0] * y) * e[v][k] + fa[0] * (psi[i] * e[v][j] - psi[j] * e[v][i]) + fb[0] * pe * psi[k];
        }
    }
}

void ctn_beam_rotate(const double psi[3], const double e[3], double x[3])
{
    ctn_beam_rotate_n(psi, 1, (const double(*)[3])e, (double(*)[3])x);
}

int ctn_beam_spin_node(unsigned fix)
{
    unsigned r = fix & CTN_FIX_ROT;
    return r == 0 || r == CTN_FIX_ROT;
}

/* The triad T = R(psi) E0 of one node, columns t[j] (psi: variables v .. v + 2). */
static void triad(const double *psi0, int v, const double E0[3][3], ctn_jet t[3][3])
{
    ctn_jet psi[3], y, c[3], f;
    double fa[3], fb[3];
    for (int k = 0; k < 3; k++) ctn_jet_var(&psi[k], psi0[k], v + k);
    ctn_jet_dot(&y, psi, psi);
    ctn_beam_rod_a(y.v, fa);
    ctn_beam_rod_b(y.v, fb);
    ctn_jet_fn(&c[1], &y, fa[0], fa[1], fa[2]);
    ctn_jet_fn(&c[2], &y, fb[0], fb[1], fb[2]);
    ctn_jet_mul(&f, &c[2], &y);
    ctn_jet_const(&c[0], 1);
    ctn_jet_lin(&c[0], 1, &c[0], -1, &f);
    for (int j = 0; j < 3; j++) rotate(t[j], psi, c, E0[j]);
}

/* The triad of end a (its rotation: variables 3 + 3 a ..): over the spin dw of
 * R = exp(dw) exp(psi) at dw = 0 (the reference axes turned by exp(psi) first), or over
 * psi itself (beam3.h, spin). */
static void node_triad(const ctn_beam_props *p, int a, const double *psi, const double E0[3][3], ctn_jet t[3][3])
{
    static const double zero[3] = { 0, 0, 0 };
    if (!(p->spin >> a & 1u)) {
        triad(psi, 3 + 3 * a, E0, t);
        return;
    }
    double E[3][3];
    ctn_beam_rotate_n(psi, 3, E0, E);
    triad(zero, 3 + 3 * a, (const double(*)[3])E, t);
}

/* theta = log(Rr^T T) for the frame r (rows r[i]) and triad t (columns t[j]): the skew
 * part w of Rr^T T is sin(theta) n, and theta = asin(|w|) / |w| w while cos(theta) > 0.
 * Returns 1 past 90 degrees. */
static int local_rotation(ctn_jet r[3][3], ctn_jet t[3][3], ctn_jet th[3])
{
    ctn_jet w[3], a, b, y;
    double tr = 0, fh[3];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) tr += r[i][k].v * t[i][k].v;
    if (!(tr > 1)) return 1;                           /* cos(theta) = (tr - 1) / 2 */
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;          /* w_k = (R_ji - R_ij) / 2 */
        ctn_jet_dot(&a, r[j], t[i]);
        ctn_jet_dot(&b, r[i], t[j]);
        ctn_jet_lin(&w[k], 0.5, &a, -0.5, &b);
    }
    ctn_jet_dot(&y, w, w);
    if (!(y.v < 1)) return 1;
    ctn_beam_log_h(y.v, fh);
    ctn_jet_fn(&y, &y, fh[0], fh[1], fh[2]);
    for (int k = 0; k < 3; k++) ctn_jet_mul(&th[k], &y, &w[k]);
    return 0;
}

/* The chord length l and the local rotations th[a] of both ends, on jets over the chord
 * (variables 0..2) and the rotation vectors (3..5, 6..8). Returns 1 if they cannot be
 * formed (a collapsed chord, the chord along the triads' mean y axis, a local rotation
 * past 90 degrees). */
int ctn_beam_kinematics(const ctn_beam_props *p, const double *X, const double *u, ctn_jet *l, ctn_jet th[2][3],
                        double R[3][3])
{
    ctn_jet x[3], r[3][3], q[3], pq[3], t[2][3][3];
    double E0[3][3], L = 0;
    for (int k = 0; k < 3; k++) {
        E0[0][k] = X[3 + k] - X[k];
        L += E0[0][k] * E0[0][k];
        E0[1][k] = p->e2[k];
        E0[2][k] = p->e3[k];
        ctn_jet_var(&x[k], (X[3 + k] - X[k]) + (u[6 + k] - u[k]), k);
    }
    L = sqrt(L);
    if (!(L > 0)) return 1;
    for (int k = 0; k < 3; k++) E0[0][k] /= L;
    for (int a = 0; a < 2; a++) node_triad(p, a, u + 6 * a + 3, E0, t[a]);
    ctn_jet_dot(l, x, x);
    double ln = ctn_jet_unit(r[0], x);
    if (!(ln > 0)) return 1;
    ctn_jet_fn(l, l, ln, 0.5 / ln, -0.25 / (ln * l->v));
    for (int k = 0; k < 3; k++) ctn_jet_lin(&q[k], 0.5, &t[0][1][k], 0.5, &t[1][1][k]);
    ctn_jet_cross(pq, r[0], q);
    if (!(ctn_jet_unit(r[2], pq) > 1e-12)) return 1;
    ctn_jet_cross(r[1], r[2], r[0]);
    for (int i = 0; R && i < 3; i++)
        for (int k = 0; k < 3; k++) R[i][k] = r[i][k].v;
    return local_rotation(r, t[0], th[0]) || local_rotation(r, t[1], th[1]);
}

/* U of the chord length and the local rotations (the header's energy). */
void ctn_beam_energy(const ctn_beam_props *p, const ctn_jet *l, ctn_jet th[2][3], ctn_jet *U)
{
    ctn_jet a, b, w;
    ctn_jet_const(&a, p->L0);
    ctn_jet_lin(&a, 1, l, -1, &a);                     /* l - L0 */
    for (int k = 1; k < 3; k++) {                      /* + the bowing, int w'^2 / 2 */
        ctn_jet_mul(&w, &th[0][k], &th[0][k]);
        ctn_jet_mul(&b, &th[1][k], &th[1][k]);
        ctn_jet_lin(&w, 2, &w, 2, &b);
        ctn_jet_mul(&b, &th[0][k], &th[1][k]);
        ctn_jet_lin(&w, 1, &w, -1, &b);
        ctn_jet_lin(&a, 1, &a, p->L0 / 30, &w);
    }
    ctn_jet_mul(U, &a, &a);
    ctn_jet_lin(U, 0.5 * p->EA / p->L0, U, 0, U);
    const double c0[3] = { 0, p->cy0, p->cz0 }, c1[3] = { 0, p->cy1, p->cz1 };
    for (int k = 1; k < 3; k++) {
        ctn_jet_mul(&a, &th[0][k], &th[0][k]);
        ctn_jet_mul(&b, &th[1][k], &th[1][k]);
        ctn_jet_lin(&a, 1, &a, 1, &b);
        ctn_jet_lin(U, 1, U, c0[k], &a);
        ctn_jet_mul(&a, &th[0][k], &th[1][k]);
        ctn_jet_lin(U, 1, U, c1[k], &a);
    }
    ctn_jet_lin(&a, 1, &th[1][0], -1, &th[0][0]);
    ctn_jet_mul(&a, &a, &a);
    ctn_jet_lin(U, 1, U, 0.5 * p->kt, &a);
}

/* The member's stretch l - L0 plus its bowing (the values of energy()'s), whose EA / L0
 * times is the axial force N. */
double ctn_beam_stretch(const ctn_beam_props *p, double l, const double t[2][3])
{
    double s = l - p->L0;
    for (int k = 1; k < 3; k++)
        s += p->L0 / 30 * (2 * t[0][k] * t[0][k] - t[0][k] * t[1][k] + 2 * t[1][k] * t[1][k]);
    return s;
}

/* The jet variable of each of the 12 DOFs and its sign (beam3.h). */
const int ctn_beam_dof_var[12] = { 0, 1, 2, 3, 4, 5, 0, 1, 2, 6, 7, 8 };
const double ctn_beam_dof_sign[12] = { -1, -1, -1, 1, 1, 1, 1, 1, 1, 1, 1, 1 };

void ctn_beam_dofs(const ctn_jet *U, double *f, double *K)
{
    const int *v = ctn_beam_dof_var;
    const double *sg = ctn_beam_dof_sign;
    for (int i = 0; i < 12; i++) f[i] = sg[i] * U->g[v[i]];
    for (int i = 0; K && i < 12; i++)
        for (int j = i; j < 12; j++) {
            int a = v[i] < v[j] ? v[i] : v[j], b = v[i] + v[j] - a;
            K[ctn_packed_index(12, i, j)] = sg[i] * sg[j] * U->h[ctn_packed_index(CTN_JET_N, a, b)];
        }
}

int ctn_beam_eval(const void *props, unsigned mode, const double *X, const double *u, double *f, double *K,
                  ctn_elem_state *out)
{
    const ctn_beam_props *p = props;
    if (p->spin == 3u) return ctn_beam_eval_cf(p, mode, X, u, f, K, out);
    return ctn_beam_eval_jet(p, mode, X, u, f, K, out);
}

int ctn_beam_eval_jet(const ctn_beam_props *p, unsigned mode, const double *X, const double *u, double *f, double *K,
                      ctn_elem_state *out)
{
    ctn_jet l, th[2][3], U;
    if (p->rel & CTN_BEAM_REL_BEND) return ctn_beam_eval_released(p, mode, X, u, f, K, out);
    if (ctn_beam_kinematics(p, X, u, &l, th, NULL)) return 1;
    ctn_beam_energy(p, &l, th, &U);
    ctn_beam_dofs(&U, f, K);
    if (out) {
        double t[2][3];
        for (int a = 0; a < 2; a++)
            for (int k = 0; k < 3; k++) t[a][k] = th[a][k].v;
        double eps = ctn_beam_stretch(p, l.v, t) / p->L0, N = p->EA * eps;
        *out = (ctn_elem_state){ l.v, eps, N, (mode & CTN_EVAL_STRESS) ? N / p->A : 0, U.v, 0 };
    }
    return 0;
}

int ctn_beam_end_forces(const ctn_beam_props *p, const double *X, const double *u, double out[12], double R[3][3])
{
    ctn_jet l, th[2][3];
    if (ctn_beam_kinematics(p, X, u, &l, th, R)) return 1;
    double t[2][3];
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) t[a][k] = th[a][k].v;
    if (p->rel & CTN_BEAM_REL_BEND) ctn_beam_condense(p, th, t);
    double N = p->EA * ctn_beam_stretch(p, l.v, t) / p->L0;
    double T = p->kt * (t[1][0] - t[0][0]);
    double My[2] = { 2 * p->cy0 * t[0][1] + p->cy1 * t[1][1], 2 * p->cy0 * t[1][1] + p->cy1 * t[0][1] };
    double Mz[2] = { 2 * p->cz0 * t[0][2] + p->cz1 * t[1][2], 2 * p->cz0 * t[1][2] + p->cz1 * t[0][2] };
    for (int a = 0; a < 2; a++) {                      /* a hinge takes no moment */
        if (p->rel & CTN_RELEASE_RY1 << 3 * a) My[a] = 0;
        if (p->rel & CTN_RELEASE_RZ1 << 3 * a) Mz[a] = 0;
    }
    double Fy2 = -(Mz[0] + Mz[1]) / l.v, Fz2 = (My[0] + My[1]) / l.v;   /* the member's moment balance */
    const double e[12] = { -N, -Fy2, -Fz2, -T, My[0], Mz[0], N, Fy2, Fz2, T, My[1], Mz[1] };
    for (int k = 0; k < 12; k++) out[k] = e[k] + 0.0;   /* no negative zeros */
    return 0;
}
