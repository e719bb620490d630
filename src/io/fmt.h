/* Internal: numbers as the result writers print them, byte for byte what printf and
 * cJSON print, in the C locale whatever the process's locale, without calling printf on
 * the common path (see fmt.c). Each function writes at most CTN_FMT_MAX bytes, the
 * terminating NUL included, and returns the length without it. */
#ifndef CTN_IO_FMT_H
#define CTN_IO_FMT_H

#include <stddef.h>

#define CTN_FMT_MAX 32

/* printf("%.17g", v): 17 significant digits, round-trips. v finite. */
size_t ctn_fmt_g17(char *out, double v);
/* A JSON number: "%1.15g" when sscanf gives back v itself, else "%1.17g" (cJSON's
 * layout, whose own test, within DBL_EPSILON relative, would lose the last bit of some
 * doubles): every number reads back to the double written. v finite. */
size_t ctn_fmt_json(char *out, double v);
/* printf("%lld", v). */
size_t ctn_fmt_int(char *out, long long v);

#endif
