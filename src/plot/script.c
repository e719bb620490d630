/* gnuplot scripts of the figures: a terminal preamble the user may edit, the axes,
 * then one `plot` with a clause per curve. */
#include "plot/plot_int.h"
#include "catena/plot.h"

#include <stdio.h>
#include <string.h>

/* Okabe-Ito colours (distinguishable with colour-blindness), yellow replaced by grey. */
static const char *const palette[8] = { "#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                        "#E69F00", "#56B4E9", "#000000", "#777777" };

/* A gnuplot double-quoted string: backslash and quote escaped. */
static void put_quoted(ctn_strbuf *b, const char *s)
{
    ctn_sb_printf(b, "\"");
    for (const char *p = s ? s : ""; *p; p++) {
        if (*p == '"' || *p == '\\') ctn_sb_printf(b, "\\%c", *p);
        else if (*p == '\n') ctn_sb_printf(b, "\\n");
        else ctn_sb_printf(b, "%c", *p);
    }
    ctn_sb_printf(b, "\"");
}

static void put_terminal(ctn_strbuf *b, const ctn_plot_figure *f)
{
    ctn_sb_printf(b,
        "# catena figure '%s'. Render it in this directory:\n"
        "#     gnuplot %s.gp                   -> %s.svg\n"
        "#     gnuplot -e \"fmt='png'\" %s.gp    -> %s.png (or fmt='pdf')\n"
        "# Edit freely: terminal, sizes, fonts, colours, ranges, titles.\n"
        "if (!exists(\"fmt\")) fmt = \"svg\"\n"
        "if (fmt eq \"png\") {\n"
        "    set terminal pngcairo size 1200,800 enhanced font \"Sans,20\" linewidth 2\n"
        "} else {\n"
        "    if (fmt eq \"pdf\") {\n"
        "        set terminal pdfcairo size 15cm,10cm enhanced font \"Sans,10\"\n"
        "    } else {\n"
        "        set terminal svg size 900,600 dynamic enhanced font \"Sans,16\" linewidth 1.5 background \"white\"\n"
        "    }\n"
        "}\n"
        "set output \"%s.\".fmt\n"
        "set encoding utf8\n",
        f->name, f->name, f->name, f->name, f->name, f->name);
}

static void put_axes(ctn_strbuf *b, const ctn_plot_figure *f)
{
    if (f->title && *f->title) { ctn_sb_printf(b, "set title "); put_quoted(b, f->title); ctn_sb_printf(b, "\n"); }
    ctn_sb_printf(b, "set xlabel ");
    put_quoted(b, f->xlabel);
    ctn_sb_printf(b, "\nset ylabel ");
    put_quoted(b, f->ylabel);
    ctn_sb_printf(b, "\nset grid\nset key %s box opaque samplen 3 spacing 1.2\n", f->key ? f->key : "top right");
    if (f->logx) ctn_sb_printf(b, "set logscale x\nset format x \"10^{%%L}\"\n");
    if (f->logy) ctn_sb_printf(b, "set logscale y\nset format y \"10^{%%L}\"\n");
    for (int i = 0; i < 8; i++)
        ctn_sb_printf(b, "set linetype %d linecolor rgb \"%s\" linewidth 2 pointtype 7 pointsize 1\n",
                      i + 1, palette[i]);
    if (f->extra && *f->extra) ctn_sb_printf(b, "%s\n", f->extra);
}

static void put_series(ctn_strbuf *b, const ctn_plot_series *s, int last)
{
    static const char *const with[4] = { "lines dashtype 1", "lines dashtype 2",
                                         "points pointtype 7 pointsize 1.2",
                                         "linespoints pointtype 7 pointsize 0.6" };
    int c = s->color > 0 ? (s->color - 1) % 8 + 1 : 1;
    ctn_sb_printf(b, "    \"%s\" using %d:%d with %s linetype %d title ", s->data, s->xcol, s->ycol,
                  with[s->style], c);
    put_quoted(b, s->title);
    ctn_sb_printf(b, "%s\n", last ? "" : ", \\");
}

static int check_figure(ctn_ctx *ctx, const ctn_plot_figure *f)
{
    if (!f || !ctn_plot_name_ok(f->name) || !f->nseries || !f->series)
        return ctn_error(ctx, CTN_ERR_INVALID, "ctn_plot_write_script: bad figure");
    for (size_t i = 0; i < f->nseries; i++) {
        const ctn_plot_series *s = &f->series[i];
        if (!ctn_plot_name_ok(s->data) || s->xcol < 1 || s->ycol < 1 ||
            s->style < CTN_PLOT_LINES || s->style > CTN_PLOT_LINESPOINTS)
            return ctn_error(ctx, CTN_ERR_INVALID, "figure %s: bad curve %zu", f->name, i + 1);
    }
    return CTN_OK;
}

int ctn_plot_write_script(ctn_ctx *ctx, const char *dir, const ctn_plot_figure *f)
{
    if (!dir) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_plot_write_script: no directory");
    int rc = check_figure(ctx, f);
    if (rc) return rc;
    ctn_strbuf b = { ctx, NULL, 0, 0, 0 };
    put_terminal(&b, f);
    put_axes(&b, f);
    ctn_sb_printf(&b, "plot \\\n");
    for (size_t i = 0; i < f->nseries; i++) put_series(&b, &f->series[i], i + 1 == f->nseries);
    size_t len = strlen(f->name) + 4;
    char file[80];
    if (len > sizeof file) rc = ctn_error(ctx, CTN_ERR_INVALID, "figure name too long");
    else {
        snprintf(file, sizeof file, "%s.gp", f->name);
        rc = ctn_plot_flush(ctx, dir, file, &b);
    }
    ctn_sb_free(&b);
    return rc;
}
