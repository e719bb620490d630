/* history.csv: the time histories of a dynamics analysis (docs/format.md, "Dynamics"):
 * a header "t,ID.ux,ID.uy,...,ID.force", then one row per time step, t = 0 first;
 * numbers as "%.17g", C locale. Written into a result directory only when the solution
 * has a dynamics analysis. */
#include "io/writer.h"

#include "catena/analysis.h"

static int history_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    ctn_writer *w = p;
    return ctn_writer_open(w, m, sink);
}

/* The histories belong to the last step: written once, at it. */
static int history_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    size_t rows, cols;
    if (k + 1 < ctn_solution_step_count(s)) return CTN_OK;
    const double *h = ctn_solution_history(s, &rows, &cols);
    ctn_wbuf_puts(&w->out, "t");
    for (size_t c = 0; c < cols; c++) {
        ctn_wbuf_putc(&w->out, ',');
        ctn_wbuf_puts(&w->out, ctn_solution_history_name(s, c));
    }
    ctn_wbuf_putc(&w->out, '\n');
    for (size_t r = 0; r < rows && !w->out.err; r++) {
        for (size_t c = 0; c <= cols; c++) {
            if (c) ctn_wbuf_putc(&w->out, ',');
            ctn_wbuf_g17(&w->out, h[r * (cols + 1) + c]);
        }
        ctn_wbuf_putc(&w->out, '\n');
    }
    return w->out.err;
}

static int history_end(void *p)
{
    ctn_writer *w = p;
    return w->out.err;
}

const ctn_writer_ops ctn_writer_history_csv = { "history.csv", sizeof(ctn_writer), history_begin, history_step, history_end };
