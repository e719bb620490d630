/* Internal: an exact decimal-to-double conversion for the reader's plain numbers
 * (decimal.c), the value strtod gives, in a fraction of its time. */
#ifndef CTN_IO_DECIMAL_H
#define CTN_IO_DECIMAL_H

#include <stdint.h>

/* 1 if tok is a whole plain decimal ([+-]digits[.digits][e[+-]digits], at least one
 * digit, nothing after) of at most 19 significant digits whose value is a normal double
 * (or zero) that the conversion can decide, *out then being exactly strtod(tok)'s value
 * (correctly rounded, to nearest even); 0 otherwise, *out untouched: the caller asks
 * strtod (hexadecimal, inf, nan, a unit after the number, a subnormal, an overflow, a
 * rare halfway case). */
int ctn_parse_decimal(const char *tok, double *out);

/* floor(10^e 2^k) for e = -348 .. 347, normalized to 128 bits: { high, low } (pow10.c). */
extern const uint64_t ctn_pow10_128[696][2];
#define CTN_POW10_MIN (-348)
#define CTN_POW10_MAX 347

#endif
