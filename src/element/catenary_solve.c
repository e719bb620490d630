/* The elastic catenary's compatibility equations solved for H and Vb, nested as in the
 * closed-form solution (analytic/ecatenary.c) but for any chord, a vertical one
 * included: at fixed H, h(H, Vb) is increasing in Vb (dh/dVb = F_VV > 0), a bracketed
 * root; with Vb = Vb(H), l(H) is increasing in H (dl/dH = F_HH - F_HV^2 / F_VV, the Schur
 * complement of the positive definite flexibility), a second bracketed root from a
 * parabolic start. Both are safeguarded Newton iterations (ctn_an_root) that stop at
 * the resolution of their unknown; a vertical chord has H = 0. */
#include "analytic/an.h"
#include "element/catenary.h"

#include <float.h>
#include <math.h>

typedef struct ecat_solve {
    ctn_ecat *c;
    double lt, ht;          /* the chord to reach */
    double Vb;              /* the last inner root (a warm start) */
} ecat_solve;

/* h(H, Vb) - ht and F_VV at the current c->H. */
static int h_equation(void *data, double Vb, double *f, double *df)
{
    ecat_solve *e = data;
    double l, h;
    e->c->Vb = Vb;
    ctn_ecat_law(e->c, &l, &h);
    *f = h - e->ht;
    *df = e->c->Fvv;
    return CTN_OK;
}

/* Vb at H: D = Vb - Va = 2 Vb - W has the sign of h and |D| <= 2 EA |h| / L (the
 * elastic term alone), |D| <= |h| (2 H + W) / (L - |h|) when |h| < L. */
static int solve_vb(ecat_solve *e, double H)
{
    ctn_ecat *c = e->c;
    double ah = fabs(e->ht), Dmax = 2 * c->EA * ah / c->L, l, h;
    c->H = H;
    if (ah < c->L) Dmax = fmin(Dmax, ah * (2 * H + c->W) / (c->L - ah));
    if (!isfinite(Dmax)) return CTN_ERR_NOCONV;
    double lo = 0.5 * c->W, hi = 0.5 * (c->W + Dmax);
    if (e->ht < 0) { hi = lo; lo = 0.5 * (c->W - Dmax); }
    int rc = CTN_OK;
    if (e->ht != 0 && lo < hi) rc = ctn_an_root(h_equation, e, lo, hi, e->Vb, &e->Vb);
    else e->Vb = 0.5 * c->W;
    c->Vb = e->Vb;
    ctn_ecat_law(c, &l, &h);                           /* the flexibility at the root */
    return rc;
}

/* l(H, Vb(H)) - lt and its total derivative. */
static int l_equation(void *data, double H, double *f, double *df)
{
    ecat_solve *e = data;
    int rc = solve_vb(e, H);
    if (rc) return rc;
    double l, h;
    ctn_ecat_law(e->c, &l, &h);
    *f = l - e->lt;
    *df = e->c->Fhh - e->c->Fhv * e->c->Fhv / e->c->Fvv;
    if (!isfinite(*df)) *df = INFINITY;                /* H -> 0 with a fold: no step */
    return CTN_OK;
}

/* A start for H: the parabola of the excess length when slack, the bar when taut. */
static double start_h(const ctn_ecat *c)
{
    double C = hypot(c->l, c->h), H;
    if (c->L > C) {
        double d = sqrt(3 * C * (c->L - C) / 8);       /* sag from L = C + 8 d^2 / (3 C) */
        H = c->W * c->l * c->l / (8 * d * C);
    } else {
        H = (c->EA * (C / c->L - 1) + 0.5 * c->W) * c->l / C;
    }
    return H > 0 && isfinite(H) ? H : 1e-3 * c->W;
}

/* The fast path: Newton on both equations at once, F (dH, dVb) = -(l - lt, h - ht), from
 * the start's H and the parabola's Vb - Va = 2 H h / l; 1 unless it reached the
 * resolution of H and Vb with H > 0 within NEWTON2_MAXIT steps (then the nested roots
 * decide). */
#define NEWTON2_MAXIT 30
static int newton2(ctn_ecat *c)
{
    double lt = c->l, ht = c->h, l, h;
    c->H = start_h(c);
    c->Vb = 0.5 * c->W + c->H * ht / lt;
    for (int it = 0; it < NEWTON2_MAXIT; it++) {
        ctn_ecat_law(c, &l, &h);
        double rl = l - lt, rh = h - ht, det = c->Fhh * c->Fvv - c->Fhv * c->Fhv;
        double dH = (-c->Fvv * rl + c->Fhv * rh) / det, dV = (c->Fhv * rl - c->Fhh * rh) / det;
        if (!isfinite(dH) || !isfinite(dV)) return 1;
        double H = c->H + dH;
        if (!(H > 0.0)) H = 0.5 * c->H;                /* keep H positive: halve it */
        int done = fabs(dH) <= 8 * DBL_EPSILON * c->H && fabs(dV) <= 8 * DBL_EPSILON * fmax(fabs(c->Vb), c->W);
        c->H = H;
        c->Vb += dV;
        if (done) {
            ctn_ecat_law(c, &l, &h);                   /* the flexibility at the root */
            c->l = lt;
            c->h = ht;
            return !(isfinite(c->Fhh) && isfinite(c->Fvv));
        }
    }
    return 1;
}

int ctn_ecat_solve(ctn_ecat *c)
{
    ecat_solve e = { c, c->l, c->h, 0.5 * c->W };
    int rc;
    if (c->l > 0 && !newton2(c)) return CTN_OK;
    c->l = e.lt;
    c->h = e.ht;
    if (c->l > 0) {
        double H;
        rc = ctn_an_solve_pos(l_equation, &e, start_h(c), &H);
        if (!rc) rc = solve_vb(&e, H);
    } else {
        rc = solve_vb(&e, 0.0);                        /* vertical chord: H = 0 */
    }
    if (!rc && !(isfinite(c->H) && isfinite(c->Vb) && isfinite(c->Fvv))) rc = CTN_ERR_NOCONV;
    return rc;
}

/* x(s) - l/2 and dx/ds = H (1 / EA + 1 / T(s)). */
static int mid_equation(void *data, double s, double *f, double *df)
{
    const ctn_ecat *c = data;
    double x, z;
    ctn_ecat_point(c, s, &x, &z);
    *f = x - 0.5 * c->l;
    *df = c->H * (1 / c->EA + 1 / hypot(c->H, c->Va - c->W / c->L * s));
    return CTN_OK;
}

double ctn_ecat_sag(const ctn_ecat *c)
{
    double s, x, z;
    if (!(c->H > 0) || !(c->l > 0)) return 0;
    if (ctn_an_root(mid_equation, (void *)c, 0, c->L, 0.5 * c->L, &s)) return NAN;
    ctn_ecat_point(c, s, &x, &z);
    return 0.5 * c->h - z;
}

double ctn_ecat_max_sag(const ctn_ecat *c)
{
    double x, z;
    if (!(c->H > 0) || !(c->l > 0) || !(c->W > 0)) return 0;
    double s = (c->Va + c->H * c->h / c->l) * (c->L / c->W);   /* V(s) = Va - (W / L) s */
    ctn_ecat_point(c, fmin(fmax(s, 0), c->L), &x, &z);
    return x * (c->h / c->l) - z;
}
