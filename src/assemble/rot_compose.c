/* The rotation update of a family of finite rotations (the corotational beam): a node's
 * rotation R = exp(psi) turned by the spin increment dw, R <- exp(dw) R, its rotation
 * vector psi kept continuous. On unit quaternions, q = (cos(t/2), sin(t/2) n) for
 * psi = t n: q <- q(dw) q(psi); the new rotation is then the angle t' = 2 atan2(|v|, w)
 * in [0, 2 pi] about n' = v / |v|, and of all its rotation vectors n' (t' + 2 pi j) the
 * one nearest the old psi is kept (j = round((n' . psi - t') / 2 pi)): psi goes on past
 * pi and 2 pi as the node turns (a cantilever rolled into a full circle ends with its
 * tip at psi = 2 pi), and R, all the element sees, is exact whatever the branch.
 * A node with some rotations fixed and some free (a plane model) adds them instead:
 * its free rotations then stay the components of psi (assemble/dofmap.c). */
#include "assemble/dofmap.h"

#include <math.h>

static void quat(const double psi[3], double q[4])
{
    double t = sqrt(psi[0] * psi[0] + psi[1] * psi[1] + psi[2] * psi[2]);
    double s = t > 1e-8 ? sin(0.5 * t) / t : 0.5 - t * t / 48;          /* sin(t/2) / t */
    q[0] = cos(0.5 * t);
    for (int k = 0; k < 3; k++) q[k + 1] = s * psi[k];
}

void ctn_rot_update_compose(double *psi, const double *dw)
{
    const double pi = 3.14159265358979323846;
    double a[4], b[4], q[4];
    if (dw[0] == 0 && dw[1] == 0 && dw[2] == 0) return;
    quat(dw, a);
    quat(psi, b);
    q[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];             /* q = a b */
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3 + 1, j = (k + 2) % 3 + 1;
        q[k + 1] = a[0] * b[k + 1] + b[0] * a[k + 1] + a[i] * b[j] - a[j] * b[i];
    }
    double v = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), t = 2 * atan2(v, q[0]), n[3];
    if (!(v > 0)) {                                /* the identity: 2 pi j along the old psi */
        double p = sqrt(psi[0] * psi[0] + psi[1] * psi[1] + psi[2] * psi[2]), j = round(p / (2 * pi));
        for (int k = 0; k < 3; k++) psi[k] = p > 0 ? psi[k] * (2 * pi * j / p) : 0;
        return;
    }
    for (int k = 0; k < 3; k++) n[k] = q[k + 1] / v;
    double np = n[0] * psi[0] + n[1] * psi[1] + n[2] * psi[2];
    double tj = t + 2 * pi * round((np - t) / (2 * pi));
    for (int k = 0; k < 3; k++) psi[k] = tj * n[k];
}
