/* The writer driver, and the check that no NaN or Inf would reach a file. */
#include "io/json_buckling.h"
#include "io/json_dynamics.h"
#include "io/json_modes.h"
#include "io/writer.h"
#include "catena/io.h"

#include <math.h>

int ctn_writer_open(ctn_writer *w, const ctn_model *m, ctn_sink *sink)
{
    w->m = m;
    return ctn_wbuf_open(&w->out, w->ctx, sink);
}

int ctn_writer_mismatch(ctn_writer *w)
{
    if (!w->out.err) w->out.err = ctn_error(w->ctx, CTN_ERR_INVALID, "the solution does not match the model");
    return w->out.err;
}

int ctn_writer_run(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, ctn_sink *sink,
                   const ctn_model *m, const ctn_solution *s)
{
    size_t n = ctn_solution_step_count(s);
    return ctn_writer_run_step(ctx, ops, pretty, n ? n - 1 : 0, sink, m, s);
}

int ctn_writer_run_step(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, size_t k, ctn_sink *sink,
                        const ctn_model *m, const ctn_solution *s)
{
    return ctn_writer_run_pieces(ctx, ops, pretty, k, &ctn_pieces_local, sink, m, s);
}

/* The driver: step k of s (one-step writers), the installed state base, base_step (or NULL). */
static int run(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, size_t k, const ctn_pieces *pieces,
               ctn_sink *sink, const ctn_model *m, const ctn_solution *s, const ctn_solution *base, size_t base_step)
{
    size_t n = ctn_solution_step_count(s);
    if (!n) return ctn_error(ctx, CTN_ERR_INVALID, "%s: the solution has no step", ops->name);
    if (k >= n) return ctn_error(ctx, CTN_ERR_INVALID, "%s: no step %zu", ops->name, k + 1);
    ctn_writer *w = ctn_calloc(ctx, 1, ops->size);
    if (!w) return CTN_ERR_NOMEM;
    w->ctx = ctx;
    w->pretty = pretty;
    w->step = k;
    w->pieces = pieces;
    w->base = base;
    w->base_step = base_step;
    int rc = ops->begin(w, m, sink);
    for (size_t i = 0; i < n && !rc; i++) rc = ops->step(w, s, i);
    if (!rc) rc = ops->end(w);
    int rc_close = ctn_wbuf_close(&w->out);
    ctn_free(w);
    return rc ? rc : rc_close;
}

int ctn_writer_run_pieces(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, size_t k, const ctn_pieces *pieces,
                          ctn_sink *sink, const ctn_model *m, const ctn_solution *s)
{
    return run(ctx, ops, pretty, k, pieces, sink, m, s, NULL, 0);
}

int ctn_writer_run_case(ctn_ctx *ctx, const ctn_writer_ops *ops, int pretty, ctn_sink *sink, const ctn_model *m,
                        const ctn_solution *s, const ctn_solution *base, size_t base_step)
{
    if (!base || base_step >= ctn_solution_step_count(base))
        return ctn_error(ctx, CTN_ERR_INVALID, "%s: no installed state %zu", ops->name, base_step + 1);
    return run(ctx, ops, pretty, 0, &ctn_pieces_local, sink, m, s, base, base_step);
}

static int all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

static int summary_finite(const ctn_solution *s)
{
    ctn_solve_summary sum;
    size_t n;
    ctn_solution_summary(s, &sum);
    if (!isfinite(sum.fext_norm) || !isfinite(sum.load_factor)) return 0;
    const double *h = ctn_solution_residual_history(s, &n);
    if (!all_finite(h, n)) return 0;
    h = ctn_solution_increment_history(s, &n);
    return all_finite(h, n);
}

/* Step k: its load factor, displacements, reactions (rotations and moments) and element
 * states. */
static int step_finite(const ctn_model *m, const ctn_solution *s, size_t k)
{
    ctn_step_result st;
    size_t nn = ctn_model_node_count(m), ne = ctn_model_element_count(m);
    double mpa = ctn_model_mpa_factor(m);
    if (ctn_solution_step(s, k, &st) || !isfinite(st.load_factor)) return 0;
    if (!all_finite(st.d, 3 * nn) || !all_finite(st.react, 3 * nn)) return 0;
    const double *rot = NULL, *mom = NULL;
    ctn_solution_step_rotations(s, k, &rot, &mom);
    if (rot && (!all_finite(rot, 3 * nn) || !all_finite(mom, 3 * nn))) return 0;
    for (size_t i = 0; i < ne; i++) {
        ctn_element_state e;
        if (ctn_solution_step_element(s, k, i, &e)) return 0;
        double v[5] = { e.length, e.strain, e.force, e.stress, mpa > 0 ? e.stress * mpa : 0 };
        if (!all_finite(v, 5)) return 0;
    }
    return 1;
}

/* The model's numbers in the output: coordinates, l0, cable lengths and sags. */
static int model_finite(const ctn_model *m, const ctn_solution *s)
{
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info p;
        if (ctn_model_node(m, i, &p) || !all_finite(p.X, 3)) return 0;
    }
    for (size_t i = 0; i < ctn_model_element_count(m); i++) {
        ctn_element_info e;
        if (ctn_model_element(m, i, &e) || !isfinite(e.l0)) return 0;
    }
    for (size_t i = 0; i < ctn_model_cable_count(m); i++) {
        ctn_cable_info c;
        double sag = 0;
        if (ctn_model_cable(m, i, &c) || !isfinite(c.length)) return 0;
        if (!ctn_solution_cable_sag(m, s, i, &sag) && !isfinite(sag)) return 0;
    }
    return 1;
}

int ctn_result_check(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s)
{
    int ok = summary_finite(s) && model_finite(m, s) && ctn_modes_finite(m, s) && ctn_buckling_finite(m, s) &&
             ctn_dynamics_finite(s);
    for (size_t k = 0; ok && k < ctn_solution_step_count(s); k++) ok = step_finite(m, s, k);
    return ok ? CTN_OK : ctn_error(ctx, CTN_ERR_INVALID, "the result holds a NaN or Inf; not written");
}
