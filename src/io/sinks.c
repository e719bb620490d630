/* Sinks into a FILE and into memory. */
#include "io/sink.h"

#include <errno.h>
#include <string.h>

static int stdio_write(void *ud, const char *p, size_t n)
{
    ctn_stdio_sink *st = ud;
    errno = 0;
    if (fwrite(p, 1, n, st->f) == n) return CTN_OK;
    return ctn_error(st->ctx, CTN_ERR_IO, "%s: write error: %s", st->name,
                     errno ? strerror(errno) : "short write");
}

ctn_sink ctn_sink_stdio(ctn_stdio_sink *st, ctn_ctx *ctx, FILE *f, const char *name)
{
    *st = (ctn_stdio_sink){ ctx, f, name };
    return (ctn_sink){ stdio_write, st };
}

int ctn_sink_stdio_flush(ctn_stdio_sink *st)
{
    errno = 0;
    if (!fflush(st->f) && !ferror(st->f)) return CTN_OK;
    return ctn_error(st->ctx, CTN_ERR_IO, "%s: write error: %s", st->name,
                     errno ? strerror(errno) : "I/O error");
}

static int mem_write(void *ud, const char *p, size_t n)
{
    ctn_mem_sink *mb = ud;
    if (mb->cap - mb->n <= n) {                    /* keep a byte for the NUL */
        size_t cap = mb->cap ? mb->cap : 4096;
        while (cap - mb->n <= n) {
            if (cap > (size_t)-1 / 2) return ctn_error(mb->ctx, CTN_ERR_NOMEM, "output too large");
            cap *= 2;
        }
        char *s = ctn_realloc(mb->ctx, mb->s, cap, 1);
        if (!s) return CTN_ERR_NOMEM;
        mb->s = s;
        mb->cap = cap;
    }
    memcpy(mb->s + mb->n, p, n);
    mb->n += n;
    return CTN_OK;
}

ctn_sink ctn_sink_mem(ctn_mem_sink *mb, ctn_ctx *ctx)
{
    *mb = (ctn_mem_sink){ ctx, NULL, 0, 0 };
    return (ctn_sink){ mem_write, mb };
}

int ctn_sink_mem_take(ctn_mem_sink *mb, char **text)
{
    *text = NULL;
    if (!mb->s) {                                  /* nothing written */
        mb->s = ctn_malloc(mb->ctx, 1, 1);
        if (!mb->s) return CTN_ERR_NOMEM;
        mb->cap = 1;
    }
    mb->s[mb->n] = '\0';
    *text = mb->s;
    *mb = (ctn_mem_sink){ mb->ctx, NULL, 0, 0 };
    return CTN_OK;
}

void ctn_sink_mem_free(ctn_mem_sink *mb)
{
    ctn_free(mb->s);
    *mb = (ctn_mem_sink){ mb->ctx, NULL, 0, 0 };
}
