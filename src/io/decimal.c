/* The reader's numbers: decimal text to double by Clinger's exact fast path, else the
 * Eisel-Lemire method (Lemire, "Number parsing at a gigabyte per second", Software:
 * Practice and Experience 51, 2021; the form of Go's strconv.eiselLemire64): the decimal
 * mantissa w (19 digits at most) times a 128-bit truncation of 10^q gives the 54 leading
 * bits of w 10^q; when those bits cannot decide the rounding (the truncation's error
 * could cross a rounding boundary, or the value is exactly halfway), the conversion
 * declines and the caller uses strtod. Every value it returns is the correctly rounded
 * one, strtod's own (tests/test_decimal.c checks that over edge cases and more than a
 * million random numbers). */
#include "io/decimal.h"

#include <string.h>

__extension__ typedef unsigned __int128 u128;

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* The digits of tok: the first 19 significant ones in *w, the power of ten that scales
 * them in *q; 0 if tok is not a plain decimal or has more than 19 significant digits. */
static int scan(const char *p, uint64_t *w, long *q)
{
    uint64_t m = 0;
    int nsig = 0, ndig = 0;
    long scale = 0, e = 0;
    for (; is_digit(*p); p++, ndig++) {
        if (m || *p != '0') {
            if (nsig++ == 19) return 0;
            m = m * 10 + (uint64_t)(*p - '0');
        }
    }
    if (*p == '.') {
        for (p++; is_digit(*p); p++, ndig++, scale--) {
            if (m || *p != '0') {
                if (nsig++ == 19) return 0;
                m = m * 10 + (uint64_t)(*p - '0');
            }
        }
    }
    if (!ndig) return 0;
    if (*p == 'e' || *p == 'E') {
        int neg = p[1] == '-';
        p += p[1] == '-' || p[1] == '+' ? 2 : 1;
        if (!is_digit(*p)) return 0;
        for (; is_digit(*p); p++)
            if (e < 100000) e = e * 10 + (*p - '0');        /* beyond: out of range anyway */
        if (neg) e = -e;
    }
    if (*p) return 0;
    *w = m;
    *q = scale + e;
    return 1;
}

/* w 10^q when both w and 10^|q| are doubles (w <= 2^53, |q| <= 22): one product or
 * quotient of exact operands, rounded once (Clinger's fast path); 0 otherwise. */
static int clinger(uint64_t w, long q, double *out)
{
    static const double p10[23] = { 1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22 };
    if (w > (1ull << 53) || q < -22 || q > 22) return 0;
    *out = q >= 0 ? (double)w * p10[q] : (double)w / p10[-q];
    return 1;
}

/* w 10^q as a double's bits (sign not included) into *bits; 0 if undecided. */
static int eisel_lemire(uint64_t w, long q, uint64_t *bits)
{
    if (q < CTN_POW10_MIN || q > CTN_POW10_MAX) return 0;
    int clz = __builtin_clzll(w);
    w <<= clz;
    uint64_t exp2 = (uint64_t)(((217706 * q) >> 16) + 64 + 1023) - (uint64_t)clz;
    const uint64_t *t = ctn_pow10_128[q - CTN_POW10_MIN];
    u128 x = (u128)w * t[0];
    uint64_t xhi = (uint64_t)(x >> 64), xlo = (uint64_t)x;
    if ((xhi & 0x1FF) == 0x1FF && xlo + w < w) {        /* the wider product decides */
        u128 y = (u128)w * t[1];
        uint64_t yhi = (uint64_t)(y >> 64), ylo = (uint64_t)y;
        uint64_t mhi = xhi, mlo = xlo + yhi;
        if (mlo < xlo) mhi++;
        if ((mhi & 0x1FF) == 0x1FF && mlo + 1 == 0 && ylo + w < w) return 0;
        xhi = mhi;
        xlo = mlo;
    }
    uint64_t msb = xhi >> 63, mant = xhi >> (msb + 9);
    exp2 -= 1 ^ msb;
    if (xlo == 0 && (xhi & 0x1FF) == 0 && (mant & 3) == 1) return 0;   /* halfway */
    mant += mant & 1;                                    /* 54 bits to 53, to nearest */
    mant >>= 1;
    if (mant >> 53) {
        mant >>= 1;
        exp2++;
    }
    if (exp2 - 1 >= 0x7FF - 1) return 0;                 /* subnormal or overflow */
    *bits = exp2 << 52 | (mant & 0x000FFFFFFFFFFFFFull);
    return 1;
}

int ctn_parse_decimal(const char *tok, double *out)
{
    const char *p = tok;
    int neg = *p == '-';
    if (*p == '-' || *p == '+') p++;
    uint64_t w = 0, bits = 0;
    long q = 0;
    double v = 0;
    if (!scan(p, &w, &q)) return 0;
    if (w && clinger(w, q, &v)) {
        *out = neg ? -v : v;
        return 1;
    }
    if (w && !eisel_lemire(w, q, &bits)) return 0;
    bits |= (uint64_t)neg << 63;                         /* w == 0: a signed zero */
    memcpy(out, &bits, sizeof *out);
    return 1;
}
