/* Minimal test harness: CHECK-style assertions that count and report, never abort.
 * Each test program ends with CHECK_DONE(), which prints "N passed, N failed" and
 * returns non-zero if any check failed. */
#ifndef CTN_TEST_CHECK_H
#define CTN_TEST_CHECK_H

#include <math.h>
#include <stdio.h>
#include <string.h>

static int check_passed_, check_failed_;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (cond) check_passed_++;                                                   \
        else { check_failed_++; fprintf(stderr, "%s:%d: CHECK failed: %s\n",         \
                                        __FILE__, __LINE__, #cond); }                \
    } while (0)

#define CHECK_MSG(cond, ...)                                                         \
    do {                                                                             \
        if (cond) check_passed_++;                                                   \
        else { check_failed_++; fprintf(stderr, "%s:%d: CHECK failed: %s: ",         \
                                        __FILE__, __LINE__, #cond);                  \
               fprintf(stderr, __VA_ARGS__); fputc('\n', stderr); }                  \
    } while (0)

/* |a - b| <= rtol * max(|a|, |b|) + atol */
#define CHECK_CLOSE(a, b, rtol, atol)                                                \
    do {                                                                             \
        double ca_ = (a), cb_ = (b);                                                 \
        double tol_ = (rtol) * fmax(fabs(ca_), fabs(cb_)) + (atol);                  \
        if (isfinite(ca_) && isfinite(cb_) && fabs(ca_ - cb_) <= tol_) check_passed_++; \
        else { check_failed_++; fprintf(stderr, "%s:%d: CHECK_CLOSE failed: %s = %.17g, " \
               "%s = %.17g (diff %.3g, tol %.3g)\n", __FILE__, __LINE__, #a, ca_, #b,   \
               cb_, fabs(ca_ - cb_), tol_); }                                         \
    } while (0)

#define CHECK_DONE()                                                                 \
    do {                                                                             \
        printf("%d passed, %d failed\n", check_passed_, check_failed_);              \
        return check_failed_ ? 1 : 0;                                                \
    } while (0)

#endif
