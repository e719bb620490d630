/* The dynamics directives (docs/format.md, "Dynamics"): `dynamics` (the time
 * integration, into the solve options), `damping` (Rayleigh's, into them too) and
 * `record` (the time histories, into the model). */
#include "io/parse.h"
#include "catena/analysis.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* A keyword-valued key: index into words[], *out unchanged when absent. */
static int word(ctn_line *l, const char *key, const char *const *words, int n, int *out)
{
    const char *v = ctn_parse_key(l, 1, key);
    if (!v) return CTN_OK;
    for (int i = 0; i < n; i++)
        if (!strcmp(v, words[i])) {
            *out = i;
            return CTN_OK;
        }
    char b[64];
    return ctn_parse_error(l, "unknown %s '%s'", key, ctn_parse_show(v, b, sizeof b));
}

/* An integer key in [lo, hi]; *out unchanged when absent. */
static int integer(ctn_line *l, const char *key, int lo, int hi, int *out)
{
    const char *v = ctn_parse_key(l, 1, key);
    long long n = 0;
    if (!v) return CTN_OK;
    if (!ctn_parse_integral(v, &n) || n < lo || n > hi)
        return ctn_parse_error(l, "%s must be an integer from %d to %d (found %.40s)", key, lo, hi, v);
    *out = (int)n;
    return CTN_OK;
}

/* dynamics dt= t_end= [method=] [rho_inf=] [alpha=] [gamma=] [beta=] [mass=] [tol=]
 * [maxit=] [cutbacks=] [output_every=] [vtu=] [relative_wind=] */
int ctn_parse_dynamics(ctn_line *l)
{
    static const char *const methods[] = { "genalpha", "hht", "newmark", "central" }, *const masses[] = { "consistent", "lumped" };
    ctn_dynamics_options o = l->opt->dynamics;
    int method = (int)o.method, mass = (int)o.mass;
    int rc = ctn_parse_positional(l, 0, "dynamics dt=STEP t_end=TIME [method=genalpha|hht|newmark|central] [rho_inf=R] "
                                        "[alpha=A] [gamma=G beta=B] [mass=consistent|lumped] [output_every=K] [vtu=0|1] "
                                        "[relative_wind=0|1]");
    if (!rc && l->opt->dynamics.line > 0)
        return ctn_parse_error(l, "dynamics: given twice (first on line %d)", l->opt->dynamics.line);
    if (!rc) rc = ctn_parse_key_num(l, 1, "dt", 1, &o.dt);
    if (!rc) rc = ctn_parse_key_num(l, 1, "t_end", 1, &o.t_end);
    if (!rc) rc = word(l, "method", methods, 4, &method);
    if (!rc) rc = word(l, "mass", masses, 2, &mass);
    if (!rc) rc = ctn_parse_key_num(l, 1, "rho_inf", 0, &o.rho_inf);
    if (!rc) rc = ctn_parse_key_num(l, 1, "alpha", 0, &o.alpha);
    if (!rc) rc = ctn_parse_key_num(l, 1, "gamma", 0, &o.gamma);
    if (!rc) rc = ctn_parse_key_num(l, 1, "beta", 0, &o.beta);
    if (!rc) rc = ctn_parse_key_num(l, 1, "tol", 0, &o.tol);
    if (!rc) rc = integer(l, "maxit", 1, 1000, &o.maxit);
    if (!rc) rc = integer(l, "cutbacks", 0, 40, &o.maxcuts);
    if (!rc) rc = integer(l, "output_every", 1, 1000000000, &o.output_every);
    if (!rc) rc = integer(l, "vtu", 0, 1, &o.frames);
    if (!rc) rc = integer(l, "relative_wind", 0, 1, &o.relative_wind);
    if (rc) return rc;
    if (!isnan(o.alpha) && method != CTN_DYN_HHT) return ctn_parse_error(l, "dynamics: alpha= is HHT's: give method=hht");
    if ((ctn_parse_key(l, 1, "gamma") || ctn_parse_key(l, 1, "beta")) && method != CTN_DYN_NEWMARK)
        return ctn_parse_error(l, "dynamics: gamma= and beta= are Newmark's: give method=newmark");
    if (ctn_parse_key(l, 1, "rho_inf") && (method == CTN_DYN_NEWMARK || method == CTN_DYN_CENTRAL))
        return ctn_parse_error(l, "dynamics: rho_inf= is for method=genalpha or hht");
    if (!(o.dt > 0)) return ctn_parse_error(l, "dynamics: dt must be > 0 (found %g)", o.dt);
    if (!(o.t_end > 0)) return ctn_parse_error(l, "dynamics: t_end=%g is not after the start t = 0", o.t_end);
    if ((rc = ctn_parse_leftovers(l, 1, "dynamics"))) return rc;
    o.method = (ctn_dyn_method)method;
    o.mass = (ctn_mass_matrix)mass;
    o.line = l->line;
    o.steps_before = (int)l->m->steps.n;
    o.from_rest = o.steps_before == 0;
    if (ctn_dynamics_options_check(l->m->ctx, &o)) {
        char msg[256];
        snprintf(msg, sizeof msg, "%s", ctn_ctx_message(l->m->ctx));
        return ctn_parse_error(l, "%s", msg);
    }
    l->opt->dynamics = o;
    return CTN_OK;
}

/* Two numbers "A,B" of key, both > 0. */
static int pair(ctn_line *l, const char *key, double v[2])
{
    const char *s = ctn_parse_key(l, 1, key);
    char buf[128], *comma;
    if (!s) return ctn_parse_missing(l, 1, NULL, key, NULL);
    snprintf(buf, sizeof buf, "%s", s);
    if (!(comma = strchr(buf, ','))) return ctn_parse_error(l, "damping: %s= takes two values A,B (found '%.40s')", key, s);
    *comma = '\0';
    int rc = ctn_parse_num(l, key, buf, &v[0]);
    if (!rc) rc = ctn_parse_num(l, key, comma + 1, &v[1]);
    if (!rc && !(v[0] > 0 && v[1] > 0)) return ctn_parse_error(l, "damping: %s= must be two positive values (found '%.40s')", key, s);
    return rc;
}

/* Rayleigh's alpha and beta from two damping ratios at two frequencies [Hz]:
 * zeta_i = alpha / (2 omega_i) + beta omega_i / 2. */
static int from_ratios(ctn_line *l, double *alpha, double *beta)
{
    double z[2], f[2];
    int rc = pair(l, "ratio", z);
    if (!rc) rc = pair(l, "freq", f);
    if (rc) return rc;
    double w1 = 6.28318530717958647692 * f[0], w2 = 6.28318530717958647692 * f[1];
    if (fabs(w1 - w2) <= 1e-12 * w2) return ctn_parse_error(l, "damping: freq= needs two different frequencies");
    *alpha = 2 * w1 * w2 * (z[0] * w2 - z[1] * w1) / (w2 * w2 - w1 * w1);
    *beta = 2 * (z[1] * w2 - z[0] * w1) / (w2 * w2 - w1 * w1);
    if (*alpha < 0 || *beta < 0)
        return ctn_parse_error(l, "damping: these ratios give a negative Rayleigh coefficient (alpha=%g, beta=%g)", *alpha, *beta);
    return CTN_OK;
}

/* modal=Z1[,Z2,...] [modes=N]: the ratios and the modes damped (default: as many as
 * ratios; one ratio with modes=N damps N modes at it). */
static int modal(ctn_line *l, ctn_dynamics_options *o)
{
    const char *s = ctn_parse_key(l, 1, "modal");
    char buf[1024];
    int n = 0, count = 0, rc = CTN_OK;
    snprintf(buf, sizeof buf, "%s", s);
    for (char *tok = buf, *next; tok && !rc; tok = next) {
        if ((next = strchr(tok, ','))) *next++ = '\0';
        if (n == CTN_DYN_MODAL_MAX) return ctn_parse_error(l, "damping: modal= takes at most %d ratios", CTN_DYN_MODAL_MAX);
        rc = ctn_parse_num(l, "modal", tok, &o->modal_zeta[n]);
        if (!rc && !(o->modal_zeta[n] >= 0 && o->modal_zeta[n] < 1))
            return ctn_parse_error(l, "damping: modal ratio %d must be from 0 to below 1 (found %g)", n + 1, o->modal_zeta[n]);
        n++;
    }
    count = n;
    if (!rc) rc = integer(l, "modes", 1, CTN_DYN_MODAL_MAX, &count);
    if (!rc && n > 1 && count != n)
        return ctn_parse_error(l, "damping: modes=%d but modal= gives %d ratios (give one ratio for all, or one per mode)",
                               count, n);
    o->modal_nzeta = n;
    o->modal_count = count;
    return rc;
}

/* damping alpha= beta= | damping ratio=Z1,Z2 freq=F1,F2 (either with modal=) |
 * damping modal=Z1[,Z2,...] [modes=N] */
int ctn_parse_damping(ctn_line *l)
{
    double a = 0, b = 0;
    int rc = ctn_parse_positional(l, 0, "damping alpha=MASS_FACTOR beta=STIFFNESS_FACTOR | damping ratio=Z1,Z2 freq=F1,F2 "
                                        "| damping modal=Z1[,Z2,...] [modes=N]");
    int by_ratio = ctn_parse_key(l, 1, "ratio") || ctn_parse_key(l, 1, "freq");
    int by_modes = !rc && ctn_parse_key(l, 1, "modal");
    if (!rc && ctn_parse_key(l, 1, "modes") && !by_modes) return ctn_parse_error(l, "damping: modes= goes with modal=");
    if (by_modes) rc = modal(l, &l->opt->dynamics);
    if (!rc && by_modes && !by_ratio && !ctn_parse_key(l, 1, "alpha") && !ctn_parse_key(l, 1, "beta")) {
        if ((rc = ctn_parse_leftovers(l, 1, "damping"))) return rc;
        l->opt->dynamics.damping_alpha = l->opt->dynamics.damping_beta = 0;
        return CTN_OK;
    }
    if (!rc && by_ratio && (ctn_parse_key(l, 1, "alpha") || ctn_parse_key(l, 1, "beta")))
        return ctn_parse_error(l, "damping: give alpha= beta= or ratio= freq=, not both");
    if (!rc && by_ratio) rc = from_ratios(l, &a, &b);
    if (!rc && !by_ratio) {
        rc = ctn_parse_key_num(l, 1, "alpha", 0, &a);
        if (!rc) rc = ctn_parse_key_num(l, 1, "beta", 0, &b);
        if (!rc && !ctn_parse_key(l, 1, "alpha") && !ctn_parse_key(l, 1, "beta"))
            return ctn_parse_error(l, "damping: give alpha= and/or beta=, or ratio= freq=");
        if (!rc && !(a >= 0 && b >= 0)) return ctn_parse_error(l, "damping: alpha and beta must be >= 0 (found %g, %g)", a, b);
    }
    if (!rc) rc = ctn_parse_leftovers(l, 1, "damping");
    if (rc) return rc;
    l->opt->dynamics.damping_alpha = a;
    l->opt->dynamics.damping_beta = b;
    return CTN_OK;
}

/* dof=ux,uy,uz,rx,ry,rz (any of them, each once) into bits. */
static int dofs(ctn_line *l, unsigned *bits)
{
    static const char *const name[6] = { "ux", "uy", "uz", "rx", "ry", "rz" };
    const char *s = ctn_parse_key(l, 1, "dof");
    *bits = 0;
    while (s && *s) {
        unsigned b = 0;
        for (int k = 0; k < 6 && !b; k++) b = strncmp(s, name[k], 2) ? 0 : 1u << k;
        if (!b || (*bits & b) || (s[2] && s[2] != ','))
            return ctn_parse_error(l, "record: dof= takes ux, uy, uz, rx, ry, rz separated by commas, each once (found "
                                   "'%.40s')", ctn_parse_key(l, 1, "dof"));
        *bits |= b;
        s += s[2] ? 3 : 2;
    }
    return CTN_OK;
}

/* record node=ID [dof=ux,uy,uz,rx,ry,rz] [reaction] | record element=ID force */
int ctn_parse_record(ctn_line *l)
{
    int id = 0, reaction = 0;
    unsigned bits = 0;
    int rc = ctn_parse_positional(l, 0, "record node=ID [dof=ux,uy,uz,rx,ry,rz] [reaction] | record element=ID force");
    const char *node = rc ? NULL : ctn_parse_key(l, 1, "node"), *elem = rc ? NULL : ctn_parse_key(l, 1, "element");
    if (!rc && !!node == !!elem) return ctn_parse_error(l, "record: give node=ID or element=ID");
    if (!rc) rc = ctn_parse_int(l, node ? "the node id" : "the element id", node ? node : elem, &id);
    if (!rc && node) rc = dofs(l, &bits);
    if (!rc && node) reaction = ctn_parse_flag(l, 1, "reaction");
    if (!rc && elem && !ctn_parse_flag(l, 1, "force"))
        return ctn_parse_error(l, "record: element=%d records its axial force: give the word force", id);
    if (!rc) rc = ctn_parse_leftovers(l, 1, "record");
    if (rc) return rc;
    if (reaction) return ctn_model_record_reaction(l->m, id, bits);
    return node ? ctn_model_record_node(l->m, id, bits) : ctn_model_record_element(l->m, id);
}

/* The path of a table named in the model file `file`: as given when absolute, else
 * beside the model file. */
static int table_path(const ctn_line *l, const char *name, char *path, size_t size)
{
    const char *slash = strrchr(l->file, '/');
    int n = name[0] == '/' || !slash ? snprintf(path, size, "%s", name)
                                     : snprintf(path, size, "%.*s/%s", (int)(slash - l->file), l->file, name);
    return n >= 0 && (size_t)n < size ? CTN_OK : ctn_parse_error(l, "function: table path too long");
}

/* Grow t, v to hold n + 1 points. */
static int table_room(ctn_ctx *ctx, double **t, double **v, size_t n, size_t *cap)
{
    size_t c1 = *cap, c2 = *cap;
    int rc = ctn_array_reserve(ctx, (void **)t, &c1, n + 1, sizeof(double));
    if (!rc) rc = ctn_array_reserve(ctx, (void **)v, &c2, n + 1, sizeof(double));
    if (!rc) *cap = c1 < c2 ? c1 : c2;
    return rc;
}

/* The points of a table file: a time and a value per line (blanks or a comma between
 * them, '#' comments, blank lines skipped); its errors at the table's file:line. */
#define CTN_TABLE_MAX_BYTES ((off_t)1 << 26)    /* 64 MiB */

static int read_table(ctn_line *l, const char *path, double **t, double **v, size_t *n)
{
    char *data = NULL;
    size_t len = 0, pos = 0, cap = 0;
    struct stat st;
    if (stat(path, &st)) return ctn_parse_error(l, "function %s: cannot read table '%.200s': %s", l->tok[1], path, strerror(errno));
    if (!S_ISREG(st.st_mode) || st.st_size > CTN_TABLE_MAX_BYTES)
        return ctn_parse_error(l, "function %s: table '%.200s' is not a regular file of at most 64 MiB", l->tok[1], path);
    int rc = ctn_read_all(l->m->ctx, path, &data, &len);
    if (rc) return rc == CTN_ERR_IO ? ctn_parse_error(l, "function %s: %s", l->tok[1], ctn_ctx_message(l->m->ctx)) : rc;
    for (size_t i = 0; i < len; i++)
        if (data[i] == ',') data[i] = ' ';
    ctn_line tl = *l;
    tl.file = path;
    tl.line = 0;
    *n = 0;
    while (!rc && pos < len) {
        tl.line++;
        if ((rc = ctn_parse_scan_line(&tl, data, len, &pos)) || tl.ntok == 0) continue;
        double tv[2];
        if (tl.ntok != 2) rc = ctn_parse_error(&tl, "a table line holds a time and a value (found %d fields)", tl.ntok);
        for (int k = 0; k < 2 && !rc; k++) rc = ctn_parse_num(&tl, k ? "a value" : "a time", tl.tok[k], &tv[k]);
        if (!rc && *n && !(tv[0] > (*t)[*n - 1]))
            rc = ctn_parse_error(&tl, "table times must increase: t=%g is not after t=%g (function %s, line %d of %s)", tv[0],
                                 (*t)[*n - 1], l->tok[1], l->line, l->file);
        if (!rc) rc = table_room(l->m->ctx, t, v, *n, &cap);
        if (!rc) {
            (*t)[*n] = tv[0];
            (*v)[(*n)++] = tv[1];
        }
    }
    ctn_free(data);
    if (!rc && *n < 2) rc = ctn_parse_error(l, "function %s: table '%s' holds %zu point(s); it needs two or more", l->tok[1], path, *n);
    return rc;
}

/* function NAME ramp t0= t1= | step t0= | harmonic amp= freq= [phase=DEG] [offset=] |
 * table FILE */
int ctn_parse_function(ctn_line *l)
{
    static const char *const kinds[] = { "ramp", "step", "harmonic", "table" };
    int rc = ctn_parse_positional(l, l->ntok > 3 && !strcmp(l->tok[2], "table") ? 3 : 2,
                                  "function NAME ramp t0=T0 t1=T1 | step t0=T0 | harmonic amp=A freq=HZ [phase=DEG] "
                                  "[offset=B] | table FILE");
    int kind = -1;
    for (int k = 0; !rc && k < 4; k++)
        if (!strcmp(l->tok[2], kinds[k])) kind = k;
    if (!rc && kind < 0) return ctn_parse_error(l, "function: unknown kind '%.40s' (expected ramp, step, harmonic or table)", l->tok[2]);
    double par[4] = { 0, 0, 0, 0 }, *t = NULL, *v = NULL, deg = 0;
    size_t n = 0;
    if (!rc && kind <= CTN_FN_STEP) rc = ctn_parse_key_num(l, 3, "t0", 1, &par[0]);
    if (!rc && kind == CTN_FN_RAMP) rc = ctn_parse_key_num(l, 3, "t1", 1, &par[1]);
    if (!rc && kind == CTN_FN_HARMONIC) {
        rc = ctn_parse_key_num(l, 3, "amp", 1, &par[0]);
        if (!rc) rc = ctn_parse_key_num(l, 3, "freq", 1, &par[1]);
        if (!rc) rc = ctn_parse_key_num(l, 3, "phase", 0, &deg);
        if (!rc) rc = ctn_parse_key_num(l, 3, "offset", 0, &par[3]);
        par[2] = deg * 0.017453292519943295769;       /* degrees to radians */
    }
    if (!rc && kind == CTN_FN_TABLE && l->ntok < 4) return ctn_parse_error(l, "function %s: table needs a FILE", l->tok[1]);
    if (!rc) rc = ctn_parse_leftovers(l, kind == CTN_FN_TABLE ? 4 : 3, "function");
    char path[4096];
    if (!rc && kind == CTN_FN_TABLE) rc = table_path(l, l->tok[3], path, sizeof path);
    if (!rc && kind == CTN_FN_TABLE) rc = read_table(l, path, &t, &v, &n);
    if (!rc) rc = ctn_model_add_function(l->m, l->tok[1], (ctn_fn_kind)kind, par, t, v, n);
    ctn_free(t);
    ctn_free(v);
    return rc;
}

/* remove element=ID t=TIME: the element severed at TIME in the dynamics */
int ctn_parse_remove(ctn_line *l)
{
    int id = 0;
    double t = 0;
    int rc = ctn_parse_positional(l, 0, "remove element=ID t=TIME");
    const char *e = rc ? NULL : ctn_parse_key(l, 1, "element");
    if (!rc && !e) return ctn_parse_missing(l, 1, NULL, "element", NULL);
    if (!rc) rc = ctn_parse_int(l, "the element id", e, &id);
    if (!rc) rc = ctn_parse_key_num(l, 1, "t", 1, &t);
    if (!rc) rc = ctn_parse_leftovers(l, 1, "remove");
    return rc ? rc : ctn_model_add_removal(l->m, id, t);
}
