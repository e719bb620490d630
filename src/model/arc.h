/* Internal: circular-arc placement of a chain of nodes between two points, sagging
 * along gravity, and the paper's Newton start (the concentric arc of larger radius).
 * Used by the `cable` generator and by the solver's pre-shaping of slack chains. */
#ifndef CTN_MODEL_ARC_H
#define CTN_MODEL_ARC_H

typedef struct ctn_arc {
    double mid[3], u[3], n[3];  /* chord midpoint, unit chord, unit sag direction */
    double chord;               /* chord length */
    double alpha;               /* half-angle of the arc (0: straight) */
    double R;                   /* radius (0 when straight) */
} ctn_arc;

/* Arc of length S >= chord from A to B, sagging along g's component normal to the
 * chord (S == chord: the straight chord, g unused). Returns 0, or -1 if g is zero or
 * parallel to the chord, or S < chord. */
int ctn_arc_make(const double A[3], const double B[3], const double g[3], double S,
                 ctn_arc *arc);
/* Point at fraction t in [0, 1] of the arc length; with delta > 0 also the
 * displacement that moves it radially onto the concentric arc of radius R (1 + delta). */
void ctn_arc_point(const ctn_arc *arc, double t, double delta, double X[3], double guess[3]);
/* delta such that a chord spanning the arc fraction dt is stretched by strain eps
 * relative to its arc length on the larger arc. */
double ctn_arc_delta(const ctn_arc *arc, double dt, double eps);

#endif
