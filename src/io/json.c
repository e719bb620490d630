/* Result JSON (docs/format.md, "Results"), streamed: the bytes cJSON_Print (pretty) or
 * cJSON_PrintUnformatted gave when the document was built as a cJSON tree, without the
 * tree. Numbers round-trip as cJSON prints them (17 digits when 15 do not); a result
 * holding a NaN or Inf is refused (CTN_ERR_INVALID) before anything is written. */
#include "io/json_buckling.h"
#include "io/json_dynamics.h"
#include "io/json_modes.h"
#include "io/jsonw.h"
#include "io/writer.h"
#include "catena/io.h"
#include "catena/parallel.h"

#include <math.h>
#include <string.h>

typedef struct json_writer {
    ctn_writer w;
    ctn_jw j;
    size_t nsteps;
    const ctn_solution *s;     /* the solution written (its cases go last) */
} json_writer;

static const char *const xyz[3] = { "x", "y", "z" };

static void numbers(ctn_jw *j, const char *key, const double *v, size_t n)
{
    ctn_jw_array(j, key);
    for (size_t i = 0; i < n; i++) ctn_jw_number(j, NULL, v[i]);
    ctn_jw_end(j);
}

/* "stable" (checked for converged solutions) and, when not, "stability": why. */
static void put_stability(ctn_jw *j, const ctn_solution *s)
{
    ctn_stability st;
    if (ctn_solution_stability(s, &st)) return;
    ctn_jw_bool(j, "stable", st.stable);
    if (st.stable) {
        ctn_jw_string(j, "stable_by", st.by_tension ? "tension" : "factorization");
        return;
    }
    ctn_jw_object(j, "stability");
    ctn_jw_string(j, "kind", st.semidefinite ? "semi-definite" : "unstable");
    ctn_jw_number(j, "negative_eigenvalues", (double)st.negative);
    if (st.node) ctn_jw_number(j, "node", st.node);
    if (st.dir >= 0 && st.dir < 6) ctn_jw_string(j, "direction", ctn_dof_name(st.dir));
    ctn_jw_end(j);
}

/* The name of the first case or combination of s that did not converge; NULL if none. */
static const char *failed_case(const ctn_solution *s)
{
    for (size_t i = 0; i < ctn_solution_case_count(s); i++) {
        ctn_step_result st;
        if (!ctn_solution_step(ctn_solution_case(s, i), 0, &st) && st.reason != CTN_CONVERGED) return st.name;
    }
    return NULL;
}

/* "converged": the steps and every case and combination ("failed_case" names the first
 * that did not); "reason": the steps'. */
static void put_summary(json_writer *jw, const ctn_solution *s)
{
    ctn_jw *j = &jw->j;
    ctn_solve_summary sum;
    size_t n;
    const char *failed = failed_case(s);
    ctn_solution_summary(s, &sum);
    ctn_jw_bool(j, "converged", sum.reason == CTN_CONVERGED && !failed);
    if (failed) ctn_jw_string(j, "failed_case", failed);
    ctn_jw_string(j, "reason", ctn_reason_name(sum.reason));
    ctn_jw_number(j, "iterations", sum.iterations);
    const double *h = ctn_solution_residual_history(s, &n);
    numbers(j, "residual_history", h, n);
    h = ctn_solution_increment_history(s, &n);
    numbers(j, "increment_history", h, n);
    ctn_jw_number(j, "external_force_norm", sum.fext_norm);
    ctn_jw_number(j, "load_factor", sum.load_factor);
    ctn_jw_number(j, "cutbacks", sum.cuts);
    ctn_jw_number(j, "factorizations", sum.factorizations);
    ctn_jw_number(j, "solves", sum.solves);
    ctn_jw_number(j, "reused_factorizations", sum.reused);
    if (sum.fdensity) ctn_jw_bool(j, "force_density_start", 1);
    ctn_jw_string(j, "ordering", ctn_ordering_name(sum.ordering));
    ctn_jw_number(j, "factor_nonzeros", (double)sum.nnz_factor);
    ctn_jw_number(j, "factor_flops", sum.flops_factor);
    ctn_jw_string(j, "blas", sum.blas);
    ctn_jw_number(j, "threads", sum.threads);
    ctn_jw_number(j, "solve_threads", sum.solve_threads);
    const char *ls = ctn_solution_linear_solver(s);
    if (ctn_solution_ranks(s) > 1 || !strncmp(ls, "petsc", 5)) {   /* an MPI or PETSc run */
        ctn_jw_number(j, "ranks", ctn_solution_ranks(s));
        ctn_jw_string(j, "linear_solver", ls);
    }
    ctn_jw_object(j, "units");
    ctn_jw_string(j, "force", ctn_model_force_unit(jw->w.m));
    ctn_jw_string(j, "length", ctn_model_length_unit(jw->w.m));
    ctn_jw_end(j);
    if ((sum.reason == CTN_DIVERGED_INDEFINITE || sum.reason == CTN_DIVERGED_MECHANISM) && sum.fail_dir >= 0 &&
        sum.fail_dir < 6) {
        ctn_jw_number(j, "fail_node", sum.fail_node);
        ctn_jw_string(j, "fail_direction", ctn_dof_name(sum.fail_dir));
    }
    if (sum.reason != CTN_CONVERGED && sum.fail_element) ctn_jw_number(j, "fail_element", sum.fail_element);
    if ((sum.floor || sum.reason == CTN_DIVERGED_ROUNDOFF) && isfinite(sum.residual_floor) && isfinite(sum.force_scale)) {
        ctn_jw_number(j, "residual_floor", sum.residual_floor);
        ctn_jw_number(j, "force_scale", sum.force_scale);
    }
    put_stability(j, s);
}

/* The three numbers v[0..2] under the keys k[0..2]. */
static void put3(ctn_jw *j, const char *const *k, const double *v)
{
    for (int a = 0; a < 3; a++) ctn_jw_number(j, k[a], v[a]);
}

/* "nodes" (coordinates, displacements and, in a model with rotations, the rotations rx,
 * ry, rz) and "reactions" (of the supported nodes; with rotations, the moments mx, my,
 * mz too) of step k. */
static void put_nodes_from(json_writer *jw, const ctn_solution *s, size_t k, const double *base);

static void put_nodes(json_writer *jw, const ctn_solution *s, size_t k)
{
    put_nodes_from(jw, s, k, NULL);
}

/* The same; with base (the installed state's displacements, 3 per node), each node's
 * displacement from it too: ux_from, uy_from, uz_from. */
static void put_nodes_from(json_writer *jw, const ctn_solution *s, size_t k, const double *base)
{
    static const char *const fromk[3] = { "ux_from", "uy_from", "uz_from" };
    static const char *const uk[3] = { "ux", "uy", "uz" }, *const fk[3] = { "fx", "fy", "fz" };
    static const char *const rk[3] = { "rx", "ry", "rz" }, *const mk[3] = { "mx", "my", "mz" };
    ctn_jw *j = &jw->j;
    size_t nn = ctn_model_node_count(jw->w.m);
    const ctn_pieces *src = jw->w.pieces;
    ctn_node_piece pc;
    ctn_node_info p;
    ctn_jw_array(j, "nodes");
    for (size_t lo = 0; lo < nn; lo = pc.hi) {
        if (src->nodes(src->ud, s, k, lo, nn, &pc)) {
            ctn_writer_mismatch(&jw->w);
            return;
        }
        for (size_t i = pc.lo; i < pc.hi && !ctn_model_node(jw->w.m, i, &p); i++) {
            ctn_jw_object(j, NULL);
            ctn_jw_number(j, "id", p.id);
            put3(j, xyz, p.X);
            put3(j, uk, ctn_piece_d(&pc, i));
            if (base) {
                const double *u = ctn_piece_d(&pc, i);
                double du[3] = { u[0] - base[3 * i], u[1] - base[3 * i + 1], u[2] - base[3 * i + 2] };
                put3(j, fromk, du);
            }
            if (pc.rot) put3(j, rk, ctn_piece_rot(&pc, i));
            ctn_jw_end(j);
        }
    }
    ctn_jw_end(j);
    ctn_jw_array(j, "reactions");
    for (size_t lo = 0; lo < nn; lo = pc.hi) {
        if (src->nodes(src->ud, s, k, lo, nn, &pc)) {
            ctn_writer_mismatch(&jw->w);
            return;
        }
        for (size_t i = pc.lo; i < pc.hi && !ctn_model_node(jw->w.m, i, &p); i++) {
            if (!p.fix) continue;
            ctn_jw_object(j, NULL);
            ctn_jw_number(j, "node", p.id);
            put3(j, fk, ctn_piece_react(&pc, i));
            if (pc.mom) put3(j, mk, ctn_piece_mom(&pc, i));
            ctn_jw_end(j);
        }
    }
    ctn_jw_end(j);
}

static int node_id(const ctn_model *m, int index)
{
    ctn_node_info p;
    return ctn_model_node(m, (size_t)index, &p) ? 0 : p.id;
}

/* A catenary's forces and its shape at CTN_JSON_SHAPE + 1 points (docs/format.md). */
#define CTN_JSON_SHAPE 20
/* "target": what set the length of a cable or catenary element, and what was reached. */
static void put_target(ctn_jw *j, const ctn_cable_info *c)
{
    static const char *const kind[] = { "length", "H", "sag", "tension" };
    if (c->target == CTN_TARGET_NONE) return;
    ctn_jw_object(j, "target");
    ctn_jw_string(j, "kind", kind[c->target]);
    ctn_jw_number(j, "value", c->target_value);
    ctn_jw_number(j, "achieved", c->target_achieved);
    ctn_jw_number(j, "iterations", c->target_iterations);
    ctn_jw_end(j);
}

static void put_catenary(json_writer *jw, const ctn_solution *s, size_t k, size_t i)
{
    ctn_jw *j = &jw->j;
    ctn_catenary_result c = { .size = sizeof c };
    ctn_cable_info t;
    double xyzv[3 * (CTN_JSON_SHAPE + 1)];
    if (!ctn_model_element_target(jw->w.m, i, &t)) put_target(j, &t);
    if (ctn_solution_catenary(jw->w.m, s, k, i, &c)) return;
    ctn_jw_number(j, "H", c.H);
    numbers(j, "tension", c.tension, 2);
    ctn_jw_array(j, "end_forces");
    for (int a = 0; a < 2; a++) numbers(j, NULL, c.force[a], 3);
    ctn_jw_end(j);
    numbers(j, "V", c.V, 2);
    ctn_jw_number(j, "sag", c.sag);
    ctn_jw_number(j, "stretched_length", c.length);
    if (ctn_solution_element_shape(jw->w.m, s, k, i, CTN_JSON_SHAPE + 1, xyzv)) return;
    ctn_jw_array(j, "shape");
    for (int p = 0; p <= CTN_JSON_SHAPE; p++) numbers(j, NULL, xyzv + 3 * p, 3);
    ctn_jw_end(j);
}

/* A beam's end forces in its local axes (ctn_solution_beam). */
static void put_beam(json_writer *jw, const ctn_solution *s, size_t k, size_t i)
{
    ctn_jw *j = &jw->j;
    ctn_beam_result b = { .size = sizeof b };
    if (ctn_solution_beam(jw->w.m, s, k, i, &b)) return;
    ctn_jw_array(j, "end_forces_local");
    for (int a = 0; a < 2; a++) numbers(j, NULL, b.end[a], 6);
    ctn_jw_end(j);
    ctn_jw_number(j, "torque", b.T);
    ctn_jw_number(j, "moment_max", b.M_max);
    if (!(b.fy > 0)) return;                         /* the utilisation of a yield stress */
    ctn_jw_number(j, "stress_combined", b.stress);
    ctn_element_info e;
    if (!ctn_model_element(jw->w.m, i, &e) && !(e.capacity > 0)) ctn_jw_number(j, "utilisation", b.utilisation);
}

static void put_element(json_writer *jw, const ctn_element_info *e, const ctn_element_state *es,
                        const ctn_solution *s, size_t k, size_t i)
{
    ctn_jw *j = &jw->j;
    double mpa = ctn_model_mpa_factor(jw->w.m);
    ctn_jw_object(j, NULL);
    ctn_jw_number(j, "id", e->id);
    ctn_jw_array(j, "nodes");
    for (int a = 0; a < e->nnodes; a++) ctn_jw_number(j, NULL, node_id(jw->w.m, e->nodes[a]));
    ctn_jw_end(j);
    ctn_jw_number(j, "l0", e->l0);
    ctn_jw_number(j, "length", es->length);
    ctn_jw_number(j, "strain", es->strain);
    ctn_jw_number(j, "force", es->force);
    if (strcmp(e->type, "cable")) ctn_jw_string(j, "type", e->type);
    if (e->has_section) {                           /* a spring: a force, no stress */
        ctn_jw_number(j, "stress", es->stress);
        if (mpa > 0) ctn_jw_number(j, "stress_mpa", es->stress * mpa);
    }
    if (e->tension_only) ctn_jw_bool(j, "slack", es->slack);
    if (e->capacity > 0) ctn_jw_number(j, "utilisation", ctn_utilisation(e, es));
    if (e->group) ctn_jw_string(j, "group", e->group);
    if (!strcmp(e->type, "catenary")) put_catenary(jw, s, k, i);
    if (!strcmp(e->type, "beam")) put_beam(jw, s, k, i);
    ctn_jw_end(j);
}

/* "elements": the element states of step k. */
static void put_elements(json_writer *jw, const ctn_solution *s, size_t k)
{
    size_t ne = ctn_model_element_count(jw->w.m);
    ctn_jw_array(&jw->j, "elements");
    for (size_t i = 0; i < ne && !jw->w.out.err; i++) {
        ctn_element_info e;
        ctn_element_state es;
        if (ctn_model_element(jw->w.m, i, &e) || ctn_solution_step_element(s, k, i, &es)) {
            ctn_writer_mismatch(&jw->w);
            break;
        }
        put_element(jw, &e, &es, s, k, i);
    }
    ctn_jw_end(&jw->j);
}

static void put_cables(json_writer *jw, const ctn_solution *s)
{
    ctn_jw *j = &jw->j;
    const ctn_model *m = jw->w.m;
    ctn_jw_array(j, "cables");
    for (size_t i = 0; i < ctn_model_cable_count(m) && !jw->w.out.err; i++) {
        ctn_cable_info c;
        ctn_element_info first, last;
        double sag = 0, dmax = 0;
        if (ctn_model_cable(m, i, &c) || ctn_model_element(m, c.first, &first) ||
            ctn_model_element(m, c.first + c.count - 1, &last)) {
            ctn_writer_mismatch(&jw->w);
            break;
        }
        ctn_jw_object(j, NULL);
        ctn_jw_number(j, "node1", node_id(m, c.node[0]));
        ctn_jw_number(j, "node2", node_id(m, c.node[1]));
        ctn_jw_number(j, "first_element", first.id);
        ctn_jw_number(j, "last_element", last.id);
        ctn_jw_number(j, "length", c.length);
        if (!ctn_solution_cable_sag(m, s, i, &sag)) ctn_jw_number(j, "sag", sag);
        if (!ctn_solution_cable_max_sag_from_chord(m, s, i, &dmax)) ctn_jw_number(j, "max_sag_from_chord", dmax);
        put_target(j, &c);
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
}

/* One meshed cable i at the end of step k: its sag, the largest and smallest element
 * force and the stretched and unstressed lengths (sums over its elements). */
static void put_state_cable(json_writer *jw, const ctn_solution *s, size_t k, size_t i)
{
    ctn_jw *j = &jw->j;
    const ctn_model *m = jw->w.m;
    ctn_cable_info c;
    ctn_element_info first, last, ei;
    ctn_element_state es;
    double sag = 0, hi = -INFINITY, lo = INFINITY, len = 0, l0 = 0;
    if (ctn_model_cable(m, i, &c) || ctn_model_element(m, c.first, &first) ||
        ctn_model_element(m, c.first + c.count - 1, &last)) {
        ctn_writer_mismatch(&jw->w);
        return;
    }
    for (size_t e = c.first; e < c.first + c.count; e++) {
        if (ctn_model_element(m, e, &ei) || ctn_solution_step_element(s, k, e, &es)) {
            ctn_writer_mismatch(&jw->w);
            return;
        }
        hi = fmax(hi, es.force);
        lo = fmin(lo, es.force);
        len += es.length;
        l0 += ei.l0;
    }
    ctn_jw_object(j, NULL);
    ctn_jw_number(j, "node1", node_id(m, c.node[0]));
    ctn_jw_number(j, "node2", node_id(m, c.node[1]));
    ctn_jw_number(j, "first_element", first.id);
    ctn_jw_number(j, "last_element", last.id);
    if (!ctn_solution_step_cable_sag(m, s, k, i, &sag)) ctn_jw_number(j, "sag", sag);
    ctn_jw_number(j, "max_tension", hi);
    ctn_jw_number(j, "min_tension", lo);
    ctn_jw_number(j, "stretched_length", len);
    ctn_jw_number(j, "unstressed_length", l0);
    ctn_jw_end(j);
}

/* A catenary element i at the end of step k: its exact sag, end tensions (the smallest
 * tension is H when the curve's vertex lies inside the span: both supports lift it) and
 * lengths. */
static void put_state_catenary(json_writer *jw, const ctn_solution *s, size_t k, size_t i,
                               const ctn_element_info *e)
{
    ctn_jw *j = &jw->j;
    ctn_catenary_result c = { .size = sizeof c };
    if (ctn_solution_catenary(jw->w.m, s, k, i, &c)) return;
    double hi = fmax(c.tension[0], c.tension[1]), lo = fmin(c.tension[0], c.tension[1]);
    if (c.V[0] > 0 && c.V[1] > 0) lo = c.H;
    ctn_jw_object(j, NULL);
    ctn_jw_number(j, "element", e->id);
    ctn_jw_number(j, "node1", node_id(jw->w.m, e->node[0]));
    ctn_jw_number(j, "node2", node_id(jw->w.m, e->node[1]));
    ctn_jw_number(j, "sag", c.sag);
    ctn_jw_number(j, "max_tension", hi);
    ctn_jw_number(j, "min_tension", lo);
    ctn_jw_number(j, "stretched_length", c.length);
    ctn_jw_number(j, "unstressed_length", e->l0);
    ctn_jw_end(j);
}

/* "cables" of a step or case entry: each generated cable, then each catenary element;
 * the key is left out when the model has neither. */
static void put_state_cables(json_writer *jw, const ctn_solution *s, size_t k)
{
    const ctn_model *m = jw->w.m;
    size_t nc = ctn_model_cable_count(m), ne = ctn_model_element_count(m), ncat = 0;
    ctn_element_info e;
    for (size_t i = 0; i < ne; i++) ncat += !ctn_model_element(m, i, &e) && !strcmp(e.type, "catenary");
    if (!nc && !ncat) return;
    ctn_jw_array(&jw->j, "cables");
    for (size_t i = 0; i < nc && !jw->w.out.err; i++) put_state_cable(jw, s, k, i);
    for (size_t i = 0; i < ne && ncat && !jw->w.out.err; i++)
        if (!ctn_model_element(m, i, &e) && !strcmp(e.type, "catenary")) put_state_catenary(jw, s, k, i, &e);
    ctn_jw_end(&jw->j);
}

/* "groups": totals and extremes of each group at the end of step k. */
static void put_groups(json_writer *jw, const ctn_solution *s, size_t k)
{
    ctn_jw *j = &jw->j;
    ctn_jw_array(j, "groups");
    for (size_t g = 0; g < ctn_model_group_count(jw->w.m) && !jw->w.out.err; g++) {
        ctn_group_result r;
        if (ctn_solution_group(jw->w.m, s, k, g, &r)) {
            ctn_writer_mismatch(&jw->w);
            break;
        }
        ctn_jw_object(j, NULL);
        ctn_jw_string(j, "name", r.name);
        ctn_jw_number(j, "elements", (double)r.elements);
        ctn_jw_number(j, "max_force", r.max_force);
        ctn_jw_number(j, "min_force", r.min_force);
        ctn_jw_number(j, "max_stress", r.max_stress);
        ctn_jw_number(j, "max_strain", r.max_strain);
        ctn_jw_number(j, "max_utilisation", r.max_utilisation);          /* 0 without an mbl */
        if (r.has_capacity) ctn_jw_number(j, "worst_element", r.worst_element);
        ctn_jw_number(j, "slack", (double)r.slack);
        ctn_jw_number(j, "length", r.length);
        ctn_jw_number(j, "stressed_length", r.stressed_length);
        ctn_jw_number(j, "weight", r.weight);
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
}

/* The body of one entry of "steps" (or of "cases", base: its installed state's
 * displacements): step k's outcome and state. */
static void put_step_body(json_writer *jw, const ctn_solution *s, size_t k, const ctn_step_result *st,
                          const double *base)
{
    ctn_jw *j = &jw->j;
    ctn_jw_string(j, "name", st->name);
    ctn_jw_bool(j, "converged", st->reason == CTN_CONVERGED);
    ctn_jw_string(j, "reason", ctn_reason_name(st->reason));
    ctn_jw_number(j, "load_factor", st->load_factor);
    ctn_jw_number(j, "iterations", st->iterations);
    put_nodes_from(jw, s, k, base);
    put_elements(jw, s, k);
    if (ctn_model_group_count(jw->w.m)) put_groups(jw, s, k);
    put_state_cables(jw, s, k);
}

static void put_step(json_writer *jw, const ctn_solution *s, size_t k, const ctn_step_result *st)
{
    ctn_jw_object(&jw->j, NULL);
    put_step_body(jw, s, k, st, NULL);
    ctn_jw_end(&jw->j);
}

/* "cases" or "combinations" (comb): each a step's results, with its installed state
 * ("from") and a combination's terms. */
static void put_cases(json_writer *jw, int comb)
{
    ctn_jw *j = &jw->j;
    const ctn_model *m = jw->w.m;
    ctn_jw_array(j, comb ? "combinations" : "cases");
    for (size_t i = 0; i < ctn_solution_case_count(jw->s) && !jw->w.out.err; i++) {
        const ctn_solution *cs = ctn_solution_case(jw->s, i);
        const char *name = NULL;
        int from = 0, kind = 0;
        ctn_step_result st;
        if (ctn_model_case_info(m, i, &name, &from, &kind) || ctn_solution_step(cs, 0, &st)) {
            ctn_writer_mismatch(&jw->w);
            break;
        }
        if (kind != comb) continue;
        ctn_step_result base;
        if (ctn_solution_step(jw->s, (size_t)from, &base)) {
            ctn_writer_mismatch(&jw->w);
            break;
        }
        ctn_jw_object(j, NULL);
        put_step_body(jw, cs, 0, &st, base.d);
        ctn_jw_string(j, "from", ctn_model_step_name(m, (size_t)from));
        if (comb) {
            ctn_jw_array(j, "terms");
            for (size_t t = 0; t < ctn_model_case_terms(m, i); t++) {
                const char *cn = NULL;
                double f = 0;
                ctn_model_case_term(m, i, t, &cn, &f);
                ctn_jw_object(j, NULL);
                ctn_jw_string(j, "case", cn);
                ctn_jw_number(j, "factor", f);
                ctn_jw_end(j);
            }
            ctn_jw_end(j);
        }
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
}

/* "envelope": over the converged cases and combinations, each element's largest and
 * smallest force and the case that governs each, and each node's largest displacement
 * from the installed state of its case. */
static void put_envelope(json_writer *jw)
{
    ctn_jw *j = &jw->j;
    const ctn_model *m = jw->w.m;
    size_t nc = ctn_solution_case_count(jw->s);
    ctn_jw_object(j, "envelope");
    ctn_jw_array(j, "elements");
    for (size_t e = 0; e < ctn_model_element_count(m) && !jw->w.out.err; e++) {
        ctn_element_info ei;
        double hi = 0, lo = 0, util = 0;
        const char *hn = NULL, *ln = NULL, *un = NULL;
        ctn_model_element(m, e, &ei);
        for (size_t i = 0; i < nc; i++) {
            const ctn_solution *cs = ctn_solution_case(jw->s, i);
            ctn_step_result st;
            ctn_element_state es;
            const char *name = NULL;
            if (ctn_solution_step(cs, 0, &st) || st.reason != CTN_CONVERGED || ctn_solution_step_element(cs, 0, e, &es))
                continue;
            ctn_model_case_info(m, i, &name, NULL, NULL);
            if (!hn || es.force > hi) hi = es.force, hn = name;
            if (!ln || es.force < lo) lo = es.force, ln = name;
            if (ei.capacity > 0 && (!un || ctn_utilisation(&ei, &es) > util)) util = ctn_utilisation(&ei, &es), un = name;
        }
        if (!hn) continue;
        ctn_jw_object(j, NULL);
        ctn_jw_number(j, "id", ei.id);
        ctn_jw_number(j, "max_force", hi);
        ctn_jw_string(j, "max_case", hn);
        ctn_jw_number(j, "min_force", lo);
        ctn_jw_string(j, "min_case", ln);
        if (un) {
            ctn_jw_number(j, "max_utilisation", util);
            ctn_jw_string(j, "utilisation_case", un);
        }
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
    ctn_jw_array(j, "nodes");
    for (size_t p = 0; p < ctn_model_node_count(m) && !jw->w.out.err; p++) {
        double big = -1;
        const char *bn = NULL;
        for (size_t i = 0; i < nc; i++) {
            const ctn_solution *cs = ctn_solution_case(jw->s, i);
            ctn_step_result st, base;
            const char *name = NULL;
            int from = 0;
            ctn_model_case_info(m, i, &name, &from, NULL);
            if (ctn_solution_step(cs, 0, &st) || st.reason != CTN_CONVERGED ||
                ctn_solution_step(jw->s, (size_t)from, &base))
                continue;
            double dx = st.d[3 * p] - base.d[3 * p], dy = st.d[3 * p + 1] - base.d[3 * p + 1];
            double dz = st.d[3 * p + 2] - base.d[3 * p + 2], u = sqrt(dx * dx + dy * dy + dz * dz);
            if (u > big) big = u, bn = name;
        }
        if (!bn) continue;
        ctn_jw_object(j, NULL);
        ctn_jw_number(j, "id", node_id(m, (int)p));
        ctn_jw_number(j, "max_displacement", big);
        ctn_jw_string(j, "case", bn);
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
    ctn_jw_end(j);
}

static int json_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    json_writer *jw = p;
    int rc = ctn_writer_open(&jw->w, m, sink);
    if (rc) return rc;
    ctn_jw_init(&jw->j, &jw->w.out, jw->w.pretty);
    ctn_jw_object(&jw->j, NULL);
    return jw->w.out.err;
}

/* Step 0 also writes the summary, the final state (the last step) and the cables; the
 * steps array follows when there is more than one step. */
static int json_step(void *p, const ctn_solution *s, size_t k)
{
    json_writer *jw = p;
    ctn_step_result st;
    jw->nsteps = ctn_solution_step_count(s);
    jw->s = s;
    if (k == 0) {
        if (ctn_solution_step(s, jw->nsteps - 1, &st)) return ctn_writer_mismatch(&jw->w);
        put_summary(jw, s);
        put_nodes(jw, s, jw->nsteps - 1);
        put_elements(jw, s, jw->nsteps - 1);
        put_cables(jw, s);
        if (ctn_model_group_count(jw->w.m)) put_groups(jw, s, jw->nsteps - 1);
        ctn_json_put_modes(&jw->j, jw->w.m, s);
        ctn_json_put_buckling(&jw->j, jw->w.m, s);
        ctn_json_put_dynamics(&jw->j, s);
        if (jw->nsteps > 1) ctn_jw_array(&jw->j, "steps");
    }
    if (jw->nsteps > 1) {
        if (ctn_solution_step(s, k, &st)) return ctn_writer_mismatch(&jw->w);
        put_step(jw, s, k, &st);
    }
    return jw->w.out.err;
}

/* "sag_tension": the rows of the sag-tension chart (`sagtension`): each row's case or
 * combination, its temperature change, the case it adds to, and its cables as in
 * "cases". */
static void put_chart(json_writer *jw)
{
    ctn_jw *j = &jw->j;
    const ctn_model *m = jw->w.m;
    ctn_jw_array(j, "sag_tension");
    for (size_t r = 0; r < ctn_model_chart_count(m) && !jw->w.out.err; r++) {
        size_t i = 0;
        double dT = 0;
        const char *base = NULL, *name = NULL;
        const ctn_solution *cs = NULL;
        if (ctn_model_chart_row(m, r, &i, &dT, &base) || ctn_model_case_info(m, i, &name, NULL, NULL) ||
            !(cs = ctn_solution_case(jw->s, i))) {
            ctn_writer_mismatch(&jw->w);
            break;
        }
        ctn_jw_object(j, NULL);
        ctn_jw_string(j, "name", name);
        ctn_jw_number(j, "dT", dT);
        if (base) ctn_jw_string(j, "case", base);
        put_state_cables(jw, cs, 0);
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
}

static int json_end(void *p)
{
    json_writer *jw = p;
    if (jw->nsteps > 1) ctn_jw_end(&jw->j);
    if (jw->s && ctn_model_case_count(jw->w.m)) {
        put_cases(jw, 0);
        put_cases(jw, 1);
        put_envelope(jw);
        if (ctn_model_chart_count(jw->w.m)) put_chart(jw);
    }
    ctn_jw_end(&jw->j);
    return jw->w.out.err;
}

const ctn_writer_ops ctn_writer_json = { "result.json", sizeof(json_writer), json_begin, json_step, json_end };

int ctn_result_json(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s, int pretty,
                    char **json)
{
    if (!m || !s || !json) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_result_json: bad arguments");
    *json = NULL;
    int rc = ctn_result_check(ctx, m, s);
    if (rc) return rc;
    ctn_mem_sink mb;
    ctn_sink sink = ctn_sink_mem(&mb, ctx);
    rc = ctn_writer_run(ctx, &ctn_writer_json, pretty, &sink, m, s);
    if (!rc) rc = ctn_sink_mem_take(&mb, json);
    ctn_sink_mem_free(&mb);
    return rc;
}

void ctn_json_free(char *json) { ctn_free(json); }

int ctn_write_json(ctn_ctx *ctx, FILE *out, const ctn_model *m, const ctn_solution *s,
                   int pretty)
{
    if (!out || !m || !s) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_write_json: bad arguments");
    int rc = ctn_result_check(ctx, m, s);
    if (rc) return rc;
    ctn_stdio_sink st;
    ctn_sink sink = ctn_sink_stdio(&st, ctx, out, out == stdout ? "stdout" : "output stream");
    rc = ctn_writer_run(ctx, &ctn_writer_json, pretty, &sink, m, s);
    if (!rc) rc = ctn_sink_stdio_flush(&st);
    return rc;
}
