/* Internal: the model structure shared by model/, assemble/, solve/ and io/. */
#ifndef CTN_MODEL_MODEL_H
#define CTN_MODEL_MODEL_H

#include "catena/model.h"
#include "core/ctx.h"
#include "model/idmap.h"

#define CTN_NAME_MAX 64
#define CTN_ELEM_NPAR 3  /* per-element parameters a family keeps in the model record */

typedef struct ctn_node {
    int id;
    double X[3];     /* reference coordinates */
    double guess[3]; /* starting displacement */
    unsigned fix;
    int line;        /* defining line in the source, 0 if from the API */
    double mass;     /* lumped point mass [force s^2/length], 0 if none */
    int ndof;        /* 3, or 6 once an element of a 6-DOF family reaches it */
} ctn_node;

typedef struct ctn_material {
    char name[CTN_NAME_MAX];
    double E;
    ctn_strain strain;
    int tension_only;
    double alpha;    /* coefficient of thermal expansion [1/K] */
    double G;        /* shear modulus [force/length^2], 0 if not given */
    double fy;       /* yield stress [force/length^2], 0 if not given */
} ctn_material;

typedef struct ctn_section {
    char name[CTN_NAME_MAX];
    int material;    /* index */
    double A, w;
    int line;
    double mbl;      /* minimum breaking load [force], 0 if not given */
    double safety;   /* factor on mbl: capacity = mbl / safety */
    double mass;     /* per unit unstressed length; CTN_MASS_DEFAULT: w / g */
    double Iy, Iz, J;   /* beams: second moments of area, torsion constant [length^4] */
    double Asy, Asz;    /* beams: shear areas [length^2], 0 if not given */
    double Wy, Wz;      /* beams: elastic section moduli [length^3], 0 if not given */
} ctn_section;

typedef struct ctn_element {
    int id;
    int type;        /* element family (element/registry.c) */
    int nnodes;      /* number of nodes */
    size_t conn;     /* its node indices are conn.v[conn .. conn + nnodes - 1] */
    int section;     /* section index, -1 for families without one */
    double l0;       /* unstressed (free) length */
    double par[CTN_ELEM_NPAR]; /* the family's own parameters, from the spec by its
                                  params op (spring, rspring: par[0] = k), else 0 */
    int line;        /* defining line in the source, 0 if from the API */
    int group;       /* group index, -1 if none */
} ctn_element;

/* Form finding: the force density or target force of a member (density.c). */
typedef struct ctn_density {
    size_t e;        /* element index */
    double q;        /* force density q = N / l [force/length], 0 if none */
    double force;    /* target force [force], 0 if none */
} ctn_density;

typedef struct ctn_group {
    char name[CTN_NAME_MAX];
    int line;        /* first line that named it */
} ctn_group;

/* A temperature change dT of the elements it targets, from its step on. */
enum { CTN_TARGET_ALL = 0, CTN_TARGET_ELEMENT = 1, CTN_TARGET_GROUP = 2, CTN_TARGET_SET = 3 };

/* A named set of nodes or elements (`set`, sets.c): member[i] is 1 for the node or
 * element index i in it. */
typedef struct ctn_set {
    char name[CTN_NAME_MAX];
    int nodes;       /* 1: a node set; 0: an element set */
    unsigned char *member;   /* nodes.n or elements.n bytes (at the set's definition) */
    size_t size;     /* the member array's length */
    size_t count;    /* members */
    int line;
} ctn_set;
typedef struct ctn_tload {
    int kind;        /* CTN_TARGET_* */
    int target;      /* element index or group index */
    double dT;       /* [K] */
    int step;
    int line;
} ctn_tload;

typedef struct ctn_hload {
    double q;
    int reference;   /* 1: on the reference projection (a dead load); 0: the deformed one */
    int first, last; /* element ids, inclusive */
    int group;       /* or a group index (then first, last are unused); -1 if none */
    int line;
    int step;        /* 0: before any step directive, else the step number */
} ctn_hload;

/* A load per unit unstressed length q [force/length], fixed in direction, on the cable
 * elements of its target (lineload.c), from its step on (or in its case). */
typedef struct ctn_lload {
    int kind;        /* CTN_TARGET_* */
    int target;      /* element index or group index */
    double q[3];     /* drag: q_w times the wind's unit direction */
    int step;        /* the record's tag, as ctn_pload's */
    int line;
    int drag;        /* 1: wind drag, q_w per unit length of the chord projected on the
                        plane normal to the wind, following the geometry (follow.c) */
    double dir[3];   /* drag: the wind's unit direction */
    double cdp, d;   /* drag: cd p [force/length^2] and the bare diameter d [length]:
                        q_w = cdp d, or cdp (d + 2 t) on iced elements */
    double t;        /* ice: the sleeve's thickness [length] (0: another lineload) */
    double rho, speed, cd; /* drag given by speed= rho=: the air's density [mass/L^3], the
                        wind's speed [L/s] and cd (a dynamics' relative wind); rho NAN
                        when given by pressure= (ctn_model_wind_air) */
} ctn_lload;

/* A load case (cases.c): the load records tagged CTN_CASE_TAG0 + its index, solved from
 * the state at the end of model step `from` (0-based), not cumulatively. */
#define CTN_CASE_TAG0 (1 << 28)
#define CTN_MAX_CASE_TERMS 64   /* terms of a combination at most */
typedef struct ctn_case {
    char name[CTN_NAME_MAX];
    int from;        /* step index of the installed state */
    int substeps;    /* 0: the solve options' steps */
    int line;
} ctn_case;

/* A combination: sum of factor * case over its terms (m->terms[first .. first+count)). */
typedef struct ctn_combo_term {
    int c;           /* case index */
    double factor;
} ctn_combo_term;
typedef struct ctn_combo {
    char name[CTN_NAME_MAX];
    size_t first, count;
    int from;        /* the cases' common installed state */
    int line;
} ctn_combo;

/* A row of the sag-tension chart (`sagtension`, directives_chart.c): the case or
 * combination solved at temperature change dT, alone (base -1) or with case `base`. */
typedef struct ctn_chart_row {
    int combination; /* 1: index is a combination's; 0: a case's */
    int index;
    double dT;       /* [K] */
    int base;        /* case index, or -1 */
} ctn_chart_row;

/* Which load records a solve takes: every record of tag 0 .. upto (the totals of model
 * step k: upto = k + 1), and the records of the n extra tags times their factors (a case:
 * its own tag, factor 1; a combination: its cases'). */
typedef struct ctn_loadsel {
    int upto;
    size_t n;
    const int *tag;
    const double *factor;
} ctn_loadsel;

static inline double ctn_loadsel_weight(const ctn_loadsel *s, int tag)
{
    if (tag <= s->upto) return 1.0;
    for (size_t i = 0; i < s->n; i++)
        if (s->tag[i] == tag) return s->factor[i];
    return 0.0;
}

/* The selection of model step k (0-based): its cumulative totals. */
static inline ctn_loadsel ctn_loadsel_step(size_t k)
{
    ctn_loadsel s = { (int)k + 1, 0, NULL, NULL };
    return s;
}

typedef struct ctn_pload {
    int node;        /* node index */
    double F[3];     /* a force, or (in mloads) a moment */
    int step;
    int line;        /* defining line in the source, 0 if from the API */
} ctn_pload;

typedef struct ctn_pdisp {
    int node;        /* node index */
    double u[3];     /* increments of prescribed displacement (or rotation) on fixed DOFs */
    int step;
    int rot;         /* 1: rotations about x, y, z (u in rad) */
} ctn_pdisp;

typedef struct ctn_step {
    char name[CTN_NAME_MAX];
    int substeps;    /* 0: the solve options' steps */
} ctn_step;

typedef struct ctn_cable {
    int node[2];
    size_t first, count;
    double length;
    int start;       /* ctn_cable_start as given */
    int shape;       /* ctn_cable_shape */
    int target;      /* ctn_cable_target: the length is found to meet it */
    double target_value;
    int line;
    int resolved;    /* the length meets the target (ctn_model_resolve_targets) */
    double target_achieved;  /* the target's value in the solved first step */
    int target_iterations;   /* outer iterations that found the length */
} ctn_cable;

/* A time history a dynamics analysis records (records.c). */
typedef struct ctn_record {
    int node;        /* node index, or -1 */
    unsigned dofs;   /* the node's directions (CTN_FIX_X | _Y | _Z); a reaction's 0: the
                        node's fixed ones */
    int element;     /* element index (its axial force), or -1 */
    int line;
    int reaction;    /* 1: the node's support reactions in dofs (not its displacements) */
} ctn_record;

/* A function of time f(t) scaling loads and support motions in a dynamics analysis
 * (functions.c): ramp (0 before t0, linear to 1 at t1, 1 after), step (0 before t0, 1
 * from it), harmonic (offset + amp sin(2 pi freq t + phase)), table (linear between its
 * points, held beyond its ends). */
typedef struct ctn_fn {
    char name[CTN_NAME_MAX];
    int kind;        /* ctn_fn_kind */
    double par[4];   /* ramp, step: t0, t1; harmonic: amp, freq [Hz], phase [rad], offset */
    double *t, *v;   /* table: n points, t increasing (owned) */
    size_t n;
    int line;
} ctn_fn;

/* A force at a node, or a prescribed motion of its fixed DOFs, times a function of time:
 * applied by a dynamics analysis only (functions.c). */
typedef struct ctn_dload {
    int node;        /* node index */
    unsigned dofs;   /* motion: the fixed directions it moves (CTN_FIX_X | _Y | _Z); 0: a force */
    double F[3];     /* the force, or the motion's amplitudes */
    int fn;          /* function index */
    int line;
} ctn_dload;

/* An element removed at time t of a dynamics analysis (a cable that breaks). */
typedef struct ctn_removal {
    int element;     /* element index */
    double t;        /* [s] */
    int line;
} ctn_removal;

/* A growable array: data, count and capacity. */
#define CTN_ARRAY(T) struct { T *v; size_t n, cap; }

struct ctn_model {
    ctn_ctx *ctx;
    char file[256];  /* origin of the definitions being added */
    int line;
    char force_unit[4], length_unit[4];
    double mpa;      /* stress unit -> MPa, 0 if unit-less */
    double gravity[3];
    int gravity_line;
    CTN_ARRAY(ctn_node) nodes;
    CTN_ARRAY(ctn_material) materials;
    CTN_ARRAY(ctn_section) sections;
    CTN_ARRAY(ctn_element) elements;
    CTN_ARRAY(int) conn;            /* element connectivity (node indices) */
    CTN_ARRAY(ctn_pload) ploads;
    CTN_ARRAY(ctn_pload) mloads;    /* nodal moments */
    size_t rot_nodes;               /* nodes with 6 DOFs */
    CTN_ARRAY(ctn_pdisp) pdisps;
    CTN_ARRAY(ctn_hload) hloads;
    CTN_ARRAY(ctn_step) steps;      /* empty: one implicit step */
    CTN_ARRAY(ctn_cable) cables;
    CTN_ARRAY(ctn_group) groups;
    CTN_ARRAY(ctn_tload) tloads;
    CTN_ARRAY(ctn_lload) lloads;    /* loads per unstressed length (lineload) */
    CTN_ARRAY(ctn_case) cases;      /* load cases, in order */
    CTN_ARRAY(ctn_combo) combos;    /* combinations of cases */
    CTN_ARRAY(ctn_combo_term) terms;
    CTN_ARRAY(ctn_set) sets;        /* named node and element sets (sets.c) */
    int in_case;                    /* load records now go to the last case */
    double fconv, lconv;            /* the model's force and length units in N and m, 0
                                       when unit-less (values with units: units.c) */
    int converted;                  /* a value with a unit was converted (line), so the
                                       units may no longer change */
    ctn_idmap node_ids, element_ids;
    int max_node_id, max_element_id;
    CTN_ARRAY(ctn_density) densities; /* form finding: the members given q= or force=, by
                                       increasing element index */
    CTN_ARRAY(ctn_cable) etargets;  /* catenary elements set by a target, each as the
                                       record of a one-element cable (first = the element
                                       index, count = 1), by increasing element index */
    CTN_ARRAY(ctn_record) records;  /* time histories of a dynamics analysis, in order */
    CTN_ARRAY(ctn_fn) fns;          /* functions of time (dynamics) */
    CTN_ARRAY(ctn_dload) dloads;    /* forces and support motions that follow them */
    CTN_ARRAY(ctn_removal) removals; /* elements removed in time, in order */
    CTN_ARRAY(ctn_chart_row) chart; /* the sag-tension chart's rows, in order */
};

/* Make room for one more item in a CTN_ARRAY; 0 or CTN_ERR_NOMEM. */
#define CTN_ARRAY_RESERVE(ctx, a, extra)                                                 \
    ctn_array_reserve((ctx), (void **)&(a).v, &(a).cap, (a).n + (extra), sizeof *(a).v)
int ctn_array_reserve(ctn_ctx *ctx, void **v, size_t *cap, size_t need, size_t size);

/* Whether horizontal load h acts on element index e. Members without a section (springs)
 * carry none: `all`, ranges and groups pass over them, as temperature changes do. */
static inline int ctn_hload_on(const ctn_model *m, const ctn_hload *h, size_t e)
{
    const ctn_element *el = &m->elements.v[e];
    if (el->section < 0) return 0;
    return h->group >= 0 ? el->group == h->group : el->id >= h->first && el->id <= h->last;
}

/* The tag of a load record added now: the current step's, or the current case's. */
static inline int ctn_model_load_tag(const ctn_model *m)
{
    return m->in_case ? CTN_CASE_TAG0 + (int)m->cases.n - 1 : (int)m->steps.n;
}

/* Convert v, carrying `unit`, to the model's units for a quantity of force^f length^l
 * second^t (t = 2 for masses: kg = N s^2/m) (units.c); 1 with a message when the unit is
 * unknown, of another dimension, or the model has no units. */
int ctn_model_convert(ctn_model *m, const char *unit, int f, int l, int t, double *v, char *msg, size_t size);

/* Report an error located at the model's current origin (file:line if known). */
int ctn_model_error(const ctn_model *m, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Node indices of element e. */
static inline const int *ctn_elem_nodes(const ctn_model *m, size_t e)
{
    return m->conn.v + m->elements.v[e].conn;
}

/* The loads of a selection into f and the prescribed displacements into u (3 per node,
 * either may be NULL); dead_only: as below. */
void ctn_model_sel_loads(const ctn_model *m, const ctn_loadsel *sel, int dead_only, double *f, double *u);
/* Moments and prescribed rotations of a selection (either may be NULL). */
void ctn_model_sel_moments(const ctn_model *m, const ctn_loadsel *sel, double *M, double *r);
/* Temperature changes of a selection (ne). */
void ctn_model_sel_temperatures(const ctn_model *m, const ctn_loadsel *sel, double *dT);
/* Add the lineloads of a selection to f (3 per node): q l0 / 2 at each end; with
 * !dead_only the winds too, on the reference geometry (lineload.c). */
void ctn_model_add_lineloads(const ctn_model *m, const ctn_loadsel *sel, int dead_only, double *f);
/* Add the moments of the uniform loads on the families that take them with moments
 * (beams: the fixed-end moments of their weight and of a selection's lineloads) to M
 * (3 per node) (lineload.c). */
void ctn_model_add_line_moments(const ctn_model *m, const ctn_loadsel *sel, double *M);
/* The uniform load per unstressed length [F/L] on element e of a family with line_load
 * (weight w g and a selection's lineloads), global axes; 0 for other families. */
void ctn_model_element_line(const ctn_model *m, const ctn_loadsel *sel, size_t e, double q[3]);
/* wind TARGET: drag cdp d [force/length] along the unit direction dir, cdp = cd p and d
 * the bare diameter (lineload.c). */
int ctn_model_add_wind(ctn_model *m, const char *target, const double dir[3], double cdp, double d);
/* The air of the wind just added: its density rho [mass/L^3] (NAN: given by pressure=),
 * speed [L/s] and cd, for a dynamics analysis's drag on the relative velocity. */
int ctn_model_wind_air(ctn_model *m, double rho, double speed, double cd);
/* ice TARGET: the sleeve's weight q (a lineload) and its thickness t, which widens the
 * wind's diameter to d + 2 t on the elements it covers in the same solve. */
int ctn_model_add_ice(ctn_model *m, const char *target, const double q[3], double t);
/* The drag per unit projected length [force/length] of wind l on element e in a
 * selection (unweighted): cdp d, or cdp (d + 2 T) where ice of thickness T (the
 * thickest of the selection's ice on e with a positive weight) covers it. */
double ctn_model_drag_q(const ctn_model *m, const ctn_lload *l, const ctn_loadsel *sel, size_t e);
/* The unit direction of wind l. */
void ctn_lload_dir(const ctn_lload *l, double u[3]);
/* Whether lineload l acts on element e (cable elements of its target). */
int ctn_lload_on(const ctn_model *m, const ctn_lload *l, size_t e);
/* Checks made when the model is solved: every lineload reaches an element, and none a
 * family it cannot load exactly (lineload.c). */
int ctn_model_check_lineloads(const ctn_model *m);
/* lineload TARGET q: add the record (TARGET all, an element id or a group name). */
int ctn_model_add_lineload(ctn_model *m, const char *target, const double q[3]);

/* The selection of case or combination i (ctn_model_case_info; tags and factors: room
 * for its terms, at most the case count or 1) (cases.c). */
int ctn_model_case_sel(const ctn_model *m, size_t i, ctn_loadsel *sel, int *tags, double *factors);
int ctn_model_find_case(const ctn_model *m, const char *name);

/* ctn_model_step_loads; dead_only: without the hloads on the deformed projection (the
 * solver adds those at each state). */
int ctn_model_step_loads_ex(const ctn_model *m, size_t k, int dead_only, double *f, double *u);
/* Node index of user id, or a model error "undefined node ID". */
int ctn_model_node_lookup(const ctn_model *m, int id, int *index);
/* Copy a caller's versioned spec struct (its first field is its size) into dst, whose
 * fields the library has defaulted: only the bytes the caller's struct has are taken. */
void ctn_spec_copy(void *dst, size_t dst_size, const void *src);
/* Every part of the model (a set of elements joined through shared nodes) must hold a
 * node with at least one fixed DOF; else CTN_ERR_MODEL naming the part's elements, at
 * the line of its first element (parts.c). Linear time. */
int ctn_model_check_parts(const ctn_model *m);

int ctn_model_find_section(const ctn_model *m, const char *name);
/* A load's TARGET (groups.c): "all", an element id or a defined group, into *kind
 * (CTN_TARGET_*) and *index (the element's or group's index). An element the family
 * test accepts() refuses is a model error "WHAT: element ID is a FAMILY" + refusal;
 * an undefined id or name is one too. */
int ctn_model_load_target(ctn_model *m, const char *what, const char *target,
                          int (*accepts)(const ctn_model *, size_t), const char *refusal, int *kind, int *index);
/* Sets (sets.c). The index of set `name`, -1 if none. */
int ctn_model_find_set(const ctn_model *m, const char *name);
/* Whether element e is in the target (kind, index) of a load: all, an element, a group
 * or an element set (springs are in none but their own id: the caller tests families). */
int ctn_model_target_has(const ctn_model *m, int kind, int index, size_t e);
/* A new set `name` of nodes (nodes = 1) or elements with the given membership (n bytes,
 * copied); an error if the name is taken or the set is empty. */
int ctn_model_add_set(ctn_model *m, const char *name, int nodes, const unsigned char *member, size_t n);
/* Free the sets (model.c). */
void ctn_model_free_sets(ctn_model *m);
/* The generated cable with end node ids a and b (in that order or reversed: *reversed),
 * -1 with a model error when there is none or more than one. */
int ctn_model_find_cable(ctn_model *m, const char *what, int a, int b, int *reversed);
/* Group index of a name, -1 if none (groups.c). */
int ctn_model_find_group(const ctn_model *m, const char *name);
/* Group index of name, created (named at the current line) if new; a model error if the
 * name is not a valid group name. */
int ctn_model_group_get(ctn_model *m, const char *name, int *index);
/* Put element index e in group g: a model error if it is in another group. */
int ctn_model_group_put(ctn_model *m, size_t e, int g);
/* Temperature change of every element at the end of step k (0-based) into dT (ne). */
void ctn_model_step_temperatures(const ctn_model *m, size_t k, double *dT);
/* The same for element e alone. */
double ctn_model_element_temperature(const ctn_model *m, size_t k, size_t e);
/* The same in a selection (a case or a combination). */
double ctn_model_sel_element_temperature(const ctn_model *m, const ctn_loadsel *sel, size_t e);

/* Mass per unit unstressed length of section i: its mass=, else w / g (g standard
 * gravity in the model's units); NAN when the model has no units and the section a
 * weight but no mass= (mass.c). */
double ctn_model_section_mass(const ctn_model *m, int i);
int ctn_model_find_material(const ctn_model *m, const char *name);
/* The value of function i at time t (functions.c). */
double ctn_model_fn_value(const ctn_model *m, int i, double t);
/* The form-finding record of element e, NULL if it has none (density.c). */
const ctn_density *ctn_model_density_of(const ctn_model *m, size_t e);
/* Set it (inserted in order; CTN_ERR_NOMEM unless there is room: reserve first). */
int ctn_model_put_density(ctn_model *m, size_t e, double q, double force);

/* CTN_OK when every cable and catenary set by a target has had its length found
 * (ctn_model_resolve_targets); else CTN_ERR_INVALID naming the first at its line: what
 * reads a model's lengths (the problem, the comparisons and studies) refuses one that
 * still holds placeholders. */
int ctn_model_targets_found(ctn_ctx *ctx, const ctn_model *m);

#endif
