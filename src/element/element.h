/* Internal: element families behind one ops table.
 *
 * A family (cable, spring, ...) is a table of operations on opaque per-element
 * properties: setup builds the properties of element e from the model, eval is a pure
 * kernel (no allocation, no I/O) that returns internal forces, the tangent and the
 * element's state; load lumps the loads that belong to the element (self-weight).
 * The assembler, the checks and the result code call the ops through one element loop
 * (assemble/asm.h) and never look inside the properties. Registered families are listed
 * in registry.c; a new one is a file here and a line there (docs/architecture.md). */
#ifndef CTN_ELEMENT_ELEMENT_H
#define CTN_ELEMENT_ELEMENT_H

#include "model/model.h"

#define CTN_ELEM_MAX_NODES 64   /* most nodes of one element (pulley chains) */
#define CTN_ELEM_MAX_DOF_NODE 6 /* most DOFs per node of any family */

/* What an evaluation reports besides forces and stiffness. */
typedef struct ctn_elem_state {
    double l;           /* current length (of the whole member) */
    double strain;      /* strain of the element's measure */
    double N;           /* axial tension (true force) */
    double stress;      /* N / A for members with a section (with CTN_EVAL_STRESS), else 0 */
    double energy;      /* stored energy; its gradient is the internal force */
    int slack;          /* tension-only member with no force */
} ctn_elem_state;

/* Evaluation modes (bit flags). */
enum {
    CTN_EVAL_CUT_COMPRESSION = 1,  /* members that can go slack (CTN_ELEM_FLEXIBLE) carry
                                      no compression, whatever their material */
    CTN_EVAL_STRESS = 2            /* fill st->stress (results only: a division the
                                      iterations do not need) */
};

/* Family flags. */
enum {
    CTN_ELEM_FLEXIBLE = 1,  /* a cable: hangs when slack; may be pre-shaped on an arc and
                               relaxed with compression cut off by the solver */
    CTN_ELEM_SECTION = 2,   /* takes a section (section=): required; others refuse one */
    CTN_ELEM_TENSION_ONLY = 4, /* never compressed, whatever the material (catenary, pulley) */
    CTN_ELEM_FINITE_ROTATION = 8 /* its rotation DOFs are the node's total rotation vector:
                                    a rigid motion composes them (beam) */
};

/* eval(props, mode, X, u, f, K, st): X = reference coordinates of the element's nodes
 * (3 per node), u = their displacements (ndof_node per node; the current chord is formed
 * as (X2 - X1) + (u2 - u1), which keeps round-off at the scale of the element); f =
 * internal nodal forces (ndof_node per node); K = the upper triangle of the symmetric
 * tangent packed row by row (ctn_packed_index), or NULL to skip it; st may be NULL.
 * Returns 0, or 1 if the element has collapsed (zero length): an outcome, not a status. */
typedef int (*ctn_elem_eval_fn)(const void *props, unsigned mode, const double *X,
                                const double *u, double *f, double *K, ctn_elem_state *st);

typedef struct ctn_element_ops {
    const char *name;       /* family name, as the model file and the API spell it */
    int nnodes;             /* nodes per element; 0: two or more, given per element */
    int ndof_node;          /* DOFs per node the family uses (3: translations x, y, z) */
    size_t props_size;      /* bytes of one element's properties (a multiple of 8) */
    unsigned flags;         /* CTN_ELEM_* */
    /* Check a new element record (nodes, section, parameters) before it is added:
     * CTN_OK or a model error (ctn_model_error) naming what is wrong. */
    int (*check)(const ctn_model *m, const ctn_element *e);
    /* Optional: the family's own parameters of the spec into par (CTN_ELEM_NPAR, zeroed),
     * kept in the element's record for check, setup and prestress_l0 (k= of a spring). */
    void (*params)(const ctn_element_spec *s, double *par);
    /* Properties of element e of the model into props (props_size bytes). */
    void (*setup)(const ctn_model *m, size_t e, void *props);
    ctn_elem_eval_fn eval;
    /* Optional: nodal loads that belong to element e (self-weight w l0 along g), ndof_node
     * per node, added to f (3 per node in model node order). */
    void (*load)(const ctn_model *m, size_t e, double *f);
    /* Stiffness scale of the tangent (E A / l0, k), for shifts and tolerances. */
    double (*stiffness)(const void *props);
    /* Unstressed length of a flexible member (CTN_ELEM_FLEXIBLE) or one that hangs, else NULL. */
    double (*rest_length)(const void *props);
    /* Optional (members that hang): the chord v (first node to second) the member takes
     * when it carries the force S at its middle (the pull at its second end plus half its
     * own weight, which the loads carry at its nodes), engineering strain; v is the
     * gradient in S of the convex phi(S) returned (its complementary energy), H a positive
     * definite stand-in of its Hessian (3 x 3). NAN where S gives no direction. Used by
     * the start heuristics (src/start/hang.c). */
    double (*hang)(const void *props, const double S[3], double v[3], double H[9]);
    /* Optional: the unstressed length l0 that gives element e (its section or k set) the
     * prestress `kind` of value v at length l; a model error (ctn_model_error) if none. */
    int (*prestress_l0)(const ctn_model *m, const ctn_element *e, int kind, double v, double l, double *l0);
    /* Optional: a temperature change dT [K] from the reference state: the unstressed
     * length becomes l0 (1 + alpha dT) (alpha of the element's material); weight and mass
     * stay those of l0. Families without it do not expand. */
    void (*temperature)(void *props, double dT);
    /* Optional: the element's mass matrix, packed upper triangle like the tangent
     * (ctn_packed_index, ndof_node per node), lumped (1) or consistent (0). Mass is per
     * unstressed length and conserved under stretch, so the matrix does not depend on
     * the state; X holds the element's nodes' input coordinates (3 per node), for a
     * family that shares its mass by reference lengths (pulley). NULL: the family is
     * massless (springs). */
    void (*mass)(const void *props, const double *X, int lumped, double *M);
    /* Optional: eval for a two-node family of 3 DOFs per node whose tangent is
     * [[k, -k], [-k, k]] with k symmetric (an axial member): the forces f (6) and k's
     * upper triangle kk (6: xx, xy, xz, yy, yz, zz) instead of the packed 6 x 6, bit for
     * bit the values eval gives. The assembler then writes the tangent node by node
     * (assemble/gather.c); eval stays the generic path. */
    /* Optional: the consistent nodal loads of a uniform load q [F/L] per unstressed
     * length in a fixed global direction on element e, added to f (forces, 3 per node in
     * model node order) and M (moments, likewise); either may be NULL. A family without
     * it takes a lineload as q l0 / 2 at each node (cable). */
    void (*line_load)(const ctn_model *m, size_t e, const double q[3], double *f, double *M);
    int (*eval_axial)(const void *props, unsigned mode, const double *X, const double *u, double *f,
                      double *kk, ctn_elem_state *st);
    /* Optional: the stiffness scale of the element's forces against an error in its
     * chord (its nodes' positions), for the residual's round-off floor
     * (analysis/static/floor.c): a beam's transverse 12 E I / L^3 where that exceeds
     * E A / L (elements shorter than sqrt(12 I / A)). NULL: stiffness. */
    double (*round_stiffness)(const void *props);
    /* Optional: sever the member (a cable that breaks, in a dynamics analysis): its force,
     * stiffness and energy zero from now on, its mass kept; setup restores it. NULL: the
     * family cannot be removed. */
    void (*sever)(void *props);
} ctn_element_ops;

/* Entries of the packed upper triangle of an n x n matrix. */
static inline int ctn_packed_size(int n) { return n * (n + 1) / 2; }

/* Index of (i, j), i <= j < n, in the packed upper triangle of an n x n matrix. */
static inline int ctn_packed_index(int n, int i, int j)
{
    return i * n - i * (i - 1) / 2 + (j - i);
}

/* ---- registry (registry.c) ---- */
/* Number of registered families; family i (0-based); NULL if out of range. */
int ctn_element_family_count(void);
const ctn_element_ops *ctn_element_family(int type);
/* Family index of a name, -1 if none. */
int ctn_element_family_find(const char *name);

/* The families (one file each). */
extern const ctn_element_ops ctn_cable2_ops;
extern const ctn_element_ops ctn_spring2_ops;
extern const ctn_element_ops ctn_catenary2_ops;   /* catenary2.c, props in catenary.h */
extern const ctn_element_ops ctn_pulley_ops;      /* pulley.c */
extern const ctn_element_ops ctn_rspring_ops;     /* rspring.c: 6 DOFs per node */
extern const ctn_element_ops ctn_beam3_ops;       /* beam3.c, beam3_model.c: corotational beam */

/* Each family's properties are its own: cable2.h (ctn_cable_props, which the pulley's
 * embed), spring2.h, pulley.h, catenary.h, rspring.c. */

#endif
