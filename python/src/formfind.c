/* _catena.formfind(name, text, out, tol, maxit, interruptible) -> report dict: form
 * finding by force density of the model in text (ctn_read_string, ctn_formfind) and, when
 * it converged, the found model written to out (ctn_formfind_write: the source's lines,
 * rewritten where it changed them). The GIL is released. */
#include "pycatena.h"

static const char *const ff_reasons[] = { "converged", "maximum iterations reached", "stalled" };

static PyObject *report(const ctn_formfind_report *r)
{
    int k = (int)r->reason;
    return Py_BuildValue("{s:O,s:s,s:i,s:i,s:n,s:n,s:d,s:d,s:d,s:d,s:d}", "converged",
                         r->reason == CTN_FF_CONVERGED ? Py_True : Py_False, "reason",
                         k >= 0 && k < 3 ? ff_reasons[k] : "?", "iterations", r->iterations, "factorizations",
                         r->factorizations, "free_nodes", (Py_ssize_t)r->free_nodes, "targets",
                         (Py_ssize_t)r->targets, "force_mismatch", r->force_mismatch, "load_change", r->load_change,
                         "residual", r->residual, "force_min", r->force_min, "force_max", r->force_max);
}

PyObject *pyctn_formfind(PyObject *module, PyObject *args)
{
    pyctn_state *st = pyctn_state_of(module);
    const char *name, *text;
    Py_ssize_t len;
    PyObject *out;
    double tol = -1;
    int maxit = -1, irq_on = 0;
    if (!PyArg_ParseTuple(args, "ss#O&|dip", &name, &text, &len, PyUnicode_FSConverter, &out, &tol, &maxit, &irq_on))
        return NULL;
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_formfind_options opt;
    ctn_formfind_report rep;
    ctn_formfind_options_init(&opt);
    if (tol > 0) opt.tol = tol;
    if (maxit > 0) opt.maxit = maxit;
    if (ctn_ctx_create(&ctx)) {
        Py_DECREF(out);
        return PyErr_NoMemory();
    }
    pyctn_irq q;
    int rc;
    pyctn_irq_begin(&q, ctx, irq_on);
    Py_BEGIN_ALLOW_THREADS
    rc = ctn_read_string(ctx, name, text, (size_t)len, &m, NULL);
    if (!rc) rc = ctn_formfind(ctx, m, &opt, &rep);
    if (!rc && rep.reason == CTN_FF_CONVERGED) rc = ctn_formfind_write(ctx, m, text, (size_t)len, PyBytes_AS_STRING(out));
    Py_END_ALLOW_THREADS
    PyObject *r = NULL;
    if (!pyctn_irq_end(&q, ctx)) r = rc ? pyctn_raise(st, ctx, rc) : report(&rep);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    Py_DECREF(out);
    return r;
}
