/* buckling.csv: one row per factor of the solution's buckling analysis (docs/format.md),
 * numbers as "%.17g", C locale. Written into a result directory only when there are
 * buckling factors. */
#include "io/writer.h"

#include "catena/analysis.h"

static int buckling_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    ctn_writer *w = p;
    int rc = ctn_writer_open(w, m, sink);
    if (!rc) ctn_wbuf_puts(&w->out, "mode,factor,node,residual\n");
    return w->out.err;
}

/* The factors belong to the last step: written once, at it. */
static int buckling_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    if (k + 1 < ctn_solution_step_count(s)) return CTN_OK;
    for (size_t i = 0; i < ctn_solution_buckling_count(s) && !w->out.err; i++) {
        ctn_buckling_mode b;
        if (ctn_solution_buckling(s, i, &b)) return ctn_writer_mismatch(w);
        ctn_wbuf_int(&w->out, (int)i + 1);
        ctn_wbuf_putc(&w->out, ',');
        ctn_wbuf_g17(&w->out, b.factor);
        ctn_wbuf_putc(&w->out, ',');
        ctn_wbuf_int(&w->out, b.node);
        ctn_wbuf_putc(&w->out, ',');
        ctn_wbuf_g17(&w->out, b.residual);
        ctn_wbuf_putc(&w->out, '\n');
    }
    return w->out.err;
}

static int buckling_end(void *p)
{
    ctn_writer *w = p;
    return w->out.err;
}

const ctn_writer_ops ctn_writer_buckling_csv = { "buckling.csv", sizeof(ctn_writer), buckling_begin, buckling_step,
                                                 buckling_end };
