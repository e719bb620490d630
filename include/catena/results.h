/*
 * catena/results.h - a solution's results per load step: nodes, elements, catenary and
 * beam elements, groups, utilisation (split from catena/solve.h, which includes it; a
 * program includes catena.h or catena/solve.h, not this header alone).
 */
#ifndef CATENA_RESULTS_H
#define CATENA_RESULTS_H

#include <stddef.h>

#include "catena/core.h"
#include "catena/model.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

typedef struct ctn_solution ctn_solution;

/* Results per load step (ctn_model_step_count, or the arc-length steps): the same
 * quantities as above, at the end of step k. A step that did not converge holds its
 * last converged state. */
typedef struct ctn_step_result {
    const char *name;     /* step name ("" for the implicit step; "arc N" for arc-length) */
    ctn_reason reason;
    double load_factor;   /* t reached (1 = the whole step) or arc-length load factor */
    int iterations;       /* Newton iterations spent in the step */
    const double *d;      /* displacements, 3 per node */
    const double *react;  /* reactions, 3 per node */
} ctn_step_result;
size_t ctn_solution_step_count(const ctn_solution *s);
/* The results of the model's load cases then combinations (ctn_model_case_info), each a
 * solution of one step (its state, elements and summary: converged or why not); the
 * count is 0 when the steps did not converge. Owned by s. */
size_t ctn_solution_case_count(const ctn_solution *s);
const ctn_solution *ctn_solution_case(const ctn_solution *s, size_t i);
int ctn_solution_step(const ctn_solution *s, size_t k, ctn_step_result *out);
int ctn_solution_step_element(const ctn_solution *s, size_t k, size_t i, ctn_element_state *out);

/* A catenary element at the state of step k (docs/format.md, "catenary"): its forces
 * solved from the chord, in the plane of the chord and gravity. */
typedef struct ctn_catenary_result {
    size_t size;          /* sizeof(ctn_catenary_result), set by the caller */
    double H;             /* horizontal component of the tension (normal to gravity) [force] */
    double tension[2];    /* tension at its first and last node [force] */
    double force[2][3];   /* the force the cable applies to its first and last node (along
                             its tangent there; the two sum to its weight) [force] */
    double V[2];          /* upward component of the support forces on the cable at the
                             first and last node (V[0] + V[1] = its weight) [force] */
    double sag;           /* the distance along gravity from the mid-point of the chord down
                             to the cable at mid-span (half the horizontal span); 0 for a
                             vertical chord or a weightless member [length] */
    double length;        /* stretched length [length] */
} ctn_catenary_result;
/* Element i (a "catenary") at the end of step k. CTN_ERR_INVALID if i is not a catenary
 * or k, i are out of range; CTN_ERR_NOCONV if its compatibility equations have no
 * solution at that state (a collapsed chord). The caller sets out->size. */
int ctn_solution_catenary(const ctn_model *m, const ctn_solution *s, size_t k, size_t i,
                          ctn_catenary_result *out);
/* A beam element at the state of step k (docs/format.md, "beam"): the forces and
 * moments its two nodes apply to it, in its current local axes (x along the chord, y
 * and z the corotated section axes): end[a] = (Fx, Fy, Fz, Mx, My, Mz) at its first
 * (a = 0) and second node, the stiffness method's end forces; N = end[1][0] its axial
 * tension, T = end[1][3] its torque. */
typedef struct ctn_beam_result {
    size_t size;          /* sizeof(ctn_beam_result), set by the caller */
    double end[2][6];     /* end forces [force] and moments [force length], local axes */
    double N;             /* axial tension [force] */
    double T;             /* torque about the member's axis [force length] */
    double M_max;         /* the largest bending moment hypot(My, Mz) along the element: the
                             larger end's, or inside under a uniform load [force length] */
    double stress;        /* the largest combined stress |N| / A + |My| / Wy + |Mz| / Wz along
                             the element (N, My, Mz at the same section), 0 when its section
                             has no Wy, Wz [force/length^2] */
    double fy;            /* its material's yield stress, 0 if not given [force/length^2] */
    double utilisation;   /* stress / fy, 0 without fy */
} ctn_beam_result;
/* The beam element of the largest utilisation (ctn_beam_result.utilisation) at the end of
 * step k: its index in *e and its result in *out (out->size set by the caller);
 * CTN_ERR_INVALID when no beam's material has fy. */
int ctn_solution_worst_beam(const ctn_model *m, const ctn_solution *s, size_t k, size_t *e, ctn_beam_result *out);
/* Element i (a "beam") at the end of step k. CTN_ERR_INVALID if i is not a beam or k, i
 * are out of range; CTN_ERR_NOCONV if its state cannot be evaluated. The caller sets
 * out->size. */
int ctn_solution_beam(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, ctn_beam_result *out);
/* The deformed shape of element i at the end of step k: n >= 2 points (3 coordinates
 * each, into xyz[3 n]) evenly spaced along its unstressed length: on the elastic catenary
 * for a catenary, on its straight segments for the other families (a pulley's pass
 * through its pulley nodes). CTN_ERR_INVALID on bad arguments. */
int ctn_solution_element_shape(const ctn_model *m, const ctn_solution *s, size_t k, size_t i,
                               int n, double *xyz);

/* Sag of generated cable i (ctn_model_cable), the one definition of catena (the same as
 * ctn_compare_values.sag; docs/format.md, "cables"). "Down" is gravity or, without
 * gravity, the direction of the resultant of the model's concentrated loads.
 *   - The mid-span sag: the distance along down from the mid-point of the deformed
 *     chord (the line between the cable's current end positions) to the deformed cable
 *     at the point whose projection on the plane normal to down is the chord's
 *     mid-point, positive below the chord. Between nodes the cable is read on the
 *     parabola through the three nodes nearest to mid-span, or on the straight element
 *     when the middle one of them carries a concentrated load (`load`) or the cable has
 *     one element.
 *   - With no down, or a chord along down (a vertical chord): the largest distance from
 *     the chord, ctn_solution_cable_max_sag_from_chord.
 * CTN_ERR_DOMAIN if the deformed cable does not cross mid-span (folded back). */
int ctn_solution_cable_sag(const ctn_model *m, const ctn_solution *s, size_t i, double *sag);
/* The same at the end of step k (ctn_solution_step). */
int ctn_solution_step_cable_sag(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, double *sag);
/* The largest distance of the deformed cable i from its chord (the line through its
 * current end positions), >= 0: the largest over its nodes, which is that of the
 * polyline of its straight elements. */
int ctn_solution_cable_max_sag_from_chord(const ctn_model *m, const ctn_solution *s, size_t i,
                                          double *d);

/* Capacity: the utilisation of an element is its force / (mbl / safety) of its section
 * (ctn_element_info.capacity); it is defined only when the section has an mbl. */
double ctn_utilisation(const ctn_element_info *e, const ctn_element_state *st);   /* 0 without */

/* Totals and extremes of group g (ctn_model_group_name) at the end of step k. */
typedef struct ctn_group_result {
    const char *name;
    size_t elements;         /* members */
    double max_force, min_force;   /* [force] */
    double max_stress;       /* largest N / A of the members with a section [force/length^2] */
    double max_strain;
    int has_capacity;        /* 1 if some member's section has an mbl, or is a beam whose
                                material has fy */
    double max_utilisation;  /* largest utilisation of those members (0 if none): a cable's
                                force / (mbl / safety), a beam's combined stress / fy */
    int worst_element;       /* id of the member with it (0 if none) */
    size_t slack;            /* slack tension-only members */
    double length;           /* sum of unstressed lengths (reference temperature) [length] */
    double stressed_length;  /* sum of current lengths [length] */
    double weight;           /* sum of w l0 |g| [force] */
} ctn_group_result;
int ctn_solution_group(const ctn_model *m, const ctn_solution *s, size_t k, size_t g, ctn_group_result *out);
/* The most utilised element at the end of step k: its index in *e and its utilisation
 * in *u; CTN_ERR_INVALID when no section has an mbl. */
int ctn_solution_worst_utilisation(const ctn_model *m, const ctn_solution *s, size_t k, size_t *e, double *u);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
