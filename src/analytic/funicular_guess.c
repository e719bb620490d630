/* Funicular polygon: starting force for Newton's method. Joints are placed at their
 * unstressed arc-length fraction along the span; the vertical loads give the moments of
 * the simply supported beam, M(x) = H (chord - y)(x) for a cable, so H ~ M_max / sag
 * with the sag of a parabola of the same excess length, sqrt(3 C (sum L0 - C) / 8). */
#include "analytic/an.h"

#include <math.h>

typedef struct beam {
    double R_A;     /* left reaction of the simply supported beam [N] */
    double M_max;   /* largest |moment| at a joint [N m] */
    double P_abs;   /* sum of |P_k| [N] */
} beam;

/* Beam reaction and largest moment; downward load W = -Py at x = l * cum / Ltot. */
static beam beam_of(const ctn_funicular_in *in, double Ltot)
{
    beam b = {0.0, 0.0, 0.0};
    double cum = 0.0, SW = 0.0, SWx = 0.0;
    for (size_t k = 1; k < in->n && in->P; k++) {
        cum += in->L0[k - 1];
        double x = in->l * cum / Ltot, W = -in->P[2 * k - 1];
        b.R_A += W * (in->l - x) / in->l;
        b.P_abs += hypot(in->P[2 * k - 2], in->P[2 * k - 1]);
    }
    cum = 0.0;
    for (size_t k = 1; k < in->n && in->P; k++) {
        cum += in->L0[k - 1];
        double x = in->l * cum / Ltot, W = -in->P[2 * k - 1];
        b.M_max = fmax(b.M_max, fabs(b.R_A * x - x * SW + SWx)); /* sum_j<k W_j (x - x_j) */
        SW += W;
        SWx += W * x;
    }
    return b;
}

void ctn_an_funicular_guess(const ctn_funicular_in *in, double *F)
{
    double Ltot = 0.0, comp = 0.0, C = hypot(in->l, in->h);
    for (size_t i = 0; i < in->n; i++) {
        Ltot += in->L0[i];
        comp += in->EA ? in->L0[i] / in->EA[i] : 0.0;          /* sum L0 / EA */
    }
    beam b = beam_of(in, Ltot);
    double excess = Ltot - C, H = 0.0;
    if (excess > 0.0) H = b.M_max / fmin(sqrt(0.375 * C * excess), 0.5 * Ltot);
    if (excess < 0.0 && comp > 0.0) H = fmax(H, -excess / comp * in->l / C);
    if (!(H > 0.0) || !isfinite(H)) H = b.P_abs > 0.0 ? b.P_abs : 1.0;
    F[0] = H;
    F[1] = H * in->h / in->l - b.R_A;
}
