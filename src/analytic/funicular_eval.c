/* Funicular polygon: evaluation on the joint coordinates, and the summary. */
#include "analytic/an.h"

#include <math.h>

/* First segment i whose x-range contains x; n if none. */
static size_t segment_at(size_t n, const double *xy, double x)
{
    for (size_t i = 0; i < n; i++) {
        double xa = xy[2 * i], xb = xy[2 * i + 2];
        if (fmin(xa, xb) <= x && x <= fmax(xa, xb)) return i;
    }
    return n;
}

int ctn_funicular_y(size_t n, const double *xy, double x, double *y)
{
    if (!xy || !y || !isfinite(x)) return CTN_ERR_INVALID;
    size_t i = segment_at(n, xy, x);
    if (i == n) return CTN_ERR_INVALID;
    double xa = xy[2 * i], xb = xy[2 * i + 2], ya = xy[2 * i + 1], yb = xy[2 * i + 3];
    *y = xb == xa ? ya : ya + (yb - ya) * (x - xa) / (xb - xa);
    return CTN_OK;
}

int ctn_funicular_tension(size_t n, const double *xy, const double *N, double x, double *T)
{
    if (!xy || !N || !T || !isfinite(x)) return CTN_ERR_INVALID;
    size_t i = segment_at(n, xy, x);
    if (i == n) return CTN_ERR_INVALID;
    *T = N[i];
    return CTN_OK;
}

/* Reactions: -F_0 on the left, F_{n-1} = F_0 - sum P on the right. */
static void reactions(const ctn_funicular_in *in, const double *F, ctn_analytic_summary *sum)
{
    double Fr[2] = {F[0], F[1]};
    for (size_t k = 0; in->P && k + 1 < in->n; k++) {
        Fr[0] -= in->P[2 * k];
        Fr[1] -= in->P[2 * k + 1];
    }
    sum->H = F[0];
    sum->reaction_left[0] = -F[0];
    sum->reaction_left[1] = -F[1];
    sum->reaction_right[0] = Fr[0];
    sum->reaction_right[1] = Fr[1];
}

/* Largest |chord - y| over the joints, lengths, tension extremes. */
static void scan(const ctn_funicular_in *in, const double *xy, const double *N,
                 ctn_funicular *out)
{
    ctn_analytic_summary *sum = &out->sum;
    for (size_t j = 0; j <= in->n; j++) {
        double d = in->h * xy[2 * j] / in->l - xy[2 * j + 1];
        if (fabs(d) > fabs(sum->sag)) { sum->sag = d; sum->x_sag = xy[2 * j]; }
    }
    for (size_t i = 0; i < in->n; i++) {
        sum->length += hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]);
        sum->length0 += in->L0[i];
        if (N[i] > N[out->i_T_max]) out->i_T_max = i;
        if (N[i] < N[out->i_T_min]) out->i_T_min = i;
    }
    sum->T_max = N[out->i_T_max];
    sum->x_T_max = 0.5 * (xy[2 * out->i_T_max] + xy[2 * out->i_T_max + 2]);
    sum->T_min = N[out->i_T_min];
    sum->x_T_min = 0.5 * (xy[2 * out->i_T_min] + xy[2 * out->i_T_min + 2]);
}

void ctn_an_funicular_summary(const ctn_funicular_in *in, const double *F, const double *xy,
                              const double *N, ctn_funicular *out)
{
    double y_mid;
    out->n = in->n;
    reactions(in, F, &out->sum);
    scan(in, xy, N, out);
    if (ctn_funicular_y(in->n, xy, 0.5 * in->l, &y_mid) == CTN_OK)
        out->sum.sag_mid = 0.5 * in->h - y_mid;
}
