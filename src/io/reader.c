/* The .cable reader: the text from a string or a file, whole, to the scanner (scan.c:
 * lines to tokens to the deck), then the deck's directives run (deck.c). Numbers are parsed in the C locale
 * whatever the caller's locale is. */
#include "io/deck.h"
#include "catena/io.h"

#include <errno.h>
#include <locale.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#define CTN_MAX_FILE ((size_t)1 << 31)
#define CTN_READ_CHUNK ((size_t)1 << 18)     /* bytes read at a time: stays in cache */

/* Where the text comes from: a string (text, len) or a file (f, path). */
typedef struct source {
    const char *text;
    size_t len;
    FILE *f;
    const char *path;
} source;

static size_t bom(const char *text, size_t len)
{
    return len >= 3 && !memcmp(text, "\xef\xbb\xbf", 3) ? 3 : 0;   /* UTF-8 BOM */
}

/* A string: copied once (the scanner works in place), the copy kept by the deck. */
static int feed_string(ctn_line *l, const source *src)
{
    char *buf = ctn_malloc(l->m->ctx, src->len + 1, 1);
    if (!buf) return CTN_ERR_NOMEM;
    if (src->len) memcpy(buf, src->text, src->len);
    buf[src->len] = '\0';
    if (ctn_deck_keep(l->m->ctx, l->deck, buf)) return CTN_ERR_NOMEM;
    size_t skip = bom(buf, src->len);
    return ctn_parse_lines(l, buf + skip, src->len - skip);
}

/* Read a chunk into buf[*n .. cap) from the file; *final when the file ended. */
static int fill(ctn_ctx *ctx, const source *src, char *buf, size_t cap, size_t *n, int *final)
{
    size_t want = cap - *n < CTN_READ_CHUNK ? cap - *n : CTN_READ_CHUNK;
    size_t k = fread(buf + *n, 1, want, src->f);
    if (ferror(src->f)) return ctn_error(ctx, CTN_ERR_IO, "%s: read error (is it a directory?)", src->path);
    *n += k;
    *final = k < want;
    if (*n >= CTN_MAX_FILE) return ctn_error(ctx, CTN_ERR_IO, "%s: file larger than 2 GiB", src->path);
    return CTN_OK;
}

/* A file, whole, a chunk at a time (the progress reported after each; the buffer sized
 * for a regular file, else doubled as it fills), then scanned; the deck keeps it. */
static int feed_file(ctn_line *l, const source *src)
{
    ctn_ctx *ctx = l->m->ctx;
    size_t cap = CTN_READ_CHUNK, n = 0;
    struct stat st;
    double size = !fstat(fileno(src->f), &st) && S_ISREG(st.st_mode) ? (double)st.st_size : 0;
    if (size > 0 && size < (double)CTN_MAX_FILE) cap = (size_t)size + 1;   /* one read to the end */
    char *buf = ctn_malloc(ctx, cap + 1, 1);
    int rc = buf ? CTN_OK : CTN_ERR_NOMEM, final = 0;
    while (!rc && !final) {
        if ((rc = fill(ctx, src, buf, cap, &n, &final))) break;
        ctn_progress(ctx, "reading", (double)n, size);
        if ((rc = ctn_interrupted(ctx))) break;
        if (!final && n == cap) {
            char *p = ctn_realloc(ctx, buf, 2 * cap + 1, 1);
            if (!p) rc = CTN_ERR_NOMEM;
            else buf = p, cap *= 2;
        }
    }
    if (rc) {
        ctn_free(buf);
        return rc;
    }
    buf[n] = '\0';
    if (ctn_deck_keep(ctx, l->deck, buf)) return CTN_ERR_NOMEM;
    size_t skip = bom(buf, n);
    return ctn_parse_lines(l, buf + skip, n - skip);
}

/* The lines of src into m, numbered from first_line, in the C locale; the `solve` line
 * into *opt. */
static int read_into(ctn_model *m, const char *name, int first_line, const source *src, ctn_solve_options *opt)
{
    ctn_line l;
    memset(&l, 0, sizeof l);
    l.m = m;
    l.opt = opt;
    l.file = name;
    l.line = first_line;
    locale_t c = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    locale_t old = c ? uselocale(c) : (locale_t)0;
    ctn_deck deck;                    /* read whole, then run definitions first (deck.h) */
    memset(&deck, 0, sizeof deck);
    l.deck = &deck;
    int rc = src->f ? feed_file(&l, src) : feed_string(&l, src);
    if (!rc) rc = ctn_deck_run(&deck, &l);
    ctn_deck_free(&deck);
    if (c) {
        uselocale(old);
        freelocale(c);
    }
    return rc;
}

/* A new model in *out from src, with the solve options in *opt. */
static int read_model(ctn_ctx *ctx, const char *name, const source *src, ctn_model **out,
                      ctn_solve_options *opt)
{
    ctn_solve_options own;
    ctn_solve_options_default(opt ? opt : &own);
    ctn_model *m = NULL;
    int rc = ctn_model_create(ctx, &m);
    if (!rc) rc = ctn_model_set_origin(m, name, 0);
    if (!rc) rc = read_into(m, name, 1, src, opt ? opt : &own);
    if (rc) ctn_model_destroy(&m);
    *out = m;
    return rc;
}

int ctn_read_string_into(ctn_model *m, const char *name, int first_line, const char *text, size_t len,
                         ctn_solve_options *opt)
{
    if (!m || (!text && len) || first_line < 1) return CTN_ERR_INVALID;
    ctn_solve_options own;
    if (!opt) ctn_solve_options_default(opt = &own);
    name = name ? name : "<string>";
    source src = { text, len, NULL, NULL };
    int rc = ctn_model_set_origin(m, name, 0);
    return rc ? rc : read_into(m, name, first_line, &src, opt);
}

int ctn_read_string(ctn_ctx *ctx, const char *name, const char *text, size_t len,
                    ctn_model **out, ctn_solve_options *opt)
{
    if (!out || (!text && len)) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_read_string: bad arguments");
    *out = NULL;
    source src = { text, len, NULL, NULL };
    return read_model(ctx, name ? name : "<string>", &src, out, opt);
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
    FILE *f = fopen(path, "rb");
    if (!f) return ctn_error(ctx, CTN_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    ctn_ctx_note_input(ctx, fileno(f));
    source src = { NULL, 0, f, path };
    int rc = read_model(ctx, path, &src, out, opt);
    fclose(f);
    return rc;
}

int ctn_model_read_file(ctn_ctx *ctx, const char *path, ctn_model **out)
{
    return ctn_read_file(ctx, path, out, NULL);
}
