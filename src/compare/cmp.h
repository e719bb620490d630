/* Internal: the comparison object and the helpers shared by src/compare/. */
#ifndef CTN_COMPARE_CMP_H
#define CTN_COMPARE_CMP_H

#include "catena/analytic.h"
#include "catena/compare.h"
#include "core/ctx.h"
#include "element/catenary.h"

#define CTN_CMP_SAMPLES 201        /* points of a sampled closed-form curve */

struct ctn_compare {
    ctn_ctx *ctx;
    char file[256];        /* the model's file name (ctn_model_file), "" if none */
    ctn_span span;
    size_t *node;          /* [n + 1] node indices along the span, support 0 first */
    size_t *elem;          /* [n] element indices in span order */
    double *l0;            /* [n] unstressed lengths */
    double *EA;            /* [n] axial stiffnesses (all span.EA) */
    double *Xref;          /* [3 (n + 1)] reference positions of the span's nodes */
    double *P;             /* [2 (n + 1)] lumped loads of the nodes, in plane (x, y) */
    double W;              /* total load along -y [force] */
    double down[3];        /* the model's "down" (ctn_sag_down): -span.ey */
    unsigned char *kink;   /* [n + 1] 1 if chain node j carries a concentrated load */
    unsigned has;          /* bit (1 << form) set for each form with values */
    ctn_compare_values v[CTN_FORM_COUNT];
    ctn_catenary cat;
    ctn_ecatenary ecat;
    ctn_parabola par[2];   /* inextensible, elastic */
    double *poly[2];       /* [3 n + 2] funicular polygons (inextensible, elastic):
                              joints x0 y0 ... xn yn, then the n segment tensions */
    double *fea;           /* [3 n + 2] FEA: node positions, then element forces */
    int follow;            /* the hload is on the deformed projection: the polygons take
                              the loads of the FEA's geometry (follow_loads.c) */
    double *Pref;          /* [2 (n + 1)] then: P on the reference geometry */
    int catenary;          /* the span is one catenary element: the FEA is its curve */
    ctn_catenary_props catp; /* its properties */
    ctn_ecat fea_cat;      /* its solved state (ctn_compare_set_fea) */
    double fea_x0[3], fea_ex[3]; /* its first node and unit horizontal chord */
};

/* Record an error about the model of `file`: the message starts "file: " (nothing
 * when file is "" or NULL), like the model checks' (compare.c). Returns code. */
int ctn_cmp_error(ctn_ctx *ctx, const char *file, int code, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* Span detection (span.c): fills span.n, support, generated, node, elem, l0, EA and
 * the section data; allocates the arrays. */
int ctn_cmp_find_span(ctn_compare *c, const ctn_model *m);
/* Geometry and loads (span_loads.c): plane, l, h, w, q, loads flags, P, W. */
int ctn_cmp_span_loads(ctn_compare *c, const ctn_model *m);
/* An hload on the deformed projection: P at the deformed positions x (3 per model node)
 * of the FEA, and the polygons solved again with them (follow_loads.c). */
int ctn_cmp_follow_loads(ctn_compare *c, const double *d);
/* Closed forms (forms.c): every form that applies, into has / v / cat ... poly. */
int ctn_cmp_solve_forms(ctn_compare *c);
/* Sag of the span's chain with node j at point(c, ud, j, x) in space, by the one
 * definition of src/solve/sag.h (values.c). */
typedef void (*ctn_cmp_point_fn)(const ctn_compare *c, const void *ud, size_t j, double x[3]);
int ctn_cmp_sag(const ctn_compare *c, ctn_cmp_point_fn point, const void *ud, double *sag);
/* Values of a polyline of n segments (xy [2 (n + 1)], forces N [n]) in the span's
 * plane, supports carrying the loads P[0..1] and P[2n..2n+1] (fea.c). */
int ctn_cmp_polyline_values(const ctn_compare *c, const double *xy, const double *N,
                            ctn_compare_values *v);
/* Dot product and plane coordinates (x, y) of a 3D point relative to span.origin. */
double ctn_cmp_dot3(const double a[3], const double b[3]);
void ctn_cmp_to_plane(const ctn_span *s, const double p[3], double xy[2]);

/* The FEA values of a span made of one catenary element at displacements d (fea.c). */
int ctn_cmp_catenary_fea(ctn_compare *c, const double *d);
/* Point t in [0, 1] (of the unstressed length) of that catenary in the span's plane:
 * (x, y), or (x, T / A) for the stress curve (curve.c). */
void ctn_cmp_catenary_sample(const ctn_compare *c, int stress, double t, double out[2]);

/* A fresh single-span model like the span of base (see ctn_study_run): unstressed
 * length L0, n cable elements, strain measure; n == 0: one catenary element (build.c). */
int ctn_cmp_build(ctn_ctx *ctx, const ctn_model *base, const ctn_span *span, double L0,
                  size_t n, ctn_strain strain, ctn_model **out);
/* Solve a built model with options base (NULL: defaults; tol > 0 replaces its tol); on
 * non-convergence with a method other than AUTO, solve again with AUTO (*fallback = 1).
 * *s owns the last solution. */
int ctn_cmp_solve(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *base, double tol,
                  ctn_solution **s, int *fallback);

#endif
