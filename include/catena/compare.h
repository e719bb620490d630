/*
 * catena/compare.h - a model's single cable span against the classical closed forms.
 *
 * Three tools, one prefix each:
 *   ctn_compare_*      one model: find its span, solve the closed forms that apply, take
 *                      the FEA values from a solution, tabulate, sample curves, figures;
 *   ctn_study_*        the founding paper's study: the span re-solved for many unstressed
 *                      lengths, FEA against the inextensible catenary, error vs stress;
 *   ctn_convergence_*  mesh convergence: the span re-meshed with n elements, engineering
 *                      strain, FEA against the elastic catenary, observed order.
 *
 * A SPAN is one cable between two supports: either a `cable` directive or a chain of
 * elements, both end nodes fixed in x, y and z, every interior node shared by exactly two
 * elements, and no other element in the model. All elements must have the same E, A, w
 * and strain measure. The span is described in its plane: x horizontal (normal to
 * gravity) from the first support to the second, y up (against gravity); l the horizontal
 * span, h the height of the second support above the first (see catena/analytic.h). The
 * supports are taken where they are at the end of the last step (prescribed
 * displacements included). Without gravity, "down" is the direction of the resultant load.
 *
 * Loads found on the span decide which closed forms apply (ctn_compare_has):
 *   distributed (self-weight w and/or a load q per unit horizontal length on the whole
 *   span), no point loads:
 *       catenary, elastic catenary  with the total distributed load spread uniformly
 *                                   along the unstressed length (exact for w alone);
 *       parabola, elastic parabola  with the total load spread uniformly along the
 *                                   horizontal (exact for q alone; the classical
 *                                   approximation for self-weight);
 *   point loads on interior nodes (any other load pattern):
 *       funicular (inextensible)    of the lumped joint loads;
 *   always:
 *       elastic funicular           the polygon of the lumped joint loads with the
 *                                   elements' l0 and EA: with engineering strain it IS
 *                                   the finite element solution (to rounding).
 * A closed form with no solution (an inextensible length not longer than the chord, a
 * slack chain) is simply absent.
 *
 * Compared quantities (ctn_compare_values), the same for every form:
 *   sag         mid-span sag: the vertical distance from the chord's mid-point down to the
 *               cable, by catena's one definition (ctn_solution_cable_sag, the same
 *               number as `catena solve`); the FEA and the polygons are read between
 *               their nodes on the parabola through the three nodes nearest to
 *               mid-span, or linearly (the chain is straight between joints) when the
 *               middle one of them carries a concentrated load;
 *   T_max       the tension at the more loaded support. For the FEA and the polygons it
 *               is the magnitude of the support reaction, which includes the load lumped
 *               on the support node; the force in the first element is lower by that
 *               load's share (several % on deep cables) and is NOT what is compared;
 *   T_min       the smallest tension: at the vertex for the continuous forms, the least
 *               loaded element (FEA) or segment (polygons);
 *   H           horizontal component of the force at the first support;
 *   stress_*    T / A, A the unstressed area (the FEA reports the same N / A).
 * Stresses are in model units (force / length^2); ctn_span.mpa converts them to MPa.
 */
#ifndef CATENA_COMPARE_H
#define CATENA_COMPARE_H

#include <stddef.h>

#include "catena/core.h"
#include "catena/model.h"
#include "catena/solve.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* The solutions compared. */
typedef enum ctn_form {
    CTN_FORM_FEA = 0,         /* the finite element solution */
    CTN_FORM_CATENARY = 1,    /* inextensible catenary */
    CTN_FORM_ECATENARY = 2,   /* elastic catenary (Irvine, engineering strain) */
    CTN_FORM_PARABOLA = 3,    /* inextensible parabola */
    CTN_FORM_EPARABOLA = 4,   /* elastic parabola (engineering strain) */
    CTN_FORM_FUNICULAR = 5,   /* inextensible funicular polygon */
    CTN_FORM_EFUNICULAR = 6,  /* elastic funicular polygon (engineering strain) */
    CTN_FORM_COUNT = 7
} ctn_form;

/* JSON key of a form: "fea", "catenary", "elastic_catenary", "parabola",
 * "elastic_parabola", "funicular", "elastic_funicular"; "" if out of range. */
const char *ctn_form_key(ctn_form f);
/* Name for people: "FEA", "catenary", "elastic catenary", ...; "" if out of range. */
const char *ctn_form_name(ctn_form f);

/* Loads found on a span (bit flags of ctn_span.loads). */
enum { CTN_SPAN_WEIGHT = 1, CTN_SPAN_HLOAD = 2, CTN_SPAN_POINT = 4 };

/* A single span, in its plane. */
typedef struct ctn_span {
    size_t n;              /* number of elements */
    int support[2];        /* user ids of the first and second support */
    int generated;         /* 1 if the span is a `cable` directive */
    double l;              /* horizontal span, > 0 [length] */
    double h;              /* height of the second support above the first [length] */
    double L0;             /* total unstressed length (sum of l0) [length] */
    double E, A, EA;       /* modulus [force/length^2], area [length^2], E A [force] */
    ctn_strain strain;     /* strain measure of the elements */
    double w;              /* self-weight per unit unstressed length (section w times
                              the length of the gravity vector) [force/length] */
    double q;              /* load per unit horizontal length (hload) [force/length] */
    unsigned loads;        /* CTN_SPAN_* flags */
    double origin[3];      /* first support, current position [length] */
    double ex[3], ey[3];   /* unit vectors of the plane: horizontal along the span, up */
    double g[3];           /* the model's gravity vector (zero if none) */
    double X[2][3];        /* current positions of the supports (X[0] == origin) [length] */
    double mpa;            /* factor from a model stress to MPa, 0 if the model has no
                              units (ctn_model_mpa_factor) */
    char force_unit[8];    /* unit labels of the model ("" if none) */
    char length_unit[8];
} ctn_span;

/* The compared quantities of one solution (see the header comment). */
typedef struct ctn_compare_values {
    double sag;            /* mid-span sag [length] */
    double T_max;          /* tension at the more loaded support [force] */
    double T_min;          /* smallest tension [force] */
    double H;              /* horizontal force at the first support [force] */
    double stress_max;     /* T_max / A [force/length^2] */
    double stress_min;     /* T_min / A [force/length^2] */
} ctn_compare_values;

typedef struct ctn_compare ctn_compare;

/* Check m (ctn_model_validate), find its span (CTN_ERR_MODEL with a message naming the
 * problem if the model is not a single span, or its loads leave the plane) and solve its
 * closed forms. Messages about the model, here and in ctn_compare_set_fea, ctn_study_run
 * and ctn_convergence_run, start with its file name (ctn_model_file) when it has one:
 * "FILE: not a single span: ...", or the model checks' "FILE:LINE: ...".
 * *out owns a new comparison (ctn_compare_destroy); it keeps no pointer to m. */
int ctn_compare_create(ctn_ctx *ctx, const ctn_model *m, ctn_compare **out);
/* Destroy; NULL or *c == NULL is a harmless no-op; sets *c to NULL. */
void ctn_compare_destroy(ctn_compare **c);
/* The span (owned by c). */
const ctn_span *ctn_compare_span(const ctn_compare *c);
/* Take the FEA values (and curves) from s, a solution of the model given to
 * ctn_compare_create (not kept). CTN_ERR_DOMAIN if the deformed cable never crosses
 * mid-span or a value is not finite. */
int ctn_compare_set_fea(ctn_compare *c, const ctn_solution *s);
/* 1 if form f has values (FEA: after ctn_compare_set_fea). */
int ctn_compare_has(const ctn_compare *c, ctn_form f);
/* Values of form f; CTN_ERR_DOMAIN (zeroed *out) if it has none. */
int ctn_compare_get(const ctn_compare *c, ctn_form f, ctn_compare_values *out);
/* Relative difference (a - b) / b, 0 when b == 0. */
double ctn_compare_rel(double a, double b);

/* Curves of a form, in the span's plane:
 *   CTN_CURVE_SHAPE   (x, y) of the cable [length];
 *   CTN_CURVE_STRESS  (x, stress): FEA and polygons one point per element at its
 *                     mid-point, closed forms sampled [length, force/length^2]. */
typedef enum ctn_curve { CTN_CURVE_SHAPE = 0, CTN_CURVE_STRESS = 1 } ctn_curve;
/* Number of points of the curve (0 if the form is absent). */
size_t ctn_compare_curve_size(const ctn_compare *c, ctn_form f, ctn_curve k);
/* Write the ctn_compare_curve_size() points as x0, y0, x1, y1, ... into xy. */
int ctn_compare_curve(const ctn_compare *c, ctn_form f, ctn_curve k, double *xy);

/* Write the two figures of the comparison into dir (created if missing): the deformed
 * configuration (compare_shape) and the stress along the cable (compare_stress), FEA
 * against the closed forms: data files compare_<curve>_<form>.dat and the scripts
 * compare_shape.gp, compare_stress.gp (catena/plot.h). Stresses in MPa when the model
 * has units. Names of the scripts written (without .gp) go to names[0..1] when names is
 * not NULL. */
int ctn_compare_write_figures(ctn_ctx *ctx, const ctn_compare *c, const char *dir,
                              const char *names[2]);

/* ---------------------------------------------------------------------------------------
 * The length study (the founding paper's Section 5). The span of a base model is rebuilt
 * for each unstressed length L0 (same supports, section, loads, number of elements,
 * strain measure and solve options; the interior nodes on the arc of length L0, or on
 * the chord when L0 <= chord) and solved; each row holds the FEA, the catenary, the
 * elastic catenary and the elastic funicular. A length whose solution does not
 * converge with the model's method is solved again with CTN_METHOD_AUTO (row.fallback).
 * Only spans with distributed loads (no point loads) can be studied.
 * With CTN_STUDY_CATENARY each length is solved on ONE exact catenary element (Irvine,
 * engineering strain, no mesh) and that element is the row's FEA form; a span of cable
 * elements is solved on its mesh as well (row.mesh), for the figures and the tables.
 * A base whose span is one catenary element is studied on one catenary element.
 * ------------------------------------------------------------------------------------- */
/* What each length of a study is solved on. */
typedef enum ctn_study_element {
    CTN_STUDY_MESH = 0,       /* the span's own elements: n cable elements (the paper's) or
                                 its one catenary element */
    CTN_STUDY_CATENARY = 1    /* one catenary element per length (and the mesh beside it) */
} ctn_study_element;
typedef struct ctn_study_options {
    const double *lengths;  /* [nlengths] lengths of the marked cases (e.g. the paper's
                               four); NULL if none */
    size_t nlengths;
    size_t sweep;           /* number of sweep lengths, spaced geometrically in
                               L0 - chord between the two bounds below; 0: no sweep */
    double sweep_from;      /* smallest L0 of the sweep, > chord [length]; 0: chord
                               (1 + 2e-4) */
    double sweep_to;        /* largest L0 of the sweep [length]; 0: 1.5 chord */
    const double *claims;   /* [2 nclaims] reference points (stress level, difference in
                               %) drawn on the error figure, e.g. a paper's conclusions;
                               stress in MPa (in model units if the model has none) */
    size_t nclaims;
    const char *claims_title; /* legend of those points; NULL: "reference points" */
    const ctn_solve_options *solve; /* options of every FEA solve (NULL: the defaults) */
    ctn_study_element element; /* default CTN_STUDY_MESH; CTN_STUDY_CATENARY needs a span
                                  under self-weight only (no hload) */
} ctn_study_options;

void ctn_study_options_default(ctn_study_options *opt);

/* One length of a study. */
typedef struct ctn_study_row {
    double L0;              /* unstressed length [length] */
    int marked;             /* 1 if L0 is one of the options' lengths */
    ctn_reason reason;      /* outcome of the FEA (CTN_CONVERGED, or why not) */
    int iterations;         /* Newton iterations */
    int fallback;           /* 1 if the model's method failed and CTN_METHOD_AUTO solved */
    unsigned present;       /* bit (1 << f) set when v[f] holds form f's values */
    ctn_compare_values v[CTN_FORM_COUNT];
    int has_mesh;           /* 1 when the rows are catenary elements (CTN_STUDY_CATENARY)
                               and the span's mesh of n cable elements converged too */
    ctn_reason mesh_reason; /* outcome of the mesh's solve (CTN_STUDY_CATENARY only) */
    ctn_compare_values mesh;/* the mesh's values, beside the element's v[CTN_FORM_FEA] */
} ctn_study_row;

typedef struct ctn_study ctn_study;

/* Run the study of the base model's span; rows sorted by L0 (duplicates merged).
 * Without lengths the base model's own length is the marked one. Non-converged lengths
 * are rows without the FEA bit, not errors. */
int ctn_study_run(ctn_ctx *ctx, const ctn_model *base, const ctn_study_options *opt,
                  ctn_study **out);
void ctn_study_destroy(ctn_study **s);
const ctn_span *ctn_study_span(const ctn_study *s);
/* What the rows were solved on: CTN_STUDY_CATENARY when the FEA form of the rows is one
 * catenary element (asked for, or the base's span is one), else CTN_STUDY_MESH. */
ctn_study_element ctn_study_element_kind(const ctn_study *s);
size_t ctn_study_count(const ctn_study *s);
/* Row i (0-based, by increasing L0); NULL if out of range. Owned by s. */
const ctn_study_row *ctn_study_row_at(const ctn_study *s, size_t i);

/* The error of the catenary against the FEA at a stress level, on the TAUT branch of the
 * sweep (the lengths below the one of least FEA support stress, where the support stress
 * falls as L0 grows), interpolated linearly between the two rows that bracket it. */
typedef enum ctn_level_axis {
    CTN_LEVEL_FEA = 0,      /* the level is the FEA's support stress */
    CTN_LEVEL_CATENARY = 1  /* the level is the catenary's support stress */
} ctn_level_axis;
typedef struct ctn_study_level {
    double stress;          /* the level [force/length^2] */
    int found;              /* 0 if the taut branch does not reach this level */
    double L0;              /* interpolated length [length] */
    double stress_fea;      /* support stress of the FEA and of the catenary there */
    double stress_cat;
    double err_max;         /* relative difference catenary - FEA: support stress */
    double err_min;         /* ... minimum (vertex) stress */
    double err_sag;         /* ... mid-span sag */
} ctn_study_level;
int ctn_study_level_at(const ctn_study *s, ctn_level_axis axis, double stress,
                       ctn_study_level *out);

/* Write the study figures into dir (created if missing): study_stress_max,
 * study_stress_min, study_sag (against L0 - chord, log scale: FEA, catenary, elastic
 * catenary, marked lengths) and study_error (|relative difference| against the stress
 * level, both readings, taut branch, and the claims). Data: study_<form>.dat for the FEA,
 * catenary, elastic catenary and elastic funicular (L0, L0 - chord, sag, support and
 * vertex stress (MPa when the model has units), H), study_marked_<form>.dat,
 * study_error.dat, study_claims.dat. Script names go to names[0..3] when names is not
 * NULL. */
int ctn_study_write_figures(ctn_ctx *ctx, const ctn_study *s, const char *dir,
                            const char *names[4]);
/* A study on catenary elements with the span's mesh beside them (CTN_STUDY_CATENARY on a
 * span of cable elements): the figure study_element into dir, |X - element| / element
 * against L0 - chord (log-log) for X = the mesh and the elastic catenary (sag, support
 * stress, H; data study_element.dat, rows where both converged). *name (may be NULL)
 * gets "study_element", or NULL when the study has no mesh (then nothing is written). */
int ctn_study_write_element_figure(ctn_ctx *ctx, const ctn_study *s, const char *dir,
                                   const char **name);

/* ---------------------------------------------------------------------------------------
 * Mesh convergence: the base model's span rebuilt with n elements (engineering strain,
 * whatever the model's material says) for each n, solved, and compared with the elastic
 * catenary of the same L0, w and EA. Needs a span loaded by self-weight only. The solve
 * options are the model's with tol = 1e-12 (the residual test is waived at the round-off
 * floor, see catena/solve.h), so the errors are those of the discretization.
 * ------------------------------------------------------------------------------------- */
typedef struct ctn_convergence_row {
    size_t n;               /* number of elements */
    ctn_reason reason;      /* outcome of the FEA */
    int iterations;
    ctn_compare_values fea; /* FEA values (zero when not converged) */
    double err_sag;         /* |FEA - elastic catenary| / elastic catenary: sag */
    double err_T;           /* ... support tension T_max */
    double err_H;           /* ... horizontal force */
} ctn_convergence_row;

typedef struct ctn_convergence ctn_convergence;

/* Run the study for ns[0..count-1] (each >= 2; sorted and duplicates merged), solving
 * with options opt (NULL: the defaults; tol is set to 1e-12). */
int ctn_convergence_run(ctn_ctx *ctx, const ctn_model *base, const ctn_solve_options *opt,
                        const size_t *ns, size_t count, ctn_convergence **out);
void ctn_convergence_destroy(ctn_convergence **c);
const ctn_span *ctn_convergence_span(const ctn_convergence *c);
/* The reference: the elastic catenary's values. */
const ctn_compare_values *ctn_convergence_reference(const ctn_convergence *c);
size_t ctn_convergence_count(const ctn_convergence *c);
const ctn_convergence_row *ctn_convergence_row_at(const ctn_convergence *c, size_t i);
/* Observed order of convergence of an error column (0 sag, 1 support tension, 2 H):
 * the least-squares slope of -log(err) against log(n) over the converged rows whose
 * error is above the round-off floor (err > 1e-13). CTN_ERR_DOMAIN if fewer than two. */
int ctn_convergence_order(const ctn_convergence *c, int column, double *order);
/* Write convergence.dat and the log-log figure convergence (script convergence.gp)
 * into dir (created if missing). */
int ctn_convergence_write_figures(ctn_ctx *ctx, const ctn_convergence *c, const char *dir);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
