/* Internal: kinematics shared by two-node axial members (cable, spring): the current
 * chord, the nodal forces of an axial force and its tangent. */
#ifndef CTN_ELEMENT_AXIAL_H
#define CTN_ELEMENT_AXIAL_H

#include "element/element.h"

#include <math.h>

/* Inline: they are the inner loop of every axial kernel. */

/* Unit chord e and length l of the current configuration X + u (3 per node, 2 nodes);
 * 1 if the element has collapsed (l not positive and finite), else 0. */
static inline int ctn_axial_chord(const double *X, const double *u, double e[3], double *l)
{
    double a[3];
    for (int i = 0; i < 3; i++) a[i] = (X[3 + i] - X[i]) + (u[3 + i] - u[i]);
    *l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(*l > 0) || !isfinite(*l)) return 1;
    for (int i = 0; i < 3; i++) e[i] = a[i] / *l;
    return 0;
}

/* f1 = -N e, f2 = N e. */
static inline void ctn_axial_forces(const double e[3], double N, double *f)
{
    for (int i = 0; i < 3; i++) {
        f[i] = -N * e[i];
        f[3 + i] = N * e[i];
    }
}

/* k = dN/dl e e^T + N/l (I - e e^T), its upper triangle kk (xx, xy, xz, yy, yz, zz:
 * ctn_packed_index(3, i, j)): the block of an axial member's tangent [[k, -k], [-k, k]]. */
static inline void ctn_axial_k(const double e[3], double l, double N, double dNdl, double kk[6])
{
    double s = N / l;
    int t = 0;
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) kk[t++] = (dNdl - s) * e[i] * e[j] + (i == j ? s : 0.0);
}

/* Packed upper triangle of K = [[k, -k], [-k, k]] from k's upper triangle kk. */
static inline void ctn_axial_expand(const double kk[6], double *K)
{
    int t = 0;
    for (int i = 0; i < 3; i++) {
        for (int j = i; j < 3; j++) K[t++] = kk[ctn_packed_index(3, i, j)];          /* node 1 - node 1 */
        for (int j = 0; j < 3; j++) K[t++] = -kk[i <= j ? ctn_packed_index(3, i, j) : ctn_packed_index(3, j, i)];
    }                                                                                 /* node 1 - node 2 */
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) K[t++] = kk[ctn_packed_index(3, i, j)];          /* node 2 - node 2 */
}

/* The generic eval of an axial family from its eval_axial (the same bits): the forces,
 * and the packed 6 x 6 tangent expanded from k when K is wanted. */
static inline int ctn_axial_eval(int (*axial)(const void *, unsigned, const double *, const double *, double *,
                                              double *, ctn_elem_state *),
                                 const void *props, unsigned mode, const double *X, const double *u, double *f,
                                 double *K, ctn_elem_state *out)
{
    ctn_elem_state st;
    double kk[6];
    if (axial(props, mode, X, u, f, K ? kk : NULL, &st)) return 1;
    if (K) ctn_axial_expand(kk, K);
    if (out) *out = st;
    return 0;
}

/* Packed upper triangle of K = [[k, -k], [-k, k]], k = dN/dl e e^T + N/l (I - e e^T). */
static inline void ctn_axial_tangent(const double e[3], double l, double N, double dNdl, double *K)
{
    double kk[6];
    ctn_axial_k(e, l, N, dNdl, kk);
    ctn_axial_expand(kk, K);
}

/* Packed upper triangle of the mass matrix of a two-node member of mass ms (linear
 * interpolation along it): consistent ms/6 [[2I, I], [I, 2I]], lumped ms/2 [[I, 0], [0, I]]. */
static inline void ctn_axial_mass(double ms, int lumped, double *M)
{
    double d = lumped ? ms / 2 : ms / 3, o = lumped ? 0.0 : ms / 6;
    for (int t = 0; t < 21; t++) M[t] = 0.0;
    for (int i = 0; i < 3; i++) {
        M[ctn_packed_index(6, i, i)] = d;                      /* node 1 - node 1 */
        M[ctn_packed_index(6, 3 + i, 3 + i)] = d;              /* node 2 - node 2 */
        M[ctn_packed_index(6, i, 3 + i)] = o;                  /* node 1 - node 2 */
    }
}

#endif
