/* Versioned public structs: read by the caller's size (versioned.h). */
#include "core/versioned.h"

#include "core/ctx.h"

#include <string.h>

int ctn_versioned_take(ctn_ctx *ctx, void *dst, size_t dst_size, const void *src, const char *what)
{
    size_t n;
    memcpy(&n, src, sizeof n);
    if (n < sizeof(size_t))
        return ctn_error(ctx, CTN_ERR_INVALID, "%s: size is %zu: fill the struct by its _default function first",
                         what, n);
    if (n > dst_size)
        return ctn_error(ctx, CTN_ERR_INVALID, "%s: size is %zu, this library knows %zu bytes of it (a program "
                         "built against a newer catena)", what, n, dst_size);
    memcpy(dst, src, n);
    memcpy(dst, &dst_size, sizeof dst_size);
    return CTN_OK;
}
