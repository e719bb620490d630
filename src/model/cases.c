/* Load cases and combinations (docs/format.md, `case`, `combination`): definitions and
 * the load selection each is solved with. */
#include "model/model.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* A case or combination name: a letter first, then letters, digits, '_', '.'. */
static int valid_name(const char *s)
{
    if (!s || !isalpha((unsigned char)*s) || strlen(s) >= CTN_NAME_MAX) return 0;
    for (const char *p = s; *p; p++)
        if (!isalnum((unsigned char)*p) && *p != '_' && *p != '.') return 0;
    return 1;
}

int ctn_model_find_case(const ctn_model *m, const char *name)
{
    for (size_t i = 0; i < m->cases.n; i++)
        if (!strcmp(m->cases.v[i].name, name)) return (int)i;
    return -1;
}

static int find_combo(const ctn_model *m, const char *name)
{
    for (size_t i = 0; i < m->combos.n; i++)
        if (!strcmp(m->combos.v[i].name, name)) return (int)i;
    return -1;
}

static int check_name(ctn_model *m, const char *what, const char *name)
{
    if (!valid_name(name))
        return ctn_model_error(m, CTN_ERR_MODEL, "%s name '%.63s' is not valid (a letter first, then letters, digits, "
                               "'_' or '.', at most %d characters)", what, name ? name : "", CTN_NAME_MAX - 1);
    if (ctn_model_find_case(m, name) >= 0 || find_combo(m, name) >= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "%s '%s': the name is already a case or a combination", what, name);
    return CTN_OK;
}

int ctn_model_add_case(ctn_model *m, const char *name, const char *from, int substeps)
{
    if (!m) return CTN_ERR_INVALID;
    int rc = check_name(m, "case", name), k = m->steps.n ? (int)m->steps.n - 1 : 0;
    if (rc) return rc;
    if (from) {
        for (k = (int)m->steps.n - 1; k >= 0 && strcmp(m->steps.v[k].name, from); k--) {}
        if (k < 0)
            return ctn_model_error(m, CTN_ERR_MODEL, "case '%s': unknown step '%.63s' in from= (%s)", name, from,
                                   m->steps.n ? "a step defined on an earlier line" : "the model has no step");
    }
    if (substeps < 0 || substeps > CTN_SUBSTEPS_MAX)
        return ctn_model_error(m, CTN_ERR_MODEL, "case '%s': substeps must be between 1 and %d", name, CTN_SUBSTEPS_MAX);
    if ((rc = CTN_ARRAY_RESERVE(m->ctx, m->cases, 1))) return rc;
    ctn_case *c = &m->cases.v[m->cases.n++];
    snprintf(c->name, sizeof c->name, "%s", name);
    c->from = k;
    c->substeps = substeps;
    c->line = m->line;
    m->in_case = 1;                                /* the loads that follow are the case's */
    return CTN_OK;
}

int ctn_model_add_combination(ctn_model *m, const char *name, const char *const *cases, const double *factors,
                              size_t n)
{
    if (!m || (n && (!cases || !factors))) return CTN_ERR_INVALID;
    int rc = check_name(m, "combination", name);
    if (rc) return rc;
    if (!n) return ctn_model_error(m, CTN_ERR_MODEL, "combination '%s': give at least one term FACTOR*CASE", name);
    if (n > CTN_MAX_CASE_TERMS)
        return ctn_model_error(m, CTN_ERR_MODEL, "combination '%s': at most %d terms", name, CTN_MAX_CASE_TERMS);
    if ((rc = CTN_ARRAY_RESERVE(m->ctx, m->terms, n)) || (rc = CTN_ARRAY_RESERVE(m->ctx, m->combos, 1))) return rc;
    ctn_combo cb = { .first = m->terms.n, .count = n, .from = -1, .line = m->line };
    snprintf(cb.name, sizeof cb.name, "%s", name);
    for (size_t i = 0; i < n; i++) {
        int c = ctn_model_find_case(m, cases[i]);
        if (c < 0) return ctn_model_error(m, CTN_ERR_MODEL, "combination '%s': unknown case '%.63s'", name, cases[i]);
        if (!isfinite(factors[i])) return ctn_model_error(m, CTN_ERR_MODEL, "combination '%s': factor of '%s' must be finite", name, cases[i]);
        for (size_t j = 0; j < i; j++)
            if (!strcmp(cases[j], cases[i]))
                return ctn_model_error(m, CTN_ERR_MODEL, "combination '%s': case '%s' given twice", name, cases[i]);
        int from = m->cases.v[c].from;
        if (cb.from >= 0 && from != cb.from)
            return ctn_model_error(m, CTN_ERR_MODEL, "combination '%s': its cases start from different states ('%s' "
                                   "from step '%s', '%s' from step '%s'): combine cases of one installed state", name,
                                   cases[0], ctn_model_step_name(m, (size_t)cb.from), cases[i],
                                   ctn_model_step_name(m, (size_t)from));
        cb.from = from;
    }
    for (size_t i = 0; i < n; i++) {
        ctn_combo_term t = { ctn_model_find_case(m, cases[i]), factors[i] };
        m->terms.v[m->terms.n + i] = t;
    }
    m->terms.n += n;
    m->combos.v[m->combos.n++] = cb;
    return CTN_OK;
}

size_t ctn_model_case_count(const ctn_model *m) { return m ? m->cases.n + m->combos.n : 0; }

int ctn_model_case_sel(const ctn_model *m, size_t i, ctn_loadsel *sel, int *tags, double *factors)
{
    if (!m || i >= m->cases.n + m->combos.n) return CTN_ERR_INVALID;
    if (i < m->cases.n) {
        tags[0] = CTN_CASE_TAG0 + (int)i;
        factors[0] = 1.0;
        *sel = (ctn_loadsel){ m->cases.v[i].from + 1, 1, tags, factors };
        return CTN_OK;
    }
    const ctn_combo *cb = &m->combos.v[i - m->cases.n];
    for (size_t k = 0; k < cb->count; k++) {
        tags[k] = CTN_CASE_TAG0 + m->terms.v[cb->first + k].c;
        factors[k] = m->terms.v[cb->first + k].factor;
    }
    *sel = (ctn_loadsel){ cb->from + 1, cb->count, tags, factors };
    return CTN_OK;
}

int ctn_model_case_info(const ctn_model *m, size_t i, const char **name, int *from, int *combination)
{
    if (!m || i >= m->cases.n + m->combos.n) return CTN_ERR_INVALID;
    int comb = i >= m->cases.n;
    const ctn_case *c = comb ? NULL : &m->cases.v[i];
    const ctn_combo *cb = comb ? &m->combos.v[i - m->cases.n] : NULL;
    if (name) *name = comb ? cb->name : c->name;
    if (from) *from = comb ? cb->from : c->from;
    if (combination) *combination = comb;
    return CTN_OK;
}

size_t ctn_model_case_terms(const ctn_model *m, size_t i)
{
    return m && i >= m->cases.n && i < m->cases.n + m->combos.n ? m->combos.v[i - m->cases.n].count : 0;
}

int ctn_model_case_term(const ctn_model *m, size_t i, size_t k, const char **name, double *factor)
{
    if (k >= ctn_model_case_terms(m, i)) return CTN_ERR_INVALID;
    const ctn_combo_term *t = &m->terms.v[m->combos.v[i - m->cases.n].first + k];
    if (name) *name = m->cases.v[t->c].name;
    if (factor) *factor = t->factor;
    return CTN_OK;
}
