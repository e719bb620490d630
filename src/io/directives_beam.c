/* The beam directive (docs/format.md, "beam"):
 *   beam ID NODE1 NODE2 section=SECTION [orient=VX,VY,VZ] [n=COUNT] [release=END:DOFS,...] [group=NAME] */
#include "io/parse.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* orient=VX,VY,VZ: three numbers separated by commas, not all zero. */
static int orient_key(ctn_line *l, const char *what, double v[3])
{
    const char *s = ctn_parse_key(l, 4, "orient");
    char buf[128], *p, *tok[3];
    int k = 0;
    if (!s) return CTN_OK;
    snprintf(buf, sizeof buf, "%s", s);
    for (p = buf; k < 3; k++) {
        tok[k] = p;
        char *c = strchr(p, ',');
        if (!c) break;
        *c = '\0';
        p = c + 1;
    }
    if (k != 2 || strchr(tok[2], ','))
        return ctn_parse_error(l, "%s: orient must be three numbers VX,VY,VZ separated by commas (found '%.60s')", what, s);
    for (k = 0; k < 3; k++) {
        int rc = ctn_parse_num(l, "an orient component", tok[k], &v[k]);
        if (rc) return rc;
    }
    if (v[0] == 0 && v[1] == 0 && v[2] == 0)
        return ctn_parse_error(l, "%s: orient must not be the zero vector", what);
    return CTN_OK;
}

/* n=COUNT: an integer from 1 to CTN_BEAM_MAX_N (default 1). */
static int count_key(ctn_line *l, const char *what, int *n)
{
    const char *v = ctn_parse_key(l, 4, "n");
    long long k = 0;
    double x;
    if (!v) return CTN_OK;
    int rc = ctn_parse_num(l, "'n'", v, &x);
    if (rc) return rc;
    if (!ctn_parse_integral(v, &k) || k < 1 || k > CTN_BEAM_MAX_N)
        return ctn_parse_error(l, "%s: n must be an integer from 1 to %d (found %.40s)", what, CTN_BEAM_MAX_N, v);
    *n = (int)k;
    return CTN_OK;
}

/* One END:DOFS item of release= (END 1 or 2, DOFS letters among rx ry rz) into *mask. */
static int release_item(ctn_line *l, const char *what, const char *item, unsigned *mask)
{
    static const char *const dofs[3] = { "rx", "ry", "rz" };
    if ((item[0] != '1' && item[0] != '2') || item[1] != ':' || !item[2])
        return ctn_parse_error(l, "%s: release must be END:DOFS items separated by commas, END 1 or 2 and DOFS among "
                               "rx ry rz (found '%.40s')", what, item);
    int end = item[0] - '1';
    for (const char *c = item + 2; *c; c += 2) {
        int k = 0;
        while (k < 3 && strncmp(c, dofs[k], 2)) k++;
        if (k == 3)
            return ctn_parse_error(l, "%s: release: '%.20s' is not a rotation among rx ry rz (in '%.40s')", what, c, item);
        if (*mask & 1u << (3 * end + k))
            return ctn_parse_error(l, "%s: release: %s given twice at end %d", what, dofs[k], end + 1);
        *mask |= 1u << (3 * end + k);
    }
    return CTN_OK;
}

/* release=END:DOFS[,END:DOFS]: the hinges at the member's ends. */
static int release_key(ctn_line *l, const char *what, unsigned *mask)
{
    const char *s = ctn_parse_key(l, 4, "release");
    char buf[128];
    if (!s) return CTN_OK;
    if (strlen(s) >= sizeof buf) return ctn_parse_error(l, "%s: release is too long (found '%.40s...')", what, s);
    snprintf(buf, sizeof buf, "%s", s);
    for (char *p = buf, *c; p; p = c ? c + 1 : NULL) {
        c = strchr(p, ',');
        if (c) *c = '\0';
        int rc = release_item(l, what, p, mask);
        if (rc) return rc;
    }
    return CTN_OK;
}

int ctn_parse_beam(ctn_line *l)
{
    int id = 0, nodes[2] = { 0, 0 }, n = 1;
    char what[32];
    ctn_element_spec spec;
    ctn_element_spec_init(&spec);
    int rc = ctn_parse_positional(l, 3, "beam ID NODE1 NODE2 section=SECTION [orient=VX,VY,VZ] [n=COUNT] [release=END:DOFS,...] [group=NAME]");
    if (!rc) rc = ctn_parse_int(l, "the element id", l->tok[1], &id);
    for (int k = 0; k < 2 && !rc; k++) rc = ctn_parse_int(l, "a node id", l->tok[2 + k], &nodes[k]);
    if (rc) return rc;
    snprintf(what, sizeof what, "beam %d", id);
    spec.section = ctn_parse_key(l, 4, "section");
    if (!spec.section) return ctn_parse_missing(l, 4, what, "section", NULL);
    spec.group = ctn_parse_key(l, 4, "group");
    if (!rc) rc = orient_key(l, what, spec.orient);
    if (!rc) rc = count_key(l, what, &n);
    if (!rc) rc = release_key(l, what, &spec.release);
    if (!rc) rc = ctn_parse_leftovers(l, 4, "beam");
    if (rc) return rc;
    spec.type = "beam";
    spec.id = id;
    spec.nnodes = 2;
    spec.nodes = nodes;
    return ctn_model_add_beam(l->m, &spec, n);
}
