/* Data files of the figures: a '#' header and rows of %.17g numbers. */
#include "plot/plot_int.h"
#include "catena/io.h"
#include "catena/plot.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int ctn_plot_name_ok(const char *name)
{
    if (!name || !*name || *name == '.') return 0;
    for (const char *p = name; *p; p++)
        if (*p == '/' || *p == '"' || *p == '\'' || *p == '\\' || isspace((unsigned char)*p) ||
            iscntrl((unsigned char)*p))
            return 0;
    return 1;
}

int ctn_plot_flush(ctn_ctx *ctx, const char *dir, const char *file, ctn_strbuf *b)
{
    if (b->err) return ctn_error(ctx, b->err, "out of memory writing %s", file);
    size_t len = strlen(dir) + strlen(file) + 2;
    char *path = ctn_malloc(ctx, len, 1);
    if (!path) return CTN_ERR_NOMEM;
    snprintf(path, len, "%s/%s", dir, file);
    int rc = ctn_write_file_atomic(ctx, path, b->s ? b->s : "", b->n);
    ctn_free(path);
    return rc;
}

int ctn_plot_mkdir(ctn_ctx *ctx, const char *dir)
{
    if (!dir || !*dir) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_plot_mkdir: no directory given");
    struct stat st;
    if (mkdir(dir, 0755) && errno != EEXIST)
        return ctn_error(ctx, CTN_ERR_IO, "%s: cannot create directory: %s", dir, strerror(errno));
    if (stat(dir, &st) || !S_ISDIR(st.st_mode))
        return ctn_error(ctx, CTN_ERR_IO, "%s: not a directory", dir);
    return CTN_OK;
}

/* Header lines, each prefixed with "# ". */
static void put_header(ctn_strbuf *b, const char *header)
{
    const char *p = header ? header : "";
    while (*p) {
        size_t k = strcspn(p, "\n");
        ctn_sb_printf(b, "# %.*s\n", (int)k, p);
        p += k + (p[k] == '\n');
    }
}

int ctn_plot_write_data(ctn_ctx *ctx, const char *dir, const char *file, const char *header,
                        size_t ncol, size_t nrow, const double *data)
{
    if (!dir || !ctn_plot_name_ok(file) || ncol == 0 || (nrow && !data))
        return ctn_error(ctx, CTN_ERR_INVALID, "ctn_plot_write_data: bad arguments (file '%s')",
                         file ? file : "(null)");
    for (size_t i = 0; i < ncol * nrow; i++)
        if (!isfinite(data[i]))
            return ctn_error(ctx, CTN_ERR_INVALID, "%s: row %zu holds a NaN or Inf; not written",
                             file, i / ncol + 1);
    ctn_strbuf b = { ctx, NULL, 0, 0, 0 };
    put_header(&b, header);
    for (size_t r = 0; r < nrow; r++)
        for (size_t c = 0; c < ncol; c++)
            ctn_sb_printf(&b, "%.17g%c", data[r * ncol + c], c + 1 < ncol ? ' ' : '\n');
    int rc = ctn_plot_flush(ctx, dir, file, &b);
    ctn_sb_free(&b);
    return rc;
}
