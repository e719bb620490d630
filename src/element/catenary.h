/* Internal: Irvine's elastic catenary as an element kernel (catenary_law.c,
 * catenary_solve.c) and the family's properties (catenary2.c).
 *
 * A cable of unstressed length L, axial rigidity EA (engineering strain, T = EA (lambda
 * - 1)) and total weight W = w L along gravity, between node 1 and node 2. In the plane
 * of the chord and gravity, with "up" opposite gravity: l >= 0 the horizontal and h the
 * upward component of the chord x2 - x1. H >= 0 is the horizontal tension, Va and Vb
 * the upward forces of the supports on the cable at nodes 1 and 2 (Va + Vb = W); along
 * the unstressed coordinate s the vertical tension is V(s) = Va - (W / L) s and
 * T(s) = sqrt(H^2 + V(s)^2). The compatibility equations (docs/theory.md):
 *   l = H L / EA + H L m1,            m1 = mean of 1 / T over V in [-Vb, Va]
 *   h = L (Vb - Va) [1 / (2 EA) + 1 / (Ta + Tb)]
 * and the flexibility F = d(l, h) / d(H, Vb) (Va = W - Vb):
 *   F_HH = L / EA + L m2,  F_HV = L H (Va - Vb) / (Ta Tb (Ta + Tb)),  F_VV = L / EA + L m3,
 * m2, m3 the means of V^2 / T^3 and H^2 / T^3. Every mean is written without a division
 * by W that cancels, so that W -> 0 tends to the straight bar. */
#ifndef CTN_ELEMENT_CATENARY_H
#define CTN_ELEMENT_CATENARY_H

#include "element/element.h"

/* A solved catenary. */
typedef struct ctn_ecat {
    double L, EA, W;        /* unstressed length, axial rigidity, total weight (> 0) */
    double l, h;            /* horizontal (>= 0) and upward chord */
    double H, Va, Vb;       /* horizontal tension, upward support forces at nodes 1, 2 */
    double Fhh, Fhv, Fvv;   /* flexibility d(l, h) / d(H, Vb) */
} ctn_ecat;

/* The chord (l, h) and flexibility of c->H, c->Vb (c->Va = W - Vb set here). */
void ctn_ecat_law(ctn_ecat *c, double *l, double *h);
/* Solve the compatibility equations for H, Va, Vb from c->L, EA, W, l, h (W > 0) by
 * safeguarded Newton steps to round-off; the flexibility at the solution is in c.
 * CTN_OK, or CTN_ERR_NOCONV if no finite solution was found. */
int ctn_ecat_solve(ctn_ecat *c);
/* Stored energy: elastic plus the weight's potential relative to the chord's mid-height,
 * U = H l + (Vb - Va) h / 2 - C(H, Vb), C the complementary energy (docs/theory.md). */
double ctn_ecat_energy(const ctn_ecat *c);
/* Point at unstressed coordinate s in [0, L] relative to node 1: horizontal (along the
 * horizontal chord) and upward components. */
void ctn_ecat_point(const ctn_ecat *c, double s, double *x, double *z);
/* Stretched length L + (1 / EA) int T ds. */
double ctn_ecat_length(const ctn_ecat *c);
/* Sag: the distance along gravity from the chord's mid-point down to the cable at
 * mid-span (horizontal coordinate l / 2); 0 for a vertical chord (H = 0). */
double ctn_ecat_sag(const ctn_ecat *c);
/* The largest distance along gravity below the chord at the same horizontal position:
 * at the point whose slope is the chord's, V(s) = -H h / l; 0 for a vertical chord. */
double ctn_ecat_max_sag(const ctn_ecat *c);

/* Properties of a catenary element (catenary2.c). */
typedef struct ctn_catenary_props {
    double EA;          /* axial rigidity [force] */
    double l0;          /* unstressed length [length] (after any temperature change) */
    double A;           /* area [length^2], for the stress */
    double W;           /* total weight w l0_ref |g| [force] (constant) */
    double up[3];       /* unit vector opposite gravity (zero without weight) */
    double l0_ref;      /* unstressed length at the reference temperature */
    double alpha;       /* thermal expansion coefficient [1/K] */
    double mass;        /* m' l0_ref [force s^2/length]; NAN when the model cannot tell */
} ctn_catenary_props;

/* The solved catenary (or bar, W = 0) of element props at X + u, in c, with the unit
 * horizontal chord ex and the up vector; returns 0, 1 if the chord collapsed or the
 * solve failed. *bar = 1 when there is no weight (then c holds only l, h, and the bar's
 * tension is EA (|chord| / L - 1), 0 when slack). */
int ctn_catenary_state(const ctn_catenary_props *p, const double *X, const double *u,
                       ctn_ecat *c, double ex[3], int *bar);

/* prestress_l0 of the catenary family (catenary_prestress.c): N0 is its largest end
 * tension in the reference chord. */
int ctn_catenary_prestress_l0(const ctn_model *m, const ctn_element *e, int kind, double v, double l, double *l0);

#endif
