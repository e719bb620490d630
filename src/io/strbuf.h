/* Internal: a growable text buffer for writers. */
#ifndef CTN_IO_STRBUF_H
#define CTN_IO_STRBUF_H

#include "core/ctx.h"

typedef struct ctn_strbuf {
    ctn_ctx *ctx;
    char *s;
    size_t n, cap;
    int err;          /* first error (CTN_ERR_NOMEM), sticky */
} ctn_strbuf;

/* printf-style append; on failure err is set and later appends do nothing. */
void ctn_sb_printf(ctn_strbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void ctn_sb_free(ctn_strbuf *b);

#endif
