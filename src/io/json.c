/* Result JSON (cJSON). Numbers round-trip (cJSON prints 17 digits when 15 do not).
 * NaN or Inf never reach the text: such a value is refused with CTN_ERR_INVALID. */
#include "model/model.h"
#include "solve/solution.h"
#include "catena/io.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>

typedef struct jb {
    int ok;          /* 0 after an allocation failure */
    int finite;      /* 0 after a non-finite number */
} jb;

static cJSON *num(jb *b, cJSON *obj, const char *key, double v)
{
    if (!isfinite(v)) b->finite = 0;
    cJSON *r = cJSON_AddNumberToObject(obj, key, isfinite(v) ? v : 0.0);
    if (!r) b->ok = 0;
    return r;
}

static cJSON *arr(jb *b, cJSON *obj, const char *key)
{
    cJSON *r = cJSON_AddArrayToObject(obj, key);
    if (!r) b->ok = 0;
    return r;
}

static cJSON *item(jb *b, cJSON *array)
{
    cJSON *o = cJSON_CreateObject();
    if (!o || !cJSON_AddItemToArray(array, o)) {
        cJSON_Delete(o);
        b->ok = 0;
        return NULL;
    }
    return o;
}

static void numbers(jb *b, cJSON *obj, const char *key, const double *v, size_t n)
{
    cJSON *a = arr(b, obj, key);
    for (size_t i = 0; a && i < n; i++) {
        if (!isfinite(v[i])) b->finite = 0;
        cJSON *x = cJSON_CreateNumber(isfinite(v[i]) ? v[i] : 0.0);
        if (!x || !cJSON_AddItemToArray(a, x)) { cJSON_Delete(x); b->ok = 0; return; }
    }
}

static void add_summary(jb *b, cJSON *root, const ctn_model *m, const ctn_solution *s)
{
    size_t n;
    const double *h = ctn_solution_residual_history(s, &n);
    b->ok &= cJSON_AddBoolToObject(root, "converged", s->sum.reason == CTN_CONVERGED) != NULL;
    b->ok &= cJSON_AddStringToObject(root, "reason", ctn_reason_name(s->sum.reason)) != NULL;
    num(b, root, "iterations", s->sum.iterations);
    numbers(b, root, "residual_history", h, n);
    h = ctn_solution_increment_history(s, &n);
    numbers(b, root, "increment_history", h, n);
    num(b, root, "external_force_norm", s->sum.fext_norm);
    num(b, root, "load_factor", s->sum.load_factor);
    num(b, root, "cutbacks", s->sum.cuts);
    cJSON *u = cJSON_AddObjectToObject(root, "units");
    if (!u) { b->ok = 0; return; }
    b->ok &= cJSON_AddStringToObject(u, "force", m->force_unit) != NULL;
    b->ok &= cJSON_AddStringToObject(u, "length", m->length_unit) != NULL;
    if (s->sum.reason == CTN_DIVERGED_INDEFINITE) {
        num(b, root, "fail_node", s->sum.fail_node);
        b->ok &= cJSON_AddStringToObject(root, "fail_direction", (const char *[]){ "x", "y", "z" }[s->sum.fail_dir]) != NULL;
    }
}

static void add_nodes(jb *b, cJSON *root, const ctn_model *m, const ctn_step_state *s)
{
    cJSON *a = arr(b, root, "nodes"), *r = arr(b, root, "reactions");
    static const char *xk[] = { "x", "y", "z" }, *uk[] = { "ux", "uy", "uz" }, *fk[] = { "fx", "fy", "fz" };
    for (size_t i = 0; a && r && b->ok && i < m->nodes.n; i++) {
        cJSON *o = item(b, a);
        if (!o) return;
        num(b, o, "id", m->nodes.v[i].id);
        for (int k = 0; k < 3; k++) num(b, o, xk[k], m->nodes.v[i].X[k]);
        for (int k = 0; k < 3; k++) num(b, o, uk[k], s->d[3 * i + k]);
        if (!m->nodes.v[i].fix) continue;
        cJSON *q = item(b, r);
        if (!q) return;
        num(b, q, "node", m->nodes.v[i].id);
        for (int k = 0; k < 3; k++) num(b, q, fk[k], s->react[3 * i + k]);
    }
}

static void add_elements(jb *b, cJSON *root, const ctn_model *m, const ctn_step_state *s)
{
    cJSON *a = arr(b, root, "elements");
    for (size_t i = 0; a && b->ok && i < m->elements.n; i++) {
        const ctn_element *e = &m->elements.v[i];
        const ctn_element_state *st = &s->elem[i];
        cJSON *o = item(b, a);
        if (!o) return;
        num(b, o, "id", e->id);
        const int *en = ctn_elem_nodes(m, i);
        int ids[2] = { m->nodes.v[en[0]].id, m->nodes.v[en[e->nnodes - 1]].id };
        cJSON *nd = cJSON_CreateIntArray(ids, 2);
        if (!nd || !cJSON_AddItemToObject(o, "nodes", nd)) { cJSON_Delete(nd); b->ok = 0; return; }
        num(b, o, "l0", e->l0);
        num(b, o, "length", st->length);
        num(b, o, "strain", st->strain);
        num(b, o, "force", st->force);
        num(b, o, "stress", st->stress);
        if (m->mpa > 0) num(b, o, "stress_mpa", st->stress * m->mpa);
        if (e->section >= 0 && m->materials.v[m->sections.v[e->section].material].tension_only)
            b->ok &= cJSON_AddBoolToObject(o, "slack", st->slack) != NULL;
    }
}

static void add_cables(jb *b, cJSON *root, const ctn_model *m, const ctn_solution *s)
{
    cJSON *a = arr(b, root, "cables");
    for (size_t i = 0; a && b->ok && i < m->cables.n; i++) {
        const ctn_cable *c = &m->cables.v[i];
        cJSON *o = item(b, a);
        double sag = 0, dmax = 0;
        if (!o) return;
        num(b, o, "node1", m->nodes.v[c->node[0]].id);
        num(b, o, "node2", m->nodes.v[c->node[1]].id);
        num(b, o, "first_element", m->elements.v[c->first].id);
        num(b, o, "last_element", m->elements.v[c->first + c->count - 1].id);
        num(b, o, "length", c->length);
        if (!ctn_solution_cable_sag(m, s, i, &sag)) num(b, o, "sag", sag);
        if (!ctn_solution_cable_max_sag_from_chord(m, s, i, &dmax)) num(b, o, "max_sag_from_chord", dmax);
    }
}

/* Every step's state (load steps, or arc-length path points). */
static void add_steps(jb *b, cJSON *root, const ctn_model *m, const ctn_solution *s)
{
    cJSON *a = arr(b, root, "steps");
    for (size_t k = 0; a && b->ok && k < s->nsteps; k++) {
        const ctn_step_state *st = &s->steps[k];
        cJSON *o = item(b, a);
        if (!o) return;
        b->ok &= cJSON_AddStringToObject(o, "name", st->name) != NULL;
        b->ok &= cJSON_AddBoolToObject(o, "converged", st->reason == CTN_CONVERGED) != NULL;
        b->ok &= cJSON_AddStringToObject(o, "reason", ctn_reason_name(st->reason)) != NULL;
        num(b, o, "load_factor", st->t);
        num(b, o, "iterations", st->iterations);
        add_nodes(b, o, m, st);
        add_elements(b, o, m, st);
    }
}

int ctn_result_json(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s, int pretty,
                    char **json)
{
    if (!m || !s || !json) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_result_json: bad arguments");
    *json = NULL;
    jb b = { 1, 1 };
    cJSON *root = cJSON_CreateObject();
    if (!root) return ctn_error(ctx, CTN_ERR_NOMEM, "out of memory building JSON");
    add_summary(&b, root, m, s);
    const ctn_step_state *last = &s->steps[s->nsteps - 1];
    if (b.ok) add_nodes(&b, root, m, last);
    if (b.ok) add_elements(&b, root, m, last);
    if (b.ok) add_cables(&b, root, m, s);
    if (b.ok && s->nsteps > 1) add_steps(&b, root, m, s);
    if (b.ok && b.finite) *json = pretty ? cJSON_Print(root) : cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    if (!b.finite) return ctn_error(ctx, CTN_ERR_INVALID, "result holds a NaN or Inf; not written");
    if (!*json) return ctn_error(ctx, CTN_ERR_NOMEM, "out of memory building JSON");
    return CTN_OK;
}

void ctn_json_free(char *json) { cJSON_free(json); }
