/* net NAME flat|hypar nx= ny= lx= ly= section= [h=] [origin=X,Y,Z] [fix=xyz]
 * [N0=|s0=|eps0=] [q=|force=] [group=]: a generated cable net (docs/format.md "net",
 * model/net_gen.c). */
#include "io/parse.h"
#include "model/net_gen.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

#define NET_USAGE "net NAME flat|hypar nx=BAYS ny=BAYS lx=LENGTH ly=LENGTH section=SECTION [h=RISE] [origin=X,Y,Z] [fix=xyz] [N0=|s0=|eps0=] [q=|force=] [group=NAME]"

/* The set rule: a letter first, then letters, digits, '_', '-', '.'; room for ".inner". */
static int net_name(ctn_line *l, const char *s)
{
    int ok = isalpha((unsigned char)*s) && strcmp(s, "all") && strlen(s) + 6 < CTN_NAME_MAX;
    for (const char *p = s; ok && *p; p++) ok = isalnum((unsigned char)*p) || strchr("_-.", *p);
    return ok ? CTN_OK : ctn_parse_error(l, "net: the name '%.63s' is not valid (a letter first, then letters, digits, '_', '-' or '.', "
                                         "at most %d characters; not 'all')", s, CTN_NAME_MAX - 7);
}

/* An integer key from 2 to 100000 (required). */
static int bays(ctn_line *l, const char *key, int *out)
{
    const char *v = ctn_parse_key(l, 3, key);
    long long n = 0;
    if (!v) return ctn_parse_missing(l, 3, NULL, key, NULL);
    if (!ctn_parse_integral(v, &n) || n < 2 || n > 100000)
        return ctn_parse_error(l, "net: %s must be an integer from 2 to 100000 (found %.40s)", key, v);
    *out = (int)n;
    return CTN_OK;
}

/* origin=X,Y,Z: three coordinates separated by commas. */
static int origin_key(ctn_line *l, double X[3])
{
    const char *s = ctn_parse_key(l, 3, "origin");
    char buf[192], *p = buf;
    if (!s) return CTN_OK;
    snprintf(buf, sizeof buf, "%s", s);
    for (int k = 0; k < 3; k++) {
        char *c = strchr(p, ',');
        if ((k < 2) != (c != NULL))
            return ctn_parse_error(l, "net: origin must be three coordinates X,Y,Z separated by commas (found '%.60s')", s);
        if (c) *c = '\0';
        int rc = ctn_parse_num(l, "a coordinate", p, &X[k]);
        if (rc) return rc;
        p = c ? c + 1 : p;
    }
    return CTN_OK;
}

/* fix= (default xyz): the boundary's translations. */
static int fix_key(ctn_line *l, unsigned *fix)
{
    const char *f = ctn_parse_key(l, 3, "fix");
    *fix = CTN_FIX_X | CTN_FIX_Y | CTN_FIX_Z;
    if (!f) return CTN_OK;
    *fix = 0;
    for (const char *p = f; *p; p++) {
        unsigned bit = *p == 'x' ? CTN_FIX_X : *p == 'y' ? CTN_FIX_Y : *p == 'z' ? CTN_FIX_Z : 0;
        if (!bit || (*fix & bit)) return ctn_parse_error(l, "net: fix= takes the letters x, y, z, each once (found '%.40s')", f);
        *fix |= bit;
    }
    return CTN_OK;
}

/* q= or force= (form finding), positive, not with a prestress. */
static int density(ctn_line *l, ctn_net_spec *s)
{
    int hq = ctn_parse_key(l, 3, "q") != NULL, hf = ctn_parse_key(l, 3, "force") != NULL;
    if (hq && hf) return ctn_parse_error(l, "net: give q= or force=, not both");
    if (!hq && !hf) return CTN_OK;
    if (s->prestress) return ctn_parse_error(l, "net: %s= is for form finding: give it without N0=, s0=, eps0=", hq ? "q" : "force");
    double *v = hq ? &s->q : &s->force;
    int rc = ctn_parse_key_num(l, 3, hq ? "q" : "force", 1, v);
    if (!rc && !(*v > 0)) return ctn_parse_error(l, "net: %s must be positive (found %g)", hq ? "q" : "force", *v);
    return rc;
}

static int shape_word(ctn_line *l, ctn_net_shape *shape)
{
    if (!strcmp(l->tok[2], "flat")) *shape = CTN_NET_FLAT;
    else if (!strcmp(l->tok[2], "hypar")) *shape = CTN_NET_HYPAR;
    else {
        char b[64];
        return ctn_parse_error(l, "net: unknown shape '%s' (expected flat or hypar)", ctn_parse_show(l->tok[2], b, sizeof b));
    }
    return CTN_OK;
}

int ctn_parse_net(ctn_line *l)
{
    ctn_net_spec s;
    memset(&s, 0, sizeof s);
    int rc = ctn_parse_positional(l, 2, NET_USAGE);
    if (!rc) rc = net_name(l, l->tok[1]);
    if (!rc) rc = shape_word(l, &s.shape);
    if (!rc) rc = bays(l, "nx", &s.nx);
    if (!rc) rc = bays(l, "ny", &s.ny);
    if (!rc) rc = ctn_parse_key_num(l, 3, "lx", 1, &s.lx);
    if (!rc) rc = ctn_parse_key_num(l, 3, "ly", 1, &s.ly);
    if (!rc) rc = ctn_parse_key_num(l, 3, "h", 0, &s.h);
    if (!rc && s.shape == CTN_NET_FLAT && ctn_parse_key(l, 3, "h")) return ctn_parse_error(l, "net: h= is the rise of a hypar (this net is flat)");
    s.section = rc ? NULL : ctn_parse_key(l, 3, "section");
    if (!rc && !s.section) return ctn_parse_missing(l, 3, NULL, "section", NULL);
    if (!rc) rc = origin_key(l, s.origin);
    if (!rc) rc = fix_key(l, &s.fix);
    if (!rc) rc = ctn_parse_prestress(l, 3, "net", NULL, &s.prestress, &s.prestress_value);
    if (!rc) rc = density(l, &s);
    s.group = rc ? NULL : ctn_parse_key(l, 3, "group");
    if (!rc) rc = ctn_parse_leftovers(l, 3, "net");
    s.name = l->tok[1];
    return rc ? rc : ctn_model_add_net(l->m, &s, NULL, NULL);
}
