/* Internal: the corotational 3D beam (beam3.c): its properties, and what its kernel
 * gives the results (the end forces in the member's local axes). */
#ifndef CTN_ELEMENT_BEAM3_H
#define CTN_ELEMENT_BEAM3_H

#include "element/element.h"
#include "element/jet.h"

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
    unsigned rel;       /* end releases, CTN_RELEASE_* (bit 3 a + k: end a, local axis k);
                           a torsion release sets kt = 0 (beam3_model.c) */
    unsigned spin;      /* bit a: node a's rotations are all free or all fixed, so the DOF
                           map composes them (ctn_rot_update_compose): the kernel's rotation
                           variables there are the spin dw of R = exp(dw) exp(psi) at dw = 0,
                           its moments the true (spatial) moments; else (some fixed, some
                           free: a plane model) the rotation vector psi itself, added */
} ctn_beam_props;

/* The spin flag of a node with fix flags `fix` (CTN_FIX_*): its rotations all free or all
 * fixed (the rule the DOF map's update follows, assemble/rot_compose.c). */
int ctn_beam_spin_node(unsigned fix);

/* x = exp(psi) e (Rodrigues, any |psi|); the _n form turns n vectors e[v] into x[v]. */
void ctn_beam_rotate(const double psi[3], const double e[3], double x[3]);
void ctn_beam_rotate_n(const double psi[3], int n, const double (*e)[3], double (*x)[3]);

/* The releases of bending (about local y or z, at either end): the kernel then takes
 * the condensed energy (beam3_release.c). */
#define CTN_BEAM_REL_BEND (CTN_RELEASE_RY1 | CTN_RELEASE_RZ1 | CTN_RELEASE_RY2 | CTN_RELEASE_RZ2)

/* The kernel (the family's eval, element.h): ctn_beam_eval_cf for a member whose nodes
 * both take spins (the closed-form forces, their Jacobian the tangent), else
 * ctn_beam_eval_jet (the energy on second-order jets: any node, and the reference the
 * closed form is tested against, tests/test_beam_cf.c). The same contract and answers. */
int ctn_beam_eval(const void *props, unsigned mode, const double *X, const double *u, double *f, double *K,
                  ctn_elem_state *out);
int ctn_beam_eval_jet(const ctn_beam_props *p, unsigned mode, const double *X, const double *u, double *f, double *K,
                      ctn_elem_state *out);
int ctn_beam_eval_cf(const ctn_beam_props *p, unsigned mode, const double *X, const double *u, double *f, double *K,
                     ctn_elem_state *out);

/* The element's end forces at displacements u (12: x, y, z, rx, ry, rz per node):
 * out[0..5] at node 1 and out[6..11] at node 2, each (Fx, Fy, Fz, Mx, My, Mz) in the
 * current local axes of the member, the forces and moments the nodes apply to the
 * member (the stiffness method's end forces: N = out[6], T = out[9]). Returns 0, or 1
 * if the state cannot be evaluated (a collapsed chord, a local rotation past 90 deg).
 * R (may be NULL) gets the current local axes, rows x, y, z in global components. */
int ctn_beam_end_forces(const ctn_beam_props *p, const double *X, const double *u, double out[12], double R[3][3]);

/* The pieces of the kernel (beam3.c) the released member shares (beam3_release.c):
 * the chord length l and the local rotations th[a] of both ends as jets over the chord
 * (variables 0..2) and the two rotation vectors (3..5, 6..8), 1 if they cannot be formed;
 * the energy U of l and th (any jets); the stretch l - L0 plus the bowing of the local
 * rotations t (EA / L0 times it is N); the forces f and packed tangent K (may be NULL) of
 * the 12 DOFs from U as a jet over the kinematics' variables. The kinematics' R (may be
 * NULL) gets the corotated frame's axes (rows x, y, z). */
int ctn_beam_kinematics(const ctn_beam_props *p, const double *X, const double *u, ctn_jet *l, ctn_jet th[2][3],
                        double R[3][3]);
void ctn_beam_energy(const ctn_beam_props *p, const ctn_jet *l, ctn_jet th[2][3], ctn_jet *U);
double ctn_beam_stretch(const ctn_beam_props *p, double l, const double t[2][3]);
void ctn_beam_dofs(const ctn_jet *U, double *f, double *K);
/* The kernel variable of each of the 12 DOFs (0..2 the chord x2 - x1, 3..5 and 6..8 the
 * ends' rotations) and its sign (-1 on node 1's translations). */
extern const int ctn_beam_dof_var[12];
extern const double ctn_beam_dof_sign[12];

/* A member with bending releases (p->rel & CTN_BEAM_REL_BEND), beam3_release.c: the
 * local rotations the energy takes, from the kinematics' th, into t: a rotation released
 * at both ends of an axis is 0, one released at one end -rho times the other end's
 * (rho = c1 / (2 c0): its bending moment 0, the static condensation of that end), the
 * others th's. */
void ctn_beam_condense(const ctn_beam_props *p, ctn_jet th[2][3], double t[2][3]);
/* The kernel of a member with bending releases: the energy of the condensed rotations,
 * its gradient and Hessian in the DOFs (ctn_beam_eval's contract). */
int ctn_beam_eval_released(const ctn_beam_props *p, unsigned mode, const double *X, const double *u, double *f,
                           double *K, ctn_elem_state *out);

/* The consistent nodal loads of a uniform load q per unstressed length (global, fixed)
 * on beam element e of the model, on its reference chord (beam3_model.c): forces F[a]
 * and moments M[a] at its nodes a = 0, 1: q L0 / 2 and +-(L0^2 / 12) e1 x q, with a
 * released end's moment condensed onto the other end and the shears. */
void ctn_beam_line_loads(const ctn_model *m, size_t e, const double q[3], double F[2][3], double M[2][3]);

/* Scalar functions of y = |v|^2 with their first two derivatives in y (beam3_fn.c):
 * the Rodrigues coefficients a = sin(t)/t and b = (1 - cos t)/t^2 of t = sqrt(y), and
 * the coefficient of the rotation log, asin(s)/s of s = sqrt(y) (y < 1). */
void ctn_beam_rod_a(double y, double f[3]);
void ctn_beam_rod_b(double y, double f[3]);
void ctn_beam_log_h(double y, double f[3]);

#endif
