/* include FILE: the lines of another model file read in place of the include line
 * (docs/format.md). The path is relative to the including file's directory; a file that
 * includes itself, directly or through others, is an error naming the chain. */
#define _XOPEN_SOURCE 700   /* realpath */
#include "io/deck.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define CTN_INCLUDE_DEPTH 32

/* dir(of) + "/" + name, or name when it is absolute or `of` has no directory. */
static int resolve(const char *of, const char *name, char *out, size_t size)
{
    const char *slash = strrchr(of, '/');
    int n = name[0] == '/' || !slash ? snprintf(out, size, "%s", name)
                                     : snprintf(out, size, "%.*s/%s", (int)(slash - of), of, name);
    return n >= 0 && (size_t)n < size;
}

/* "a.cable -> b.cable -> a.cable": the chain from the top file to path. */
static void chain(const ctn_line *l, const ctn_incl *top, const char *path, char *buf, size_t size)
{
    const ctn_incl *v[CTN_INCLUDE_DEPTH + 2];
    int n = 0;
    for (const ctn_incl *p = top; p && n < CTN_INCLUDE_DEPTH + 1; p = p->up) v[n++] = p;
    size_t len = 0;
    buf[0] = '\0';
    for (int i = n - 1; i >= 0 && len < size; i--)
        len += (size_t)snprintf(buf + len, size - len, "%.200s -> ", v[i]->path);
    if (len < size) snprintf(buf + len, size - len, "%.200s", path);
    (void)l;
}

/* Read path's lines with l as the reader, the chain extended by `self`. */
static int read_into(ctn_line *l, const char *path, ctn_incl *self)
{
    char *data = NULL, *text = NULL;
    size_t len = 0;
    ctn_ctx *ctx = l->m->ctx;
    if (ctn_read_all(ctx, path, &data, &len)) {
        char msg[CTN_MSG_MAX];
        snprintf(msg, sizeof msg, "%s", ctn_ctx_message(ctx));
        return ctn_parse_error(l, "include: %s", msg);
    }
    text = ctn_malloc(ctx, len + 1, 1);
    if (!text) {
        ctn_free(data);
        return CTN_ERR_NOMEM;
    }
    if (len) memcpy(text, data, len);
    text[len] = '\0';
    ctn_free(data);
    const char *file = NULL;
    if (ctn_deck_keep(ctx, l->deck, text) || ctn_deck_file(ctx, l->deck, path, &file)) return CTN_ERR_NOMEM;
    size_t skip = len >= 3 && !memcmp(text, "\xef\xbb\xbf", 3) ? 3 : 0;
    ctn_line saved = *l;
    l->file = file;
    l->line = 1;
    l->incl = self;
    int rc = ctn_parse_lines(l, text + skip, len - skip);
    l->file = saved.file;
    l->line = saved.line;
    l->incl = saved.incl;
    return rc;
}

int ctn_parse_include(ctn_line *l)
{
    int rc = ctn_parse_positional(l, 1, "include FILE");
    if (!rc) rc = ctn_parse_leftovers(l, 2, "include");
    if (rc) return rc;
    char path[PATH_MAX], real[PATH_MAX], topreal[PATH_MAX], names[1024];
    if (!resolve(l->file, l->tok[1], path, sizeof path)) return ctn_parse_error(l, "include: path too long");
    struct stat st;
    if (!realpath(path, real) || stat(real, &st))
        return ctn_parse_error(l, "include: cannot open '%.200s': %s", path, strerror(errno));
    if (!S_ISREG(st.st_mode)) return ctn_parse_error(l, "include: '%.200s' is not a regular file", path);
    ctn_incl top = { l->file, topreal, 0, NULL };           /* the top file, when this is it */
    const ctn_incl *up = l->incl;
    if (!up) {
        if (!realpath(l->file, topreal)) topreal[0] = '\0';
        up = &top;
    }
    int depth = 0;
    for (const ctn_incl *p = up; p; p = p->up, depth++)
        if (!strcmp(p->real, real)) {
            chain(l, up, path, names, sizeof names);
            return ctn_parse_error(l, "include: a cycle of includes: %s", names);
        }
    if (depth > CTN_INCLUDE_DEPTH) return ctn_parse_error(l, "include: nested more than %d deep", CTN_INCLUDE_DEPTH);
    ctn_incl self = { path, real, l->line, up };
    return read_into(l, path, &self);
}
