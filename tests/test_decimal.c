/* The reader's exact decimal conversion (src/io/decimal.c) against the C library's
 * strtod, the independent truth: whenever ctn_parse_decimal accepts a token, strtod
 * must read the whole token without a range error and give the same bits; and it must
 * accept the plain numbers it is for (the printed doubles of a model file), so that the
 * fast path is the one taken. The corpus: edge cases (zeros, the smallest and largest
 * normals and their neighbours, the classic hard cases, halfway cases that round to
 * even, tokens that are not plain decimals) and random numbers in the forms programs
 * print (%.17g, %.15g, %.6g, %.3e, random digit strings with random exponents).
 * ctest-cost: 2 */
#include "check.h"
#include "io/decimal.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static int mismatches, accepted, tried;

/* 1 if ctn_parse_decimal on s agrees with strtod (or declines); counts acceptance. */
static int agree(const char *s)
{
    double fast = 0, ref;
    char *end;
    tried++;
    if (!ctn_parse_decimal(s, &fast)) return 1;
    accepted++;
    errno = 0;
    ref = strtod(s, &end);
    int ok = *end == '\0' && end != s && errno == 0 && !memcmp(&fast, &ref, sizeof ref);
    if (!ok && mismatches++ < 10)
        fprintf(stderr, "'%s': ctn_parse_decimal %.17g, strtod %.17g (rest '%s', errno %d)\n", s, fast, ref, end, errno);
    return ok;
}

/* xorshift64*: a fixed sequence, so a failure repeats. */
static uint64_t next(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 0x2545F4914F6CDD1Dull;
}

static void edge_cases(void)
{
    static const char *const yes[] = {
        "0", "-0", "+0.0", "0.000e5", "1", "-1", "0.1", ".5", "5.", "8.98846567431158e307",
        "2.2250738585072014e-308", "1.7976931348623157e308", "1.7976931348623158e308",
        "1e22", "1e-22", "4.9406564584124654e-300",
        "199800000", "0.00031399999999999999", "-3.9999600000000002e-05", "0.059999999999999998",
        "1234567890123456789", "0.1234567890123456789", "7.2057594037927933e16", "1E5", "1e+5",
    };
    static const char *const maybe[] = {   /* halfway or hard: declined, or strtod's value */
        "1e23", "9007199254740993", "9007199254740995", "4.5036e15", "2.4703282292062328e-324",
        "1.00000000000000011102230246251565404236316680908203125",
    };
    for (size_t i = 0; i < sizeof maybe / sizeof *maybe; i++) CHECK_MSG(agree(maybe[i]), "'%s'", maybe[i]);
    static const char *const no[] = {
        "", "-", "+", ".", "e5", "1e", "1e+", "1e-", "0x10", "inf", "-inf", "nan", "1,5", "1.5.2",
        "1e5x", "200GPa", "12345678901234567890", "1e400", "1e-400", "5e-324",
        "2.2250738585072011e-308", "1.7976931348623159e308", " 1", "1 ", "--1", "+-1",
    };
    double v = 0;
    for (size_t i = 0; i < sizeof yes / sizeof *yes; i++) {
        CHECK_MSG(ctn_parse_decimal(yes[i], &v), "'%s' should take the fast path", yes[i]);
        CHECK_MSG(agree(yes[i]), "'%s'", yes[i]);
    }
    for (size_t i = 0; i < sizeof no / sizeof *no; i++)
        CHECK_MSG(!ctn_parse_decimal(no[i], &v), "'%s' is for strtod", no[i]);
    CHECK(ctn_parse_decimal("-0", &v) && v == 0 && signbit(v));
    CHECK(!ctn_parse_decimal("9007199254740993", &v) || v == 9007199254740992.0);   /* halfway: to even */
    CHECK(!ctn_parse_decimal("9007199254740995", &v) || v == 9007199254740996.0);
    CHECK(ctn_parse_decimal("0.5", &v) && v == 0.5);
    CHECK(ctn_parse_decimal("-2.5e-3", &v) && v == -0.0025);
}

/* Halfway cases: (2^53 + 2k + 1) 2^j, exactly between two doubles, in full digits. */
static int halfway(void)
{
    int ok = 1;
    char s[64];
    for (int j = 0; j < 10; j++)
        for (uint64_t k = 0; k < 200; k++) {
            snprintf(s, sizeof s, "%llu", (unsigned long long)(((1ull << 53) + 2 * k + 1) << j));
            ok &= agree(s);
        }
    return ok;
}

static int random_numbers(int n)
{
    uint64_t seed = 0x9E3779B97F4A7C15ull;
    char s[64];
    int ok = 1, printed = 0, printed_ok = 0;
    for (int i = 0; i < n; i++) {
        uint64_t r = next(&seed), bits = next(&seed);
        double d;
        memcpy(&d, &bits, sizeof d);
        if (!isfinite(d)) continue;
        static const char *const forms[4] = { "%.17g", "%.15g", "%.6g", "%.3e" };
        snprintf(s, sizeof s, forms[r & 3], d);
        int before = accepted;
        ok &= agree(s);
        if (fabs(d) >= 2.2250738585072014e-308 && fabs(d) < 1e300) {   /* normal, not near overflow */
            printed++;
            printed_ok += accepted > before;
        }
        int ndig = 1 + (int)((r >> 8) % 19), e = (int)((r >> 16) % 700) - 350, neg = (int)(r >> 40 & 1);
        char dig[24];                                     /* ndig random digits */
        snprintf(dig, sizeof dig, "%019llu", (unsigned long long)(next(&seed) % 10000000000000000000ull));
        dig[ndig] = '\0';
        snprintf(s, sizeof s, "%s%se%d", neg ? "-" : "", dig, e);
        ok &= agree(s);
        int k = (int)((r >> 42) % (uint64_t)ndig);          /* the same with a point after k digits */
        snprintf(s, sizeof s, "%s%.*s.%se%d", neg ? "-" : "", k, dig, dig + k, e);
        ok &= agree(s);
    }
    CHECK_MSG(printed_ok > printed * 99 / 100, "the fast path took %d of %d printed normal doubles", printed_ok, printed);
    return ok;
}

int main(void)
{
    edge_cases();
    CHECK(halfway());
    CHECK(random_numbers(400000));
    CHECK_MSG(mismatches == 0, "%d mismatches with strtod", mismatches);
    printf("%d tokens, %d converted by the fast path, %d mismatches\n", tried, accepted, mismatches);
    CHECK_DONE();
}
