/* modes.csv: one row per mode of the solution's modal analysis (docs/format.md), numbers
 * as "%.17g", C locale. Written into a result directory only when there are modes. */
#include "io/writer.h"

static int modes_begin(void *p, const ctn_model *m, ctn_sink *sink)
{
    ctn_writer *w = p;
    int rc = ctn_writer_open(w, m, sink);
    if (!rc) ctn_wbuf_puts(&w->out, "mode,kind,frequency,period,angular_frequency,eigenvalue,participation_x,"
                                    "participation_y,participation_z,effective_mass_x,effective_mass_y,"
                                    "effective_mass_z,node\n");
    return w->out.err;
}

static void mode_row(ctn_wbuf *b, size_t k, const ctn_mode *md)
{
    double v[10] = { md->frequency, md->period, md->angular_frequency, md->eigenvalue, md->participation[0],
                     md->participation[1], md->participation[2], md->effective_mass[0], md->effective_mass[1],
                     md->effective_mass[2] };
    ctn_wbuf_int(b, (int)k + 1);
    ctn_wbuf_putc(b, ',');
    ctn_wbuf_puts(b, ctn_mode_kind_name(md->kind));
    for (int i = 0; i < 10; i++) {
        ctn_wbuf_putc(b, ',');
        ctn_wbuf_g17(b, v[i]);
    }
    ctn_wbuf_putc(b, ',');
    ctn_wbuf_int(b, md->node);
    ctn_wbuf_putc(b, '\n');
}

/* The modes belong to the last step: written once, at it. */
static int modes_step(void *p, const ctn_solution *s, size_t k)
{
    ctn_writer *w = p;
    if (k + 1 < ctn_solution_step_count(s)) return CTN_OK;
    for (size_t i = 0; i < ctn_solution_mode_count(s) && !w->out.err; i++) {
        ctn_mode md;
        if (ctn_solution_mode(s, i, &md)) return ctn_writer_mismatch(w);
        mode_row(&w->out, i, &md);
    }
    return w->out.err;
}

static int modes_end(void *p)
{
    ctn_writer *w = p;
    return w->out.err;
}

const ctn_writer_ops ctn_writer_modes_csv = { "modes.csv", sizeof(ctn_writer), modes_begin, modes_step, modes_end };
