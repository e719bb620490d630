/* Damping of a model with rotations (beams): Rayleigh's alpha M + beta K_0 and modal
 * damping's C_m = U E U^T act on the spatial velocities, a rotation's angular velocity
 * w = R W (W the material one the analysis keeps, R the node's rotation at that
 * velocity's time), so that their moments are spatial, as the residual's are (K_0's
 * rotation variables are the spins at the start). The mass-proportional part on a
 * rotation is alpha R J W: a damping moment along the body's own angular momentum,
 * alpha (R J R^T) w at the current rotation (for a rigid body turning about a point,
 * alpha I W in the body frame: Euler's equations with I W' + W x I W = tau - alpha I W).
 * Modal damping's U = M Phi takes the rotary inertia's rows R0 J R0^T at the start, the
 * modes (with their rotations) normalized on the analysis's own mass. Their tangent in
 * the spin of R1 is c2 times C (and alpha c2 R1 J R1^T), leaving out the frame's turn
 * (of order h |W|, as the inertia's gyroscopic part). docs/theory.md "Dynamics". */
#include "analysis/dynamics/dyn_rot.h"

#include <string.h>

/* R (row-major) of node k at the state d. */
static void node_rotation(const struct ctn_dyn_rot *r, size_t k, const double *d, double R[9])
{
    double q[4];
    dr_quat(d + r->st[k], q);
    dr_rmat(q, R);
}

/* The node's material vector x (3) from its equations' entries of v (0 where fixed). */
static void node_vector(const struct ctn_dyn_rot *r, size_t k, const double *v, double x[3])
{
    for (int c = 0; c < 3; c++) {
        int q = r->eq[3 * k + (size_t)c];
        x[c] = q >= 0 ? v[q] : 0.0;
    }
}

void ctn_dyn_rot_spatial(const ctn_dyn *dy, const double *d, const double *v, double *vs)
{
    const struct ctn_dyn_rot *r = dy->rot;
    if (vs != v) memcpy(vs, v, dy->p->ndof * sizeof(double));
    for (size_t k = 0; r && k < r->n; k++) {
        double R[9], W[3], w[3];
        node_rotation(r, k, d, R);
        node_vector(r, k, v, W);
        dr_mv(R, W, w);
        for (int c = 0; c < 3; c++) {
            int q = r->eq[3 * k + (size_t)c];
            if (q >= 0) vs[q] = w[c];
        }
    }
}

void ctn_dyn_rot_damp_mass(const ctn_dyn *dy, const double *d, const double *v, double alpha, double *y)
{
    const struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; r && alpha > 0 && k < r->n; k++) {
        double R[9], W[3], JW[3], m[3];
        node_rotation(r, k, d, R);
        node_vector(r, k, v, W);
        dr_mv(r->J + 9 * k, W, JW);
        dr_mv(R, JW, m);                                 /* R J W */
        for (int c = 0; c < 3; c++) {
            int q = r->eq[3 * k + (size_t)c];
            if (q >= 0) y[q] += alpha * m[c];
        }
    }
}

void ctn_dyn_rot_mass_mult(const ctn_dyn *dy, const double *d, const double *x, double *y)
{
    const struct ctn_dyn_rot *r = dy->rot;
    for (size_t k = 0; r && k < r->n; k++) {
        double R[9], xs[3], xm[3], Jx[3], m[3];
        node_rotation(r, k, d, R);
        node_vector(r, k, x, xs);
        dr_mtv(R, xs, xm);
        dr_mv(r->J + 9 * k, xm, Jx);
        dr_mv(R, Jx, m);                                 /* R J R^T x */
        for (int c = 0; c < 3; c++) {
            int q = r->eq[3 * k + (size_t)c];
            if (q >= 0) y[q] += m[c];
        }
    }
}

void ctn_dyn_damp_at(const ctn_dyn *dy, const double *d, const double *v, double *vs, double *y)
{
    if (!dy->rot) {
        if (vs != v) memcpy(vs, v, dy->p->ndof * sizeof(double));
        ctn_dyn_damp(dy, v, y);
        return;
    }
    ctn_dyn_rot_spatial(dy, d, v, vs);
    ctn_dyn_damp(dy, vs, y);
    ctn_dyn_rot_damp_mass(dy, d, v, dy->o->damping_alpha, y);
}
