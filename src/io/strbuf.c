/* Growable text buffer. */
#include "io/strbuf.h"

#include <stdarg.h>
#include <stdio.h>

void ctn_sb_printf(ctn_strbuf *b, const char *fmt, ...)
{
    if (b->err) return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int k = vsnprintf(b->s ? b->s + b->n : NULL, b->s ? b->cap - b->n : 0, fmt, ap);
        va_end(ap);
        if (k < 0) { b->err = CTN_ERR_INVALID; return; }
        if (b->s && b->n + (size_t)k < b->cap) { b->n += (size_t)k; return; }
        size_t cap = b->cap ? b->cap : 4096;
        while (cap <= b->n + (size_t)k) cap *= 2;
        char *p = ctn_realloc(b->ctx, b->s, cap, 1);
        if (!p) { b->err = CTN_ERR_NOMEM; return; }
        b->s = p;
        b->cap = cap;
    }
}

void ctn_sb_free(ctn_strbuf *b)
{
    ctn_free(b->s);
    b->s = NULL;
    b->n = b->cap = 0;
}
