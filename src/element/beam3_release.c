/* End releases of the corotational beam (beam3.c): a hinge about the local y or z axis
 * at an end frees that end's local rotation from the node's. The energy U(l, theta) of
 * beam3.c is then taken at its minimum over the released rotations (static condensation
 * in the local frame, exact: the bowing's coupling with the axial force included):
 * - released at one end of an axis: Newton on that rotation (and the other axis's, the
 *   two meet in the stretch), started from the linear condensation
 *   theta_r = -c1 theta_other / (2 c0) (for Euler-Bernoulli -theta_other / 2);
 * - released at both ends: the minimum is theta = 0 for both while the member is stable
 *   (the bending and the bowing are even in them), so the axis carries no bending;
 * - torsion released at either end: kt = 0 (beam3_model.c).
 * The condensed energy's gradient is the full energy's in the kept variables (the
 * released ones stationary) and its Hessian H_kk - H_kr H_rr^-1 H_rk (the implicit
 * function's); both are carried to the DOFs through the kinematics' jets by the chain
 * rule, so the tangent stays the exact Hessian of the condensed energy. */
#include "element/beam3.h"

#include <math.h>
#include <string.h>

#define NZ 7    /* z = (l, th[0][0..2], th[1][0..2]) */

enum { KEPT, FREE, ZERO };   /* the role of a variable of z */

static void roles(const ctn_beam_props *p, int role[NZ])
{
    role[0] = KEPT;
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) {
            int here = (p->rel >> (3 * a + k)) & 1, there = (p->rel >> (3 * (1 - a) + k)) & 1;
            role[1 + 3 * a + k] = k == 0 || !here ? KEPT : there ? ZERO : FREE;
        }
}

/* The energy as a jet over z (variables 0..6) at the values t, with l at lv. */
static void energy_z(const ctn_beam_props *p, double lv, const double t[2][3], const int role[NZ], ctn_jet *U)
{
    ctn_jet l, th[2][3];
    ctn_jet_var(&l, lv, 0);
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) {
            int i = 1 + 3 * a + k;
            if (role[i] == ZERO) ctn_jet_const(&th[a][k], 0);
            else ctn_jet_var(&th[a][k], t[a][k], i);
        }
    ctn_beam_energy(p, &l, th, U);
}

/* Solve the symmetric system H_rr x = b of the n <= 2 free variables (scale: the
 * bending stiffness c); 1 if it is singular. */
static int solve_free(int n, const double Hr[2][2], const double b[2], double c, double x[2])
{
    if (n == 1) {
        if (!(fabs(Hr[0][0]) > 1e-9 * c)) return 1;
        x[0] = b[0] / Hr[0][0];
        return 0;
    }
    double det = Hr[0][0] * Hr[1][1] - Hr[0][1] * Hr[1][0];
    if (!(fabs(det) > 1e-9 * c * c)) return 1;
    x[0] = (Hr[1][1] * b[0] - Hr[0][1] * b[1]) / det;
    x[1] = (Hr[0][0] * b[1] - Hr[1][0] * b[0]) / det;
    return 0;
}

static double hess(const ctn_jet *U, int i, int j)
{
    return U->h[i <= j ? ctn_packed_index(CTN_JET_N, i, j) : ctn_packed_index(CTN_JET_N, j, i)];
}

/* The free rotations of t where the energy is stationary in them (Newton from the
 * linear condensation: the minimum of a stable member); U the energy there. */
static int minimize(const ctn_beam_props *p, double lv, double t[2][3], const int role[NZ], int nf, const int fr[2],
                    ctn_jet *U)
{
    double c = fmin(p->cy0, p->cz0);
    for (int a = 0; a < 2; a++)                        /* start: the linear condensation */
        for (int k = 1; k < 3; k++) {
            double c0 = k == 1 ? p->cy0 : p->cz0, c1 = k == 1 ? p->cy1 : p->cz1;
            if (role[1 + 3 * a + k] == FREE) t[a][k] = -c1 * t[1 - a][k] / (2 * c0);
            if (role[1 + 3 * a + k] == ZERO) t[a][k] = 0;
        }
    for (int it = 0; it < 50; it++) {
        double Hr[2][2], b[2], x[2] = { 0, 0 }, step = 0, size = 0;
        energy_z(p, lv, t, role, U);
        for (int i = 0; i < nf; i++) {
            b[i] = -U->g[fr[i]];
            for (int j = 0; j < nf; j++) Hr[i][j] = hess(U, fr[i], fr[j]);
        }
        if (solve_free(nf, Hr, b, c, x)) return 1;
        for (int i = 0; i < nf; i++) {
            double *ti = &t[(fr[i] - 1) / 3][(fr[i] - 1) % 3];
            *ti += x[i];
            step = fmax(step, fabs(x[i]));
            size = fmax(size, fabs(*ti));
        }
        if (step <= 1e-14 * size || step == 0) {
            energy_z(p, lv, t, role, U);
            return 0;
        }
    }
    return 1;
}

int ctn_beam_condense(const ctn_beam_props *p, const ctn_jet *l, ctn_jet th[2][3], double t[2][3], double g[7],
                      double H[7][7], double *Uv)
{
    int role[NZ], fr[2], nf = 0;
    double c = fmin(p->cy0, p->cz0);
    ctn_jet U;
    roles(p, role);
    for (int i = 1; i < NZ; i++)
        if (role[i] == FREE) fr[nf++] = i;
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) t[a][k] = th[a][k].v;
    if (nf) {
        if (minimize(p, l->v, t, role, nf, fr, &U)) return 1;
    } else {
        for (int i = 1; i < NZ; i++)
            if (role[i] == ZERO) t[(i - 1) / 3][(i - 1) % 3] = 0;
        energy_z(p, l->v, t, role, &U);
    }
    double Hr[2][2] = { { 1, 0 }, { 0, 1 } }, col[2][NZ];
    for (int i = 0; i < nf; i++)
        for (int j = 0; j < nf; j++) Hr[i][j] = hess(&U, fr[i], fr[j]);
    for (int j = 0; j < NZ; j++) {                     /* col = H_rr^-1 H_rj */
        double b[2] = { 0, 0 }, x[2] = { 0, 0 };
        for (int i = 0; i < nf; i++) b[i] = hess(&U, fr[i], j);
        if (nf && solve_free(nf, Hr, b, c, x)) return 1;
        col[0][j] = x[0];
        col[1][j] = x[1];
    }
    for (int i = 0; i < NZ; i++) {
        g[i] = role[i] == KEPT ? U.g[i] : 0;
        for (int j = 0; j < NZ; j++) {
            double h = hess(&U, i, j);
            for (int r = 0; r < nf; r++) h -= hess(&U, i, fr[r]) * col[r][j];
            H[i][j] = role[i] == KEPT && role[j] == KEPT ? h : 0;
        }
    }
    *Uv = U.v;
    return 0;
}

int ctn_beam_eval_released(const ctn_beam_props *p, unsigned mode, const double *X, const double *u, double *f,
                           double *K, ctn_elem_state *out)
{
    ctn_jet l, th[2][3], W;
    double t[2][3], g[NZ], H[NZ][NZ], Uv;
    if (ctn_beam_kinematics(p, X, u, &l, th, NULL) || ctn_beam_condense(p, &l, th, t, g, H, &Uv)) return 1;
    const ctn_jet *z[NZ] = { &l, &th[0][0], &th[0][1], &th[0][2], &th[1][0], &th[1][1], &th[1][2] };
    ctn_jet_const(&W, Uv);                             /* W = U(z(q)): the chain rule */
    for (int i = 0; i < NZ; i++) {
        if (g[i] != 0) ctn_jet_lin(&W, 1, &W, g[i], z[i]);
        for (int j = 0; j < NZ; j++) {
            if (H[i][j] == 0) continue;
            for (int v = 0, s = 0; v < CTN_JET_N; v++)
                for (int w = v; w < CTN_JET_N; w++, s++) W.h[s] += H[i][j] * z[i]->g[v] * z[j]->g[w];
        }
    }
    W.v = Uv;
    ctn_beam_dofs(&W, f, K);
    if (out) {
        double eps = ctn_beam_stretch(p, l.v, t) / p->L0, N = p->EA * eps;
        *out = (ctn_elem_state){ l.v, eps, N, (mode & CTN_EVAL_STRESS) ? N / p->A : 0, Uv, 0 };
    }
    return 0;
}
