/* The buffered output of the writers: a fixed buffer handed to a sink when full. */
#include "io/fmt.h"
#include "io/sink.h"

#include <string.h>

int ctn_wbuf_open(ctn_wbuf *b, ctn_ctx *ctx, ctn_sink *sink)
{
    *b = (ctn_wbuf){ ctx, sink, NULL, 0, 0, CTN_OK };
    b->p = ctn_malloc(ctx, CTN_WBUF_SIZE, 1);
    if (!b->p) b->err = CTN_ERR_NOMEM;
    return b->err;
}

int ctn_wbuf_flush(ctn_wbuf *b)
{
    if (!b->err && b->n) {
        b->err = ctn_interrupted(b->ctx);
        if (!b->err) b->err = b->sink->write(b->sink->ud, b->p, b->n);
        if (!b->err) b->total += b->n;
        if (!b->err) ctn_progress(b->ctx, "writing", (double)b->total, 0);
    }
    b->n = 0;
    return b->err;
}

int ctn_wbuf_close(ctn_wbuf *b)
{
    int rc = ctn_wbuf_flush(b);
    ctn_free(b->p);
    b->p = NULL;
    return rc;
}

char *ctn_wbuf_room(ctn_wbuf *b, size_t k)
{
    if (b->err) return NULL;
    if (CTN_WBUF_SIZE - b->n < k && ctn_wbuf_flush(b)) return NULL;
    return b->p + b->n;
}

void ctn_wbuf_write(ctn_wbuf *b, const char *s, size_t n)
{
    while (n && !b->err) {
        if (b->n == CTN_WBUF_SIZE && ctn_wbuf_flush(b)) return;
        size_t k = CTN_WBUF_SIZE - b->n < n ? CTN_WBUF_SIZE - b->n : n;
        memcpy(b->p + b->n, s, k);
        b->n += k;
        s += k;
        n -= k;
    }
}

void ctn_wbuf_puts(ctn_wbuf *b, const char *s) { ctn_wbuf_write(b, s, strlen(s)); }

void ctn_wbuf_putc(ctn_wbuf *b, char c)
{
    char *p = ctn_wbuf_room(b, 1);
    if (p) {
        *p = c;
        b->n++;
    }
}

void ctn_wbuf_fill(ctn_wbuf *b, char c, size_t k)
{
    while (k && !b->err) {
        size_t m = k < 64 ? k : 64;
        char *p = ctn_wbuf_room(b, m);
        if (!p) return;
        memset(p, c, m);
        b->n += m;
        k -= m;
    }
}

void ctn_wbuf_g17(ctn_wbuf *b, double v)
{
    char *p = ctn_wbuf_room(b, CTN_FMT_MAX);
    if (p) b->n += ctn_fmt_g17(p, v);
}

void ctn_wbuf_cjson(ctn_wbuf *b, double v)
{
    char *p = ctn_wbuf_room(b, CTN_FMT_MAX);
    if (p) b->n += ctn_fmt_json(p, v);
}

void ctn_wbuf_int(ctn_wbuf *b, long long v)
{
    char *p = ctn_wbuf_room(b, CTN_FMT_MAX);
    if (p) b->n += ctn_fmt_int(p, v);
}
