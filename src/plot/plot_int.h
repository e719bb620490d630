/* Internal helpers of the plot module. */
#ifndef CTN_PLOT_PLOT_INT_H
#define CTN_PLOT_PLOT_INT_H

#include "core/ctx.h"
#include "io/strbuf.h"

/* 1 if name is a plain file name: non-empty, no '/', quote, backslash or white space. */
int ctn_plot_name_ok(const char *name);
/* Write the buffer to dir/file atomically; reports b->err (out of memory) first. */
int ctn_plot_flush(ctn_ctx *ctx, const char *dir, const char *file, ctn_strbuf *b);

#endif
