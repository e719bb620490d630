/* Elastic catenary: summary (reactions, sags, lengths, tension extremes). */
#include "analytic/an.h"

#include <math.h>

/* Sag d = h x / l - y at the point of unstressed coordinate s; x into *x. */
static double sag_at_s(const ctn_ecatenary *cat, double s, double *x)
{
    double y;
    ctn_ecatenary_point(cat, s, x, &y);
    return cat->in.h * *x / cat->in.l - y;
}

/* Stretched length L0 + (1/EA) int T ds, int T ds = [V T + H^2 asinh(V/H)] / (2w). */
static double stretched_length(const ctn_ecatenary *cat)
{
    double H = cat->H, Va = cat->V_left, Vb = cat->V_right, w = cat->in.w;
    double A = ctn_an_asinh_diff(H, Va, -Vb, w * cat->in.L0);
    double intT = (Va * hypot(H, Va) + Vb * hypot(H, Vb) + H * H * A) / (2.0 * w);
    return cat->in.L0 + intT / cat->in.EA;
}

static void tension_extremes(ctn_ecatenary *cat)
{
    ctn_analytic_summary *sum = &cat->sum;
    double H = cat->H, Ta = hypot(H, cat->V_left), Tb = hypot(H, cat->V_right), y;
    int right = Tb > Ta;
    sum->T_max = right ? Tb : Ta;
    sum->x_T_max = right ? cat->in.l : 0.0;
    if (cat->V_left >= 0.0 && cat->V_right >= 0.0) {   /* vertex on the cable */
        cat->s_T_min = fmin(cat->V_left / cat->in.w, cat->in.L0);
        sum->T_min = H;
        ctn_ecatenary_point(cat, cat->s_T_min, &sum->x_T_min, &y);
    } else {
        cat->s_T_min = right ? 0.0 : cat->in.L0;
        sum->T_min = right ? Ta : Tb;
        sum->x_T_min = right ? 0.0 : cat->in.l;
    }
}

int ctn_an_ecatenary_summary(ctn_ecatenary *cat)
{
    ctn_analytic_summary *sum = &cat->sum;
    double l = cat->in.l, s_mid, x_mid;
    ctn_an_reactions(sum, cat->H, cat->V_left, cat->V_right);
    double s = (cat->V_left + cat->H * cat->in.h / l) / cat->in.w; /* slope = chord slope */
    cat->s_sag = fmin(fmax(s, 0.0), cat->in.L0);
    sum->sag = sag_at_s(cat, cat->s_sag, &sum->x_sag);
    int st = ctn_ecatenary_s_at(cat, 0.5 * l, &s_mid);
    if (st != CTN_OK) return st;
    sum->sag_mid = sag_at_s(cat, s_mid, &x_mid);
    sum->length0 = cat->in.L0;
    sum->length = stretched_length(cat);
    tension_extremes(cat);
    return CTN_OK;
}
