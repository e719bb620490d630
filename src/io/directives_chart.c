/* sagtension dT=T1,T2,... [cases=CASE,...] [from=STEP]: the sag-tension (stringing)
 * chart of a line (docs/format.md "sagtension"): for each temperature change a case
 * dT_<T> (the temperature of every element changed by T, from the installed state), and
 * for each named case and temperature the combination <CASE>_dT_<T> = CASE + dT_<T>;
 * the JSON's "sag_tension" lists their cables' sag and tensions row by row. */
#include "io/parse.h"

#include <stdio.h>
#include <string.h>

#define CHART_MAX 64     /* temperatures, and cases, at most */

/* Comma-separated items of value v into item[] (in buf); their count, -1 if too many
 * or one is empty. */
static int split(const char *v, char *buf, size_t size, char **item)
{
    int n = 0;
    snprintf(buf, size, "%s", v);
    for (char *p = buf, *c; p; p = c ? c + 1 : NULL) {
        c = strchr(p, ',');
        if (c) *c = '\0';
        if (!*p || n == CHART_MAX) return -1;
        item[n++] = p;
    }
    return n;
}

/* The case name of temperature change t: dT_<t>, '-' written 'm' ("dT_m20", "dT_12.5"). */
static void case_name(double t, char *out, size_t size)
{
    char v[40];
    snprintf(v, sizeof v, "%.15g", t);
    size_t k = (size_t)snprintf(out, size, "dT_");
    for (const char *p = v; *p && k + 1 < size; p++) out[k++] = *p == '-' ? 'm' : *p == '+' ? 'p' : *p;
    out[k] = '\0';
}

static int add_row(ctn_model *m, int combination, double dT, int base)
{
    if (CTN_ARRAY_RESERVE(m->ctx, m->chart, 1)) return CTN_ERR_NOMEM;
    ctn_chart_row *r = &m->chart.v[m->chart.n++];
    r->combination = combination;
    r->index = (int)(combination ? m->combos.n : m->cases.n) - 1;
    r->dT = dT;
    r->base = base;
    return CTN_OK;
}

/* The temperatures' cases, from step `from` (NULL: the last). */
static int temperature_cases(ctn_line *l, const double *t, int nt, const char *from)
{
    int rc = CTN_OK;
    for (int i = 0; i < nt && !rc; i++) {
        char name[CTN_NAME_MAX];
        case_name(t[i], name, sizeof name);
        rc = ctn_model_add_case(l->m, name, from, 0);
        if (!rc) rc = ctn_model_add_temperature(l->m, "all", t[i]);
        if (!rc) rc = add_row(l->m, 0, t[i], -1);
    }
    return rc;
}

/* Each named case with each temperature's case. */
static int combinations(ctn_line *l, char **cases, int nc, const double *t, int nt)
{
    int rc = CTN_OK;
    for (int c = 0; c < nc && !rc; c++) {
        int ci = ctn_model_find_case(l->m, cases[c]);
        for (int i = 0; i < nt && !rc; i++) {
            char tn[CTN_NAME_MAX], name[2 * CTN_NAME_MAX];
            case_name(t[i], tn, sizeof tn);
            snprintf(name, sizeof name, "%s_%s", cases[c], tn);
            const char *terms[2] = { cases[c], tn };
            const double f[2] = { 1, 1 };
            rc = ctn_model_add_combination(l->m, name, terms, f, 2);
            if (!rc) rc = add_row(l->m, 1, t[i], ci);
        }
    }
    return rc;
}

/* The step the named cases start from (all the same), or NULL: the last step. */
static int common_from(ctn_line *l, char **cases, int nc, const char **from)
{
    *from = NULL;
    for (int c = 0; c < nc; c++) {
        int ci = ctn_model_find_case(l->m, cases[c]);
        if (ci < 0) return ctn_parse_error(l, "sagtension: unknown case '%.63s' in cases= (a case defined on an earlier line)", cases[c]);
        const char *f = l->m->steps.n ? l->m->steps.v[l->m->cases.v[ci].from].name : NULL;
        if (c && f != *from)
            return ctn_parse_error(l, "sagtension: the cases in cases= start from different steps ('%s' and '%s')", *from, f);
        *from = f;
    }
    return CTN_OK;
}

int ctn_parse_sagtension(ctn_line *l)
{
    char tbuf[1024], cbuf[1024], *titem[CHART_MAX], *citem[CHART_MAX];
    double t[CHART_MAX];
    int rc = ctn_parse_positional(l, 0, "sagtension dT=T1,T2,... [cases=CASE,...] [from=STEP]");
    const char *tv = rc ? NULL : ctn_parse_key(l, 1, "dT"), *cv = rc ? NULL : ctn_parse_key(l, 1, "cases");
    const char *from = rc ? NULL : ctn_parse_key(l, 1, "from");
    if (!rc && !tv) return ctn_parse_missing(l, 1, NULL, "dT", NULL);
    if (!rc) rc = ctn_parse_leftovers(l, 1, "sagtension");
    if (rc) return rc;
    int nt = split(tv, tbuf, sizeof tbuf, titem), nc = cv ? split(cv, cbuf, sizeof cbuf, citem) : 0;
    if (nt < 0 || nc < 0) return ctn_parse_error(l, "sagtension: dT= and cases= are lists of at most %d items separated by commas", CHART_MAX);
    for (int i = 0; i < nt && !rc; i++) rc = ctn_parse_num(l, "'dT'", titem[i], &t[i]);
    const char *cfrom = NULL;
    if (!rc) rc = common_from(l, citem, nc, &cfrom);
    if (!rc && from && nc && cfrom && strcmp(from, cfrom))
        return ctn_parse_error(l, "sagtension: from=%.63s, but the cases in cases= start from '%s'", from, cfrom);
    if (!rc) rc = temperature_cases(l, t, nt, from ? from : cfrom);
    if (!rc) rc = combinations(l, citem, nc, t, nt);
    l->m->in_case = 0;                              /* the lines after it: no case open */
    return rc;
}
