/*
 * catena/plot.h - figures as gnuplot scripts and data files.
 *
 * catena draws nothing itself: a figure is a data file per curve (whitespace-separated
 * columns, numbers printed with %.17g, '#' comment header) and a gnuplot script NAME.gp
 * that reads them and writes NAME.svg. Both are plain text the user may edit and re-run:
 *
 *     cd DIR && gnuplot NAME.gp                   # NAME.svg
 *     cd DIR && gnuplot -e "fmt='png'" NAME.gp    # NAME.png (pngcairo terminal)
 *     cd DIR && gnuplot -e "fmt='pdf'" NAME.gp    # NAME.pdf (pdfcairo terminal)
 *
 * ctn_plot_render() runs gnuplot on a script when gnuplot is installed (gnuplot-nox on
 * Debian) and reports, without failing, when it is not. Every file is written
 * atomically (ctn_write_file_atomic). File names are plain names, not paths: they may
 * not contain '/', quotes or white space (CTN_ERR_INVALID).
 */
#ifndef CATENA_PLOT_H
#define CATENA_PLOT_H

#include <stddef.h>

#include "catena/core.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* How a curve is drawn. */
typedef enum ctn_plot_style {
    CTN_PLOT_LINES = 0,       /* solid line */
    CTN_PLOT_DASHED = 1,      /* dashed line */
    CTN_PLOT_POINTS = 2,      /* markers only */
    CTN_PLOT_LINESPOINTS = 3  /* line with markers */
} ctn_plot_style;

/* One curve of a figure: columns xcol, ycol (1-based) of a data file. */
typedef struct ctn_plot_series {
    const char *data;        /* data file name, in the script's directory */
    int xcol, ycol;          /* columns, >= 1 */
    const char *title;       /* legend entry (gnuplot enhanced text); "" or NULL: none */
    ctn_plot_style style;
    int color;               /* 1-based index into catena's palette (8 colours, cycling) */
} ctn_plot_series;

/* A figure: axes, labels and its curves. */
typedef struct ctn_plot_figure {
    const char *name;        /* base name: NAME.gp renders NAME.svg */
    const char *title;       /* figure title; NULL or "": none */
    const char *xlabel;      /* axis labels, with units, e.g. "x [m]" */
    const char *ylabel;
    int logx, logy;          /* 1: logarithmic axis */
    const char *key;         /* legend placement in gnuplot words ("top right", "bottom
                                left", ...); NULL: "top right" */
    const char *extra;       /* further gnuplot commands placed before `plot` (one per
                                line, e.g. "set yrange [0:*]"); NULL: none */
    size_t nseries;
    const ctn_plot_series *series;
} ctn_plot_figure;

/* Write DIR/NAME.gp for the figure. dir must exist. */
int ctn_plot_write_script(ctn_ctx *ctx, const char *dir, const ctn_plot_figure *fig);

/* Write DIR/FILE: a comment header (header, may hold several lines separated by '\n';
 * each gets a leading "# "), then nrow rows of ncol numbers from data (row-major).
 * A non-finite number is refused (CTN_ERR_INVALID, nothing written). */
int ctn_plot_write_data(ctn_ctx *ctx, const char *dir, const char *file, const char *header,
                        size_t ncol, size_t nrow, const double *data);

/* Create directory dir if it does not exist (one level). */
int ctn_plot_mkdir(ctn_ctx *ctx, const char *dir);

/* Run `gnuplot NAME.gp` in directory dir. *rendered = 1 when gnuplot ran and succeeded;
 * 0 when no gnuplot program is on the PATH (not an error: the script and its data are
 * there to render later). A gnuplot that runs and fails gives CTN_ERR_IO. The program
 * can be overridden by the environment variable CATENA_GNUPLOT (a program name or path). */
int ctn_plot_render(ctn_ctx *ctx, const char *dir, const char *name, int *rendered);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
