/* Token helpers of the .cable reader: numbers, ids, key=value options, messages. */
#include "io/decimal.h"
#include "io/parse.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int ctn_parse_error(const ctn_line *l, const char *fmt, ...)
{
    char msg[CTN_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return ctn_error_at(l->m->ctx, CTN_ERR_MODEL, l->file, l->line, "%s", msg);
}

const char *ctn_parse_show(const char *tok, char *buf, size_t size)
{
    size_t k = 0;
    for (const unsigned char *p = (const unsigned char *)tok; *p && k + 5 < size; p++) {
        if (k > 40) {
            memcpy(buf + k, "...", 3);
            k += 3;
            break;
        }
        if (isprint(*p)) buf[k++] = (char)*p;
        else k += (size_t)snprintf(buf + k, size - k, "\\x%02x", *p);
    }
    buf[k] = '\0';
    return buf;
}

int ctn_parse_positional(ctn_line *l, int n, const char *usage)
{
    int have = 0;
    while (1 + have < l->ntok && !strchr(l->tok[1 + have], '=')) have++;
    if (have < n) return ctn_parse_error(l, "expected '%s': missing argument (%d of %d given)", usage, have, n);
    for (int i = 1 + n; i < l->ntok; i++) {
        char b[64];
        char *eq = strchr(l->tok[i], '=');
        if (!eq) continue;                                 /* a flag, or a stray word */
        if (eq == l->tok[i]) return ctn_parse_error(l, "missing key before '=' in '%s'", ctn_parse_show(l->tok[i], b, sizeof b));
        if (!eq[1]) return ctn_parse_error(l, "missing value for key '%.*s'", (int)(eq - l->tok[i]) > 40 ? 40 : (int)(eq - l->tok[i]), l->tok[i]);
        for (int j = 1 + n; j < i; j++) {
            size_t kl = (size_t)(eq - l->tok[i]);
            if (!strncmp(l->tok[j], l->tok[i], kl) && l->tok[j][kl] == '=')
                return ctn_parse_error(l, "key '%.*s' given twice", (int)kl > 40 ? 40 : (int)kl, l->tok[i]);
        }
    }
    return CTN_OK;
}

/* Digits from *p on (advancing *p): their count, and in *v their value saturated at
 * cap (v == NULL: skip them). */
static size_t digits(const char **p, long long *v, long long cap)
{
    size_t n = 0;
    for (; isdigit((unsigned char)**p); (*p)++, n++)
        if (v) *v = *v > (cap - (**p - '0')) / 10 ? cap : *v * 10 + (**p - '0');
    return n;
}

int ctn_parse_integral(const char *tok, long long *out)
{
    const long long cap = (long long)INT_MAX + 1;       /* values beyond are out of range */
    const char *p = tok, *mant;
    int neg = *p == '-';
    if (*p == '+' || *p == '-') p++;
    mant = p;
    size_t nint = digits(&p, NULL, 0), nfrac = 0;
    if (*p == '.') p++, nfrac = digits(&p, NULL, 0);
    if (nint + nfrac == 0) return 0;
    const char *end_mant = p;
    long long e = 0;
    if (*p == 'e' || *p == 'E') {
        int eneg = p[1] == '-';
        p += p[1] == '+' || p[1] == '-' ? 2 : 1;
        if (!digits(&p, &e, 1000000)) return 0;
        if (eneg) e = -e;
    }
    if (*p) return 0;
    /* value = 0.d1 d2 ... dn x 10^(nint + e): digit k (from 0) has weight 10^(nint + e - 1 - k) */
    long long point = (long long)nint + e, v = 0, k = 0;
    for (const char *q = mant; q < end_mant; q++) {
        if (*q == '.') continue;
        if (k >= point && *q != '0') return 0;           /* a fractional digit */
        if (k < point) v = v > (cap - (*q - '0')) / 10 ? cap : v * 10 + (*q - '0');
        k++;
    }
    for (; k < point && v > 0 && v < cap; k++) v = v > cap / 10 ? cap : v * 10;   /* trailing zeros */
    *out = neg ? -v : v;
    return 1;
}

int ctn_parse_int(const ctn_line *l, const char *what, const char *tok, int *out)
{
    char b[64];
    long long v = 0;
    if (!ctn_parse_integral(tok, &v))
        return ctn_parse_error(l, "expected an integer for %s, found '%s'", what, ctn_parse_show(tok, b, sizeof b));
    if (v < 1 || v > INT_MAX)
        return ctn_parse_error(l, "%s must be an integer from 1 to %d, found '%s'", what, INT_MAX, ctn_parse_show(tok, b, sizeof b));
    *out = (int)v;
    return CTN_OK;
}

/* A number followed by a unit (end: the unit) converted to the model's units. */
static int with_unit(const ctn_line *l, const char *what, const char *tok, const char *end, double *v)
{
    char b[64], msg[256];
    int f = 0, d = 0, t = 0;
    if (!ctn_parse_unit_dim(what, &f, &d, &t))
        return ctn_parse_error(l, "expected a number for %s, found '%s' (%s takes no unit)", what,
                               ctn_parse_show(tok, b, sizeof b), what);
    if (ctn_model_convert(l->m, end, f, d, t, v, msg, sizeof msg))
        return ctn_parse_error(l, "expected a number for %s, found '%s': %s", what, ctn_parse_show(tok, b, sizeof b), msg);
    return CTN_OK;
}

int ctn_parse_num(const ctn_line *l, const char *what, const char *tok, double *out)
{
    char b[64], *end;
    if (ctn_parse_decimal(tok, out)) return CTN_OK;       /* a plain number: strtod's value */
    errno = 0;
    double v = strtod(tok, &end);
    int unit = end != tok && *end && isalpha((unsigned char)*end) && isfinite(v) && !(errno == ERANGE && fabs(v) > 1.0);
    if (unit && with_unit(l, what, tok, end, &v)) return CTN_ERR_MODEL;
    if (end == tok || (*end && !unit)) return ctn_parse_error(l, "expected a number for %s, found '%s'", what, ctn_parse_show(tok, b, sizeof b));
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1.0))
        return ctn_parse_error(l, "non-finite number for %s: '%s'", what, ctn_parse_show(tok, b, sizeof b));
    *out = v;
    return CTN_OK;
}

const char *ctn_parse_key(ctn_line *l, int from, const char *key)
{
    size_t kl = strlen(key);
    for (int i = from; i < l->ntok && i < 64; i++)
        if (!strncmp(l->tok[i], key, kl) && l->tok[i][kl] == '=') {
            l->used |= 1ull << i;
            return l->tok[i] + kl + 1;
        }
    return NULL;
}

int ctn_parse_flag(ctn_line *l, int from, const char *flag)
{
    for (int i = from; i < l->ntok && i < 64; i++)
        if (!strcmp(l->tok[i], flag)) {
            l->used |= 1ull << i;
            return 1;
        }
    return 0;
}

/* The edit distance of a and b (n and m bytes), or 3 when it is more than 2. */
static int near_edits(const char *a, size_t n, const char *b, size_t m)
{
    if (n > m + 2 || m > n + 2 || n > 30 || m > 30) return 3;
    int d[32][32];
    for (size_t i = 0; i <= n; i++) d[i][0] = (int)i;
    for (size_t j = 0; j <= m; j++) d[0][j] = (int)j;
    for (size_t i = 1; i <= n; i++)
        for (size_t j = 1; j <= m; j++) {
            int c = tolower((unsigned char)a[i - 1]) != tolower((unsigned char)b[j - 1]);
            int v = d[i - 1][j - 1] + c;
            if (d[i - 1][j] + 1 < v) v = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < v) v = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < v)
                v = d[i - 2][j - 2] + 1;                               /* a transposition */
            d[i][j] = v;
        }
    return d[n][m] < 3 ? d[n][m] : 3;
}

int ctn_parse_missing(const ctn_line *l, int from, const char *what, const char *key, const char *more)
{
    size_t kl = strlen(key);
    for (int i = from; i < l->ntok && i < 64; i++) {
        const char *eq = strchr(l->tok[i], '=');
        if ((l->used >> i & 1) || !eq || eq == l->tok[i]) continue;
        size_t n = (size_t)(eq - l->tok[i]);
        if (near_edits(l->tok[i], n, key, kl) < (kl == 1 ? 1 : kl == 2 ? 2 : 3))
            return ctn_parse_error(l, "unknown key '%.*s' for directive '%s' (did you mean '%s='?)", (int)n,
                                   l->tok[i], l->tok[0], key);
    }
    return ctn_parse_error(l, "%s: missing required key '%s='%s", what ? what : l->tok[0], key, more ? more : "");
}

int ctn_parse_key_num(ctn_line *l, int from, const char *key, int required, double *out)
{
    const char *v = ctn_parse_key(l, from, key);
    if (!v) return required ? ctn_parse_missing(l, from, NULL, key, NULL) : CTN_OK;
    if (ctn_parse_decimal(v, out)) return CTN_OK;          /* a plain number: no name needed */
    char what[80];
    snprintf(what, sizeof what, "'%s'", key);
    return ctn_parse_num(l, what, v, out);
}

int ctn_parse_leftovers(const ctn_line *l, int from, const char *directive)
{
    for (int i = from; i < l->ntok; i++) {
        if (l->used >> i & 1) continue;
        char b[64];
        const char *eq = strchr(l->tok[i], '=');
        if (eq) return ctn_parse_error(l, "unknown key '%.*s' for directive '%s'",
                                       (int)(eq - l->tok[i]) > 40 ? 40 : (int)(eq - l->tok[i]), l->tok[i], directive);
        return ctn_parse_error(l, "unexpected '%s' for directive '%s'", ctn_parse_show(l->tok[i], b, sizeof b), directive);
    }
    return CTN_OK;
}
