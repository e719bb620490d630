/* Whole-text helpers for tools that walk a model file's lines themselves (the form-finding
 * writer copies a model line by line): read a file whole, find a line's end, split a line
 * into tokens by the reader's rules. The reader itself scans in chunks (reader.c, scan.c). */
#include "io/parse.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#define CTN_MAX_FILE ((size_t)1 << 31)

int ctn_read_tokenize(ctn_line *l, char *s)
{
    size_t pos = 0;
    return ctn_parse_scan_line(l, s, strlen(s), &pos);     /* the reader's own rules */
}

size_t ctn_read_line_end(const char *text, size_t start, size_t len, size_t *next)
{
    size_t i = start;
    while (i < len && text[i] != '\n' && text[i] != '\r') i++;
    *next = i + (i + 1 < len && text[i] == '\r' && text[i + 1] == '\n' ? 2 : 1);
    return i;
}


int ctn_read_all(ctn_ctx *ctx, const char *path, char **data, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return ctn_error(ctx, CTN_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    ctn_ctx_note_input(ctx, fileno(f));
    size_t cap = 1 << 16, n = 0;
    char *buf = ctn_malloc(ctx, cap, 1);
    int rc = buf ? CTN_OK : CTN_ERR_NOMEM;
    while (!rc) {
        if (n == cap) {
            char *p = cap >= CTN_MAX_FILE ? NULL : ctn_realloc(ctx, buf, cap * 2, 1);
            if (!p) { rc = cap >= CTN_MAX_FILE ? ctn_error(ctx, CTN_ERR_IO, "%s: file larger than 2 GiB", path) : CTN_ERR_NOMEM; break; }
            buf = p;
            cap *= 2;
        }
        size_t k = fread(buf + n, 1, cap - n, f);
        n += k;
        if (k == 0) {
            if (ferror(f)) rc = ctn_error(ctx, CTN_ERR_IO, "%s: read error (is it a directory?)", path);
            break;
        }
    }
    fclose(f);
    if (rc) { ctn_free(buf); return rc; }
    *data = buf;
    *len = n;
    return CTN_OK;
}

