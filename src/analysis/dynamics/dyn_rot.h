/* Internal: finite rotations in a dynamics analysis, shared by dyn_rot.c (the implicit
 * methods' rotary inertia), dyn_rot_damp.c (damping on the rotations) and
 * dyn_rot_central.c (the explicit rotation update): the nodes with free rotations and
 * their rotary inertia, and the small quaternion and 3 x 3 helpers. */
#ifndef CTN_ANALYSIS_DYN_ROT_H
#define CTN_ANALYSIS_DYN_ROT_H

#include "analysis/dynamics/dynamics.h"

#include <math.h>

struct ctn_dyn_rot {
    size_t n;              /* nodes with a free rotation */
    size_t *node;          /* their indices */
    size_t *st;            /* the state index of each one's rx */
    int *eq;               /* 3 per node: the equations of its rotations (-1 fixed) */
    int *slot;             /* 9 per node: the tangent's value of (a, b), eq[a] <= eq[b] (-1) */
    long *at;              /* per model node: its index here, -1 */
    double *work;          /* an element's packed mass and coordinates */
    double *J;             /* 9 per node: the rotary inertia, material frame */
    double *W0, *A0, *W1, *A1, *I0, *I1;   /* 3 per node */
    struct ctn_dyn_exact *exact;           /* the consistent tangent (dyn_rot_exact.c), or NULL */
};

/* dyn_rot_exact.c: its blocks freed. */
void ctn_dyn_exact_free(struct ctn_dyn_rot *r);

/* q = the unit quaternion of the rotation vector psi. */
static inline void dr_quat(const double psi[3], double q[4])
{
    double t = sqrt(psi[0] * psi[0] + psi[1] * psi[1] + psi[2] * psi[2]);
    double s = t > 1e-8 ? sin(0.5 * t) / t : 0.5 - t * t / 48;
    q[0] = cos(0.5 * t);
    for (int k = 0; k < 3; k++) q[k + 1] = s * psi[k];
}

/* The rotation vector of conj(a) b: log(R_a^T R_b), its angle in [0, pi]. */
static inline void dr_log_rel(const double a[4], const double b[4], double th[3])
{
    double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3], v[3];
    for (int k = 0; k < 3; k++) {                       /* conj(a) b */
        int i = (k + 1) % 3 + 1, j = (k + 2) % 3 + 1;
        v[k] = a[0] * b[k + 1] - b[0] * a[k + 1] - (a[i] * b[j] - a[j] * b[i]);
    }
    if (w < 0) {
        w = -w;
        for (int k = 0; k < 3; k++) v[k] = -v[k];
    }
    double s = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double f = s > 1e-12 ? 2 * atan2(s, w) / s : 2 / w;
    for (int k = 0; k < 3; k++) th[k] = f * v[k];
}

/* R (row-major) of q. */
static inline void dr_rmat(const double q[4], double R[9])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

static inline void dr_mv(const double M[9], const double x[3], double y[3])
{
    for (int i = 0; i < 3; i++) y[i] = M[3 * i] * x[0] + M[3 * i + 1] * x[1] + M[3 * i + 2] * x[2];
}

static inline void dr_mtv(const double M[9], const double x[3], double y[3])
{
    for (int i = 0; i < 3; i++) y[i] = M[i] * x[0] + M[3 + i] * x[1] + M[6 + i] * x[2];
}

#endif
