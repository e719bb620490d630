/* End releases of the corotational beam (beam3.c): a hinge about the local y or z axis
 * at an end frees that end's local rotation from the node's. The released rotation is
 * condensed out of the element's bending energy c0 (t1^2 + t2^2) + c1 t1 t2 (static
 * condensation in the corotated frame): its bending moment 2 c0 t_r + c1 t_other = 0
 * gives t_r = -rho t_other, rho = c1 / (2 c0) (1/2 for Euler-Bernoulli), and the energy
 * of beam3.c is taken with it:
 * - released at one end of an axis: t_r = -rho t_other, a linear function of the other
 *   end's local rotation, so the bending energy becomes (c0 - c1^2 / (4 c0)) t_other^2
 *   (3 EI / L for Euler-Bernoulli: the propped member) and the bowing that of the
 *   condensed shape (the released element's own geometric stiffness);
 * - released at both ends: t = 0 for both (no bending about that axis: a link);
 * - torsion released at either end: kt = 0 (beam3_model.c).
 * The energy stays a composition of jets over the DOFs, so the forces and the tangent
 * are its exact gradient and Hessian, in every state (tension or compression), and the
 * node's rotation about a released axis does no work on the element. */
#include "element/beam3.h"

/* The local rotations the energy takes, from the kinematics' th, into tr (jets). */
static void condensed(const ctn_beam_props *p, ctn_jet th[2][3], ctn_jet tr[2][3])
{
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) {
            int here = (p->rel >> (3 * a + k)) & 1, there = (p->rel >> (3 * (1 - a) + k)) & 1;
            double c0 = k == 1 ? p->cy0 : p->cz0, c1 = k == 1 ? p->cy1 : p->cz1;
            if (k == 0 || !here) tr[a][k] = th[a][k];
            else if (there) ctn_jet_const(&tr[a][k], 0);
            else ctn_jet_lin(&tr[a][k], -c1 / (2 * c0), &th[1 - a][k], 0, &th[1 - a][k]);
        }
}

void ctn_beam_condense(const ctn_beam_props *p, ctn_jet th[2][3], double t[2][3])
{
    ctn_jet tr[2][3];
    condensed(p, th, tr);
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) t[a][k] = tr[a][k].v;
}

int ctn_beam_eval_released(const ctn_beam_props *p, unsigned mode, const double *X, const double *u, double *f,
                           double *K, ctn_elem_state *out)
{
    ctn_jet l, th[2][3], tr[2][3], U;
    if (ctn_beam_kinematics(p, X, u, &l, th, NULL)) return 1;
    condensed(p, th, tr);
    ctn_beam_energy(p, &l, tr, &U);
    ctn_beam_dofs(&U, f, K);
    if (out) {
        double t[2][3];
        for (int a = 0; a < 2; a++)
            for (int k = 0; k < 3; k++) t[a][k] = tr[a][k].v;
        double eps = ctn_beam_stretch(p, l.v, t) / p->L0, N = p->EA * eps;
        *out = (ctn_elem_state){ l.v, eps, N, (mode & CTN_EVAL_STRESS) ? N / p->A : 0, U.v, 0 };
    }
    return 0;
}
