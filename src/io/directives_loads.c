/* The directives of loads stated as engineers state them: lineload, case, combination
 * (docs/format.md). */
#include "io/parse.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* lineload TARGET [qx=] [qy=] [qz=]: at least one component. */
int ctn_parse_lineload(ctn_line *l)
{
    static const char *const keys[3] = { "qx", "qy", "qz" };
    double q[3] = { 0, 0, 0 };
    int given = 0;
    int rc = ctn_parse_positional(l, 1, "lineload TARGET [qx=LOAD] [qy=LOAD] [qz=LOAD] (TARGET: all, an element id or a group)");
    for (int k = 0; k < 3 && !rc; k++) {
        given |= ctn_parse_key(l, 2, keys[k]) != NULL;
        rc = ctn_parse_key_num(l, 2, keys[k], 0, &q[k]);
    }
    if (!rc && !given) return ctn_parse_missing(l, 2, NULL, "qx", " (give at least one of qx=, qy=, qz=)");
    if (!rc) rc = ctn_parse_leftovers(l, 2, "lineload");
    return rc ? rc : ctn_model_add_lineload(l->m, l->tok[1], q);
}

/* case NAME [from=STEP] [substeps=N] */
int ctn_parse_case(ctn_line *l)
{
    int rc = ctn_parse_positional(l, 1, "case NAME [from=STEP] [substeps=N]");
    const char *from = rc ? NULL : ctn_parse_key(l, 2, "from");
    const char *sub = rc ? NULL : ctn_parse_key(l, 2, "substeps");
    long long n = 0;
    double x;
    if (!rc && sub) {
        rc = ctn_parse_num(l, "'substeps'", sub, &x);
        if (!rc && (!ctn_parse_integral(sub, &n) || n < 1 || n > CTN_SUBSTEPS_MAX))
            return ctn_parse_error(l, "substeps must be an integer from 1 to %d (found %.40s)", CTN_SUBSTEPS_MAX, sub);
    }
    if (!rc) rc = ctn_parse_leftovers(l, 2, "case");
    return rc ? rc : ctn_model_add_case(l->m, l->tok[1], from, (int)n);
}

/* One term [SIGN][FACTOR*]CASE of a combination from s + *pos (the terms joined without
 * blanks); the case's name is copied into name. */
static int combo_term(ctn_line *l, const char *s, size_t *pos, char *name, double *factor)
{
    size_t i = *pos, k = 0;
    double sign = 1, f = 1;
    if (s[i] == '+' || s[i] == '-') sign = s[i++] == '-' ? -1 : 1;
    if (s[i] == '.' || (s[i] >= '0' && s[i] <= '9')) {
        char *end;
        f = strtod(s + i, &end);
        if (*end != '*') return ctn_parse_error(l, "combination: expected FACTOR*CASE, found '%.40s'", s + i);
        i = (size_t)(end - s) + 1;
    }
    while (s[i] && s[i] != '+' && s[i] != '-' && k + 1 < CTN_NAME_MAX) name[k++] = s[i++];
    name[k] = '\0';
    if (!k) return ctn_parse_error(l, "combination: a term has no case name (expected FACTOR*CASE, found '%.40s')", s + *pos);
    *factor = sign * f;
    *pos = i;
    return CTN_OK;
}

/* combination NAME F1*CASE1 + F2*CASE2 ... (blanks around + optional) */
int ctn_parse_combination(ctn_line *l)
{
    int rc = ctn_parse_positional(l, 2, "combination NAME FACTOR*CASE [+ FACTOR*CASE ...]");
    char text[4096], names[CTN_MAX_TOKENS][CTN_NAME_MAX];
    const char *np[CTN_MAX_TOKENS];
    double f[CTN_MAX_TOKENS];
    size_t len = 0, n = 0, pos = 0;
    for (int k = 2; k < l->ntok && !rc; k++) {
        size_t tl = strlen(l->tok[k]);
        if (len + tl + 1 > sizeof text) return ctn_parse_error(l, "combination: too long");
        memcpy(text + len, l->tok[k], tl);
        len += tl;
    }
    text[len] = '\0';
    while (!rc && text[pos] && n < CTN_MAX_TOKENS) {
        rc = combo_term(l, text, &pos, names[n], &f[n]);
        np[n] = names[n];
        n++;
    }
    if (!rc && text[pos]) return ctn_parse_error(l, "combination: too many terms (at most %d)", CTN_MAX_TOKENS);
    l->used = ~0ull;
    return rc ? rc : ctn_model_add_combination(l->m, l->tok[1], np, f, n);
}

/* ice TARGET thickness=T density=RHO d=DIAMETER: the weight of a radial ice sleeve,
 * rho g pi t (d + t) per unstressed length along gravity, as a lineload. */
int ctn_parse_ice(ctn_line *l)
{
    double t = 0, rho = 0, d = 0, g[3];
    int rc = ctn_parse_positional(l, 1, "ice TARGET thickness=LENGTH density=MASS_PER_VOLUME d=DIAMETER");
    if (!rc) rc = ctn_parse_key_num(l, 2, "thickness", 1, &t);
    if (!rc) rc = ctn_parse_key_num(l, 2, "density", 1, &rho);
    if (!rc) rc = ctn_parse_key_num(l, 2, "d", 1, &d);
    if (!rc) rc = ctn_parse_leftovers(l, 2, "ice");
    if (rc) return rc;
    if (!(t >= 0 && rho >= 0 && d >= 0)) return ctn_parse_error(l, "ice: thickness, density and d must be >= 0");
    double g0 = ctn_model_standard_gravity(l->m), gn = 0;
    if (!(g0 > 0)) return ctn_parse_error(l, "ice: the weight of a density needs the model's units (give 'units FORCE LENGTH')");
    ctn_model_gravity(l->m, g);
    gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (!(gn > 0)) return ctn_parse_error(l, "ice: its weight acts along gravity, and there is none (give a gravity line)");
    double w = rho * g0 * 3.14159265358979323846 * t * (d + t), q[3];
    for (int k = 0; k < 3; k++) q[k] = w * g[k] / gn;
    return ctn_model_add_ice(l->m, l->tok[1], q, t);
}

/* dir=X,Y,Z: three numbers. */
static int parse_dir(ctn_line *l, const char *v, double dir[3])
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", v);
    char *p = buf;
    for (int k = 0; k < 3; k++) {
        char *c = strchr(p, ',');
        if ((k < 2) != (c != NULL)) return ctn_parse_error(l, "wind: dir= takes three numbers X,Y,Z (found '%.40s')", v);
        if (c) *c = '\0';
        int rc = ctn_parse_num(l, "a wind direction component", p, &dir[k]);
        if (rc) return rc;
        p = c ? c + 1 : p;
    }
    return CTN_OK;
}

/* wind TARGET dir=X,Y,Z (pressure=P | speed=V rho=RHO) [cd=CD] d=D: drag cd p d per unit
 * length of each chord projected on the plane normal to the wind, p = 1/2 rho V^2. */
int ctn_parse_wind(ctn_line *l)
{
    double dir[3], p = 0, V = 0, rho = 0, cd = 1, d = 0;
    int rc = ctn_parse_positional(l, 1, "wind TARGET dir=X,Y,Z pressure=P|speed=V rho=RHO [cd=CD] d=DIAMETER");
    const char *dv = rc ? NULL : ctn_parse_key(l, 2, "dir");
    if (!rc) ctn_parse_key(l, 2, "d");                      /* d= is not a misspelt dir= */
    if (!rc && !dv) return ctn_parse_missing(l, 2, NULL, "dir", " (the wind's direction X,Y,Z)");
    if (!rc) rc = parse_dir(l, dv, dir);
    int hp = !rc && ctn_parse_key(l, 2, "pressure"), hv = !rc && ctn_parse_key(l, 2, "speed");
    if (!rc && hp == hv) return ctn_parse_error(l, "wind: give pressure= or speed= (with rho=), one of them");
    if (!rc && hp) rc = ctn_parse_key_num(l, 2, "pressure", 1, &p);
    if (!rc && hv) rc = ctn_parse_key_num(l, 2, "speed", 1, &V);
    if (!rc && hv) rc = ctn_parse_key_num(l, 2, "rho", 1, &rho);
    if (!rc) rc = ctn_parse_key_num(l, 2, "cd", 0, &cd);
    if (!rc) rc = ctn_parse_key_num(l, 2, "d", 1, &d);
    if (!rc) rc = ctn_parse_leftovers(l, 2, "wind");
    if (rc) return rc;
    if (hv) p = 0.5 * rho * V * V;
    if (!(p >= 0 && cd >= 0 && d >= 0 && rho >= 0))
        return ctn_parse_error(l, "wind: pressure, rho, cd and d must be >= 0");
    rc = ctn_model_add_wind(l->m, l->tok[1], dir, cd * p, d);
    return rc ? rc : ctn_model_wind_air(l->m, hv ? rho : NAN, V, cd);   /* a dynamics' relative wind */
}
