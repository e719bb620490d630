/* Groups of elements and temperature changes (loads that target elements or groups). */
#include "element/element.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

int ctn_model_find_group(const ctn_model *m, const char *name)
{
    for (size_t i = 0; i < m->groups.n; i++)
        if (!strcmp(m->groups.v[i].name, name)) return (int)i;
    return -1;
}

/* A letter first (so that a group never reads as an element id), then letters, digits,
 * '_', '-', '.'; not "all". */
static int valid_name(const char *s)
{
    if (!s || !isalpha((unsigned char)*s) || !strcmp(s, "all") || strlen(s) >= CTN_NAME_MAX) return 0;
    for (const char *p = s; *p; p++)
        if (!isalnum((unsigned char)*p) && !strchr("_-.", *p)) return 0;
    return 1;
}

int ctn_model_group_get(ctn_model *m, const char *name, int *index)
{
    if (!valid_name(name))
        return ctn_model_error(m, CTN_ERR_MODEL, "group name '%.63s' is not valid (a letter first, then letters, "
                               "digits, '_', '-' or '.', at most %d characters; not 'all')", name ? name : "",
                               CTN_NAME_MAX - 1);
    int g = ctn_model_find_group(m, name);
    if (g < 0 && ctn_model_find_set(m, name) >= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "group '%s': the name is already a set", name);
    if (g < 0) {
        int rc = CTN_ARRAY_RESERVE(m->ctx, m->groups, 1);
        if (rc) return rc;
        g = (int)m->groups.n++;
        snprintf(m->groups.v[g].name, CTN_NAME_MAX, "%s", name);
        m->groups.v[g].line = m->line;
    }
    *index = g;
    return CTN_OK;
}

int ctn_model_group_put(ctn_model *m, size_t e, int g)
{
    ctn_element *el = &m->elements.v[e];
    if (el->group >= 0 && el->group != g)
        return ctn_model_error(m, CTN_ERR_MODEL, "element %d is already in group '%s' (an element belongs to at most one group)",
                               el->id, m->groups.v[el->group].name);
    el->group = g;
    return CTN_OK;
}

int ctn_model_add_group(ctn_model *m, const char *name, int first, int last)
{
    if (!m) return CTN_ERR_INVALID;
    if (last < first) return ctn_model_error(m, CTN_ERR_MODEL, "group '%s': empty element range %d-%d", name ? name : "", first, last);
    int g = -1, rc = ctn_model_group_get(m, name, &g), hit = 0;
    if (rc) return rc;
    if (first == last) {                       /* one id: it must exist */
        int e = ctn_idmap_get(&m->element_ids, first);
        if (e < 0) return ctn_model_error(m, CTN_ERR_MODEL, "group '%s': undefined element %d", name, first);
        return ctn_model_group_put(m, (size_t)e, g);
    }
    for (size_t i = 0; i < m->elements.n && !rc; i++) {
        int id = m->elements.v[i].id;
        if (id < first || id > last) continue;
        hit = 1;
        rc = ctn_model_group_put(m, i, g);
    }
    if (!rc && !hit) return ctn_model_error(m, CTN_ERR_MODEL, "group '%s': no element with id in %d-%d", name, first, last);
    return rc;
}

size_t ctn_model_group_count(const ctn_model *m) { return m ? m->groups.n : 0; }

const char *ctn_model_group_name(const ctn_model *m, size_t g)
{
    return m && g < m->groups.n ? m->groups.v[g].name : NULL;
}

/* Whether element e expands with temperature (a family with a material). */
static int thermal(const ctn_model *m, size_t e)
{
    return ctn_element_family(m->elements.v[e].type)->temperature != NULL;
}

int ctn_model_load_target(ctn_model *m, const char *what, const char *target,
                          int (*accepts)(const ctn_model *, size_t), const char *refusal, int *kind, int *index)
{
    if (!strcmp(target, "all")) {
        *kind = CTN_TARGET_ALL;
        return CTN_OK;
    }
    if (isdigit((unsigned char)*target) || *target == '-' || *target == '+') {
        char *end;
        errno = 0;
        long id = strtol(target, &end, 10);
        int e = *end || errno || id <= 0 || id > 0x7fffffff ? -1 : ctn_idmap_get(&m->element_ids, (int)id);
        if (e < 0) return ctn_model_error(m, CTN_ERR_MODEL, "%s: undefined element '%.40s'", what, target);
        if (!accepts(m, (size_t)e))
            return ctn_model_error(m, CTN_ERR_MODEL, "%s: element %ld is a %s%s", what, id,
                                   ctn_element_family(m->elements.v[e].type)->name, refusal);
        *kind = CTN_TARGET_ELEMENT;
        *index = e;
        return CTN_OK;
    }
    int g = ctn_model_find_set(m, target);
    if (g >= 0 && m->sets.v[g].nodes)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: set '%.63s' is a node set; give an element set", what, target);
    if (g >= 0) {
        *kind = CTN_TARGET_SET;
        *index = g;
        return CTN_OK;
    }
    g = ctn_model_find_group(m, target);
    if (g < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s: '%.63s' is not 'all', an element id or a defined group "
                               "(or element set)", what, target);
    *kind = CTN_TARGET_GROUP;
    *index = g;
    return CTN_OK;
}

int ctn_model_add_temperature(ctn_model *m, const char *target, double dT)
{
    if (!m || !target) return CTN_ERR_INVALID;
    if (!isfinite(dT) || fabs(dT) > 1e4)
        return ctn_model_error(m, CTN_ERR_MODEL, "temperature: dT must be finite and at most 1e4 K in size (got %g)", dT);
    ctn_tload t = { 0, -1, dT, ctn_model_load_tag(m), m->line };
    int rc = ctn_model_load_target(m, "temperature", target, thermal, ", which has no thermal expansion", &t.kind,
                                   &t.target);
    if (!rc) rc = CTN_ARRAY_RESERVE(m->ctx, m->tloads, 1);
    if (rc) return rc;
    for (size_t i = 0; i < m->elements.n; i++) {   /* 1 + alpha dT must stay positive */
        if (!thermal(m, i) || !ctn_model_target_has(m, t.kind, t.target, i)) continue;
        const ctn_element *el = &m->elements.v[i];
        double alpha = m->materials.v[m->sections.v[el->section].material].alpha;
        if (!(1 + alpha * dT > 0.5))
            return ctn_model_error(m, CTN_ERR_MODEL, "temperature: dT = %g K would shrink element %d by more than half "
                                   "(alpha = %g)", dT, el->id, alpha);
    }
    m->tloads.v[m->tloads.n++] = t;
    return CTN_OK;
}

void ctn_model_step_temperatures(const ctn_model *m, size_t k, double *dT)
{
    ctn_loadsel sel = ctn_loadsel_step(k);
    ctn_model_sel_temperatures(m, &sel, dT);
}

void ctn_model_sel_temperatures(const ctn_model *m, const ctn_loadsel *sel, double *dT)
{
    memset(dT, 0, m->elements.n * sizeof *dT);
    for (size_t j = 0; j < m->tloads.n; j++) {
        const ctn_tload *t = &m->tloads.v[j];
        double w = ctn_loadsel_weight(sel, t->step);
        if (w == 0) continue;
        if (t->kind == CTN_TARGET_ELEMENT) {
            dT[t->target] += w * t->dT;
            continue;
        }
        for (size_t i = 0; i < m->elements.n; i++)
            if (thermal(m, i) && ctn_model_target_has(m, t->kind, t->target, i)) dT[i] += w * t->dT;
    }
}

double ctn_model_element_temperature(const ctn_model *m, size_t k, size_t e)
{
    ctn_loadsel sel = ctn_loadsel_step(k);
    return ctn_model_sel_element_temperature(m, &sel, e);
}

double ctn_model_sel_element_temperature(const ctn_model *m, const ctn_loadsel *sel, size_t e)
{
    double dT = 0;
    if (!thermal(m, e)) return 0;
    for (size_t j = 0; j < m->tloads.n; j++) {
        const ctn_tload *t = &m->tloads.v[j];
        double w = ctn_loadsel_weight(sel, t->step);
        if (w == 0) continue;
        if (ctn_model_target_has(m, t->kind, t->target, e)) dT += w * t->dT;
    }
    return dT;
}
