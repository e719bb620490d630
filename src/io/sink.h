/* Internal: byte sinks, and the buffered output the result writers print through.
 *
 * A sink takes bytes somewhere: a staged file (io/atomic.h), a FILE such as stdout, or
 * a growing memory buffer. Its write takes all n bytes or fails; on failure it records
 * the error (CTN_ERR_IO with the file's name and strerror, CTN_ERR_NOMEM) in its
 * context and returns the code.
 *
 * A ctn_wbuf collects small writes and formatted numbers in a fixed buffer of
 * CTN_WBUF_SIZE bytes and hands it to the sink when full. Its first error is sticky:
 * every later call does nothing, and ctn_wbuf_close returns it. */
#ifndef CTN_IO_SINK_H
#define CTN_IO_SINK_H

#include "core/ctx.h"

#include <stdio.h>

typedef struct ctn_sink {
    int (*write)(void *ud, const char *p, size_t n);   /* CTN_OK or the recorded error */
    void *ud;
} ctn_sink;

/* ---- the buffered output ---- */

#define CTN_WBUF_SIZE 65536

typedef struct ctn_wbuf {
    ctn_ctx *ctx;
    ctn_sink *sink;
    char *p;          /* CTN_WBUF_SIZE bytes, owned */
    size_t n;         /* bytes pending in p */
    size_t total;     /* bytes handed to the sink */
    int err;          /* first error, sticky */
} ctn_wbuf;

/* Allocate the buffer; CTN_ERR_NOMEM (also left in b->err) on failure. b needs
 * ctn_wbuf_close in either case. */
int ctn_wbuf_open(ctn_wbuf *b, ctn_ctx *ctx, ctn_sink *sink);
/* Flush what is pending unless an error came first, free the buffer; the first error. */
int ctn_wbuf_close(ctn_wbuf *b);
/* Hand the pending bytes to the sink; the first error. */
int ctn_wbuf_flush(ctn_wbuf *b);
/* Room for k <= CTN_WBUF_SIZE bytes at p + n (flushing first if needed); NULL after
 * an error. The caller writes there and adds what it wrote to b->n. */
char *ctn_wbuf_room(ctn_wbuf *b, size_t k);
void ctn_wbuf_write(ctn_wbuf *b, const char *s, size_t n);
void ctn_wbuf_puts(ctn_wbuf *b, const char *s);
void ctn_wbuf_putc(ctn_wbuf *b, char c);
/* k copies of c. */
void ctn_wbuf_fill(ctn_wbuf *b, char c, size_t k);
/* Numbers, as io/fmt.h prints them: "%.17g", cJSON's print_number, "%lld". */
void ctn_wbuf_g17(ctn_wbuf *b, double v);
void ctn_wbuf_cjson(ctn_wbuf *b, double v);
void ctn_wbuf_int(ctn_wbuf *b, long long v);

/* ---- sinks ---- */

/* Into a FILE: every fwrite checked; name (e.g. "stdout") starts the error message. */
typedef struct ctn_stdio_sink {
    ctn_ctx *ctx;
    FILE *f;
    const char *name;
} ctn_stdio_sink;
ctn_sink ctn_sink_stdio(ctn_stdio_sink *st, ctn_ctx *ctx, FILE *f, const char *name);
/* fflush the FILE, checked (with its error flag). */
int ctn_sink_stdio_flush(ctn_stdio_sink *st);

/* Into memory that grows as needed. */
typedef struct ctn_mem_sink {
    ctn_ctx *ctx;
    char *s;          /* owned until taken */
    size_t n, cap;
} ctn_mem_sink;
ctn_sink ctn_sink_mem(ctn_mem_sink *mb, ctn_ctx *ctx);
/* The bytes written, NUL-terminated, in *text (free with ctn_free); mb is left empty. */
int ctn_sink_mem_take(ctn_mem_sink *mb, char **text);
void ctn_sink_mem_free(ctn_mem_sink *mb);

#endif
