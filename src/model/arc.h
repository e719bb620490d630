/* Internal: circular-arc placement of a chain of nodes between two points, sagging
 * along gravity, and the Newton start (the stretched arc through the same ends).
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
/* Point at fraction t in [0, 1] of the arc length. */
void ctn_arc_point(const ctn_arc *arc, double t, double X[3]);
/* The stretched start: the arc through the same ends, sagging the same way, on which a
 * chord spanning the fraction dt of the arc is longer than dt * S by the factor
 * (1 + eps), S the length of `arc`. Returns 0, or -1 as ctn_arc_make. */
int ctn_arc_stretched(const ctn_arc *arc, const double A[3], const double B[3],
                      const double g[3], double S, double dt, double eps, ctn_arc *out);

#endif
