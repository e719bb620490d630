/* Units: the model's force and length units (`units F L`) and the units a value may carry
 * (`E=200GPa`, `A=314mm2`, `w=100N/m`), converted to the model's. A unit is a product of
 * named units with integer powers, divided by another: N, kN, MN, lbf, kip (force);
 * mm, cm, m, km, in, ft (length); Pa, kPa, MPa, GPa, psi, ksi (stress); kg, t (mass, in
 * force s^2/length: time is always in seconds). */
#include "model/model.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define CTN_LBF 4.4482216152605          /* N (exact: 0.45359237 kg x 9.80665 m/s^2) */

typedef struct unit_def {
    const char *name;
    int f, l, t;                         /* powers of force, length and time (seconds) */
    double si;                           /* value in N^f m^l s^t */
} unit_def;

static const unit_def units[] = {
    { "N", 1, 0, 0, 1.0 },        { "kN", 1, 0, 0, 1e3 },       { "MN", 1, 0, 0, 1e6 },
    { "lbf", 1, 0, 0, CTN_LBF },  { "kip", 1, 0, 0, 1e3 * CTN_LBF },
    { "mm", 0, 1, 0, 1e-3 },      { "cm", 0, 1, 0, 1e-2 },      { "m", 0, 1, 0, 1.0 },
    { "km", 0, 1, 0, 1e3 },       { "in", 0, 1, 0, 0.0254 },    { "ft", 0, 1, 0, 0.3048 },
    { "Pa", 1, -2, 0, 1.0 },      { "kPa", 1, -2, 0, 1e3 },     { "MPa", 1, -2, 0, 1e6 },
    { "GPa", 1, -2, 0, 1e9 },     { "psi", 1, -2, 0, CTN_LBF / (0.0254 * 0.0254) },
    { "ksi", 1, -2, 0, 1e3 * CTN_LBF / (0.0254 * 0.0254) },
    { "kg", 1, -1, 2, 1.0 },      { "t", 1, -1, 2, 1e3 },       /* mass: N s^2/m */
};

static const unit_def *find_unit(const char *s, size_t n)
{
    for (size_t i = 0; i < sizeof units / sizeof *units; i++)
        if (strlen(units[i].name) == n && !strncmp(units[i].name, s, n)) return &units[i];
    return NULL;
}

int ctn_model_set_units(ctn_model *m, const char *force, const char *length)
{
    if (!m || !force || !length) return CTN_ERR_INVALID;
    const unit_def *f = find_unit(force, strlen(force)), *l = find_unit(length, strlen(length));
    if (!f || f->f != 1 || f->l != 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "unknown force unit '%.40s' (expected N, kN, MN, lbf or kip)", force);
    if (!l || l->f != 0 || l->l != 1 || !strcmp(length, "cm") || !strcmp(length, "km"))
        return ctn_model_error(m, CTN_ERR_MODEL, "unknown length unit '%.40s' (expected m, mm, ft or in)", length);
    if (m->converted && (m->fconv != f->si || m->lconv != l->si))
        return ctn_model_error(m, CTN_ERR_MODEL, "units: the units change after values with units were converted "
                               "to '%s %s' (line %d): give units once, before them", m->force_unit, m->length_unit,
                               m->converted);
    snprintf(m->force_unit, sizeof m->force_unit, "%s", force);
    snprintf(m->length_unit, sizeof m->length_unit, "%s", length);
    m->fconv = f->si;
    m->lconv = l->si;
    m->mpa = f->si / (l->si * l->si) * 1e-6;             /* force/length^2 -> N/m^2 -> MPa */
    return CTN_OK;
}

/* The factor to SI and the powers of a unit expression: NAME[POWER] factors joined by
 * '*' or '.', then at most one '/' and the factors of the denominator. 0 if malformed or
 * unknown. */
static int parse_unit(const char *s, double *si, int *f, int *l, int *t)
{
    int sign = 1, any = 0;
    *si = 1, *f = 0, *l = 0, *t = 0;
    while (*s) {
        size_t n = 0;
        while (isalpha((unsigned char)s[n])) n++;
        const unit_def *u = n ? find_unit(s, n) : NULL;
        if (!u) return 0;
        s += n;
        int pw = 1;
        if (*s == '^') s++;
        if (isdigit((unsigned char)*s)) pw = *s++ - '0';
        if (!pw || isdigit((unsigned char)*s)) return 0;
        *si *= sign > 0 ? pow(u->si, pw) : 1 / pow(u->si, pw);
        *f += sign * pw * u->f;
        *l += sign * pw * u->l;
        *t += sign * pw * u->t;
        any = 1;
        if (*s == '/' && sign > 0) sign = -1, s++;
        else if (*s == '*' || *s == '.') s++;
        else if (*s) return 0;
    }
    return any;
}

/* A dimension as words: "force/length^2", "mass per length". */
static const char *dim_name(int f, int l, int t, char *buf, size_t size)
{
    if (t == 2 && f == 1 && l == -1) snprintf(buf, size, "mass (force s^2/length)");
    else if (t == 2 && f == 1 && l == -2) snprintf(buf, size, "mass per length");
    else if (t == 2 && f == 1 && l == -4) snprintf(buf, size, "density (mass/length^3)");
    else if (t == 2 && f == 1 && l < -2) snprintf(buf, size, "mass/length^%d", -(l + 1));
    else if (t) snprintf(buf, size, "force^%d length^%d s^%d", f, l, t);
    else if (f == 0 && l == 0) snprintf(buf, size, "no dimension");
    else if (f == 0 && l == 1) snprintf(buf, size, "length");
    else if (f == 0) snprintf(buf, size, "length^%d", l);
    else if (f == 1 && l == 0) snprintf(buf, size, "force");
    else if (f == 1 && l == -1) snprintf(buf, size, "force/length");
    else if (f == 1 && l == 1) snprintf(buf, size, "force length");
    else if (f == 1 && l < 0) snprintf(buf, size, "force/length^%d", -l);
    else snprintf(buf, size, "force^%d length^%d", f, l);
    return buf;
}

int ctn_model_convert(ctn_model *m, const char *unit, int f, int l, int t, double *v, char *msg, size_t size)
{
    double si;
    int uf, ul, ut;
    char a[32], b[32];
    if (!parse_unit(unit, &si, &uf, &ul, &ut)) {
        snprintf(msg, size, "unknown unit '%.40s' (units: N kN MN lbf kip, mm cm m km in ft, Pa kPa MPa GPa psi "
                 "ksi, kg t, with powers and one '/': mm2, kN/m, N/mm2, kg/m3)", unit);
        return 1;
    }
    if (uf != f || ul != l || ut != t) {
        snprintf(msg, size, "the unit '%.40s' is a %s, the value a %s", unit, dim_name(uf, ul, ut, a, sizeof a),
                 dim_name(f, l, t, b, sizeof b));
        return 1;
    }
    if (!(m->fconv > 0)) {
        snprintf(msg, size, "a value with a unit ('%.40s') needs the model's units: give a line 'units FORCE LENGTH'", unit);
        return 1;
    }
    double x = *v * si / (pow(m->fconv, f) * pow(m->lconv, l));
    if (!isfinite(x)) {
        snprintf(msg, size, "the value in '%.40s' is beyond double precision in the model's units", unit);
        return 1;
    }
    *v = x;
    if (!m->converted) m->converted = m->line > 0 ? m->line : 1;
    return 0;
}
