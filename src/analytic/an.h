/* Internal to the analytic module: root finder, stable special functions, quadrature,
 * argument checks. Prefix ctn_an_. */
#ifndef CTN_ANALYTIC_AN_H
#define CTN_ANALYTIC_AN_H

#include "catena/analytic.h"
#include "core/ctx.h"

/* A scalar function for the root finder: f(x) and f'(x) into *f, *df; returns a status
 * (anything but CTN_OK aborts the search and is passed on). */
typedef int (*ctn_an_fn)(void *data, double x, double *f, double *df);

/* Iteration limits. */
#define CTN_AN_MAXIT 300    /* safeguarded Newton/bisection iterations */
#define CTN_AN_MAXGROW 2200 /* bracket doublings/halvings (covers the double range) */

/* Safeguarded Newton-bisection (rtsafe). Requires f(lo) < 0 < f(hi) (not evaluated) and
 * lo < hi finite; x0 is the first iterate (midpoint if outside (lo, hi)). Stops when the
 * Newton step or the bracket is below 4 eps |x|. CTN_ERR_NOCONV after CTN_AN_MAXIT
 * iterations or if f is NaN. */
int ctn_an_root(ctn_an_fn fn, void *data, double lo, double hi, double x0, double *root);

/* Bracket a root of an increasing function of x > 0 starting from x0 > 0, by doubling
 * or halving: on CTN_OK f(*lo) < 0 < f(*hi) or *lo == *hi is a root. */
int ctn_an_bracket(ctn_an_fn fn, void *data, double x0, double *lo, double *hi);
/* ctn_an_bracket then ctn_an_root: the root of an increasing function of x > 0. */
int ctn_an_solve_pos(ctn_an_fn fn, void *data, double x0, double *root);

/* sinh(u)/u - 1 without cancellation (series for |u| < 1). */
double ctn_an_shc1(double u);
/* log(sinh(u)/u) for u >= 0, without overflow; its derivative into *d. */
double ctn_an_log_sinhc(double u, double *d);
/* asinh(p/H) - asinh(q/H) for H > 0 without cancellation; pmq = p - q, supplied by the
 * caller because it is often known more accurately than the difference of p and q. */
double ctn_an_asinh_diff(double H, double p, double q, double pmq);

/* Integrand callback for ctn_an_gauss: values of k functions at t into f[0..k-1]. */
typedef void (*ctn_an_integrand)(void *data, double t, double *f);
/* Integrals over [a, b] of k <= 4 functions by composite 10-point Gauss-Legendre with
 * panels no wider than hmax; results into out[0..k-1]. */
void ctn_an_gauss(ctn_an_integrand fn, void *data, int k, double a, double b, double hmax,
                  double *out);

/* Argument checks: CTN_OK, or CTN_ERR_INVALID with a message naming the argument. */
int ctn_an_check_pos(ctn_ctx *ctx, const char *what, const char *name, double v);
int ctn_an_check_finite(ctn_ctx *ctx, const char *what, const char *name, double v);
/* EA: > 0, finite or +INFINITY. */
int ctn_an_check_EA(ctn_ctx *ctx, const char *what, double EA);
/* 0 <= x <= xmax and finite (evaluation points). */
int ctn_an_in_range(double x, double xmax);

/* Fill the common summary fields from H and the two upward reactions. */
void ctn_an_reactions(ctn_analytic_summary *sum, double H, double V_left, double V_right);

/* Parabola (slope p = m - k (1 - 2x/l), m = h/l, k = q l / (2H)): exact stretched
 * length L(k) and dL/dk; unstressed length L0(H) and dL0/dH by quadrature. */
double ctn_an_parabola_length(double l, double m, double k);
double ctn_an_parabola_dlength(double l, double m, double k);
void ctn_an_parabola_length0(const ctn_parabola_in *in, double H, double *L0, double *dL0);

/* Funicular closure equation at the first-segment force F (see funicular_eq.c). */
typedef struct ctn_an_funicular_eq {
    double g[2];   /* closure residual sum l_i e_i - (l, h) [m] */
    double J[3];   /* its Jacobian (xx, xy, yy) [m/N] */
    double phi;    /* complementary energy [N m] */
    double phi_abs;/* sum of the magnitudes of its terms (its rounding scale) [N m] */
    double len;    /* sum of stretched lengths [m] */
    int slack;     /* 1 if a segment has zero force (g, J undefined) */
} ctn_an_funicular_eq;
void ctn_an_funicular_eval(const ctn_funicular_in *in, const double *F, ctn_an_funicular_eq *eq);
/* Joint coordinates xy[2(n+1)] and tensions N[n] for the force F. */
void ctn_an_funicular_shape(const ctn_funicular_in *in, const double *F, double *xy, double *N);
/* Smallest over largest segment force at F; the segment with the smallest into *imin. */
double ctn_an_funicular_slackest(const ctn_funicular_in *in, const double *F, size_t *imin);
/* At the kink F = Q_i (segment i slack, force zero, written to Q[2]): the closure gap
 * gap[2] = sum over the taut segments of l_j e_j - (l, h), and *allow = the total
 * length of the slack segments. |gap| <= *allow: the chain is in equilibrium with
 * segment i slack (Phi is minimal at the kink); otherwise -gap is a descent direction. */
void ctn_an_funicular_gap(const ctn_funicular_in *in, size_t i, double *Q, double *gap,
                          double *allow);
/* Solve for F[2] from the guess; iterations into *its. CTN_ERR_DOMAIN (with the slack
 * segment in *slack) if the minimum of Phi has a segment at zero force. */
int ctn_an_funicular_newton(const ctn_funicular_in *in, double *F, int *its, size_t *slack);
/* Starting force F[2] for Newton (beam analogy for V, sag from the excess length for H). */
void ctn_an_funicular_guess(const ctn_funicular_in *in, double *F);

/* Summaries of the solutions, from their solved parameters (one file each). */
int ctn_an_ecatenary_summary(ctn_ecatenary *cat);
void ctn_an_parabola_summary(ctn_parabola *par);
void ctn_an_funicular_summary(const ctn_funicular_in *in, const double *F, const double *xy,
                              const double *N, ctn_funicular *out);

#endif
