/*
 * catena/analytic.h - closed-form solutions of single cables (reference solutions).
 *
 * Four problems, one prefix each:
 *   ctn_catenary_*   inextensible catenary of given length under its own weight
 *   ctn_ecatenary_*  elastic catenary (Irvine): given unstressed length and EA
 *   ctn_parabola_*   cable under a load q per unit horizontal length, inextensible or elastic
 *   ctn_funicular_*  weightless chain of straight segments with point loads at the joints
 *
 * Conventions (all four):
 *   - plane problem, supports at (0, 0) and (l, h); x horizontal, y up, gravity along -y;
 *     l > 0, h of any sign (inclined spans are supported everywhere);
 *   - SI units are suggested ([m], [N]) but any consistent set works;
 *   - "tension" is the true axial force N of the (stretched) cable, >= 0;
 *   - H is the horizontal component of the cable force (> 0); for the catenaries and the
 *     parabola it is constant along the cable;
 *   - reactions are the forces exerted BY the supports ON the cable, in global axes:
 *     reaction_left = (-H, V_left), reaction_right = (+H, V_right) for a cable with
 *     vertical loads only; V_left + V_right = total vertical load;
 *   - "EA = INFINITY" (from <math.h>) means inextensible wherever an EA is accepted.
 *
 * Status codes (catena/core.h):
 *   CTN_OK           success, every output field finite;
 *   CTN_ERR_INVALID  a NULL pointer, a non-finite number or an argument out of range
 *                    (l <= 0, w <= 0, EA <= 0, evaluation point outside the cable, ...);
 *   CTN_ERR_DOMAIN   no solution exists (inextensible length <= chord, slack chain, ...);
 *   CTN_ERR_NOCONV   the safeguarded root finder hit its iteration limit (never silent).
 * On any failure the output structure is zeroed (never NaN). The solve functions record a
 * message in ctx when ctx is not NULL (ctx may be NULL: then only the status is returned).
 * No function allocates memory; arrays are owned by the caller.
 */
#ifndef CATENA_ANALYTIC_H
#define CATENA_ANALYTIC_H

#include <stddef.h>

#include "catena/core.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* ---------------------------------------------------------------------------------------
 * Summary shared by every solution.
 * "Sag" is measured vertically from the chord (the straight line between the supports)
 * down to the cable: d(x) = h x / l - y(x), positive when the cable is below the chord.
 * ------------------------------------------------------------------------------------- */
typedef struct ctn_analytic_summary {
    double H;                 /* horizontal force in the cable at the left support [N] */
    double reaction_left[2];  /* force of the left support on the cable (x, y) [N] */
    double reaction_right[2]; /* force of the right support on the cable (x, y) [N] */
    double sag;               /* d(x) of largest magnitude over [0, l] (signed) [m] */
    double x_sag;             /* x where sag occurs [m] */
    double sag_mid;           /* mid-span sag d(l / 2) [m] */
    double length;            /* stressed (current) length of the cable [m] */
    double length0;           /* unstressed length [m]; equals length when inextensible */
    double T_max;             /* largest tension [N] */
    double x_T_max;           /* x where T_max occurs [m] */
    double T_min;             /* smallest tension [N] */
    double x_T_min;           /* x where T_min occurs [m] */
} ctn_analytic_summary;

/* ---------------------------------------------------------------------------------------
 * Inextensible catenary of length S and weight w per unit length.
 * With the catenary parameter c = H / w and the vertex at (x_v, y_v) the cable is
 *     y(x) = y_v + c (cosh((x - x_v) / c) - 1),  T(x) = H cosh((x - x_v) / c),
 * i.e. the paper's s = c sinh(x/c), y = c cosh(x/c), T0 = w c, T = w y in vertex axes.
 * c solves sqrt(S^2 - h^2) = 2 c sinh(l / (2c)); exists iff S > sqrt(l^2 + h^2).
 * ------------------------------------------------------------------------------------- */
typedef struct ctn_catenary_in {
    double l; /* horizontal span, finite, > 0 [m] */
    double h; /* height of the right support above the left, finite, any sign [m] */
    double w; /* weight per unit length, finite, > 0 [N/m] */
    double S; /* cable length, finite, > chord sqrt(l^2 + h^2) [m] */
} ctn_catenary_in;

typedef struct ctn_catenary {
    ctn_catenary_in in;       /* copy of the input */
    double c;                 /* catenary parameter H / w [m] */
    double u;                 /* l / (2 c), dimensionless */
    double m;                 /* atanh(h / S): slope at x is sinh((x - l/2) / c + m) */
    double x_vertex;          /* x of the vertex (lowest point of the whole curve; may lie
                                 outside [0, l] on inclined spans) = l/2 - c m [m] */
    ctn_analytic_summary sum; /* forces, sags, lengths, tension extremes */
} ctn_catenary;

/* Solve the catenary. Inputs in *in (CTN_ERR_INVALID if out of range, CTN_ERR_DOMAIN if
 * S <= chord). Result in *out. */
int ctn_catenary_solve(ctn_ctx *ctx, const ctn_catenary_in *in, ctn_catenary *out);
/* Height y(x) of the cable above the left support at 0 <= x <= l [m]. */
int ctn_catenary_y(const ctn_catenary *cat, double x, double *y);
/* Sag d(x) = h x / l - y(x) at 0 <= x <= l, evaluated without cancellation [m]. */
int ctn_catenary_sag(const ctn_catenary *cat, double x, double *d);
/* Tension T(x) at 0 <= x <= l [N]. */
int ctn_catenary_tension(const ctn_catenary *cat, double x, double *T);
/* Arc length s(x) from the left support to abscissa 0 <= x <= l [m]. */
int ctn_catenary_arc(const ctn_catenary *cat, double x, double *s);

/* ---------------------------------------------------------------------------------------
 * Elastic catenary (Irvine), engineering strain: an element ds0 of unstressed length
 * stretches to ds0 (1 + T / EA). s in [0, L0] is the unstressed arc coordinate from the
 * left support, V the upward reaction at the left support:
 *     x(s) = H s / EA + (H / w) [asinh(V / H) - asinh((V - w s) / H)]
 *     y(s) = -(V s - w s^2 / 2) / EA - (1 / w) [sqrt(H^2 + V^2) - sqrt(H^2 + (V - w s)^2)]
 *     T(s) = sqrt(H^2 + (V - w s)^2)
 * H and V solve x(L0) = l, y(L0) = h. A solution exists for every L0 > 0 when EA is
 * finite (also L0 < chord: a taut, stretched cable); EA = INFINITY requires L0 > chord.
 * ------------------------------------------------------------------------------------- */
typedef struct ctn_ecatenary_in {
    double l;  /* horizontal span, finite, > 0 [m] */
    double h;  /* height of the right support above the left, finite [m] */
    double w;  /* weight per unit UNSTRESSED length, finite, > 0 [N/m] */
    double EA; /* axial stiffness, > 0, finite or INFINITY (inextensible) [N] */
    double L0; /* unstressed length, finite, > 0 [m] */
} ctn_ecatenary_in;

typedef struct ctn_ecatenary {
    ctn_ecatenary_in in;      /* copy of the input */
    double H;                 /* horizontal force [N] */
    double V_left;            /* upward reaction at the left support (V above) [N] */
    double V_right;           /* upward reaction at the right support, w L0 - V_left [N] */
    double s_T_min;           /* unstressed arc coordinate where T_min occurs [m] */
    double s_sag;             /* unstressed arc coordinate where sum.sag occurs [m] */
    ctn_analytic_summary sum; /* forces, sags, lengths, tension extremes */
} ctn_ecatenary;

/* Solve the elastic catenary (see the block comment above). */
int ctn_ecatenary_solve(ctn_ctx *ctx, const ctn_ecatenary_in *in, ctn_ecatenary *out);
/* Position (x, y) [m] of the material point at unstressed arc coordinate 0 <= s <= L0.
 * x(L0) equals l to rounding and may exceed it by an ulp: clamp before passing it on. */
int ctn_ecatenary_point(const ctn_ecatenary *cat, double s, double *x, double *y);
/* Tension [N] at unstressed arc coordinate 0 <= s <= L0. */
int ctn_ecatenary_tension_s(const ctn_ecatenary *cat, double s, double *T);
/* Unstressed arc coordinate s of the point with abscissa 0 <= x <= l (root finder). */
int ctn_ecatenary_s_at(const ctn_ecatenary *cat, double x, double *s);
/* Height y(x) [m] of the cable at abscissa 0 <= x <= l. */
int ctn_ecatenary_y(const ctn_ecatenary *cat, double x, double *y);
/* Tension T(x) [N] at abscissa 0 <= x <= l. */
int ctn_ecatenary_tension(const ctn_ecatenary *cat, double x, double *T);

/* ---------------------------------------------------------------------------------------
 * Parabolic cable: load q per unit HORIZONTAL length (any stretch leaves it unchanged), so
 *     y(x) = h x / l - q x (l - x) / (2 H),    T(x) = H sqrt(1 + y'(x)^2),
 * for level and inclined spans. The sag is q l^2 / (8 H) at x = l/2.
 * Inextensible (EA = INFINITY): L0 is the length, closed form, requires L0 > chord.
 * Elastic (finite EA, engineering strain): L0 is the unstressed length,
 *     L0 = integral over the cable of ds / (1 + T / EA),
 * evaluated by composite 10-point Gauss-Legendre quadrature in theta = asinh(y'), panels
 * of width <= 0.5, converged to rounding (see docs/analytic.md).
 * ------------------------------------------------------------------------------------- */
typedef struct ctn_parabola_in {
    double l;  /* horizontal span, finite, > 0 [m] */
    double h;  /* height of the right support above the left, finite [m] */
    double q;  /* load per unit horizontal length, downward, finite, > 0 [N/m] */
    double L0; /* length (inextensible) or unstressed length (elastic), finite, > 0 [m] */
    double EA; /* axial stiffness, > 0, finite or INFINITY (inextensible) [N] */
} ctn_parabola_in;

typedef struct ctn_parabola {
    ctn_parabola_in in;       /* copy of the input */
    double H;                 /* horizontal force [N] */
    ctn_analytic_summary sum; /* forces, sags, lengths, tension extremes */
} ctn_parabola;

/* Solve the parabolic cable. CTN_ERR_DOMAIN if EA = INFINITY and L0 <= chord. */
int ctn_parabola_solve(ctn_ctx *ctx, const ctn_parabola_in *in, ctn_parabola *out);
/* Height y(x) [m] at 0 <= x <= l. */
int ctn_parabola_y(const ctn_parabola *par, double x, double *y);
/* Tension T(x) [N] at 0 <= x <= l. */
int ctn_parabola_tension(const ctn_parabola *par, double x, double *T);

/* ---------------------------------------------------------------------------------------
 * Funicular polygon: a weightless chain of n straight segments from joint 0 = (0, 0) to
 * joint n = (l, h), with a point load P_k = (Px, Py) on each interior joint k = 1..n-1.
 * Segment i joins joints i and i+1; its stretched length is L0_i (1 + N_i / EA_i)
 * (engineering strain; L0_i when inextensible). Unknown: the force F_0 = (H, -V_left)
 * that segment 0 exerts on the left support; then F_i = F_0 - (P_1 + ... + P_i),
 * N_i = |F_i|, and the chain must close on (l, h). Solved by Newton's method on the 2x2
 * system (the gradient of a convex complementary energy) with a backtracking line search.
 * An equilibrium in which a segment is slack (zero force) has no taut solution and gives
 * CTN_ERR_DOMAIN: inextensible chains not longer than the chord and unloaded chains are
 * rejected up front, other slack equilibria are detected (and certified) by the solver.
 * ------------------------------------------------------------------------------------- */
typedef struct ctn_funicular_in {
    double l;          /* horizontal span, finite, > 0 [m] */
    double h;          /* height of the right support above the left, finite [m] */
    size_t n;          /* number of segments, >= 1 (n - 1 loaded joints) */
    const double *L0;  /* [n] unstressed segment lengths, finite, > 0 [m] */
    const double *EA;  /* [n] axial stiffness per segment, > 0 or INFINITY [N];
                          NULL: all segments inextensible */
    const double *P;   /* [2 (n - 1)] loads (Px, Py) of joints 1..n-1, interleaved;
                          y up, so gravity loads have Py < 0 [N]; NULL: no loads */
} ctn_funicular_in;

typedef struct ctn_funicular {
    size_t n;                 /* number of segments */
    size_t i_T_max;           /* segment carrying sum.T_max */
    size_t i_T_min;           /* segment carrying sum.T_min */
    int iterations;           /* Newton iterations used */
    ctn_analytic_summary sum; /* forces, sags, lengths, tension extremes; x_T_max and
                                 x_T_min are the mid-points of those segments, the sag is
                                 taken over the joints (where a polygon's extremes are);
                                 sum.H is the horizontal force in segment 0 (constant
                                 along the chain when every Px is 0) */
} ctn_funicular;

/* Solve the chain. Outputs, owned by the caller (xy and N are written only on success):
 *   xy [2 (n + 1)]  joint coordinates x0, y0, x1, y1, ..., xn, yn [m] (supports included;
 *                   (xn, yn) = (l, h) to the rounding floor of the closure, ~1e-15
 *                   relative unless a segment is nearly slack);
 *   N  [n]          segment tensions [N];
 *   *out            summary. */
int ctn_funicular_solve(ctn_ctx *ctx, const ctn_funicular_in *in, double *xy, double *N,
                        ctn_funicular *out);
/* Height y(x) [m] of the polygon xy (n segments, as returned by ctn_funicular_solve) at
 * abscissa x, on the first segment whose x-range contains x; CTN_ERR_INVALID if none. */
int ctn_funicular_y(size_t n, const double *xy, double x, double *y);
/* Tension [N] at abscissa x: N of the first segment whose x-range contains x. */
int ctn_funicular_tension(size_t n, const double *xy, const double *N, double x, double *T);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
