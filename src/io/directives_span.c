/* Directives of the element families that span between supports with an unstressed
 * length of their own: `catenary` (one elastic catenary) and `pulley` (a cable over
 * frictionless pulleys). docs/format.md. */
#include "element/element.h"
#include "io/parse.h"

#include <stdio.h>
#include <string.h>

/* section= (required), length= or one prestress key (N0=, s0=, eps0=), from token
 * `from`, into spec; without either the unstressed length is the reference chord. */
static int span_keys(ctn_line *l, int from, const char *what, ctn_element_spec *spec)
{
    spec->section = ctn_parse_key(l, from, "section");
    spec->group = ctn_parse_key(l, from, "group");
    if (!spec->section) return ctn_parse_missing(l, from, what, "section", NULL);
    int rc = ctn_parse_prestress(l, from, what, NULL, &spec->prestress, &spec->prestress_value);
    if (rc || !ctn_parse_key(l, from, "length")) return rc;
    if (spec->prestress != CTN_PRESTRESS_NONE)
        return ctn_parse_error(l, "%s: give at most one of length=, N0=, s0=, eps0=", what);
    rc = ctn_parse_key_num(l, from, "length", 1, &spec->l0);
    if (!rc && !(spec->l0 > 0)) return ctn_parse_error(l, "%s: length must be positive (found %g)", what, spec->l0);
    return rc;
}

/* A target H=, sag= or tension= instead of the length (at most one of every key that
 * sets the length: length=, the prestress keys, the targets). */
static int span_target(ctn_line *l, int from, const char *what, ctn_element_spec *spec)
{
    static const char *const keys[] = { "length", "H", "sag", "tension", "N0", "s0", "eps0" };
    int given = -1, rc = CTN_OK;
    for (int k = 0; k < 7; k++) {
        if (!ctn_parse_key(l, from, keys[k])) continue;
        int targets = (k >= 1 && k <= 3) || (given >= 1 && given <= 3);   /* the others: span_keys */
        if (given >= 0 && targets)
            return ctn_parse_error(l, "%s: give one of length=, H=, sag=, tension=, N0=, s0=, eps0= (found %s= and %s=)", what,
                                   keys[given], keys[k]);
        if (given < 0) given = k;
    }
    if (given < 1 || given > 3) return CTN_OK;
    double v = 0;
    rc = ctn_parse_key_num(l, from, keys[given], 1, &v);
    if (!rc && !(v > 0)) return ctn_parse_error(l, "%s: %s must be positive (found %g)", what, keys[given], v);
    spec->target = (ctn_cable_target)given;
    spec->target_value = v;
    return rc;
}

int ctn_parse_catenary(ctn_line *l)
{
    int id = 0, nodes[2] = { 0, 0 };
    char what[32];
    ctn_element_spec spec;
    ctn_element_spec_init(&spec);
    int rc = ctn_parse_positional(l, 3, "catenary ID NODE1 NODE2 section=SECTION [length=LENGTH|H=FORCE|sag=LENGTH|tension=FORCE|N0=FORCE|s0=STRESS|eps0=STRAIN] [group=NAME]");
    if (!rc) rc = ctn_parse_int(l, "the element id", l->tok[1], &id);
    for (int k = 0; k < 2 && !rc; k++) rc = ctn_parse_int(l, "a node id", l->tok[2 + k], &nodes[k]);
    snprintf(what, sizeof what, "catenary %d", id);
    if (!rc) rc = span_target(l, 4, what, &spec);
    if (!rc) rc = span_keys(l, 4, what, &spec);
    return ctn_parse_add_element(l, rc, 4, "catenary", id, 2, nodes, &spec);
}

int ctn_parse_pulley(ctn_line *l)
{
    static const char *const usage = "pulley ID NODE1 PULLEY [PULLEY ...] NODE2 section=SECTION [length=LENGTH|N0=FORCE|s0=STRESS|eps0=STRAIN] [group=NAME]";
    int id = 0, n = 0, nodes[CTN_ELEM_MAX_NODES];
    char what[32];
    while (2 + n < l->ntok && !strchr(l->tok[2 + n], '=')) n++;    /* the node ids */
    int rc = ctn_parse_positional(l, 4, usage);
    if (!rc && n > CTN_ELEM_MAX_NODES)
        return ctn_parse_error(l, "pulley: at most %d nodes (the two ends and %d pulleys; found %d)", CTN_ELEM_MAX_NODES,
                               CTN_ELEM_MAX_NODES - 2, n);
    if (!rc) rc = ctn_parse_int(l, "the element id", l->tok[1], &id);
    for (int k = 0; k < n && !rc; k++) rc = ctn_parse_int(l, "a node id", l->tok[2 + k], &nodes[k]);
    snprintf(what, sizeof what, "pulley %d", id);
    ctn_element_spec spec;
    ctn_element_spec_init(&spec);
    if (!rc) rc = span_keys(l, 2 + n, what, &spec);
    return ctn_parse_add_element(l, rc, 2 + n, "pulley", id, n, nodes, &spec);
}
