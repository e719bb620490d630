/*
 * catena/model.h - building a cable model.
 *
 * A model holds nodes (3 translational DOFs each), materials, sections, two-node cable
 * elements and loads. Build it with the ctn_model_add_* calls (or read a .cable file,
 * catena/io.h). Names (materials, sections) are case-sensitive; ids are positive ints.
 * Every call returns a status; on failure the context holds the message and the model
 * is left as it was before the call.
 */
#ifndef CATENA_MODEL_H
#define CATENA_MODEL_H

#include "catena/core.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

typedef struct ctn_model ctn_model;

/* Fixed-DOF flags of a node (bitwise or). */
enum { CTN_FIX_X = 1, CTN_FIX_Y = 2, CTN_FIX_Z = 4, CTN_FIX_ALL = 7 };
/* Fixed rotations (bitwise or with the above): only on a node that has rotations (a
 * family of 6 DOFs per node reaches it, ctn_model_node_dofs); else the model is refused
 * when it is solved (ctn_model_validate). CTN_FIX_ALL stays the three translations. */
enum { CTN_FIX_RX = 8, CTN_FIX_RY = 16, CTN_FIX_RZ = 32, CTN_FIX_ROT = 56, CTN_FIX_ALL6 = 63 };

/* Strain measure of a material (docs/theory.md). */
typedef enum ctn_strain {
    CTN_STRAIN_GREEN_LAGRANGE = 0, /* eps = (lambda^2 - 1)/2, N = E A eps lambda (paper) */
    CTN_STRAIN_ENGINEERING = 1     /* eps = lambda - 1, N = E A eps (Irvine) */
} ctn_strain;

/* Where Newton starts for a generated cable. */
typedef enum ctn_cable_start {
    CTN_START_ARC = 0,      /* the stretched arc through the ends (the paper's; default) */
    CTN_START_AUTO = 2,     /* the arc's guesses, which the default method (CTN_METHOD_AUTO)
                               replaces by the elastic catenary's where there is one: the
                               paper's pure Newton keeps the paper's start, the default
                               method starts a few iterations from the answer at any
                               inclination (the model file's default) */
    CTN_START_CATENARY = 1  /* Irvine's elastic catenary of the cable under its self-weight
                               (engineering strain), in the plane of chord and gravity; the
                               arc when the cable has no weight or a vertical chord */
} ctn_cable_start;

/* How the `cable` generator places its interior nodes. */
typedef enum ctn_cable_shape {
    CTN_SHAPE_ARC = 0,     /* circular arc of the cable's length, sagging along gravity */
    CTN_SHAPE_STRAIGHT = 1 /* on the chord between the end nodes */
} ctn_cable_shape;

#define CTN_CABLE_MAX_N 50000000   /* most elements of one generated cable */
#define CTN_SUBSTEPS_MAX 100000    /* most increments of one load step */

/* A prestress stated as engineers state it: the unstressed length is computed so that
 * the element carries it in the geometry it is given (its reference chord), by its own
 * strain law; a zero-load solve then returns it to round-off. */
typedef enum ctn_prestress {
    CTN_PRESTRESS_NONE = 0,   /* l0 as given (or the reference distance) */
    CTN_PRESTRESS_FORCE = 1,  /* N0 [force] (true axial force) */
    CTN_PRESTRESS_STRESS = 2, /* s0 = N0 / A [force/length^2] (families with a section) */
    CTN_PRESTRESS_STRAIN = 3  /* eps0, of the material's strain measure (spring: (l-l0)/l0) */
} ctn_prestress;
/* A cable set by a target instead of its length: the unstressed length that gives the
 * target in the solved model (under the span's weight and the loads acting with it) is
 * found by an outer root find (docs/theory.md, "Cables set by a target"). */
typedef enum ctn_cable_target {
    CTN_TARGET_NONE = 0,      /* the length is given */
    CTN_TARGET_H = 1,         /* horizontal tension at the first end (normal to gravity) */
    CTN_TARGET_SAG = 2,       /* largest distance below the chord, along gravity */
    CTN_TARGET_TENSION = 3    /* largest tension at the two ends */
} ctn_cable_target;
/* Parameters of a generated cable (ctn_model_add_cable). */
typedef struct ctn_cable_spec {
    int n;               /* number of elements, >= 1 */
    double length;       /* unstressed length S of the whole cable [length]; each element
                            gets l0 = S/n */
    ctn_cable_shape shape;
    double guess_strain; /* arc shape: the Newton start is the stretched arc through the
                            same ends on which every element has this strain (default
                            1e-3, see docs/theory.md); 0 starts from the arc itself */
    ctn_cable_start start;  /* CTN_START_ARC (zero-initialized default), _CATENARY or _AUTO */
    ctn_prestress prestress;  /* every element's l0 from this prestress in its generated
                                 chord instead of length / n (default none) */
    double prestress_value;
    const char *group;   /* every element joins this group (NULL: none) */
    ctn_cable_target target;  /* instead of `length`: the length is found to meet it by
                                 ctn_model_resolve_targets, which must run before the
                                 model is solved or compared (they refuse it until then) */
    double target_value;      /* H [force], sag [length] or tension [force] */
} ctn_cable_spec;
/* The `cable` directive's defaults: n and length 0 (to be set), shape arc, guess_strain
 * 1e-3, start auto, no prestress, no group, no target. Start every spec from it: a
 * zero-initialised spec means guess_strain 0 and start arc, which a sagging cable may
 * not converge from. */
void ctn_cable_spec_init(ctn_cable_spec *s);

/* Create an empty model bound to ctx (errors are recorded there; ctx must outlive it). */
int ctn_model_create(ctn_ctx *ctx, ctn_model **out);
/* Destroy; NULL or *m == NULL is a harmless no-op; sets *m to NULL. */
void ctn_model_destroy(ctn_model **m);

/* Units (labels, and the stress conversion to MPa): force "N" | "kN" | "MN",
 * length "mm" | "m". Without a call the model is unit-less. */
int ctn_model_set_units(ctn_model *m, const char *force, const char *length);
/* Gravity vector: direction and scale of self-weight (the section's w times this
 * vector, per unit unstressed length). Default: none (zero); then every section must
 * have w == 0. */
int ctn_model_set_gravity(ctn_model *m, const double g[3]);

/* Versioned spec structs. Each begins with `size`, the size of the struct as the caller
 * compiled it; ctn_*_spec_init() sets it and every other field to its default. New keys
 * are added at the end, so a program built against an older header keeps working: the
 * library reads only the fields the caller's struct has. */

/* A material. */
typedef struct ctn_material_spec {
    size_t size;          /* sizeof(ctn_material_spec) (set by ctn_material_spec_init) */
    const char *name;     /* unique name (case-sensitive), 1 to 63 characters */
    double E;             /* Young's modulus > 0 [force/length^2] */
    ctn_strain strain;    /* strain measure (default CTN_STRAIN_GREEN_LAGRANGE) */
    int tension_only;     /* 1: members carry no compression (default 0) */
    double alpha;         /* coefficient of thermal expansion [1/K] (default 0) */
    double G;             /* shear modulus >= 0 [force/length^2], for beams (default 0: not
                             given) */
    double fy;            /* yield stress > 0 [force/length^2]: the beams' utilisation,
                             combined stress / fy (default 0: not given) */
} ctn_material_spec;
void ctn_material_spec_init(ctn_material_spec *s);
int ctn_model_add_material_spec(ctn_model *m, const ctn_material_spec *s);

/* A section of a cable. */
typedef struct ctn_section_spec {
    size_t size;          /* sizeof(ctn_section_spec) (set by ctn_section_spec_init) */
    const char *name;     /* unique name */
    const char *material; /* name of a defined material */
    double A;             /* area > 0 [length^2] */
    double w;             /* weight per unit unstressed length >= 0 [force/length] (default 0) */
    double mbl;           /* minimum breaking load > 0 [force] (default 0: not given) */
    double safety;        /* safety factor > 0 on mbl: capacity = mbl / safety (default 1) */
    double mass;          /* mass per unit unstressed length >= 0 [force s^2/length^2, the
                             consistent unit: t/m for kN and m, kg/m for N and m, t/mm for
                             N and mm] (default CTN_MASS_DEFAULT: w / g, g = 9.80665 m/s^2
                             in the model's length unit; see ctn_model_set_node_mass) */
    /* Beam properties (for families with rotations; cables ignore them), each >= 0,
     * default 0 (not given): */
    double Iy, Iz;        /* second moments of area about the section's y and z axes [length^4] */
    double J;             /* torsion constant [length^4] */
    double Asy, Asz;      /* shear areas along y and z [length^2] (0: no shear deformation) */
    double Wy, Wz;        /* elastic section moduli about y and z [length^3]: the extreme
                             fibre's bending stress M / W (0: not given) */
} ctn_section_spec;
#define CTN_MASS_DEFAULT (-1.0)
void ctn_section_spec_init(ctn_section_spec *s);
int ctn_model_add_section_spec(ctn_model *m, const ctn_section_spec *s);

/* An element of a registered family (docs/format.md):
 *   "cable"  two nodes, section, unstressed length l0 (CTN_L0_DEFAULT: the reference
 *            distance between the nodes); the material's strain law, self-weight w l0;
 *   "spring" two nodes, stiffness k > 0, free length l0 (CTN_L0_DEFAULT: the reference
 *            distance); N = k (l - l0), two-way, weightless, no section;
 *   "catenary" two nodes, section, unstressed length l0 (default: the reference distance):
 *            one exact elastic catenary (Irvine, engineering strain) with its weight
 *            w l0 along gravity; prestress N0 = its largest end tension; or a target
 *            (H, sag, tension) that sets l0;
 *   "pulley" three or more nodes (ends, then pulleys in order; at most 64), section, the
 *            unstressed length l0 of the whole cable (default: the reference polyline):
 *            one tension along straight segments, tension-only;
 *   "rspring" two nodes, rotational stiffness k > 0 [force length/rad]: the moment
 *            k (theta2 - theta1) between the nodes' rotations (small rotations), no
 *            section; it gives its nodes rotations (6 DOFs, ctn_model_node_dofs);
 *   "beam"   two nodes, section with Iy, Iz, J > 0 and a material with G: a corotational
 *            3D beam (finite rotations; the rotation DOFs are the node's rotation
 *            vector), local axes by orient; self-weight w l0 lumped at the nodes. */
#define CTN_L0_DEFAULT (-1.0)
typedef struct ctn_element_spec {
    size_t size;          /* sizeof(ctn_element_spec) (set by ctn_element_spec_init) */
    const char *type;     /* family name; NULL or "cable" (default), "spring", "catenary",
                             "pulley", "rspring", "beam" */
    int id;               /* user id > 0, unique among elements */
    int nnodes;           /* number of entries of nodes (the family's node count) */
    const int *nodes;     /* user node ids (copied) */
    const char *section;  /* families with a section: its name */
    double l0;            /* unstressed / free length [length] (default CTN_L0_DEFAULT) */
    double k;             /* spring: stiffness [force/length]; rspring: [force length/rad] */
    ctn_prestress prestress;  /* instead of l0 (then l0 must stay CTN_L0_DEFAULT) */
    double prestress_value;   /* its value N0, s0 or eps0 */
    const char *group;    /* the group it joins (created if new; NULL: none) */
    double q;             /* form finding (catena/formfind.h): force density N / l
                             [force/length], > 0; 0 (default): none. ctn_solve ignores it */
    double force;         /* form finding: target force [force], > 0; 0 (default): none.
                             At most one of q and force; ctn_solve ignores it */
    ctn_cable_target target;  /* catenary: instead of l0 (then l0 must stay CTN_L0_DEFAULT
                                 and no prestress be given), the unstressed length is
                                 found to meet H, sag or tension in the solved model, as a
                                 cable's (ctn_model_resolve_targets); default
                                 CTN_TARGET_NONE */
    double target_value;      /* H [force], sag [length] or tension [force], > 0 */
    double orient[3];         /* beam: a vector in the member's local x-z plane (not along
                                 the member); 0, 0, 0 (default): global z, or global x
                                 for a vertical member */
    unsigned release;         /* beam: end releases, CTN_RELEASE_* or'ed (0, default: none):
                                 the member's end does not take the moment about that local
                                 axis (a hinge); a meshed member (n > 1) releases its first
                                 element's NODE1 end and its last element's NODE2 end */
} ctn_element_spec;
/* Beam end releases (ctn_element_spec.release): the local axes x (torsion), y, z at NODE1
 * (bits 0..2) and at NODE2 (bits 3..5). */
#define CTN_RELEASE_RX1 1u
#define CTN_RELEASE_RY1 2u
#define CTN_RELEASE_RZ1 4u
#define CTN_RELEASE_RX2 8u
#define CTN_RELEASE_RY2 16u
#define CTN_RELEASE_RZ2 32u
void ctn_element_spec_init(ctn_element_spec *s);
int ctn_model_add_element_spec(ctn_model *m, const ctn_element_spec *s);

/* Shorthands for the spec calls above, with the other fields at their defaults. */
int ctn_model_add_material(ctn_model *m, const char *name, double E, ctn_strain strain,
                           int tension_only);
/* A section: area A > 0 and weight per unit unstressed length w >= 0. */
int ctn_model_add_section(ctn_model *m, const char *name, const char *material, double A,
                          double w);
/* A node with id > 0 at reference coordinates X, fixed DOFs `fix` (CTN_FIX_*). */
int ctn_model_add_node(ctn_model *m, int id, const double X[3], unsigned fix);
/* A lumped point mass >= 0 at node id (an insulator, a clamp), in the model's consistent
 * mass unit (force s^2/length: t for kN and m, kg for N and m, t for N and mm); it
 * replaces an earlier one. Mass enters modal analysis only (ctn_problem_modes): the
 * point's weight is a load (ctn_model_add_load). */
int ctn_model_set_node_mass(ctn_model *m, int id, double mass);
/* Standard gravity 9.80665 m/s^2 in the model's length unit per s^2 (9806.65 for mm), 0
 * for a model without units: the divisor of the default mass w / g. */
double ctn_model_standard_gravity(const ctn_model *m);
/* A two-node cable element between existing nodes n1 != n2 (user ids), with unstressed
 * length l0 > 0 or CTN_L0_DEFAULT. */
int ctn_model_add_element(ctn_model *m, int id, int n1, int n2, const char *section,
                          double l0);
/* Generate a cable of spec->n elements from node a to node b (see ctn_cable_spec):
 * interior nodes and elements are numbered after the largest existing ids, in order
 * from a to b. On success *first_elem / *last_elem (may be NULL) get the element ids.
 * All checks come before anything is added; should a generated element still be
 * rejected (coincident nodes from extreme geometry), the model keeps the part already
 * made and should be discarded. */
int ctn_model_add_cable(ctn_model *m, int a, int b, const char *section,
                        const ctn_cable_spec *spec, int *first_elem, int *last_elem);
/* A beam member from spec->nodes[0] to spec->nodes[1] (spec->type is taken as "beam")
 * meshed into n elements (1 <= n <= CTN_BEAM_MAX_N) of equal length: the n - 1 interior
 * nodes are numbered after the largest existing node id, in order; the first element
 * takes spec->id, the others are numbered from CTN_BEAM_GEN_ID + 1 up (after the
 * largest element id when that is larger), so that they keep out of the way of the ids
 * of the members defined next. Should an element be rejected, the model keeps the part
 * already made and should be discarded. */
#define CTN_BEAM_MAX_N 100000
#define CTN_BEAM_GEN_ID 1000000
int ctn_model_add_beam(ctn_model *m, const ctn_element_spec *spec, int n);
/* Nodes and elements from arrays, in bulk: row i is checked and added as the
 * one-at-a-time call (ctn_model_add_node, ctn_model_add_element_spec) checks and adds it,
 * with its messages; when the model has an origin line (ctn_model_set_origin with
 * line > 0, as the reader sets it), row i is taken as line `line + i` of that file (its
 * messages name it, "file:line: duplicate node id 7 (defined on line 3)", and the record
 * keeps it), so that n rows read as the n lines of a file would. Storage for all rows is
 * reserved first. On failure the context names the first bad row; the rows before it
 * stay in the model (as a file's lines before a bad one), which should be discarded.
 *
 * n nodes: ids[i], coordinates X[3 i .. 3 i + 2], fixed DOFs fix[i] (CTN_FIX_*; fix NULL:
 * all free). */
int ctn_model_add_nodes(ctn_model *m, size_t n, const int *ids, const double *X, const unsigned *fix);
/* The columns of ctn_model_add_elements: n rows; element i takes id ids[i] and the
 * spec's nnodes node ids nodes[nnodes i .. nnodes i + nnodes - 1]; each optional column
 * (NULL: the spec's value for every row) gives row i its own value of that spec field.
 * Versioned as the specs are (size first; ctn_element_rows_init). */
typedef struct ctn_element_rows {
    size_t size;                     /* sizeof(ctn_element_rows) (set by the init) */
    size_t n;                        /* number of rows */
    const int *ids;                  /* n element ids */
    const int *nodes;                /* n * spec->nnodes user node ids */
    const double *l0;                /* spec.l0 per row, or NULL */
    const double *prestress_value;   /* spec.prestress_value per row (N0, s0 or eps0 as
                                        spec.prestress says), or NULL */
    const double *k;                 /* spec.k per row (springs), or NULL */
    const double *q;                 /* spec.q per row (form finding), or NULL */
    const double *force;             /* spec.force per row (form finding), or NULL */
    const double *target_value;      /* spec.target_value per row (catenary: H, sag or
                                        tension as spec.target says), or NULL */
    const double *orient;            /* beam: spec.orient per row, 3 per row, or NULL */
    const unsigned *release;         /* beam: spec.release per row, or NULL */
    const int *segments;             /* beam: the elements each member is meshed into
                                        (ctn_model_add_beam's n) per row; NULL: 1 */
} ctn_element_rows;
void ctn_element_rows_init(ctn_element_rows *r);
/* rows->n elements of spec's family and keys (spec->id and spec->nodes are ignored: the
 * rows give them), as ctn_model_add_element_spec would add them one by one (a beam as
 * ctn_model_add_beam with the row's segments): every family, pulleys with spec->nnodes
 * nodes each. */
int ctn_model_add_elements(ctn_model *m, const ctn_element_spec *spec, const ctn_element_rows *rows);
/* Concentrated force F at a node (summed with earlier loads on that node). Belongs
 * to the current step (see ctn_model_add_step). */
int ctn_model_add_load(ctn_model *m, int node, const double F[3]);
/* Prescribed displacement u of a node's fixed DOFs named in `dofs` (CTN_FIX_*; each
 * must be fixed). Like loads, increments add up over the steps. */
int ctn_model_add_displacement(ctn_model *m, int node, unsigned dofs, const double u[3]);
/* Concentrated moment M [force length] about x, y, z at a node (summed with earlier
 * ones; belongs to the current step). The node must have rotations by the time the model
 * is solved (else ctn_model_validate names the moment's line). */
int ctn_model_add_moment(ctn_model *m, int node, const double M[3]);
/* Prescribed rotation r [rad] about x, y, z of a node's fixed rotations named in `dofs`
 * (CTN_FIX_RX, _RY, _RZ; each must be fixed). Increments add up over the steps, as
 * displacements do. */
int ctn_model_add_rotation(ctn_model *m, int node, unsigned dofs, const double r[3]);
/* Start a new load step named `name`: the loads, horizontal loads and displacements
 * added after it are its increments; step k is solved from the state of step k-1, in
 * `substeps` equal increments (0: the solve options' `steps`). Without any step the
 * model has one implicit step holding everything. Nodes, elements and cables must be
 * defined before the first step. */
int ctn_model_add_step(ctn_model *m, const char *name, int substeps);
size_t ctn_model_step_count(const ctn_model *m);          /* >= 1 */
const char *ctn_model_step_name(const ctn_model *m, size_t k); /* "" for the implicit step */
int ctn_model_step_substeps(const ctn_model *m, size_t k);
/* Totals at the end of step k (0-based): external nodal forces f and prescribed
 * displacements u, 3 per node each (either may be NULL). Self-weight is in every step. */
int ctn_model_step_loads(const ctn_model *m, size_t k, double *f, double *u);
/* The same for the rotations: nodal moments M and prescribed rotations r at the end of
 * step k, 3 per node each (either may be NULL; zero on nodes without rotations). */
int ctn_model_step_moments(const ctn_model *m, size_t k, double *M, double *r);
/* Uniform load q [force/length] per unit horizontal projection (the plane normal to
 * gravity) on elements with ids first..last, along gravity's direction; half of each
 * element's share goes to each of its nodes. The projection is the element's current
 * one by default (CTN_PROJECT_DEFORMED: the load follows the geometry, as a deck's weight
 * on a suspension cable whatever its start shape; its derivative is in the tangent), or
 * the reference one (CTN_PROJECT_REFERENCE: a dead load, as from hangers at fixed
 * stations). Belongs to the current step. */
typedef enum ctn_projection {
    CTN_PROJECT_DEFORMED = 0,
    CTN_PROJECT_REFERENCE = 1
} ctn_projection;
int ctn_model_add_hload(ctn_model *m, double q, int first, int last);   /* deformed */
int ctn_model_add_hload_projected(ctn_model *m, double q, int first, int last, ctn_projection proj);
/* The same on the elements of a defined group. */
int ctn_model_add_hload_group(ctn_model *m, double q, const char *group, ctn_projection proj);
/* Groups of elements (names: a letter first, then letters, digits, '_', '-' or '.'; not
 * "all"). An element belongs to at most one group. Adds the elements with ids first..last
 * (the ids in the range that exist; at least one must) to group `name`, created if new. */
int ctn_model_add_group(ctn_model *m, const char *name, int first, int last);
size_t ctn_model_group_count(const ctn_model *m);
const char *ctn_model_group_name(const ctn_model *m, size_t g);   /* NULL if out of range */
/* A temperature change dT [K] from the reference temperature, of `target`: "all", a
 * group name, or an element id in decimal. Belongs to the current step (increments add
 * up over the steps, ramped in its substeps like loads). An element's unstressed length
 * becomes l0 (1 + alpha dT), alpha its material's; its weight stays w l0. */
int ctn_model_add_temperature(ctn_model *m, const char *target, double dT);
/* A load per unit unstressed length q = (qx, qy, qz) [force/length] in a fixed direction
 * on the cable elements of `target` ("all", a group name, or an element id in decimal),
 * lumped q l0 / 2 at each end of each element; in the current step or case. Catenary and
 * pulley elements are refused (the lumping would not be exact on them). */
int ctn_model_add_lineload(ctn_model *m, const char *target, const double q[3]);
/* Load cases and combinations (docs/format.md, `case`): a case NAME solved from the
 * converged end of step `from` (NULL: the last step defined so far); the loads,
 * temperatures and displacements added after it are the case's, until the next step or
 * case. A combination sums n earlier cases (of one installed state) times their factors;
 * each case and combination is solved non-linearly from the installed state. */
int ctn_model_add_case(ctn_model *m, const char *name, const char *from, int substeps);
int ctn_model_add_combination(ctn_model *m, const char *name, const char *const *cases, const double *factors,
                              size_t n);
/* Cases then combinations: their count; the i-th's name, installed state (the index of
 * its step) and kind (1: a combination). */
size_t ctn_model_case_count(const ctn_model *m);
int ctn_model_case_info(const ctn_model *m, size_t i, const char **name, int *from, int *combination);
/* The sag-tension chart (`sagtension`, docs/format.md): its rows, and row r's case or
 * combination (*entry, an index for ctn_model_case_info), its temperature change [K] and
 * the case it adds to (*base NULL: none). */
size_t ctn_model_chart_count(const ctn_model *m);
int ctn_model_chart_row(const ctn_model *m, size_t r, size_t *entry, double *dT, const char **base);
/* Term k of entry i (a combination): its case's name and factor. */
int ctn_model_case_term(const ctn_model *m, size_t i, size_t k, const char **name, double *factor);
size_t ctn_model_case_terms(const ctn_model *m, size_t i);
/* Reference "file:line" recorded with the next definitions, used in later validation
 * messages (the reader sets it; API users may ignore it). file is copied. */
int ctn_model_set_origin(ctn_model *m, const char *file, int line);

/* ---- queries ---- */
typedef struct ctn_node_info {
    int id;          /* user id */
    double X[3];     /* reference coordinates [length] */
    double guess[3]; /* displacement the Newton iteration starts from [length] */
    unsigned fix;    /* CTN_FIX_* flags */
} ctn_node_info;

typedef struct ctn_element_info {
    int id;          /* user id */
    const char *type;/* family name ("cable", "spring") */
    int nnodes;      /* number of nodes */
    const int *nodes;/* node indices (0-based, into ctn_model_node), owned by the model,
                        valid until the model changes */
    int node[2];     /* its first and last node indices (the ends) */
    double l0;       /* unstressed (free) length [length] */
    int has_section; /* 1 if the family has a section: A, E, w, strain, tension_only
                        below are its; 0 (spring): they are 0 */
    double A;        /* area [length^2] */
    double E;        /* modulus [force/length^2] */
    double w;        /* weight per unit unstressed length [force/length] */
    ctn_strain strain;
    int tension_only;
    double k;        /* spring stiffness [force/length], rspring's [force length/rad];
                        0 for other families */
    const char *group;   /* its group's name, NULL if none */
    double capacity; /* mbl / safety of its section [force], 0 if no mbl */
    double alpha;    /* thermal expansion of its material [1/K] */
} ctn_element_info;

/* A cable made by the generator: its end nodes and its element index range (also the
 * record of a catenary element set by a target, ctn_model_element_target). */
typedef struct ctn_cable_info {
    int node[2];     /* end node indices */
    size_t first;    /* index of its first element */
    size_t count;    /* number of elements, consecutive from first, ordered end 0 -> 1 */
    double length;   /* unstressed length (for a target: the length found) */
    ctn_cable_target target;  /* CTN_TARGET_NONE, or what set the length */
    double target_value;      /* the target asked */
    double target_achieved;   /* its value in the solved first step, once resolved */
    int target_iterations;    /* outer iterations of the root find (0 before it) */
} ctn_cable_info;

size_t ctn_model_node_count(const ctn_model *m);
size_t ctn_model_element_count(const ctn_model *m);
size_t ctn_model_cable_count(const ctn_model *m);
/* Index-based access; CTN_ERR_INVALID if i is out of range. */
int ctn_model_node(const ctn_model *m, size_t i, ctn_node_info *out);
int ctn_model_element(const ctn_model *m, size_t i, ctn_element_info *out);
int ctn_model_cable(const ctn_model *m, size_t i, ctn_cable_info *out);
/* The target that sets the unstressed length of element i (a catenary given H=, sag= or
 * tension=), described as a one-element cable: its end nodes, first = i, count = 1,
 * length = its unstressed length (the one found, once resolved) and the target fields.
 * out->target is CTN_TARGET_NONE for an element without a target. CTN_ERR_INVALID if i
 * is out of range. Logarithmic in the number of such elements. */
int ctn_model_element_target(const ctn_model *m, size_t i, ctn_cable_info *out);
/* Degrees of freedom of node i: 3 (translations x, y, z), or 6 (and rotations about x,
 * y, z) when a family of 6 DOFs per node reaches it; 0 if i is out of range. */
int ctn_model_node_dofs(const ctn_model *m, size_t i);
/* Whether some node has rotations (6 DOFs). */
int ctn_model_has_rotations(const ctn_model *m);
/* Node index of a user id; CTN_ERR_INVALID if there is none. */
int ctn_model_node_index(const ctn_model *m, int id, size_t *index);
/* Gravity vector (zero if none). */
void ctn_model_gravity(const ctn_model *m, double g[3]);
/* Unit labels ("" when unit-less) and the factor that turns a stress in model units
 * (force/length^2) into MPa (0 when unit-less). */
const char *ctn_model_force_unit(const ctn_model *m);
const char *ctn_model_length_unit(const ctn_model *m);
double ctn_model_mpa_factor(const ctn_model *m);
/* The file name of the last ctn_model_set_origin (for a model read by the reader, the
 * path or name it was read from), "" if none: for messages about the model. Owned by m. */
const char *ctn_model_file(const ctn_model *m);
/* External nodal force vector at the end of the last step, 3 per node (concentrated
 * + self-weight + horizontal loads, lumped; hloads on the reference projection: on the
 * deformed one they depend on the solution), written to f (length 3 * node count). */
int ctn_model_external_forces(const ctn_model *m, double *f);
/* Check the whole model (called by the solver): sections with weight need gravity,
 * at least one support, ... */
int ctn_model_validate(const ctn_model *m);

/* Time histories that a dynamics analysis records (catena/analysis.h), in the order
 * asked: the displacements of node id in the directions dofs (bits CTN_FIX_X, CTN_FIX_Y,
 * CTN_FIX_Z; 0: all three; CTN_FIX_RX .. CTN_FIX_RZ its rotation vector's components, a
 * node with rotations only), or the axial force of element id. CTN_ERR_MODEL for an
 * undefined id or one recorded twice. */
int ctn_model_record_node(ctn_model *m, int id, unsigned dofs);
int ctn_model_record_element(ctn_model *m, int id);
/* The support reactions of node id (it must have a fix=) in the directions dofs (0: its
 * fixed ones; CTN_FIX_RX .. CTN_FIX_RZ the reaction moments of a node with rotations):
 * f_int + M a + C v - f_ext there, inertia (a rotation's R (J A + W x J W)) and damping
 * included. */
int ctn_model_record_reaction(ctn_model *m, int id, unsigned dofs);
size_t ctn_model_record_count(const ctn_model *m);

/* Functions of time for a dynamics analysis (docs/format.md "Dynamics"): par holds
 * ramp, step: t0, t1 (t1 > t0 for a ramp; step: t1 unused); harmonic: amp, freq [Hz],
 * phase [rad], offset; table: t (n >= 2 points, strictly increasing) and v, linear
 * between the points, held beyond the ends. The name must be new. */
typedef enum ctn_fn_kind { CTN_FN_RAMP = 0, CTN_FN_STEP = 1, CTN_FN_HARMONIC = 2, CTN_FN_TABLE = 3 } ctn_fn_kind;
int ctn_model_add_function(ctn_model *m, const char *name, ctn_fn_kind kind, const double par[4], const double *t,
                           const double *v, size_t n);
/* A force F at node id times function fn(t), or (dofs != 0) a prescribed motion u fn(t)
 * of the node's fixed directions dofs (CTN_FIX_X | _Y | _Z) added to their static
 * displacement: both applied by a dynamics analysis only (a static analysis leaves
 * them out). CTN_ERR_MODEL for an undefined node or function, a motion of a free DOF. */
int ctn_model_add_load_fn(ctn_model *m, int id, const double F[3], const char *fn);
int ctn_model_add_motion_fn(ctn_model *m, int id, unsigned dofs, const double u[3], const char *fn);
/* Element id removed at time t >= 0 of a dynamics analysis (its force and stiffness
 * zero from then on, its mass kept: a cable that breaks). Cable elements and springs
 * only; CTN_ERR_MODEL for another family, an undefined element, one removed twice. */
int ctn_model_add_removal(ctn_model *m, int id, double t);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
