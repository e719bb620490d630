/* Internal: public structs that grow (options, specs) start with their size_t size, the
 * caller's sizeof. The library reads the keys the caller's size covers over its own
 * defaults, so a program built against an older header keeps working. */
#ifndef CTN_CORE_VERSIONED_H
#define CTN_CORE_VERSIONED_H

#include "catena/core.h"

#include <stddef.h>

/* Copy the caller's struct src over dst (dst_size bytes, holding the defaults): the
 * first min(src's size, dst_size) bytes, then dst's size set to dst_size.
 * CTN_ERR_INVALID, recorded naming what, when src's size is below sizeof(size_t) (not
 * initialised by its _default function) or above dst_size (a newer library's keys). */
int ctn_versioned_take(ctn_ctx *ctx, void *dst, size_t dst_size, const void *src, const char *what);

#endif
