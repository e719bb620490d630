/* Internal: the corotational 3D beam (beam3.c): its properties, and what its kernel
 * gives the results (the end forces in the member's local axes). */
#ifndef CTN_ELEMENT_BEAM3_H
#define CTN_ELEMENT_BEAM3_H

#include "element/element.h"

typedef struct ctn_beam_props {
    double L0;          /* reference (unstressed) length */
    double EA, A;       /* axial stiffness, area */
    double cy0, cy1;    /* bending about local y: U = cy0 (t1y^2 + t2y^2) + cy1 t1y t2y */
    double cz0, cz1;    /* bending about local z, likewise */
    double kt;          /* torsion: U = kt (t2x - t1x)^2 / 2, kt = G J / L0 */
    double e2[3], e3[3];/* the local y and z axes in the reference state */
    double rhoA;        /* mass per unit length (mass op) */
    double rhoJ;        /* rotary inertia per unit length about the axis, rhoA (Iy + Iz) / A */
    double rhoIy, rhoIz;/* ... about the local y and z axes, rhoA Iy / A, rhoA Iz / A */
} ctn_beam_props;

/* The kernel (the family's eval, element.h). */
int ctn_beam_eval(const void *props, unsigned mode, const double *X, const double *u, double *f, double *K,
                  ctn_elem_state *out);

/* The element's end forces at displacements u (12: x, y, z, rx, ry, rz per node):
 * out[0..5] at node 1 and out[6..11] at node 2, each (Fx, Fy, Fz, Mx, My, Mz) in the
 * current local axes of the member, the forces and moments the nodes apply to the
 * member (the stiffness method's end forces: N = out[6], T = out[9]). Returns 0, or 1
 * if the state cannot be evaluated (a collapsed chord, a local rotation past 90 deg). */
int ctn_beam_end_forces(const ctn_beam_props *p, const double *X, const double *u, double out[12]);

/* Scalar functions of y = |v|^2 with their first two derivatives in y (beam3_fn.c):
 * the Rodrigues coefficients a = sin(t)/t and b = (1 - cos t)/t^2 of t = sqrt(y), and
 * the coefficient of the rotation log, asin(s)/s of s = sqrt(y) (y < 1). */
void ctn_beam_rod_a(double y, double f[3]);
void ctn_beam_rod_b(double y, double f[3]);
void ctn_beam_log_h(double y, double f[3]);

#endif
