/* Funicular polygon: minimise the convex complementary energy Phi(F) (funicular_eq.c)
 * by Newton's method with a backtracking line search. A step is accepted when it
 * decreases Phi enough (Armijo) or, once Phi is flat to rounding near the solution, when
 * it decreases the residual g = grad Phi. Phi has kinks where a segment force F_i = F - Q_i
 * vanishes; Newton can be drawn into one, so near a kink the iteration either certifies
 * that the kink is the minimum (the segment is slack: no taut solution) or leaves it
 * along the steepest descent direction. */
#include "analytic/an.h"

#include <float.h>
#include <math.h>

#define FU_MAXIT 200
#define FU_MAXHALF 60
#define FU_KINK 1e-9    /* N_min / N_max below which the iterate is at a kink */

/* Newton direction d = -J^{-1} g; steepest descent scaled by the trace if J is singular. */
static void direction(const ctn_an_funicular_eq *eq, double *d)
{
    double a = eq->J[0], b = eq->J[1], c = eq->J[2], det = a * c - b * b, tr = a + c;
    if (det > 1e-14 * tr * tr && isfinite(det)) {
        d[0] = -(c * eq->g[0] - b * eq->g[1]) / det;
        d[1] = -(a * eq->g[1] - b * eq->g[0]) / det;
    } else {
        d[0] = -eq->g[0] / tr;
        d[1] = -eq->g[1] / tr;
    }
}

/* Evaluate at F0 + t d; 1 if usable (no zero force, finite). */
static int trial(const ctn_funicular_in *in, const double *F0, const double *d, double t,
                 double *Ft, ctn_an_funicular_eq *et)
{
    Ft[0] = F0[0] + t * d[0];
    Ft[1] = F0[1] + t * d[1];
    ctn_an_funicular_eval(in, Ft, et);
    return !et->slack && isfinite(et->phi) && isfinite(et->g[0]) && isfinite(et->g[1]);
}

/* Backtracking from the full Newton step; CTN_OK with F and eq updated. */
static int line_search(const ctn_funicular_in *in, double *F, ctn_an_funicular_eq *eq)
{
    double d[2], Ft[2], r0 = hypot(eq->g[0], eq->g[1]), t = 1.0;
    direction(eq, d);
    double slope = eq->g[0] * d[0] + eq->g[1] * d[1];         /* dPhi along d, < 0 */
    for (int k = 0; k < FU_MAXHALF; k++, t *= 0.5) {
        ctn_an_funicular_eq et;
        if (!trial(in, F, d, t, Ft, &et)) continue;
        int armijo = et.phi <= eq->phi + 1e-4 * t * slope;
        int flat = et.phi <= eq->phi + 1e-12 * eq->phi_abs;  /* Phi at its rounding floor */
        if (armijo || (flat && hypot(et.g[0], et.g[1]) <= (1.0 - 1e-4 * t) * r0)) {
            F[0] = Ft[0];
            F[1] = Ft[1];
            *eq = et;
            return CTN_OK;
        }
    }
    return CTN_ERR_NOCONV;
}

/* At the kink of segment i: CTN_ERR_DOMAIN if it is the minimum of Phi, else step from
 * F = Q_i along -gap, where Phi decreases at the rate |gap| - allow; the step starts at
 * the force scale fs and is halved until Armijo holds. */
static int leave_kink(const ctn_funicular_in *in, size_t i, double fs, double *F,
                      ctn_an_funicular_eq *eq)
{
    double Q[2], gap[2], allow, Ft[2];
    ctn_an_funicular_gap(in, i, Q, gap, &allow);
    double ng = hypot(gap[0], gap[1]);
    if (ng <= allow) return CTN_ERR_DOMAIN;
    double d[2] = {-gap[0] / ng, -gap[1] / ng};
    ctn_an_funicular_eq e0;
    ctn_an_funicular_eval(in, Q, &e0);                        /* Phi is finite at a kink */
    double t = fs + hypot(F[0], F[1]) + hypot(Q[0], Q[1]);
    for (int k = 0; k < FU_MAXHALF; k++, t *= 0.5) {
        ctn_an_funicular_eq et;
        if (trial(in, Q, d, t, Ft, &et) && et.phi <= e0.phi - 1e-4 * t * (ng - allow)) {
            F[0] = Ft[0];
            F[1] = Ft[1];
            *eq = et;
            return CTN_OK;
        }
    }
    return CTN_ERR_NOCONV;
}

/* What rounding leaves of the residual: the sum of n lengths, and F itself known to an
 * ulp, magnified by the Jacobian (large when a segment is nearly slack). */
static double residual_floor(const ctn_funicular_in *in, const double *F,
                             const ctn_an_funicular_eq *eq)
{
    double tr = eq->J[0] + eq->J[2];
    return 4.0 * DBL_EPSILON * (eq->len * (1.0 + sqrt((double)in->n)) + tr * hypot(F[0], F[1]));
}

int ctn_an_funicular_newton(const ctn_funicular_in *in, double *F, int *its, size_t *slack)
{
    ctn_an_funicular_eq eq;
    ctn_an_funicular_guess(in, F);
    ctn_an_funicular_eval(in, F, &eq);
    double fs = hypot(F[0], F[1]);                            /* force scale of the guess */
    for (*its = 0; *its < FU_MAXIT; (*its)++) {
        double r = hypot(eq.g[0], eq.g[1]), floor_r = residual_floor(in, F, &eq);
        int st;
        if (!eq.slack && r <= floor_r) return CTN_OK;
        double ratio = ctn_an_funicular_slackest(in, F, slack);   /* N_min / N_max */
        if (eq.slack || ratio < FU_KINK) {
            if ((st = leave_kink(in, *slack, fs, F, &eq)) != CTN_OK) return st;
            continue;
        }
        if (line_search(in, F, &eq) != CTN_OK) return r <= 16.0 * floor_r ? CTN_OK : CTN_ERR_NOCONV;
        if (hypot(eq.g[0], eq.g[1]) >= r && r <= 16.0 * floor_r) return CTN_OK; /* stalled */
    }
    return CTN_ERR_NOCONV;
}
