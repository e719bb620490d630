/* The .cable reader: file to memory, lines to tokens, tokens to directives. Lines end in
 * LF, CRLF or a lone CR. Numbers are parsed in the C locale whatever the caller's
 * locale is. */
#include "io/parse.h"
#include "catena/io.h"

#include <errno.h>
#include <locale.h>
#include <stdio.h>
#include <string.h>

#define CTN_MAX_FILE ((size_t)1 << 31)

int ctn_read_tokenize(ctn_line *l, char *s)
{
    char *hash = strchr(s, '#');
    if (hash) *hash = '\0';
    l->ntok = 0;
    l->used = 0;
    char *save = NULL;
    for (char *p = strtok_r(s, " \t\r\v\f", &save); p; p = strtok_r(NULL, " \t\r\v\f", &save)) {
        if (l->ntok == CTN_MAX_TOKENS)
            return ctn_parse_error(l, "too many fields on one line (more than %d)", CTN_MAX_TOKENS);
        l->tok[l->ntok++] = p;
    }
    return CTN_OK;
}

size_t ctn_read_line_end(const char *text, size_t start, size_t len, size_t *next)
{
    size_t i = start;
    while (i < len && text[i] != '\n' && text[i] != '\r') i++;
    *next = i + (i + 1 < len && text[i] == '\r' && text[i + 1] == '\n' ? 2 : 1);
    return i;
}

static int parse_text(ctn_model *m, ctn_solve_options *opt, const char *name, char *text, size_t len)
{
    ctn_line l;
    memset(&l, 0, sizeof l);
    l.m = m;
    l.opt = opt;
    l.file = name;
    size_t start = len >= 3 && !memcmp(text, "\xef\xbb\xbf", 3) ? 3 : 0;   /* UTF-8 BOM */
    for (l.line = 1; start < len || (start == len && l.line == 1); l.line++) {
        size_t next, end = ctn_read_line_end(text, start, len, &next);
        if (memchr(text + start, '\0', end - start))
            return ctn_parse_error(&l, "binary data (a NUL byte) in the model file");
        text[end] = '\0';
        int rc = ctn_read_tokenize(&l, text + start);
        if (!rc && l.ntok) {
            ctn_model_set_origin(m, name, l.line);
            rc = ctn_parse_directive(&l);
            if (rc == CTN_ERR_NOMEM) {                  /* say where it ran out */
                char msg[CTN_MSG_MAX];
                snprintf(msg, sizeof msg, "%s", ctn_ctx_message(m->ctx));
                ctn_error_at(m->ctx, rc, name, l.line, "%s", msg);
            }
        }
        if (rc) return rc;
        if (end == len) break;
        start = next;
    }
    ctn_model_set_origin(m, name, 0);
    return CTN_OK;
}

int ctn_read_string(ctn_ctx *ctx, const char *name, const char *text, size_t len,
                    ctn_model **out, ctn_solve_options *opt)
{
    if (!out || (!text && len)) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_read_string: bad arguments");
    *out = NULL;
    ctn_solve_options own;
    ctn_solve_options_default(opt ? opt : &own);
    ctn_model *m = NULL;
    char *buf = ctn_malloc(ctx, len + 1, 1);
    if (!buf) return CTN_ERR_NOMEM;
    if (len) memcpy(buf, text, len);
    buf[len] = '\0';
    int rc = ctn_model_create(ctx, &m);
    if (!rc) {
        locale_t c = newlocale(LC_ALL_MASK, "C", (locale_t)0);
        locale_t old = c ? uselocale(c) : (locale_t)0;
        rc = parse_text(m, opt ? opt : &own, name ? name : "<string>", buf, len);
        if (c) {
            uselocale(old);
            freelocale(c);
        }
    }
    ctn_free(buf);
    if (rc) ctn_model_destroy(&m);
    *out = m;
    return rc;
}

int ctn_read_all(ctn_ctx *ctx, const char *path, char **data, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return ctn_error(ctx, CTN_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
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

int ctn_model_read_string(ctn_ctx *ctx, const char *name, const char *text, size_t len,
                          ctn_model **out)
{
    return ctn_read_string(ctx, name, text, len, out, NULL);
}

int ctn_read_file(ctn_ctx *ctx, const char *path, ctn_model **out, ctn_solve_options *opt)
{
    if (!path || !out) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_read_file: bad arguments");
    *out = NULL;
    char *data = NULL;
    size_t len = 0;
    int rc = ctn_read_all(ctx, path, &data, &len);
    if (rc) return rc;
    rc = ctn_read_string(ctx, path, data, len, out, opt);
    ctn_free(data);
    return rc;
}

int ctn_model_read_file(ctn_ctx *ctx, const char *path, ctn_model **out)
{
    return ctn_read_file(ctx, path, out, NULL);
}
