/* Numbers for the writers: printf's "%.17g", and JSON's: cJSON's layout of a number
 * ("%1.15g", or "%1.17g" when 15 digits are not enough), byte for byte, with its test
 * made exact: 15 digits only when they read back to the same double.
 *
 * printf spends ~500 ns on a double and cJSON twice that (printf, sscanf, printf); the
 * result files hold millions of numbers. The fast path here gets P = 15 or 17
 * correctly rounded significant digits with integer arithmetic: v = m 2^q (m < 2^53)
 * times a 128-bit approximation of 10^s (relative error < 2^-126) gives N0 = floor(v 10^s)
 * and the next 64 bits of the fraction, good to 2^-63. When that cannot decide the
 * rounding (the fraction within 2^-55 of one half: a tie or nearly one), for subnormals,
 * and where cJSON's round-trip test sits on a boundary, it falls back on what printf
 * and cJSON do themselves: snprintf and sscanf in the C locale. tests/test_writers.c
 * compares every path with printf and cJSON on millions of values. */
#include "io/fmt.h"

#include <float.h>
#include <locale.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* 10^(16 i) ~ (hi 2^64 + lo) 2^e, hi >= 2^63, rounded to nearest; i = -19 ... 20
 * (generated with Python's fractions: exact 10^(16 i) scaled into [2^127, 2^128)). */
#define POW16_MIN (-19)
#define POW16_MAX 20
static const struct { uint64_t hi, lo; int e; } pow16[] = {
    { 0x8c71dcd9ba0b4925u, 0x9ff0c08b7f1d0b15u, -1137 },  /* 1e-304 */
    { 0x9becce62836ac577u, 0x4ee367f9430aec33u, -1084 },  /* 1e-288 */
    { 0xad1c8eab5ee43b66u, 0xda3243650005eecfu, -1031 },  /* 1e-272 */
    { 0xc0314325637a1939u, 0xfa911155fefb5309u, -978 },   /* 1e-256 */
    { 0xd5605fcdcf32e1d6u, 0xfb1e4a9a90880a65u, -925 },   /* 1e-240 */
    { 0xece53cec4a314ebdu, 0xa4f8bf5635246428u, -872 },   /* 1e-224 */
    { 0x8380dea93da4bc60u, 0x4247cb9e59f71e6du, -818 },   /* 1e-208 */
    { 0x91ff83775423cc06u, 0x7b6306a34627ddcfu, -765 },   /* 1e-192 */
    { 0xa21727db38cb002fu, 0xb8ada00e5a506a7du, -712 },   /* 1e-176 */
    { 0xb3f4e093db73a093u, 0x59ed216765690f57u, -659 },   /* 1e-160 */
    { 0xc7caba6e7c5382c8u, 0xfe64a52ee96b8fc1u, -606 },   /* 1e-144 */
    { 0xddd0467c64bce4a0u, 0xac7cb3f6d05ddbdfu, -553 },   /* 1e-128 */
    { 0xf64335bcf065d37du, 0x4d4617b5ff4a16d6u, -500 },   /* 1e-112 */
    { 0x88b402f7fd75539bu, 0x11dbcb0218ebb414u, -446 },   /* 1e-96 */
    { 0x97c560ba6b0919a5u, 0xdccd879fc967d41au, -393 },   /* 1e-80 */
    { 0xa87fea27a539e9a5u, 0x3f2398d747b36224u, -340 },   /* 1e-64 */
    { 0xbb127c53b17ec159u, 0x5560c018580d5d52u, -287 },   /* 1e-48 */
    { 0xcfb11ead453994bau, 0x67de18eda5814af2u, -234 },   /* 1e-32 */
    { 0xe69594bec44de15bu, 0x4c2ebe687989a9b4u, -181 },   /* 1e-16 */
    { 0x8000000000000000u, 0x0000000000000000u, -127 },   /* 1e0 */
    { 0x8e1bc9bf04000000u, 0x0000000000000000u, -74 },    /* 1e16 */
    { 0x9dc5ada82b70b59du, 0xf020000000000000u, -21 },    /* 1e32 */
    { 0xaf298d050e4395d6u, 0x9670b12b7f410000u, 32 },     /* 1e48 */
    { 0xc2781f49ffcfa6d5u, 0x3cbf6b71c76b25fbu, 85 },     /* 1e64 */
    { 0xd7e77a8f87daf7fbu, 0xdc33745ec97be906u, 138 },    /* 1e80 */
    { 0xefb3ab16c59b14a2u, 0xc5cfe94ef3ea101eu, 191 },    /* 1e96 */
    { 0x850fadc09923329eu, 0x03e2cf6bc604ddb0u, 245 },    /* 1e112 */
    { 0x93ba47c980e98cdfu, 0xc66f336c36b10137u, 298 },    /* 1e128 */
    { 0xa402b9c5a8d3a6e7u, 0x5f16206c9c6209a6u, 351 },    /* 1e144 */
    { 0xb616a12b7fe617aau, 0x577b986b314d6009u, 404 },    /* 1e160 */
    { 0xca28a291859bbf93u, 0x7d7b8f7503cfdcffu, 457 },    /* 1e176 */
    { 0xe070f78d3927556au, 0x85bbe253f47b1417u, 510 },    /* 1e192 */
    { 0xf92e0c3537826145u, 0xa7709a56ccdf8a83u, 563 },    /* 1e208 */
    { 0x8a5296ffe33cc92fu, 0x82bd6b70d99aaa70u, 617 },    /* 1e224 */
    { 0x9991a6f3d6bf1765u, 0xacca6da1e0a8ef29u, 670 },    /* 1e240 */
    { 0xaa7eebfb9df9de8du, 0xddbb901b98feeab8u, 723 },    /* 1e256 */
    { 0xbd49d14aa79dbc82u, 0x4b2d8644d8a74e19u, 776 },    /* 1e272 */
    { 0xd226fc195c6a2f8cu, 0x73832eec6fff3112u, 829 },    /* 1e288 */
    { 0xe950df20247c83fdu, 0x47c6b82ef32a2069u, 882 },    /* 1e304 */
    { 0x81842f29f2cce375u, 0xe6a1158300d46640u, 936 },    /* 1e320 */
};

static const uint64_t pow10u[19] = {
    1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u, 100000000u, 1000000000u,
    10000000000u, 100000000000u, 1000000000000u, 10000000000000u, 100000000000000u,
    1000000000000000u, 10000000000000000u, 100000000000000000u, 1000000000000000000u
};

/* A 128-bit mantissa: (hi 2^64 + lo) 2^e with hi >= 2^63. */
typedef struct wide {
    uint64_t hi, lo;
    int e;
} wide;

/* v 10^(P-1-x) = n + f 2^-64 for the P-digit scale of v: 10^(P-1) <= n < 10^P, so
 * x = floor(log10 v); f is good to 2^-63. */
typedef struct scaled {
    uint64_t n, f;
    int x;
} scaled;

/* Digits of a positive v, rounded to P significant ones. */
typedef struct decimal {
    uint64_t n;   /* the digits: 10^(P-1) <= n < 10^P */
    int x;        /* decimal exponent of the first digit */
    double t;     /* (n 10^(x-P+1) - v) / ulp(v): the rounding, in units of v's last bit */
} decimal;

static void mul64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)   /* hi:lo = a b */
{
#if defined(__SIZEOF_INT128__)
    __extension__ typedef unsigned __int128 u128;
    u128 p = (u128)a * b;
    *hi = (uint64_t)(p >> 64);
    *lo = (uint64_t)p;
#else
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    *lo = (mid << 32) | (p00 & 0xffffffffu);
#endif
}

static int clz64(uint64_t x)   /* x > 0 */
{
#if defined(__GNUC__)
    return __builtin_clzll(x);
#else
    int n = 0;
    for (int k = 32; k; k /= 2)
        if (!(x >> (64 - k))) { x <<= k; n += k; }
    return n;
#endif
}

/* 10^s = 10^(16 i) 10^j: the table entry times an exact 10^j, renormalized (truncating
 * adds < 2^-127). 0 if s is beyond the table. */
static int pow10w(int s, wide *w)
{
    int i = s >= 0 ? s / 16 : -((15 - s) / 16), j = s - 16 * i;
    if (i < POW16_MIN || i > POW16_MAX) return 0;
    w->hi = pow16[i - POW16_MIN].hi;
    w->lo = pow16[i - POW16_MIN].lo;
    w->e = pow16[i - POW16_MIN].e;
    if (!j) return 1;
    uint64_t h0, l0, h1, l1;
    mul64(w->lo, pow10u[j], &h0, &l0);
    mul64(w->hi, pow10u[j], &h1, &l1);
    uint64_t c1 = l1 + h0, c2 = h1 + (c1 < h0);             /* c2:c1:l0 = W 10^j, c2 > 0 */
    int z = clz64(c2);
    w->hi = z ? c2 << z | c1 >> (64 - z) : c2;
    w->lo = z ? c1 << z | l0 >> (64 - z) : c1;
    w->e += 64 - z;
    return 1;
}

/* Bits k ... k+63 of the 192-bit c[2]:c[1]:c[0], 0 <= k < 192. */
static uint64_t bits192(const uint64_t c[3], int k)
{
    int i = k / 64, b = k % 64;
    uint64_t r = c[i] >> b;
    if (b && i < 2) r |= c[i + 1] << (64 - b);
    return r;
}

/* v 10^s for v = m 2^q: integer part *n (< 2^64) and the fraction's top 64 bits *f.
 * 0 if out of reach. */
static int scale(uint64_t m, int q, int s, uint64_t *n, uint64_t *f)
{
    wide w;
    if (!pow10w(s, &w)) return 0;
    uint64_t h0, l0, h1, l1;
    mul64(m, w.lo, &h0, &l0);
    mul64(m, w.hi, &h1, &l1);
    uint64_t c[3] = { l0, l1 + h0, 0 };
    c[2] = h1 + (c[1] < h0);                                  /* c = m W, exact */
    int sh = -(q + w.e);                                      /* v 10^s ~ c 2^-sh */
    if (sh < 64 || sh > 191) return 0;
    if (sh + 64 < 192 && bits192(c, sh + 64)) return 0;       /* integer part >= 2^64 */
    *n = bits192(c, sh);
    *f = bits192(c, sh - 64);
    return 1;
}

/* The P-digit scale of v = m 2^q, a normal double (2^52 <= m < 2^53). 0 if out of
 * reach. */
static int scale_to(uint64_t m, int q, int P, scaled *sc)
{
    /* log2 v >= q + 52 + (m 2^-52 - 1): x starts at floor(log10 v) or one below */
    double lg = (q + 52 + ((double)m * 0x1p-52 - 1.0)) * 0.30102999566398119521;
    int x = (int)lg - (lg < 0 && (int)lg != lg);                        /* floor */
    for (int tries = 0; tries < 3; tries++) {
        if (!scale(m, q, P - 1 - x, &sc->n, &sc->f)) return 0;
        if (sc->n < pow10u[P - 1]) { x--; continue; }
        if (sc->n >= pow10u[P]) { x++; continue; }
        sc->x = x;
        return 1;
    }
    return 0;
}

/* The 15-digit scale from the 17-digit one: n / 100, and the fraction
 * ((n mod 100) 2^64 + f) / 100 = r q0 + (r 16 + f) / 100 with 2^64 = 100 q0 + 16. */
static scaled to15(const scaled *s17)
{
    const uint64_t q0 = 184467440737095516u;
    uint64_t r = s17->n % 100, f = s17->f;
    return (scaled){ s17->n / 100, r * q0 + f / 100 + (f % 100 + 16 * r) / 100, s17->x };
}

/* Round the scale to P digits. 0 when the fraction is within 2^-55 of one half (a tie,
 * or too near one to tell): the caller falls back on printf. */
static int round_to(const scaled *sc, int P, uint64_t m, decimal *d)
{
    const uint64_t half = (uint64_t)1 << 63, near = (uint64_t)1 << 9;
    uint64_t f = sc->f;
    if ((f > half ? f - half : half - f) <= near) return 0;
    int up = f > half;
    double fd = (double)f * 0x1p-64;
    d->t = (up ? 1.0 - fd : -fd) * (double)m / ((double)sc->n + fd);
    d->n = sc->n + (uint64_t)up;
    d->x = sc->x;
    if (d->n == pow10u[P]) {                                  /* 9.99... rounded up */
        d->n = pow10u[P - 1];
        d->x++;
    }
    return 1;
}

static const char two_digits[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/* The P (15 or 17) digits of n, leading zeros included, into dig. */
static void put_digits(char *dig, uint64_t n, int P)
{
    uint32_t lo = (uint32_t)(n % 100000000u), hi = (uint32_t)(n / 100000000u);
    char *p = dig + P;
    for (int i = 0; i < 4; i++, lo /= 100) {
        p -= 2;
        memcpy(p, two_digits + 2 * (lo % 100), 2);
    }
    for (int k = P - 8; k > 0; k -= 2, hi /= 100) {
        if (k == 1) { *--p = (char)('0' + hi % 10); break; }
        p -= 2;
        memcpy(p, two_digits + 2 * (hi % 100), 2);
    }
}

/* %.Pg of the digits: style e when x < -4 or x >= P, else f; trailing zeros removed. */
static size_t format_g(char *out, int neg, const decimal *d, int P)
{
    char dig[20], *p = out;
    int nd = P, x = d->x;
    put_digits(dig, d->n, P);
    while (nd > 1 && dig[nd - 1] == '0') nd--;
    if (neg) *p++ = '-';
    if (x < -4 || x >= P) {
        *p++ = dig[0];
        if (nd > 1) { *p++ = '.'; memcpy(p, dig + 1, (size_t)nd - 1); p += nd - 1; }
        *p++ = 'e';
        *p++ = x < 0 ? '-' : '+';
        int ax = x < 0 ? -x : x;
        if (ax >= 100) *p++ = (char)('0' + ax / 100);
        *p++ = (char)('0' + ax / 10 % 10);
        *p++ = (char)('0' + ax % 10);
    } else if (x >= 0) {
        memcpy(p, dig, (size_t)x + 1);
        p += x + 1;
        if (nd > x + 1) { *p++ = '.'; memcpy(p, dig + x + 1, (size_t)(nd - x - 1)); p += nd - x - 1; }
    } else {
        *p++ = '0';
        *p++ = '.';
        for (int i = 0; i < -x - 1; i++) *p++ = '0';
        memcpy(p, dig, (size_t)nd);
        p += nd;
    }
    *p = '\0';
    return (size_t)(p - out);
}

/* m and q of a normal v != 0 (v = +-m 2^q, 2^52 <= m < 2^53); 0 for subnormals. */
static int split(double v, uint64_t *m, int *q)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    int e = (int)(b >> 52 & 0x7ff);
    if (!e || e == 0x7ff) return 0;
    *m = (b & (((uint64_t)1 << 52) - 1)) | (uint64_t)1 << 52;
    *q = e - 1075;
    return 1;
}

/* The slow path: printf (and cJSON's sscanf test) in the C locale. */
static size_t slow(char *out, double v, int cjson)
{
    locale_t c = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    locale_t old = c ? uselocale(c) : (locale_t)0;
    int k = snprintf(out, CTN_FMT_MAX, cjson ? "%1.15g" : "%.17g", v);
    if (cjson) {
        double test = 0.0;
        int ok = sscanf(out, "%lg", &test) == 1;
        if (!ok || test != v) k = snprintf(out, CTN_FMT_MAX, "%1.17g", v);   /* exact only */
    }
    if (c) {
        uselocale(old);
        freelocale(c);
    }
    return k > 0 ? (size_t)k : 0;
}

static size_t zero(char *out, double v)   /* printf and cJSON keep the sign of -0 */
{
    size_t n = 0;
    if (signbit(v)) out[n++] = '-';
    out[n++] = '0';
    out[n] = '\0';
    return n;
}

size_t ctn_fmt_g17(char *out, double v)
{
    uint64_t m;
    int q;
    scaled sc;
    decimal d;
    if (v == 0) return zero(out, v);
    if (split(v, &m, &q) && scale_to(m, q, 17, &sc) && round_to(&sc, 17, m, &d))
        return format_g(out, v < 0, &d, 17);
    return slow(out, v, 0);
}

/* The 15 digits are kept when the decimal they make, v + t ulp(v), reads back to v
 * itself: |t| < 1/2 within v's binade (1/4 below its lower end, where the spacing
 * halves). 1: keep 15 digits, 0: print 17, -1: undecided (t next to 1/2, or the spacing
 * of the doubles changes near v). */
static int json_keeps_15(double t, uint64_t m)
{
    const double a = fabs(t), eps = 1e-9;
    const uint64_t lo = (uint64_t)1 << 52, hi = (uint64_t)1 << 53;
    if (a < 0.25 - eps) return 1;                             /* reads back v anywhere */
    if (t > 0 ? m + 64 >= hi : m < lo + 64) return -1;
    if (a < 0.5 - eps) return 1;
    return a > 0.5 + eps ? 0 : -1;
}

/* 15 digits when they read back to v, else 17: both from one scaling. */
size_t ctn_fmt_json(char *out, double v)
{
    uint64_t m;
    int q;
    scaled s17, s15;
    decimal d;
    if (v == 0) return zero(out, v);
    if (!split(v, &m, &q) || q < -1000 || !scale_to(m, q, 17, &s17))   /* q < -1000: tiny, */
        return slow(out, v, 1);                  /* subnormal: printf and sscanf decide */
    s15 = to15(&s17);
    if (!round_to(&s15, 15, m, &d)) return slow(out, v, 1);
    int keep = json_keeps_15(d.t, m);
    if (keep > 0) return format_g(out, v < 0, &d, 15);
    if (keep < 0 || !round_to(&s17, 17, m, &d)) return slow(out, v, 1);
    return format_g(out, v < 0, &d, 17);
}

size_t ctn_fmt_int(char *out, long long v)
{
    char tmp[24];
    unsigned long long u = v < 0 ? 0ull - (unsigned long long)v : (unsigned long long)v;
    size_t k = 0, n = 0;
    do { tmp[k++] = (char)('0' + u % 10); u /= 10; } while (u);
    if (v < 0) out[n++] = '-';
    while (k) out[n++] = tmp[--k];
    out[n] = '\0';
    return n;
}
