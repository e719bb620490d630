/* Internal: the one definition of a cable's sag (docs/format.md, "cables"), shared by
 * the solution's cable results (post.c) and the compare module (src/compare/), so that
 * `catena solve` and `catena compare` report the same number. */
#ifndef CTN_SOLVE_SAG_H
#define CTN_SOLVE_SAG_H

#include "catena/model.h"

/* A chain of n elements in order from end node 0 to end node n, as the sag reads it. */
typedef struct ctn_sag_chain {
    size_t n;                                              /* elements; nodes 0..n */
    void (*point)(const void *ud, size_t j, double x[3]); /* current position of node j */
    int (*kink)(const void *ud, size_t j);                /* 1 if node j carries a
                                                              concentrated load; NULL: none */
    const void *ud;                                        /* for point and kink */
    double down[3];                                        /* unit "down" (ctn_sag_down) or 0 */
} ctn_sag_chain;

/* The sag:
 *   - with a "down" not along the chord: the mid-span sag, measured along down from the
 *     chord's mid-point M to the cable at the point whose projection on the plane normal
 *     to down is M's (positive below the chord). Between nodes the cable is read on the
 *     parabola through the three nodes nearest to mid-span (the nodes sample a curve
 *     under distributed loads), or on the straight element when the middle one of those
 *     nodes carries a concentrated load (a kink of the chain) or n == 1;
 *   - without a down, or with the chord along it (the horizontal part of the chord at
 *     most 1e-9 of its vertical part): ctn_sag_max_from_chord.
 * CTN_ERR_DOMAIN if the cable does not cross mid-span or a value is not finite. */
int ctn_sag_mid(const ctn_sag_chain *c, double *sag);
/* The largest distance of a node of the chain from the chord line through its ends
 * (the largest distance of the polyline, which is attained at a node); 0 for n == 1. */
double ctn_sag_max_from_chord(const ctn_sag_chain *c);

/* "Down" of a model: the unit gravity vector, or without gravity the unit vector along
 * the resultant of its concentrated loads (all steps), or zero. */
void ctn_sag_down(const ctn_model *m, double down[3]);
/* Total concentrated load (all `load`s of all steps, in model order) on node index i. */
void ctn_sag_node_load(const ctn_model *m, size_t i, double F[3]);
/* The same for every node at once: F[3 i + k], 3 * node count entries (linear time; the
 * sums are the same, bit for bit, as ctn_sag_node_load's). */
void ctn_sag_node_loads(const ctn_model *m, double *F);

#endif
