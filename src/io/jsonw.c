/* Streaming JSON, laid out byte for byte as cJSON 1.7.15 prints it. */
#include "io/jsonw.h"

#include <stdio.h>
#include <string.h>

enum { JW_ARRAY = 1, JW_ITEM = 2 };

void ctn_jw_init(ctn_jw *j, ctn_wbuf *out, int pretty)
{
    memset(j, 0, sizeof *j);
    j->out = out;
    j->pretty = pretty;
}

static const char *named_escape(unsigned char c)
{
    switch (c) {
    case '"': return "\\\"";
    case '\\': return "\\\\";
    case '\b': return "\\b";
    case '\f': return "\\f";
    case '\n': return "\\n";
    case '\r': return "\\r";
    case '\t': return "\\t";
    default: return NULL;
    }
}

/* A string as cJSON's print_string_ptr escapes it: \" \\ \b \f \n \r \t, other bytes
 * below 32 as \u00xx, everything else (UTF-8 included) as it is. */
static void put_string(ctn_wbuf *b, const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    ctn_wbuf_putc(b, '"');
    for (;;) {
        const unsigned char *run = p;
        while (*p > 31 && *p != '"' && *p != '\\') p++;
        ctn_wbuf_write(b, (const char *)run, (size_t)(p - run));
        if (!*p) break;
        const char *esc = named_escape(*p);
        char u[8];
        if (!esc) {
            snprintf(u, sizeof u, "\\u%04x", *p);
            esc = u;
        }
        ctn_wbuf_puts(b, esc);
        p++;
    }
    ctn_wbuf_putc(b, '"');
}

/* What comes before a value: the separator from the previous item and, in an object,
 * the indentation and the key. */
static void item(ctn_jw *j, const char *key)
{
    unsigned char *st = j->depth ? &j->state[j->depth - 1] : NULL;
    if (st && (*st & JW_ITEM)) {
        if (*st & JW_ARRAY) ctn_wbuf_write(j->out, ", ", j->pretty ? 2 : 1);
        else ctn_wbuf_write(j->out, ",\n", j->pretty ? 2 : 1);
    }
    if (st) *st |= JW_ITEM;
    if (!key) return;
    if (j->pretty) ctn_wbuf_fill(j->out, '\t', (size_t)j->depth);
    put_string(j->out, key);
    ctn_wbuf_write(j->out, ":\t", j->pretty ? 2 : 1);
}

static void open_container(ctn_jw *j, const char *key, int array)
{
    item(j, key);
    if (j->depth == CTN_JW_DEPTH) {                 /* deeper than any result */
        if (!j->out->err) j->out->err = ctn_error(j->out->ctx, CTN_ERR_INVALID, "JSON nested too deep");
        return;
    }
    j->state[j->depth++] = array ? JW_ARRAY : 0;
    if (array) ctn_wbuf_putc(j->out, '[');
    else ctn_wbuf_write(j->out, "{\n", j->pretty ? 2 : 1);
}

void ctn_jw_object(ctn_jw *j, const char *key) { open_container(j, key, 0); }
void ctn_jw_array(ctn_jw *j, const char *key) { open_container(j, key, 1); }

void ctn_jw_end(ctn_jw *j)
{
    if (!j->depth) return;
    unsigned char st = j->state[--j->depth];
    if (st & JW_ARRAY) {
        ctn_wbuf_putc(j->out, ']');
        return;
    }
    if (j->pretty) {
        if (st & JW_ITEM) ctn_wbuf_putc(j->out, '\n');
        ctn_wbuf_fill(j->out, '\t', (size_t)j->depth);
    }
    ctn_wbuf_putc(j->out, '}');
}

void ctn_jw_number(ctn_jw *j, const char *key, double v)
{
    item(j, key);
    ctn_wbuf_cjson(j->out, v);
}

void ctn_jw_string(ctn_jw *j, const char *key, const char *s)
{
    item(j, key);
    put_string(j->out, s ? s : "");
}

void ctn_jw_bool(ctn_jw *j, const char *key, int b)
{
    item(j, key);
    ctn_wbuf_puts(j->out, b ? "true" : "false");
}
