/* The buckling analysis's options: defaults, range check, versioned copy. */
#include "problem/buckling_options.h"

#include "core/ctx.h"
#include "core/versioned.h"

#include <stdio.h>
#include <string.h>

void ctn_buckling_options_default(ctn_buckling_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->size = sizeof *opt;
    opt->count = 0;
    opt->line = 0;
}

int ctn_buckling_options_fault(const ctn_buckling_options *o, char *msg, size_t size)
{
    if (o->count < 0) return snprintf(msg, size, "buckling: count must be >= 1 (got %d)", o->count), 1;
    if (o->line < 0) return snprintf(msg, size, "buckling: line must be >= 0 (got %d)", o->line), 1;
    if (o->check != 0 && o->check != 1) return snprintf(msg, size, "buckling: check must be 0 or 1 (got %d)", o->check), 1;
    return 0;
}

int ctn_buckling_options_take(ctn_ctx *ctx, ctn_buckling_options *dst, const ctn_buckling_options *src)
{
    ctn_buckling_options_default(dst);
    return src ? ctn_versioned_take(ctx, dst, sizeof *dst, src, "buckling options") : CTN_OK;
}

int ctn_buckling_options_check(ctn_ctx *ctx, const ctn_buckling_options *opt)
{
    char msg[256];
    if (!opt) return ctn_error(ctx, CTN_ERR_INVALID, "buckling options are NULL");
    ctn_buckling_options o;
    int rc = ctn_buckling_options_take(ctx, &o, opt);
    if (rc) return rc;
    return ctn_buckling_options_fault(&o, msg, sizeof msg) ? ctn_error(ctx, CTN_ERR_INVALID, "%s", msg) : CTN_OK;
}
