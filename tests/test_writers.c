/* The streaming result writers (src/io: fmt, sink, jsonw, json, csv, results, atomic).
 *
 *   - numbers: ctn_fmt_g17 is printf's "%.17g" and ctn_fmt_json is "%1.15g" when that
 *     reads back to the same double, else "%1.17g" (cJSON's layout, its test exact), byte
 *     for byte, on special values and on random doubles of every kind (random bits,
 *     integers, short decimals, powers of two and their neighbours), and every number
 *     reads back to its double;
 *   - JSON: for several models (the paper's cable, load steps with settlement, tension-only
 *     members going slack, arc-length, a diverged unit-less solve, step names that need
 *     escaping) ctn_result_json, ctn_write_json and result.json are the text cJSON_Print /
 *     cJSON_PrintUnformatted give for a cJSON tree built here from the public accessors
 *     (its numbers as raw text of the exact rule above), and that text parses; nodes.csv and elements.csv are what fprintf gives;
 *   - failures: a sink that fails mid-way, a full device, a file size limit, NaN in the
 *     result, and every allocation on the writer path failing in turn: the right status,
 *     nothing committed, no temporary left, no leak (ASan build). */
#include "check.h"
#include "files.h"
#include "io/fmt.h"
#include "io/writer.h"

#include <catena.h>
#include <cjson/cJSON.h>

#include <dirent.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- numbers ---- */

static uint64_t rng = 0x9e3779b97f4a7c15u;

static uint64_t next(void)   /* xorshift64 */
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

static double from_bits(uint64_t b)
{
    double v;
    memcpy(&v, &b, sizeof v);
    return v;
}

/* A double of kind k: random bits, integers, short decimals, powers of two and their
 * neighbours, 17-digit decimals at any scale, tiny and huge ones. */
static double sample(int k)
{
    uint64_t r = next();
    switch (k) {
    case 0: { double v = from_bits(r); return isfinite(v) ? v : 1.5; }
    case 1: return (double)(int64_t)(r % 2000001) - 1000000.0;
    case 2: return (double)(int64_t)(r % 100000000) / pow(10, (double)(next() % 12));
    case 3: return ldexp(1.0, (int)(r % 2098) - 1074);
    case 4: { uint64_t b; double v = ldexp(1.0, (int)(r % 400) - 200);
              memcpy(&b, &v, sizeof b); return from_bits(b + next() % 129 - 64); }
    case 5: return (double)(r >> 11) / 9007199254740992.0 * pow(10, (double)((int)(next() % 60) - 30));
    case 6: return (double)(r % 100000000000000000u) * pow(10, (double)((int)(next() % 40) - 30));
    default: return from_bits(r & 0x001fffffffffffffu);          /* subnormals and tiny normals */
    }
}

/* The JSON text of v by printf and sscanf: 15 digits when they read back to v. */
static void json_number(double v, char *out, size_t size)
{
    double back = 0;
    snprintf(out, size, "%1.15g", v);
    if (sscanf(out, "%lg", &back) != 1 || back != v) snprintf(out, size, "%1.17g", v);
}

static int check_number(double v)
{
    char a[CTN_FMT_MAX], b[64];
    int bad = 0;
    size_t n = ctn_fmt_g17(a, v);
    snprintf(b, sizeof b, "%.17g", v);
    if (strcmp(a, b) || n != strlen(b)) { bad = 1; CHECK_MSG(0, "%a: g17 '%s', printf '%s'", v, a, b); }
    n = ctn_fmt_json(a, v);
    json_number(v, b, sizeof b);
    if (strcmp(a, b) || n != strlen(b)) { bad = 1; CHECK_MSG(0, "%a: '%s', printf '%s'", v, a, b); }
    double back = 0;
    if (sscanf(a, "%lg", &back) != 1 || back != v) { bad = 1; CHECK_MSG(0, "%a: '%s' reads back %a", v, a, back); }
    return bad;
}

static void test_numbers(long count)
{
    static const double special[] = {
        0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 1.5, 2.5, 1e-5, 1e-4, 9.9999999999999991e-5,
        1e15, 1e16, 1e17, 1e22, 1e23, 123456789012345678.0, 1234567890123455.0,
        999999999999999.5, 9999999999999998.0, 0.30000000000000004, 1.0 / 3.0, 2.0 / 3.0,
        DBL_MAX, -DBL_MAX, DBL_MIN, DBL_EPSILON, 4.9406564584124654e-324, 2.2250738585072009e-308,
        2147483647.0, 2147483648.0, -2147483649.0, 4294967296.0, 9007199254740993.0,
        5e-324, 1.7976931348623157e308, 0.1 + 0.2, 100.0, 200.0, 250.8777, 10.0167
    };
    long bad = 0;
    char a[CTN_FMT_MAX];
    for (size_t i = 0; i < sizeof special / sizeof *special; i++) bad += check_number(special[i]);
    for (long i = 0; i < count && bad < 20; i++) bad += check_number(sample((int)(i % 8)));
    for (long long v = -1000; v <= 1000; v++) {
        char b[32];
        ctn_fmt_int(a, v);
        snprintf(b, sizeof b, "%lld", v);
        bad += strcmp(a, b) != 0;
    }
    long long ext[2] = { LLONG_MIN, LLONG_MAX };
    for (int i = 0; i < 2; i++) {
        char b[32];
        ctn_fmt_int(a, ext[i]);
        snprintf(b, sizeof b, "%lld", ext[i]);
        bad += strcmp(a, b) != 0;
    }
    CHECK_MSG(bad == 0, "%ld numbers differ", bad);
}

/* ---- the reference: the result document as a cJSON tree, from the public accessors ---- */

static int ref_num(cJSON *o, const char *key, double v, int *finite)
{
    if (!isfinite(v)) *finite = 0;
    return cJSON_AddNumberToObject(o, key, v) != NULL;
}

static int ref_numbers(cJSON *o, const char *key, const double *v, size_t n, int *finite)
{
    cJSON *a = cJSON_AddArrayToObject(o, key);
    for (size_t i = 0; a && i < n; i++) {
        if (!isfinite(v[i])) *finite = 0;
        if (!cJSON_AddItemToArray(a, cJSON_CreateNumber(v[i]))) return 0;
    }
    return a != NULL;
}

static cJSON *ref_item(cJSON *array)
{
    cJSON *o = cJSON_CreateObject();
    if (o && !cJSON_AddItemToArray(array, o)) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

static int ref_id(const ctn_model *m, int index)
{
    ctn_node_info p;
    ctn_model_node(m, (size_t)index, &p);
    return p.id;
}

static void ref_nodes(cJSON *root, const ctn_model *m, const ctn_step_result *st, int *finite)
{
    static const char *xk[] = { "x", "y", "z" }, *uk[] = { "ux", "uy", "uz" }, *fk[] = { "fx", "fy", "fz" };
    cJSON *a = cJSON_AddArrayToObject(root, "nodes"), *r = cJSON_AddArrayToObject(root, "reactions");
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info p;
        ctn_model_node(m, i, &p);
        cJSON *o = ref_item(a);
        ref_num(o, "id", p.id, finite);
        for (int k = 0; k < 3; k++) ref_num(o, xk[k], p.X[k], finite);
        for (int k = 0; k < 3; k++) ref_num(o, uk[k], st->d[3 * i + k], finite);
        if (!p.fix) continue;
        cJSON *q = ref_item(r);
        ref_num(q, "node", p.id, finite);
        for (int k = 0; k < 3; k++) ref_num(q, fk[k], st->react[3 * i + k], finite);
    }
}

static void ref_elements(cJSON *root, const ctn_model *m, const ctn_solution *s, size_t k, int *finite)
{
    cJSON *a = cJSON_AddArrayToObject(root, "elements");
    double mpa = ctn_model_mpa_factor(m);
    for (size_t i = 0; i < ctn_model_element_count(m); i++) {
        ctn_element_info e;
        ctn_element_state st;
        ctn_model_element(m, i, &e);
        ctn_solution_step_element(s, k, i, &st);
        cJSON *o = ref_item(a);
        ref_num(o, "id", e.id, finite);
        int ids[2] = { ref_id(m, e.node[0]), ref_id(m, e.node[1]) };
        cJSON_AddItemToObject(o, "nodes", cJSON_CreateIntArray(ids, 2));
        ref_num(o, "l0", e.l0, finite);
        ref_num(o, "length", st.length, finite);
        ref_num(o, "strain", st.strain, finite);
        ref_num(o, "force", st.force, finite);
        if (!e.has_section) {
            cJSON_AddStringToObject(o, "type", e.type);
        } else {
            ref_num(o, "stress", st.stress, finite);
            if (mpa > 0) ref_num(o, "stress_mpa", st.stress * mpa, finite);
        }
        if (e.tension_only) cJSON_AddBoolToObject(o, "slack", st.slack);
    }
}

static void ref_cables(cJSON *root, const ctn_model *m, const ctn_solution *s, int *finite)
{
    cJSON *a = cJSON_AddArrayToObject(root, "cables");
    for (size_t i = 0; i < ctn_model_cable_count(m); i++) {
        ctn_cable_info c;
        ctn_element_info e0, e1;
        double sag, dmax;
        ctn_model_cable(m, i, &c);
        ctn_model_element(m, c.first, &e0);
        ctn_model_element(m, c.first + c.count - 1, &e1);
        cJSON *o = ref_item(a);
        ref_num(o, "node1", ref_id(m, c.node[0]), finite);
        ref_num(o, "node2", ref_id(m, c.node[1]), finite);
        ref_num(o, "first_element", e0.id, finite);
        ref_num(o, "last_element", e1.id, finite);
        ref_num(o, "length", c.length, finite);
        if (!ctn_solution_cable_sag(m, s, i, &sag)) ref_num(o, "sag", sag, finite);
        if (!ctn_solution_cable_max_sag_from_chord(m, s, i, &dmax)) ref_num(o, "max_sag_from_chord", dmax, finite);
    }
}

/* A step entry's "cables" (docs/format.md): each generated cable's state at step k, then
 * each catenary element's; absent when the model has neither. */
static void ref_state_cables(cJSON *root, const ctn_model *m, const ctn_solution *s, size_t k, int *finite)
{
    size_t ncat = 0;
    for (size_t i = 0; i < ctn_model_element_count(m); i++) {
        ctn_element_info e;
        ctn_model_element(m, i, &e);
        ncat += !strcmp(e.type, "catenary");
    }
    if (!ctn_model_cable_count(m) && !ncat) return;
    cJSON *a = cJSON_AddArrayToObject(root, "cables");
    for (size_t i = 0; i < ctn_model_cable_count(m); i++) {
        ctn_cable_info c;
        ctn_element_info e0, e1, e;
        ctn_element_state es;
        double sag, hi = -INFINITY, lo = INFINITY, len = 0, l0 = 0;
        ctn_model_cable(m, i, &c);
        ctn_model_element(m, c.first, &e0);
        ctn_model_element(m, c.first + c.count - 1, &e1);
        for (size_t j = c.first; j < c.first + c.count; j++) {
            ctn_model_element(m, j, &e);
            ctn_solution_step_element(s, k, j, &es);
            hi = es.force > hi ? es.force : hi;
            lo = es.force < lo ? es.force : lo;
            len += es.length;
            l0 += e.l0;
        }
        cJSON *o = ref_item(a);
        ref_num(o, "node1", ref_id(m, c.node[0]), finite);
        ref_num(o, "node2", ref_id(m, c.node[1]), finite);
        ref_num(o, "first_element", e0.id, finite);
        ref_num(o, "last_element", e1.id, finite);
        if (!ctn_solution_step_cable_sag(m, s, k, i, &sag)) ref_num(o, "sag", sag, finite);
        ref_num(o, "max_tension", hi, finite);
        ref_num(o, "min_tension", lo, finite);
        ref_num(o, "stretched_length", len, finite);
        ref_num(o, "unstressed_length", l0, finite);
    }
    for (size_t i = 0; i < ctn_model_element_count(m) && ncat; i++) {
        ctn_element_info e;
        ctn_catenary_result c = { .size = sizeof c };
        ctn_model_element(m, i, &e);
        if (strcmp(e.type, "catenary") || ctn_solution_catenary(m, s, k, i, &c)) continue;
        double hi = c.tension[0] > c.tension[1] ? c.tension[0] : c.tension[1];
        double lo = c.V[0] > 0 && c.V[1] > 0 ? c.H : c.tension[0] < c.tension[1] ? c.tension[0] : c.tension[1];
        cJSON *o = ref_item(a);
        ref_num(o, "element", e.id, finite);
        ref_num(o, "node1", ref_id(m, e.node[0]), finite);
        ref_num(o, "node2", ref_id(m, e.node[1]), finite);
        ref_num(o, "sag", c.sag, finite);
        ref_num(o, "max_tension", hi, finite);
        ref_num(o, "min_tension", lo, finite);
        ref_num(o, "stretched_length", c.length, finite);
        ref_num(o, "unstressed_length", e.l0, finite);
    }
}

static void ref_summary(cJSON *root, const ctn_model *m, const ctn_solution *s, int *finite)
{
    ctn_solve_summary sum;
    size_t n;
    ctn_solution_summary(s, &sum);
    cJSON_AddBoolToObject(root, "converged", sum.reason == CTN_CONVERGED);
    cJSON_AddStringToObject(root, "reason", ctn_reason_name(sum.reason));
    ref_num(root, "iterations", sum.iterations, finite);
    const double *h = ctn_solution_residual_history(s, &n);
    ref_numbers(root, "residual_history", h, n, finite);
    h = ctn_solution_increment_history(s, &n);
    ref_numbers(root, "increment_history", h, n, finite);
    ref_num(root, "external_force_norm", sum.fext_norm, finite);
    ref_num(root, "load_factor", sum.load_factor, finite);
    ref_num(root, "cutbacks", sum.cuts, finite);
    ref_num(root, "factorizations", sum.factorizations, finite);
    ref_num(root, "solves", sum.solves, finite);
    ref_num(root, "reused_factorizations", sum.reused, finite);
    if (sum.fdensity) cJSON_AddBoolToObject(root, "force_density_start", 1);
    cJSON_AddStringToObject(root, "ordering", ctn_ordering_name(sum.ordering));
    ref_num(root, "factor_nonzeros", (double)sum.nnz_factor, finite);
    ref_num(root, "factor_flops", sum.flops_factor, finite);
    cJSON_AddStringToObject(root, "blas", sum.blas);
    ref_num(root, "threads", sum.threads, finite);
    ref_num(root, "solve_threads", sum.solve_threads, finite);
    cJSON *u = cJSON_AddObjectToObject(root, "units");
    cJSON_AddStringToObject(u, "force", ctn_model_force_unit(m));
    cJSON_AddStringToObject(u, "length", ctn_model_length_unit(m));
    if (sum.reason == CTN_DIVERGED_INDEFINITE || sum.reason == CTN_DIVERGED_MECHANISM) {
        ref_num(root, "fail_node", sum.fail_node, finite);
        cJSON_AddStringToObject(root, "fail_direction", (const char *[]){ "x", "y", "z" }[sum.fail_dir]);
    }
    if ((sum.floor || sum.reason == CTN_DIVERGED_ROUNDOFF) && isfinite(sum.residual_floor) && isfinite(sum.force_scale)) {
        ref_num(root, "residual_floor", sum.residual_floor, finite);
        ref_num(root, "force_scale", sum.force_scale, finite);
    }
    ctn_stability st;
    if (ctn_solution_stability(s, &st) == CTN_OK) {
        cJSON_AddBoolToObject(root, "stable", st.stable);
        if (st.stable) cJSON_AddStringToObject(root, "stable_by", st.by_tension ? "tension" : "factorization");
        if (!st.stable) {
            cJSON *o = cJSON_AddObjectToObject(root, "stability");
            cJSON_AddStringToObject(o, "kind", st.semidefinite ? "semi-definite" : "unstable");
            ref_num(o, "negative_eigenvalues", (double)st.negative, finite);
            if (st.node) ref_num(o, "node", st.node, finite);
            if (st.dir >= 0 && st.dir < 3) cJSON_AddStringToObject(o, "direction", (const char *[]){ "x", "y", "z" }[st.dir]);
        }
    }
}

/* The document as the library built it with cJSON before the writers streamed it;
 * *finite = 0 if a number is not finite. */
/* Every number of the tree as raw text of the exact rule (cJSON's own test of 15 digits
 * is within DBL_EPSILON, not exact). */
static void exact_numbers(cJSON *node)
{
    for (cJSON *c = node->child, *next; c; c = next) {
        next = c->next;
        if (cJSON_IsNumber(c)) {
            char buf[64];
            json_number(c->valuedouble, buf, sizeof buf);
            cJSON *raw = cJSON_CreateRaw(buf);
            raw->string = c->string;                  /* the key moves to the raw item */
            raw->type |= c->type & cJSON_StringIsConst;
            c->string = NULL;
            cJSON_ReplaceItemViaPointer(node, c, raw);
        } else {
            exact_numbers(c);
        }
    }
}

static cJSON *reference_cjson(const ctn_model *m, const ctn_solution *s, int *finite);

static cJSON *reference(const ctn_model *m, const ctn_solution *s, int *finite)
{
    cJSON *root = reference_cjson(m, s, finite);
    if (root) exact_numbers(root);
    return root;
}

static cJSON *reference_cjson(const ctn_model *m, const ctn_solution *s, int *finite)
{
    size_t n = ctn_solution_step_count(s);
    ctn_step_result st;
    cJSON *root = cJSON_CreateObject();
    *finite = 1;
    ref_summary(root, m, s, finite);
    ctn_solution_step(s, n - 1, &st);
    ref_nodes(root, m, &st, finite);
    ref_elements(root, m, s, n - 1, finite);
    ref_cables(root, m, s, finite);
    if (n < 2) return root;
    cJSON *a = cJSON_AddArrayToObject(root, "steps");
    for (size_t k = 0; k < n; k++) {
        cJSON *o = ref_item(a);
        ctn_solution_step(s, k, &st);
        cJSON_AddStringToObject(o, "name", st.name);
        cJSON_AddBoolToObject(o, "converged", st.reason == CTN_CONVERGED);
        cJSON_AddStringToObject(o, "reason", ctn_reason_name(st.reason));
        ref_num(o, "load_factor", st.load_factor, finite);
        ref_num(o, "iterations", st.iterations, finite);
        ref_nodes(o, m, &st, finite);
        ref_elements(o, m, s, k, finite);
        ref_state_cables(o, m, s, k, finite);
    }
    return root;
}

/* nodes.csv and elements.csv as fprintf writes them. */
static char *reference_csv(const ctn_model *m, const ctn_solution *s, int elements)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    size_t k = ctn_solution_step_count(s) - 1;
    ctn_step_result st;
    ctn_solution_step(s, k, &st);
    if (!elements) {
        fprintf(f, "id,x,y,z,ux,uy,uz,fix,rx,ry,rz\n");
        for (size_t i = 0; i < ctn_model_node_count(m); i++) {
            ctn_node_info p;
            const double *d = st.d + 3 * i, *r = st.react + 3 * i;
            ctn_model_node(m, i, &p);
            fprintf(f, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s%s%s,%.17g,%.17g,%.17g\n", p.id,
                    p.X[0], p.X[1], p.X[2], d[0], d[1], d[2], p.fix & CTN_FIX_X ? "x" : "",
                    p.fix & CTN_FIX_Y ? "y" : "", p.fix & CTN_FIX_Z ? "z" : "", r[0], r[1], r[2]);
        }
    } else {
        fprintf(f, "id,node1,node2,l0,length,strain,force,stress,slack,utilisation,group\n");
        for (size_t i = 0; i < ctn_model_element_count(m); i++) {
            ctn_element_info e;
            ctn_element_state es;
            ctn_model_element(m, i, &e);
            ctn_solution_step_element(s, k, i, &es);
            fprintf(f, "%d,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%d,", e.id, ref_id(m, e.node[0]),
                    ref_id(m, e.node[1]), e.l0, es.length, es.strain, es.force, es.stress, es.slack);
            if (e.capacity > 0) fprintf(f, "%.17g", ctn_utilisation(&e, &es));
            fprintf(f, ",%s\n", e.group ? e.group : "");
        }
    }
    fclose(f);
    return text;
}

/* ---- files ---- */

static char tmpdir[64];

static void make_tmpdir(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/catena-writers.XXXXXX");
    CHECK(mkdtemp(tmpdir) != NULL);
}

/* ---- the models ---- */

typedef struct model_case {
    const char *name;
    ctn_model *m;
    ctn_solution *s;
} model_case;

static void solve_file(ctn_ctx *ctx, const char *path, model_case *c)
{
    c->name = path;
    c->m = NULL;
    c->s = NULL;
    CHECK_MSG(ctn_model_read_file(ctx, path, &c->m) == CTN_OK, "%s: %s", path, ctn_ctx_message(ctx));
    if (c->m) CHECK_MSG(ctn_solve(ctx, c->m, NULL, &c->s) == CTN_OK, "%s: %s", path, ctn_ctx_message(ctx));
}

/* Unit-less, straight start, pure Newton: diverges (indefinite tangent) at once. */
static void solve_diverged(ctn_ctx *ctx, model_case *c)
{
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = 20, .length = 250.8777, .shape = CTN_SHAPE_STRAIGHT, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    ctn_solve_options opt;
    c->name = "diverged";
    c->s = NULL;
    ctn_model_create(ctx, &c->m);
    ctn_model_set_gravity(c->m, g);
    ctn_model_add_material(c->m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0);
    ctn_model_add_section(c->m, "strand", "steel", 3.14e-4, 0.1);
    ctn_model_add_node(c->m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(c->m, 2, B, CTN_FIX_ALL);
    ctn_model_add_cable(c->m, 1, 2, "strand", &spec, NULL, NULL);
    ctn_solve_options_default(&opt);
    opt.method = CTN_METHOD_NEWTON;
    CHECK(ctn_solve(ctx, c->m, &opt, &c->s) == CTN_OK);
}

/* Unit-less, two load steps whose names need escaping in JSON. */
static void solve_escaped(ctn_ctx *ctx, model_case *c)
{
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 }, F[3] = { 0, -5, 0 };
    ctn_cable_spec spec = { .n = 20, .length = 250.8777, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    c->name = "escaped step names";
    c->s = NULL;
    ctn_model_create(ctx, &c->m);
    ctn_model_set_gravity(c->m, g);
    ctn_model_add_material(c->m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0);
    ctn_model_add_section(c->m, "strand", "steel", 3.14e-4, 0.1);
    ctn_model_add_node(c->m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(c->m, 2, B, CTN_FIX_ALL);
    ctn_model_add_cable(c->m, 1, 2, "strand", &spec, NULL, NULL);
    CHECK(ctn_model_add_step(c->m, "say \"hi\" \\ tab\there\x01 \xc3\xa9/\x7f", 0) == CTN_OK);
    CHECK(ctn_model_add_step(c->m, "line\nbreak\r\b\f\x1f", 0) == CTN_OK);
    CHECK(ctn_model_add_load(c->m, 5, F) == CTN_OK);
    CHECK(ctn_solve(ctx, c->m, NULL, &c->s) == CTN_OK);
    CHECK(ctn_solution_step_count(c->s) == 2);
}

/* The paper's cable in 2000 elements: result.json of ~1 MB, many buffers. */
static void solve_big(ctn_ctx *ctx, model_case *c)
{
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = 2000, .length = 250.8777, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_CATENARY, .prestress = CTN_PRESTRESS_NONE };
    c->name = "2000 elements";
    c->s = NULL;
    ctn_model_create(ctx, &c->m);
    ctn_model_set_units(c->m, "kN", "m");
    ctn_model_set_gravity(c->m, g);
    ctn_model_add_material(c->m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0);
    ctn_model_add_section(c->m, "strand", "steel", 3.14e-4, 0.1);
    ctn_model_add_node(c->m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(c->m, 2, B, CTN_FIX_ALL);
    ctn_model_add_cable(c->m, 1, 2, "strand", &spec, NULL, NULL);
    CHECK(ctn_solve(ctx, c->m, NULL, &c->s) == CTN_OK);
}

static void destroy_case(model_case *c)
{
    ctn_solution_destroy(&c->s);
    ctn_model_destroy(&c->m);
}

/* ---- identical text ---- */

/* The streamed JSON (memory, FILE) against cJSON's, pretty and compact. */
static void check_json(ctn_ctx *ctx, const model_case *c, int pretty)
{
    int finite;
    cJSON *ref = reference(c->m, c->s, &finite);
    char *want = pretty ? cJSON_Print(ref) : cJSON_PrintUnformatted(ref), *got = NULL;
    int rc = ctn_result_json(ctx, c->m, c->s, pretty, &got);
    if (!finite) {
        CHECK_MSG(rc == CTN_ERR_INVALID && !got, "%s: non-finite result, rc %d", c->name, rc);
    } else {
        CHECK_MSG(rc == CTN_OK && got && want && !strcmp(got, want), "%s (pretty %d): the text differs from cJSON's",
                  c->name, pretty);
        cJSON *back = got ? cJSON_Parse(got) : NULL;
        CHECK_MSG(back != NULL, "%s: not valid JSON", c->name);
        cJSON_Delete(back);
        char path[128];
        snprintf(path, sizeof path, "%s/stream.json", tmpdir);
        FILE *f = fopen(path, "w");
        CHECK(f && ctn_write_json(ctx, f, c->m, c->s, pretty) == CTN_OK);
        if (f) fclose(f);
        char *file = read_all(path);
        CHECK_MSG(file && want && !strcmp(file, want), "%s: ctn_write_json differs", c->name);
        free(file);
        unlink(path);
    }
    ctn_json_free(got);
    cJSON_free(want);
    cJSON_Delete(ref);
}

/* The files of a result directory: result.json, nodes.csv, elements.csv, result.vtu,
 * and for several steps result_K.vtu each and result.pvd. */
static int expected_files(const ctn_solution *s)
{
    size_t n = ctn_solution_step_count(s);
    return 4 + (n > 1 ? (int)n + 1 : 0);
}

/* result.json, nodes.csv and elements.csv against cJSON and fprintf (result.vtu is read
 * back by tests/cli/vtu.sh). */
static void check_files(ctn_ctx *ctx, const model_case *c)
{
    int finite;
    cJSON *ref = reference(c->m, c->s, &finite);
    char dir[128], path[160];
    snprintf(dir, sizeof dir, "%s/out", tmpdir);
    int rc = ctn_write_results(ctx, dir, c->m, c->s);
    if (!finite) {
        CHECK_MSG(rc == CTN_ERR_INVALID && count_entries(dir) <= 0, "%s: non-finite result written", c->name);
        cJSON_Delete(ref);
        remove_dir(dir);
        return;
    }
    CHECK_MSG(rc == CTN_OK, "%s: %s", c->name, ctn_ctx_message(ctx));
    CHECK_MSG(count_entries(dir) == expected_files(c->s), "%s: %d files", c->name, count_entries(dir));
    char *want[3] = { cJSON_Print(ref), reference_csv(c->m, c->s, 0), reference_csv(c->m, c->s, 1) };
    const char *names[3] = { "result.json", "nodes.csv", "elements.csv" };
    for (int i = 0; i < 3; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        char *got = read_all(path);
        CHECK_MSG(got && want[i] && !strcmp(got, want[i]), "%s: %s differs", c->name, names[i]);
        free(got);
        free(want[i]);
    }
    cJSON_Delete(ref);
    remove_dir(dir);
}

/* ---- failures ---- */

typedef struct failing {
    ctn_ctx *ctx;
    size_t left;     /* bytes accepted before the failure */
} failing;

static int failing_write(void *ud, const char *p, size_t n)
{
    failing *f = ud;
    (void)p;
    if (n > f->left) return ctn_error(f->ctx, CTN_ERR_IO, "test sink: write failed: disk full");
    f->left -= n;
    return CTN_OK;
}

/* A sink that fails after some bytes (none, 100, half the output): every writer
 * reports CTN_ERR_IO. */
static void test_failing_sink(ctn_ctx *ctx, const model_case *c)
{
    const ctn_writer_ops *ops[4] = { &ctn_writer_json, &ctn_writer_nodes_csv, &ctn_writer_elements_csv, &ctn_writer_vtu };
    for (int i = 0; i < 4; i++) {
        failing all = { ctx, (size_t)-1 };
        ctn_sink sink = { failing_write, &all };
        CHECK(ctn_writer_run(ctx, ops[i], 1, &sink, c->m, c->s) == CTN_OK);
        size_t size = (size_t)-1 - all.left, limits[3] = { 0, 100, size / 2 };
        CHECK_MSG(size > 2 * CTN_WBUF_SIZE, "%s: %zu bytes", ops[i]->name, size);
        for (int l = 0; l < 3; l++) {
            failing f = { ctx, limits[l] };
            sink.ud = &f;
            int rc = ctn_writer_run(ctx, ops[i], 1, &sink, c->m, c->s);
            CHECK_MSG(rc == CTN_ERR_IO && strstr(ctn_ctx_message(ctx), "disk full"), "%s after %zu bytes: %d",
                      ops[i]->name, limits[l], rc);
        }
    }
}

/* Pieces of 1, 2, ... 7 nodes in turn, from the solution's arrays: what a distributed
 * run's source would bring (each process's owned nodes). */
static int small_pieces(void *ud, const ctn_solution *s, size_t k, size_t lo, size_t n, ctn_node_piece *out)
{
    size_t *turn = ud;
    int rc = ctn_pieces_local.nodes(NULL, s, k, lo, n, out);
    size_t size = 1 + (*turn)++ % 7;
    if (!rc && out->hi - out->lo > size) out->hi = out->lo + size;
    return rc;
}

static char *run_bytes(ctn_ctx *ctx, const ctn_writer_ops *ops, const ctn_pieces *pieces, const model_case *c)
{
    ctn_mem_sink mb;
    ctn_sink sink = ctn_sink_mem(&mb, ctx);
    size_t n = ctn_solution_step_count(c->s);
    char *text = NULL;
    int rc = ctn_writer_run_pieces(ctx, ops, 1, n - 1, pieces, &sink, c->m, c->s);
    if (!rc) rc = ctn_sink_mem_take(&mb, &text);
    ctn_sink_mem_free(&mb);
    CHECK_MSG(rc == CTN_OK, "%s: %s", ops->name, ctn_ctx_message(ctx));
    return text;
}

/* The writers take the nodes' results a piece at a time: pieces of any size give the
 * bytes of the solution's own. */
static void test_pieces(ctn_ctx *ctx, const model_case *c)
{
    const ctn_writer_ops *ops[3] = { &ctn_writer_json, &ctn_writer_nodes_csv, &ctn_writer_vtu };
    size_t turn = 0;
    ctn_pieces small = { small_pieces, &turn };
    for (int i = 0; i < 3; i++) {
        char *a = run_bytes(ctx, ops[i], &ctn_pieces_local, c), *b = run_bytes(ctx, ops[i], &small, c);
        CHECK_MSG(a && b && !strcmp(a, b), "%s: pieces of 1-7 nodes change the bytes", ops[i]->name);
        ctn_free(a);
        ctn_free(b);
    }
    CHECK(turn >= 2);
}

/* A full device (FILE sink): CTN_ERR_IO with the cause. */
static void test_full_device(ctn_ctx *ctx, const model_case *c)
{
    FILE *f = fopen("/dev/full", "w");
    if (!f) return;                                  /* no /dev/full here */
    int rc = ctn_write_json(ctx, f, c->m, c->s, 1);
    CHECK_MSG(rc == CTN_ERR_IO && strstr(ctn_ctx_message(ctx), "write error: No space left on device"),
              "rc %d: %s", rc, ctn_ctx_message(ctx));
    fclose(f);
}

/* The file size limit (RLIMIT_FSIZE) hit while streaming result.json: CTN_ERR_IO, and
 * the directory keeps the older set, untouched, and no temporary. */
static void test_size_limit(ctn_ctx *ctx, const model_case *big, const model_case *small)
{
    char dir[128], path[160];
    struct rlimit old, lim;
    snprintf(dir, sizeof dir, "%s/limit", tmpdir);
    CHECK(ctn_write_results(ctx, dir, small->m, small->s) == CTN_OK);
    snprintf(path, sizeof path, "%s/result.json", dir);
    char *before = read_all(path);
    if (getrlimit(RLIMIT_FSIZE, &old)) return;
    void (*handler)(int) = signal(SIGXFSZ, SIG_IGN);
    lim = old;
    lim.rlim_cur = 20000;
    CHECK(setrlimit(RLIMIT_FSIZE, &lim) == 0);
    int rc = ctn_write_results(ctx, dir, big->m, big->s);
    setrlimit(RLIMIT_FSIZE, &old);
    signal(SIGXFSZ, handler);
    CHECK_MSG(rc == CTN_ERR_IO && strstr(ctn_ctx_message(ctx), "write failed"), "rc %d: %s", rc,
              ctn_ctx_message(ctx));
    CHECK(count_entries(dir) == expected_files(small->s));
    char *after = read_all(path);
    CHECK(before && after && !strcmp(before, after));
    free(before);
    free(after);
    remove_dir(dir);
}

/* NaN in the result: CTN_ERR_INVALID from every writer, nothing written, no directory.
 * The NaN goes into the solution's own displacement array, through the pointer the
 * public accessor hands out. */
static void test_nan(ctn_ctx *ctx, const model_case *c)
{
    char dir[128], path[160], *json = NULL;
    ctn_step_result st;
    CHECK(ctn_solution_step(c->s, 0, &st) == CTN_OK);
    double *d = (double *)st.d, keep = d[4];
    d[4] = NAN;
    snprintf(dir, sizeof dir, "%s/nan", tmpdir);
    CHECK(ctn_write_results(ctx, dir, c->m, c->s) == CTN_ERR_INVALID);
    CHECK(count_entries(dir) < 0);
    CHECK(ctn_result_json(ctx, c->m, c->s, 1, &json) == CTN_ERR_INVALID && !json);
    snprintf(path, sizeof path, "%s/nan.json", tmpdir);
    FILE *f = fopen(path, "w");
    CHECK(f && ctn_write_json(ctx, f, c->m, c->s, 0) == CTN_ERR_INVALID);
    if (f) fclose(f);
    struct stat sb;
    CHECK(!stat(path, &sb) && sb.st_size == 0);
    unlink(path);
    d[4] = keep;
}

/* Fail each allocation of fn in turn: CTN_ERR_NOMEM, then success; in dir nothing but
 * the complete set. *allocs gets how many allocations a successful call made. */
static void fail_each(const char *what, int (*fn)(ctn_ctx *, const model_case *, const char *),
                      const model_case *c, const char *dir)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    long k;
    for (k = 1; k < 1000; k++) {
        ctn_ctx_fail_alloc_at(ctx, k);
        long before = ctn_ctx_alloc_count(ctx);
        int rc = fn(ctx, c, dir);
        long used = ctn_ctx_alloc_count(ctx) - before;
        if (used < k) {
            CHECK_MSG(rc == CTN_OK, "%s: %s", what, ctn_ctx_message(ctx));
            break;
        }
        CHECK_MSG(rc == CTN_ERR_NOMEM, "%s: allocation %ld: rc %d", what, k, rc);
        if (dir) CHECK_MSG(count_entries(dir) <= 0, "%s: allocation %ld left files", what, k);
    }
    CHECK_MSG(k > 1 && k < 1000, "%s: %ld allocations", what, k - 1);
    ctn_ctx_destroy(&ctx);
}

static int call_results(ctn_ctx *ctx, const model_case *c, const char *dir)
{
    int rc = ctn_write_results(ctx, dir, c->m, c->s);
    if (rc) return rc;
    rc = count_entries(dir) == expected_files(c->s) ? CTN_OK : CTN_ERR_IO;
    remove_dir(dir);
    return rc;
}

static int call_json(ctn_ctx *ctx, const model_case *c, const char *dir)
{
    char *json = NULL;
    (void)dir;
    int rc = ctn_result_json(ctx, c->m, c->s, 0, &json);
    if ((rc == CTN_OK) != (json != NULL)) rc = CTN_ERR_INVALID;
    ctn_json_free(json);
    return rc;
}

static int call_stream(ctn_ctx *ctx, const model_case *c, const char *dir)
{
    FILE *f = fopen("/dev/null", "w");
    (void)dir;
    if (!f) return CTN_ERR_IO;
    int rc = ctn_write_json(ctx, f, c->m, c->s, 1);
    fclose(f);
    return rc;
}

static void test_alloc_failures(const model_case *c)
{
    char dir[128];
    snprintf(dir, sizeof dir, "%s/nomem", tmpdir);
    fail_each("ctn_write_results", call_results, c, dir);
    fail_each("ctn_result_json", call_json, c, NULL);
    fail_each("ctn_write_json", call_stream, c, NULL);
}

int main(void)
{
    enum { NFILE = 9, NCASE = 12 };
    ctn_ctx *ctx = NULL;
    model_case cases[NCASE];
    const char *files[NFILE] = { "examples/paper/s250.8777.cable", "tests/errors/ok_steps_displace.cable",
                                 "examples/robust/guy_slack.cable", "examples/robust/net_slack.cable",
                                 "examples/robust/von_mises_truss.cable", "examples/springs/elastic_support.cable",
                                 "tests/models/trust/mast_two_guys.cable", "tests/models/trust/slack_held_node.cable",
                                 "tests/models/trust/paper_E2e14.cable" };
    ctn_ctx_create(&ctx);
    make_tmpdir();
    test_numbers(400000);
    for (int i = 0; i < NFILE; i++) solve_file(ctx, files[i], &cases[i]);
    solve_diverged(ctx, &cases[NFILE]);
    solve_big(ctx, &cases[NFILE + 1]);
    solve_escaped(ctx, &cases[NFILE + 2]);
    for (int i = 0; i < NCASE; i++) {
        if (!cases[i].s) continue;
        check_json(ctx, &cases[i], 1);
        check_json(ctx, &cases[i], 0);
        check_files(ctx, &cases[i]);
        test_pieces(ctx, &cases[i]);
    }
    const model_case *small = &cases[0], *steps = &cases[1], *big = &cases[NFILE + 1];
    if (small->s && steps->s && big->s) {
        test_failing_sink(ctx, big);
        test_full_device(ctx, big);
        test_size_limit(ctx, big, small);
        test_nan(ctx, &cases[1]);
        test_alloc_failures(steps);
    }
    for (int i = 0; i < NCASE; i++) destroy_case(&cases[i]);
    CHECK(count_entries(tmpdir) == 0);
    remove_dir(tmpdir);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
