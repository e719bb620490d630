/* Internal: the elastic-catenary Newton start of a generated cable (cable_start.c). */
#ifndef CTN_MODEL_CABLE_START_H
#define CTN_MODEL_CABLE_START_H

#include "catena/analytic.h"

typedef struct ctn_catenary_place {
    ctn_ecatenary cat;        /* the solved span */
    double A[3];              /* left end */
    double up[3], along[3];   /* unit vectors: against gravity; horizontal along the span */
    int n;                    /* elements */
} ctn_catenary_place;

/* Solve the span A-B (gravity g, weight w per unstressed length, rigidity EA, unstressed
 * length S, n elements): the elastic catenary of length S, lengthened where needed so
 * that every chord of its n-gon is longer than S/n by the strain eps (on coarse meshes
 * the polygon's chords are shorter than its arcs). 0, or -1 when there is no catenary
 * to start from (no weight, vertical chord, no solution); the caller then uses the arc. */
int ctn_catenary_start(ctn_ctx *ctx, const double A[3], const double B[3], const double g[3],
                       double w, double EA, double S, int n, double eps, ctn_catenary_place *out);
/* Position of interior node k (unstressed arc coordinate k S / n). */
void ctn_catenary_start_point(const ctn_catenary_place *p, int k, double X[3]);

#endif
