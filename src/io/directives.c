/* The directives of the .cable format (docs/format.md), one handler each. */
#include "io/fmt.h"
#include "io/parse.h"
#include "catena/analysis.h"
#include "catena/formfind.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* An integer-valued key in [lo, hi]; *out unchanged when absent. */
static int key_int(ctn_line *l, const char *key, int lo, int hi, int *out)
{
    const char *v = ctn_parse_key(l, 1, key);
    double x;
    char what[64];
    snprintf(what, sizeof what, "'%s'", key);
    if (!v) return CTN_OK;
    long long n = 0;
    int rc = ctn_parse_num(l, what, v, &x);                /* not a number, or not finite */
    if (rc) return rc;
    if (!ctn_parse_integral(v, &n) || n < lo || n > hi)
        return ctn_parse_error(l, "%s must be an integer from %d to %d (found %.40s)", key, lo, hi, v);
    *out = (int)n;
    return CTN_OK;
}

/* A keyword-valued key: index into words[], *out unchanged when absent. */
static int key_word(ctn_line *l, const char *key, const char *const *words, int n, int *out)
{
    const char *v = ctn_parse_key(l, 1, key);
    if (!v) return CTN_OK;
    for (int i = 0; i < n; i++)
        if (!strcmp(v, words[i])) { *out = i; return CTN_OK; }
    char b[64];
    return ctn_parse_error(l, "unknown %s '%s'", key, ctn_parse_show(v, b, sizeof b));
}

static int d_units(ctn_line *l)
{
    int rc = ctn_parse_positional(l, 2, "units FORCE LENGTH");
    if (!rc) rc = ctn_parse_leftovers(l, 3, "units");
    return rc ? rc : ctn_model_set_units(l->m, l->tok[1], l->tok[2]);
}

static int d_gravity(ctn_line *l)
{
    double g[3];
    int rc = ctn_parse_positional(l, 3, "gravity GX GY GZ");
    for (int k = 0; k < 3 && !rc; k++) rc = ctn_parse_num(l, "a gravity component", l->tok[1 + k], &g[k]);
    if (!rc) rc = ctn_parse_leftovers(l, 4, "gravity");
    return rc ? rc : ctn_model_set_gravity(l->m, g);
}

/* nu= (Poisson's ratio, -1 < nu <= 0.5): G = E / (2 (1 + nu)), instead of G=. */
static int material_nu(ctn_line *l, ctn_material_spec *spec)
{
    double nu = 0;
    if (!ctn_parse_key(l, 2, "nu")) return CTN_OK;
    if (spec->G > 0) return ctn_parse_error(l, "material %s: give G= or nu=, not both", l->tok[1]);
    int rc = ctn_parse_key_num(l, 2, "nu", 1, &nu);
    if (!rc && !(nu > -1 && nu <= 0.5))
        return ctn_parse_error(l, "material %s: nu must be above -1 and at most 0.5 (found %g)", l->tok[1], nu);
    if (!rc) spec->G = spec->E / (2 * (1 + nu));
    return rc;
}

static int d_material(ctn_line *l)
{
    ctn_material_spec spec;
    ctn_material_spec_init(&spec);
    ctn_strain strain = CTN_STRAIN_GREEN_LAGRANGE;
    int rc = ctn_parse_positional(l, 1, "material NAME E=VALUE [strain=green-lagrange|engineering] [tension-only] [alpha=PER_KELVIN] [G=VALUE|nu=RATIO] [fy=STRESS]");
    if (!rc) rc = ctn_parse_key_num(l, 2, "E", 1, &spec.E);
    if (!rc) rc = ctn_parse_key_num(l, 2, "G", 0, &spec.G);
    if (!rc) rc = material_nu(l, &spec);
    if (!rc) rc = ctn_parse_key_num(l, 2, "alpha", 0, &spec.alpha);
    if (!rc) rc = ctn_parse_key_num(l, 2, "fy", 0, &spec.fy);
    if (!rc && ctn_parse_key(l, 2, "fy") && !(spec.fy > 0))
        return ctn_parse_error(l, "material %s: fy must be positive (found %g)", l->tok[1], spec.fy);
    const char *s = rc ? NULL : ctn_parse_key(l, 2, "strain");
    if (s && !strcmp(s, "engineering")) strain = CTN_STRAIN_ENGINEERING;
    else if (s && strcmp(s, "green-lagrange"))
        return ctn_parse_error(l, "unknown strain measure '%.40s' (expected green-lagrange or engineering)", s);
    int tension_only = rc ? 0 : ctn_parse_flag(l, 2, "tension-only");
    if (!rc) rc = ctn_parse_leftovers(l, 2, "material");
    spec.name = l->tok[1];
    spec.strain = strain;
    spec.tension_only = tension_only;
    return rc ? rc : ctn_model_add_material_spec(l->m, &spec);
}

static int d_section(ctn_line *l)
{
    ctn_section_spec spec;
    ctn_section_spec_init(&spec);
    int rc = ctn_parse_positional(l, 1, "section NAME material=MATERIAL A=AREA|d= [t=]|b= h= t=|b= h= tf= tw= [w=WEIGHT] [mass=MASS] [mbl=FORCE] [safety=FACTOR] [Iy=] [Iz=] [J=] [Asy=] [Asz=] [Wy=] [Wz=]");
    const char *mat = rc ? NULL : ctn_parse_key(l, 2, "material");
    if (!rc && !mat) return ctn_parse_missing(l, 2, NULL, "material", NULL);
    int shaped = 0;
    if (!rc) rc = ctn_parse_section_shape(l, &spec, &shaped);
    if (!rc) rc = ctn_parse_key_num(l, 2, "A", !shaped, &spec.A);
    if (!rc) rc = ctn_parse_key_num(l, 2, "w", 0, &spec.w);
    const char *mv = rc ? NULL : ctn_parse_key(l, 2, "mass");
    if (mv) {
        rc = ctn_parse_num(l, "'mass' per length", mv, &spec.mass);
        if (!rc && !(spec.mass >= 0)) return ctn_parse_error(l, "section: mass must be >= 0 (found %g)", spec.mass);
    }
    if (!rc) rc = ctn_parse_key_num(l, 2, "mbl", 0, &spec.mbl);
    if (!rc) rc = ctn_parse_key_num(l, 2, "safety", 0, &spec.safety);
    double *beam[7] = { &spec.Iy, &spec.Iz, &spec.J, &spec.Asy, &spec.Asz, &spec.Wy, &spec.Wz };
    static const char *const beam_key[7] = { "Iy", "Iz", "J", "Asy", "Asz", "Wy", "Wz" };
    const double shape_I[2] = { spec.Iy, spec.Iz }, shape_W[2] = { spec.Wy, spec.Wz };
    for (int k = 0; k < 7 && !rc; k++) rc = ctn_parse_key_num(l, 2, beam_key[k], 0, beam[k]);
    if (!rc && shaped) ctn_parse_section_moduli(l, shape_I, shape_W, &spec);
    if (!rc && ctn_parse_key(l, 2, "mbl") && !(spec.mbl > 0))
        return ctn_parse_error(l, "section %s: mbl must be positive (found %g)", l->tok[1], spec.mbl);
    if (!rc && ctn_parse_key(l, 2, "safety") && !ctn_parse_key(l, 2, "mbl"))
        return ctn_parse_error(l, "section %s: safety= applies to mbl=, which is missing", l->tok[1]);
    if (!rc) rc = ctn_parse_leftovers(l, 2, "section");
    spec.name = l->tok[1];
    spec.material = mat;
    return rc ? rc : ctn_model_add_section_spec(l->m, &spec);
}

/* fix=: the translations x, y, z and the rotations rx, ry, rz, each at most once. */
static int parse_fix(ctn_line *l, unsigned *fix)
{
    const char *f = ctn_parse_key(l, 5, "fix");
    *fix = 0;
    for (const char *p = f; p && *p; p++) {
        int rot = *p == 'r';
        p += rot;
        unsigned bit = *p == 'x' ? CTN_FIX_X : *p == 'y' ? CTN_FIX_Y : *p == 'z' ? CTN_FIX_Z : 0;
        bit <<= rot ? 3 : 0;
        if (!bit || (*fix & bit))
            return ctn_parse_error(l, "fix= takes the letters x, y, z (and rx, ry, rz for rotations), each once (found '%.40s')", f);
        *fix |= bit;
    }
    return CTN_OK;
}

static int d_node(ctn_line *l)
{
    int id = 0;
    double X[3];
    unsigned fix = 0;
    double mass = 0;
    int rc = ctn_parse_positional(l, 4, "node ID X Y Z [fix=xyz] [mass=MASS]");
    if (!rc) rc = ctn_parse_int(l, "the node id", l->tok[1], &id);
    for (int k = 0; k < 3 && !rc; k++) rc = ctn_parse_num(l, "a coordinate", l->tok[2 + k], &X[k]);
    if (!rc) rc = parse_fix(l, &fix);
    if (!rc) rc = ctn_parse_key_num(l, 5, "mass", 0, &mass);
    if (!rc && !(mass >= 0)) return ctn_parse_error(l, "node %d: mass must be >= 0 (found %g)", id, mass);
    if (!rc) rc = ctn_parse_leftovers(l, 5, "node");
    if (!rc) rc = ctn_model_add_node(l->m, id, X, fix);
    return rc || mass == 0 ? rc : ctn_model_set_node_mass(l->m, id, mass);
}

int ctn_parse_prestress(ctn_line *l, int from, const char *what, double *l0, ctn_prestress *kind, double *value)
{
    static const char *const keys[4] = { "l0", "N0", "s0", "eps0" };
    int given = 0, rc = CTN_OK;
    *kind = CTN_PRESTRESS_NONE;
    for (int k = l0 ? 0 : 1; k < 4 && !rc; k++) {
        if (!ctn_parse_key(l, from, keys[k])) continue;
        if (given++) return ctn_parse_error(l, "%s: give at most one of %s", what, l0 ? "l0=, N0=, s0=, eps0=" : "N0=, s0=, eps0=");
        double v = 0;
        rc = ctn_parse_key_num(l, from, keys[k], 1, &v);
        if (rc) return rc;
        if (k == 0) {
            if (!(v > 0)) return ctn_parse_error(l, "%s: l0 must be positive (found %g)", what, v);
            *l0 = v;
        } else {
            *kind = (ctn_prestress)k;
            *value = v;
        }
    }
    return rc;
}

/* Form-finding keys q= (force density) and force= (target force), positive, at most
 * one, and not with a key that sets the unstressed length (other: one of those given). */
static int density_keys(ctn_line *l, int from, const char *what, int other, double *q, double *force)
{
    int hq = ctn_parse_key(l, from, "q") != NULL, hf = ctn_parse_key(l, from, "force") != NULL;
    if (hq && hf) return ctn_parse_error(l, "%s: give q= or force=, not both", what);
    if ((hq || hf) && other)
        return ctn_parse_error(l, "%s: %s= is for form finding, which computes the unstressed length: "
                               "give it without l0=, N0=, s0=, eps0= (or a cable target H=, sag=, tension=)", what, hq ? "q" : "force");
    const char *key = hq ? "q" : "force";
    double *v = hq ? q : force;
    if (!hq && !hf) return CTN_OK;
    int rc = ctn_parse_key_num(l, from, key, 1, v);
    if (!rc && !(*v > 0)) return ctn_parse_error(l, "%s: %s must be positive (found %g)", what, key, *v);
    return rc;
}

static int d_element(ctn_line *l)
{
    int id = 0, a = 0, b = 0;
    double l0 = CTN_L0_DEFAULT;
    int rc = ctn_parse_positional(l, 3, "element ID NODE1 NODE2 section=SECTION [l0=LENGTH|N0=FORCE|s0=STRESS|eps0=STRAIN|q=DENSITY|force=FORCE] [group=NAME]");
    if (!rc) rc = ctn_parse_int(l, "the element id", l->tok[1], &id);
    if (!rc) rc = ctn_parse_int(l, "a node id", l->tok[2], &a);
    if (!rc) rc = ctn_parse_int(l, "a node id", l->tok[3], &b);
    const char *sec = rc ? NULL : ctn_parse_key(l, 4, "section");
    if (!rc && !sec) return ctn_parse_missing(l, 4, NULL, "section", NULL);
    char what[8 + CTN_FMT_MAX];
    memcpy(what, "element ", 8);
    ctn_fmt_int(what + 8, id);                       /* once per line: not printf */
    ctn_element_spec spec;
    int nodes[2] = { a, b };
    ctn_element_spec_init(&spec);
    if (!rc) rc = ctn_parse_prestress(l, 4, what, &l0, &spec.prestress, &spec.prestress_value);
    if (!rc) rc = density_keys(l, 4, what, l0 != CTN_L0_DEFAULT || spec.prestress, &spec.q, &spec.force);
    spec.group = rc ? NULL : ctn_parse_key(l, 4, "group");
    if (!rc) rc = ctn_parse_leftovers(l, 4, "element");
    spec.id = id;
    spec.nnodes = 2;
    spec.nodes = nodes;
    spec.section = sec;
    spec.l0 = l0;
    return rc ? rc : ctn_model_add_element_spec(l->m, &spec);
}

int ctn_parse_add_element(ctn_line *l, int rc, int from, const char *type, int id, int nnodes, const int *nodes,
                          ctn_element_spec *spec)
{
    if (!rc) rc = ctn_parse_leftovers(l, from, type);
    spec->type = type;
    spec->id = id;
    spec->nnodes = nnodes;
    spec->nodes = nodes;
    return rc ? rc : ctn_model_add_element_spec(l->m, spec);
}

/* The start of a spring's line (spring, rspring): ID NODE1 NODE2 k=STIFFNESS. */
static int spring_head(ctn_line *l, const char *usage, int *id, int nodes[2], ctn_element_spec *spec)
{
    ctn_element_spec_init(spec);
    int rc = ctn_parse_positional(l, 3, usage);
    if (!rc) rc = ctn_parse_int(l, "the element id", l->tok[1], id);
    for (int k = 0; k < 2 && !rc; k++) rc = ctn_parse_int(l, "a node id", l->tok[2 + k], &nodes[k]);
    if (!rc) rc = ctn_parse_key_num(l, 4, "k", 1, &spec->k);
    return rc;
}

static int d_spring(ctn_line *l)
{
    int id = 0, nodes[2] = { 0, 0 };
    ctn_element_spec spec;
    int rc = spring_head(l, "spring ID NODE1 NODE2 k=STIFFNESS [l0=LENGTH] [group=NAME]", &id, nodes, &spec);
    char what[8 + CTN_FMT_MAX];
    memcpy(what, "spring ", 7);
    ctn_fmt_int(what + 7, id);
    if (!rc) rc = ctn_parse_prestress(l, 4, what, &spec.l0, &spec.prestress, &spec.prestress_value);
    if (!rc) rc = density_keys(l, 4, what, spec.l0 != CTN_L0_DEFAULT || spec.prestress, &spec.q, &spec.force);
    if (!rc && !(spec.k > 0)) return ctn_parse_error(l, "spring %d: k must be positive (found %g)", id, spec.k);
    spec.group = rc ? NULL : ctn_parse_key(l, 4, "group");
    return ctn_parse_add_element(l, rc, 4, "spring", id, 2, nodes, &spec);
}

/* rspring ID NODE1 NODE2 k=STIFFNESS [group=NAME]: a rotational spring (6 DOFs per node). */
static int d_rspring(ctn_line *l)
{
    int id = 0, nodes[2] = { 0, 0 };
    ctn_element_spec spec;
    int rc = spring_head(l, "rspring ID NODE1 NODE2 k=STIFFNESS [group=NAME]", &id, nodes, &spec);
    if (!rc && !(spec.k > 0)) return ctn_parse_error(l, "rspring %d: k must be positive (found %g)", id, spec.k);
    spec.group = rc ? NULL : ctn_parse_key(l, 4, "group");
    return ctn_parse_add_element(l, rc, 4, "rspring", id, 2, nodes, &spec);
}

static int cable_shape(ctn_line *l, ctn_cable_spec *spec)
{
    const char *shape = ctn_parse_key(l, 3, "shape");
    spec->shape = CTN_SHAPE_ARC;
    if (shape && !strcmp(shape, "straight")) spec->shape = CTN_SHAPE_STRAIGHT;
    else if (shape && strcmp(shape, "arc"))
        return ctn_parse_error(l, "unknown cable shape '%.40s' (expected arc or straight)", shape);
    spec->guess_strain = 1e-3;
    static const char *const starts[] = { "arc", "catenary", "auto" };
    int start = CTN_START_AUTO, rc = key_word(l, "start", starts, 3, &start);
    spec->start = (ctn_cable_start)start;
    return rc ? rc : ctn_parse_key_num(l, 3, "guess", 0, &spec->guess_strain);
}

/* Exactly one of length=, H=, sag=, tension=: the length, or the target that sets it. */
static int cable_length(ctn_line *l, ctn_cable_spec *spec)
{
    static const char *const keys[4] = { "length", "H", "sag", "tension" };
    int given = -1;
    for (int k = 0; k < 4; k++) {
        if (!ctn_parse_key(l, 3, keys[k])) continue;
        if (given >= 0)
            return ctn_parse_error(l, "cable: give one of length=, H=, sag=, tension= (found %s= and %s=)", keys[given], keys[k]);
        given = k;
    }
    if (given < 0) return ctn_parse_missing(l, 3, NULL, "length", " (or a target H=, sag= or tension=)");
    double v = 0;
    int rc = ctn_parse_key_num(l, 3, keys[given], 1, &v);
    if (!rc && given && !(v > 0)) return ctn_parse_error(l, "cable: %s must be positive (found %g)", keys[given], v);
    if (given == 0) spec->length = v;
    spec->target = (ctn_cable_target)given;
    spec->target_value = given ? v : 0;
    return rc;
}

static int d_cable(ctn_line *l)
{
    int a = 0, b = 0, n = 0, first = 0, last = 0;
    double q = 0, force = 0;
    ctn_cable_spec spec;
    ctn_cable_spec_init(&spec);
    int rc = ctn_parse_positional(l, 2, "cable NODE1 NODE2 section=SECTION n=COUNT length=LENGTH|H=FORCE|sag=LENGTH|tension=FORCE [shape=arc|straight] [start=auto|arc|catenary] [guess=STRAIN] [N0=|s0=|eps0=|q=|force=] [group=NAME]");
    if (!rc) rc = ctn_parse_int(l, "a node id", l->tok[1], &a);
    if (!rc) rc = ctn_parse_int(l, "a node id", l->tok[2], &b);
    const char *sec = rc ? NULL : ctn_parse_key(l, 3, "section");
    if (!rc && !sec) return ctn_parse_missing(l, 3, NULL, "section", NULL);
    if (!rc && !ctn_parse_key(l, 3, "n")) return ctn_parse_missing(l, 3, NULL, "n", NULL);
    if (!rc) rc = key_int(l, "n", 1, CTN_CABLE_MAX_N, &n);
    if (!rc) rc = cable_length(l, &spec);
    if (!rc) rc = cable_shape(l, &spec);
    if (!rc) rc = ctn_parse_prestress(l, 3, "cable", NULL, &spec.prestress, &spec.prestress_value);
    if (!rc && spec.target && spec.prestress)
        return ctn_parse_error(l, "cable: a target (H=, sag=, tension=) sets the length: give no N0=, s0= or eps0= with it");
    if (!rc) rc = density_keys(l, 3, "cable", spec.prestress || spec.target, &q, &force);
    spec.group = rc ? NULL : ctn_parse_key(l, 3, "group");
    if (!rc) rc = ctn_parse_leftovers(l, 3, "cable");
    spec.n = n;
    if (!rc) rc = ctn_model_add_cable(l->m, a, b, sec, &spec, &first, &last);
    return rc || !(q > 0 || force > 0) ? rc : ctn_model_set_force_density(l->m, first, last, q, force);
}

/* Whether a load line has the three moments: seven positional tokens after `load`
 * (a fifth that is no key=value). */
static int load_has_moments(const ctn_line *l)
{
    return l->ntok > 5 && !strchr(l->tok[5], '=');
}

/* load NODE FX FY FZ [MX MY MZ], moment NODE MX MY MZ: a nodal force (and moment) or a
 * moment. */
static int nodal(ctn_line *l, int moment)
{
    int id = 0;
    double F[3], M[3];
    int npos = !moment && load_has_moments(l) ? 7 : 4;
    int rc = ctn_parse_positional(l, npos, moment ? "moment NODE MX MY MZ" : "load NODE FX FY FZ [MX MY MZ] [fn=FUNCTION]");
    if (!rc) rc = ctn_parse_int(l, "the node id", l->tok[1], &id);
    for (int k = 0; k < 3 && !rc; k++) rc = ctn_parse_num(l, moment ? "a moment component" : "a force component", l->tok[2 + k], &F[k]);
    for (int k = 0; k < 3 && !rc && npos == 7; k++) rc = ctn_parse_num(l, "a moment component", l->tok[5 + k], &M[k]);
    const char *fn = moment || npos == 7 ? NULL : ctn_parse_key(l, npos + 1, "fn");   /* dynamics: F fn(t) */
    if (!rc) rc = ctn_parse_leftovers(l, npos + 1, moment ? "moment" : "load");
    if (rc) return rc;
    if (fn) return ctn_model_add_load_fn(l->m, id, F, fn);
    if (moment) return ctn_model_add_moment(l->m, id, F);
    rc = ctn_model_add_load(l->m, id, F);
    if (rc || npos == 4 || (M[0] == 0 && M[1] == 0 && M[2] == 0)) return rc;   /* no moment: any node */
    return ctn_model_add_moment(l->m, id, M);
}

static int d_load(ctn_line *l)
{
    int named = l->ntok > 1 && (!strncmp(l->tok[1], "set=", 4) || !strncmp(l->tok[1], "cable=", 6));
    return named ? ctn_parse_load_sel(l) : nodal(l, 0);
}
static int d_moment(ctn_line *l) { return nodal(l, 1); }

/* "A-B" or "A" or "all" into an inclusive id range. */
static int parse_range(ctn_line *l, const char *s, int *first, int *last)
{
    if (!s || !strcmp(s, "all")) {
        *first = 1;
        *last = 0x7fffffff;
        return CTN_OK;
    }
    char buf[64];
    snprintf(buf, sizeof buf, "%s", s);
    char *dash = strchr(buf, '-');
    while (dash && dash > buf && (dash[-1] == 'e' || dash[-1] == 'E')) dash = strchr(dash + 1, '-');  /* 10e-1 */
    if (dash == buf || (dash && !dash[1]))
        return ctn_parse_error(l, "element range '%.40s' is not of the form FIRST-LAST, ID or all", s);
    if (dash) *dash = '\0';
    int rc = ctn_parse_int(l, "an element id", buf, first);
    if (!rc) rc = ctn_parse_int(l, "an element id", dash ? dash + 1 : buf, last);
    if (!rc && *last < *first) return ctn_parse_error(l, "element range '%.40s' is empty", s);
    return rc;
}

static int d_hload(ctn_line *l)
{
    double q = 0;
    int first = 0, last = 0;
    static const char *const projections[] = { "deformed", "reference" };
    int proj = CTN_PROJECT_DEFORMED;
    int rc = ctn_parse_positional(l, 0, "hload q=LOAD [elements=FIRST-LAST|ID|GROUP|all] [projection=deformed|reference]");
    const char *target = rc ? NULL : ctn_parse_key(l, 1, "elements");
    int group = target && isalpha((unsigned char)*target) && strcmp(target, "all") &&
                (ctn_model_find_group(l->m, target) >= 0 || !strchr(target, '-'));
    if (!rc) rc = ctn_parse_key_num(l, 1, "q", 1, &q);
    if (!rc && !group) rc = parse_range(l, target, &first, &last);
    if (!rc) rc = key_word(l, "projection", projections, 2, &proj);
    if (!rc) rc = ctn_parse_leftovers(l, 1, "hload");
    if (rc) return rc;
    return group ? ctn_model_add_hload_group(l->m, q, target, (ctn_projection)proj)
                 : ctn_model_add_hload_projected(l->m, q, first, last, (ctn_projection)proj);
}

/* The options' check (the solver's own, catena/solve.h) as an error at this line. */
static int options_error(const ctn_line *l)
{
    char msg[256];
    snprintf(msg, sizeof msg, "%s", ctn_ctx_message(l->m->ctx));
    return ctn_parse_error(l, "%s", msg);
}

static int d_solve(ctn_line *l)
{
    static const char *const orderings[] = { "auto", "natural", "amd", "metis" };
    static const char *const methods[] = { "auto", "newton", "arclength" };
    static const char *const onoff[] = { "off", "on" };
    static const char *const solvers[] = { "cholmod", "cholmod-ldl", "petsc", "petsc-ldl", "petsc-cg" };
    ctn_solve_options opt = *l->opt;
    int ord = (int)opt.ordering, method = (int)opt.method, ls = opt.linesearch, lin = -1, reuse = opt.reuse;
    int rc = ctn_parse_positional(l, 0, "solve [tol=T] [dtol=T] [maxit=N] [method=auto|newton|arclength] ...");
    if (!rc) rc = ctn_parse_key_num(l, 1, "tol", 0, &opt.tol);
    if (!rc) rc = ctn_parse_key_num(l, 1, "dtol", 0, &opt.dtol);
    if (!rc) rc = key_int(l, "maxit", 1, 100000, &opt.maxit);
    if (!rc) rc = key_word(l, "ordering", orderings, 4, &ord);
    if (!rc) rc = key_word(l, "method", methods, 3, &method);
    if (!rc) rc = key_word(l, "linesearch", onoff, 2, &ls);
    if (!rc) rc = key_word(l, "linear_solver", solvers, 5, &lin);
    if (!rc) rc = key_word(l, "reuse", onoff, 2, &reuse);
    if (!rc) rc = key_int(l, "threads", 0, 1024, &opt.threads);
    if (!rc) rc = key_int(l, "steps", 1, 100000, &opt.steps);
    if (!rc) rc = key_int(l, "cutbacks", 0, 60, &opt.maxcuts);
    if (!rc) rc = ctn_parse_key_num(l, 1, "arclength", 0, &opt.arclength);
    if (!rc) rc = key_int(l, "arcsteps", 1, 1000000, &opt.arcsteps);
    if (!rc) rc = ctn_parse_key_num(l, 1, "lambda", 0, &opt.lambda_max);
    if (!rc) rc = ctn_parse_leftovers(l, 1, "solve");
    if (rc) return rc;
    opt.ordering = (ctn_ordering)ord;
    opt.method = (ctn_method)method;
    opt.linesearch = ls;
    opt.reuse = reuse;
    if (lin >= 0) opt.linear_solver = solvers[lin];
    if (ctn_solve_options_check(l->m->ctx, &opt)) return options_error(l);
    *l->opt = opt;
    return CTN_OK;
}

static int d_modes(ctn_line *l)
{
    static const char *const masses[] = { "consistent", "lumped" }, *const solvers[] = { "block", "arpack", "auto" };
    ctn_modal_options o = l->opt->modal;
    int mass = (int)CTN_MASS_CONSISTENT, solver = (int)CTN_EIGEN_AUTO;
    o.count = 0;
    o.shift = 0;
    int rc = ctn_parse_positional(l, 0, "modes count=N [mass=lumped|consistent] [shift=HZ] [solver=auto|block|arpack]");
    if (!rc && !ctn_parse_key(l, 1, "count")) return ctn_parse_missing(l, 1, NULL, "count", NULL);
    if (!rc) rc = key_int(l, "count", 1, 0x7fffffff, &o.count);
    if (!rc) rc = key_word(l, "mass", masses, 2, &mass);
    if (!rc) rc = key_word(l, "solver", solvers, 3, &solver);
    if (!rc) rc = ctn_parse_key_num(l, 1, "shift", 0, &o.shift);
    if (!rc) rc = ctn_parse_leftovers(l, 1, "modes");
    if (rc) return rc;
    o.mass = (ctn_mass_matrix)mass;
    o.solver = (ctn_eigen_solver)solver;
    o.line = l->line;
    if (ctn_modal_options_check(l->m->ctx, &o)) return options_error(l);
    if (l->opt->modal.count > 0) return ctn_parse_error(l, "modes: given twice (first on line %d)", l->opt->modal.line);
    l->opt->modal = o;
    return CTN_OK;
}

static int d_buckling(ctn_line *l)
{
    ctn_buckling_options o = l->opt->buckling;
    o.count = 0;
    int rc = ctn_parse_positional(l, 0, "buckling count=N");
    if (!rc && !ctn_parse_key(l, 1, "count")) return ctn_parse_missing(l, 1, NULL, "count", NULL);
    if (!rc) rc = key_int(l, "count", 1, 0x7fffffff, &o.count);
    if (!rc) rc = key_int(l, "check", 0, 1, &o.check);
    if (!rc) rc = ctn_parse_leftovers(l, 1, "buckling");
    if (rc) return rc;
    o.line = l->line;
    if (ctn_buckling_options_check(l->m->ctx, &o)) return options_error(l);
    if (l->opt->buckling.count > 0)
        return ctn_parse_error(l, "buckling: given twice (first on line %d)", l->opt->buckling.line);
    l->opt->buckling = o;
    return CTN_OK;
}

static int d_step(ctn_line *l)
{
    int sub = 0;
    int rc = ctn_parse_positional(l, 1, "step NAME [substeps=N]");
    if (!rc) rc = key_int(l, "substeps", 1, CTN_SUBSTEPS_MAX, &sub);
    if (!rc) rc = ctn_parse_leftovers(l, 2, "step");
    return rc ? rc : ctn_model_add_step(l->m, l->tok[1], sub);
}

static int d_displace(ctn_line *l)
{
    static const char *const axes[6] = { "x", "y", "z", "rx", "ry", "rz" };
    int id = 0;
    unsigned dofs = 0;
    double u[6] = { 0, 0, 0, 0, 0, 0 };
    int rc = ctn_parse_positional(l, 1, "displace NODE [x=DX] [y=DY] [z=DZ] [rx=RX] [ry=RY] [rz=RZ] [fn=FUNCTION]");
    const char *fn = rc ? NULL : ctn_parse_key(l, 2, "fn");                /* dynamics: u fn(t) */
    if (!rc) rc = ctn_parse_int(l, "the node id", l->tok[1], &id);
    for (int k = 0; k < 6 && !rc; k++) {
        if (!ctn_parse_key(l, 2, axes[k])) continue;
        dofs |= 1u << k;
        rc = ctn_parse_key_num(l, 2, axes[k], 1, &u[k]);
    }
    if (!rc) rc = ctn_parse_leftovers(l, 2, "displace");
    if (!rc && !dofs) return ctn_parse_error(l, "displace: give at least one of x=, y=, z=, rx=, ry=, rz=");
    if (!rc && fn && (dofs & CTN_FIX_ROT)) return ctn_parse_error(l, "displace: fn= moves translations only (x=, y=, z=)");
    if (!rc && fn) return ctn_model_add_motion_fn(l->m, id, dofs, u, fn);
    if (!rc && (dofs & CTN_FIX_ALL)) rc = ctn_model_add_displacement(l->m, id, dofs & CTN_FIX_ALL, u);
    if (!rc && (dofs & CTN_FIX_ROT)) rc = ctn_model_add_rotation(l->m, id, dofs & CTN_FIX_ROT, u + 3);
    return rc;
}

/* group NAME ID|FIRST-LAST ... */
static int d_group(ctn_line *l)
{
    int rc = ctn_parse_positional(l, 2, "group NAME ID|FIRST-LAST ...");
    for (int k = 2; k < l->ntok && !rc; k++) {
        int first = 0, last = 0;
        if (strchr(l->tok[k], '='))
            return ctn_parse_error(l, "group: '%.40s' is not an element id or range (group takes no keys)", l->tok[k]);
        if (!strcmp(l->tok[k], "all"))
            return ctn_parse_error(l, "group: give element ids or ranges FIRST-LAST ('all' is not one)");
        rc = parse_range(l, l->tok[k], &first, &last);
        if (!rc) rc = ctn_model_add_group(l->m, l->tok[1], first, last);
    }
    l->used = ~0ull;
    return rc;
}

/* temperature TARGET dT=KELVIN */
static int d_temperature(ctn_line *l)
{
    double dT = 0;
    int rc = ctn_parse_positional(l, 1, "temperature TARGET dT=KELVIN (TARGET: all, an element id or a group)");
    if (!rc) rc = ctn_parse_key_num(l, 2, "dT", 1, &dT);
    if (!rc) rc = ctn_parse_leftovers(l, 2, "temperature");
    return rc ? rc : ctn_model_add_temperature(l->m, l->tok[1], dT);
}

typedef struct directive {
    const char *name;
    int (*fn)(ctn_line *l);
} directive;

static const directive directives[] = {
    { "units", d_units },     { "gravity", d_gravity }, { "material", d_material },
    { "section", d_section }, { "node", d_node },       { "element", d_element },
    { "cable", d_cable },     { "load", d_load },       { "hload", d_hload },
    { "solve", d_solve },     { "step", d_step },       { "displace", d_displace },
    { "spring", d_spring },   { "group", d_group },     { "temperature", d_temperature },
    { "modes", d_modes },     { "moment", d_moment },   { "rspring", d_rspring },
        { "catenary", ctn_parse_catenary }, { "pulley", ctn_parse_pulley }, { "beam", ctn_parse_beam },
    { "lineload", ctn_parse_lineload }, { "case", ctn_parse_case },
    { "combination", ctn_parse_combination }, { "ice", ctn_parse_ice },
    { "wind", ctn_parse_wind },
    { "buckling", d_buckling },
    { "dynamics", ctn_parse_dynamics }, { "damping", ctn_parse_damping }, { "record", ctn_parse_record },
    { "function", ctn_parse_function }, { "remove", ctn_parse_remove },
    { "set", ctn_parse_set }, { "include", ctn_parse_include }, { "net", ctn_parse_net },
    { "sagtension", ctn_parse_sagtension },
};

/* The index of word's directive in directives[], -1 if none (the first letter compared
 * before the names: one of every 200 000 lines is not a node, element or load). */
static int find_directive(const char *word)
{
    for (size_t i = 0; i < sizeof directives / sizeof *directives; i++)
        if (word[0] == directives[i].name[0] && !strcmp(word, directives[i].name)) return (int)i;
    return -1;
}

int ctn_parse_known(const char *word)
{
    return find_directive(word) >= 0;
}

int ctn_parse_directive(ctn_line *l)
{
    int i = find_directive(l->tok[0]);
    if (i >= 0) return directives[i].fn(l);
    char b[64];
    return ctn_parse_error(l, "unknown directive '%s'", ctn_parse_show(l->tok[0], b, sizeof b));
}
