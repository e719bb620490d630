/* The closed forms of a single cable (catena/analytic.h) for catena.analytic:
 *   catenary(l, h, w, S, x)        inextensible catenary
 *   ecatenary(l, h, w, EA, L0, x)  elastic catenary (Irvine)
 *   parabola(l, h, q, L0, EA, x)   parabolic cable
 * each -> dict of the summary and, at the abscissae of the buffer x (doubles), the height
 * y(x) and the tension T(x) as Arrays (one C loop). */
#include "pycatena.h"

typedef int (*eval_fn)(const void *sol, double x, double *v);

static PyObject *summary(const ctn_analytic_summary *s, PyObject *y, PyObject *T)
{
    return Py_BuildValue("{s:d,s:(dd),s:(dd),s:d,s:d,s:d,s:d,s:d,s:d,s:d,s:d,s:d,s:N,s:N}", "H", s->H,
                         "reaction_left", s->reaction_left[0], s->reaction_left[1], "reaction_right",
                         s->reaction_right[0], s->reaction_right[1], "sag", s->sag, "x_sag", s->x_sag, "sag_mid",
                         s->sag_mid, "length", s->length, "length0", s->length0, "T_max", s->T_max, "x_T_max",
                         s->x_T_max, "T_min", s->T_min, "x_T_min", s->x_T_min, "y", y, "T", T);
}

/* y and T at every x of the buffer xs; NULL with an exception on failure. */
static int curve(pyctn_state *st, PyObject *xs, const void *sol, eval_fn fy, eval_fn fT, PyObject **y, PyObject **T)
{
    Py_buffer b;
    *y = *T = NULL;
    if (PyObject_GetBuffer(xs, &b, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT)) return -1;
    Py_ssize_t n = b.len / (Py_ssize_t)sizeof(double);
    int rc = 0;
    if (b.itemsize != sizeof(double) || !b.format || (b.format[0] != 'd' && b.format[0] != '=' && b.format[0] != '<')) {
        PyErr_SetString(PyExc_TypeError, "x: a contiguous float64 array was expected");
        rc = -1;
    }
    pyctn_array *ay = rc ? NULL : pyctn_array_new(st, NULL, NULL, "d", 1, &n);
    pyctn_array *aT = ay ? pyctn_array_new(st, NULL, NULL, "d", 1, &n) : NULL;
    if (!aT) rc = -1;
    for (Py_ssize_t i = 0; !rc && i < n; i++) {
        double x = ((const double *)b.buf)[i];
        int e = fy(sol, x, (double *)ay->data + i);
        if (!e) e = fT(sol, x, (double *)aT->data + i);
        if (e) {
            pyctn_raise_msg(st, e, "x out of [0, l] or not finite");
            rc = -1;
        }
    }
    PyBuffer_Release(&b);
    if (rc) {
        Py_XDECREF(ay);
        Py_XDECREF(aT);
        return -1;
    }
    *y = (PyObject *)ay;
    *T = (PyObject *)aT;
    return 0;
}

static PyObject *finish(pyctn_state *st, ctn_ctx *ctx, int rc, PyObject *xs, const void *sol,
                        const ctn_analytic_summary *s, eval_fn fy, eval_fn fT, PyObject *extra)
{
    PyObject *y = NULL, *T = NULL, *d = NULL;
    if (rc) pyctn_raise(st, ctx, rc);
    else if (!curve(st, xs, sol, fy, fT, &y, &T)) d = summary(s, y, T);
    if (d && extra && PyDict_Update(d, extra)) Py_CLEAR(d);
    Py_XDECREF(extra);
    ctn_ctx_destroy(&ctx);
    return d;
}

static int cat_y(const void *s, double x, double *v) { return ctn_catenary_y(s, x, v); }
static int cat_T(const void *s, double x, double *v) { return ctn_catenary_tension(s, x, v); }
static int ecat_y(const void *s, double x, double *v) { return ctn_ecatenary_y(s, x, v); }
static int ecat_T(const void *s, double x, double *v) { return ctn_ecatenary_tension(s, x, v); }
static int par_y(const void *s, double x, double *v) { return ctn_parabola_y(s, x, v); }
static int par_T(const void *s, double x, double *v) { return ctn_parabola_tension(s, x, v); }

PyObject *pyctn_catenary(PyObject *module, PyObject *args)
{
    ctn_catenary_in in;
    ctn_catenary out;
    ctn_ctx *ctx = NULL;
    PyObject *xs;
    if (!PyArg_ParseTuple(args, "ddddO", &in.l, &in.h, &in.w, &in.S, &xs)) return NULL;
    if (ctn_ctx_create(&ctx)) return PyErr_NoMemory();
    int rc = ctn_catenary_solve(ctx, &in, &out);
    return finish(pyctn_state_of(module), ctx, rc, xs, &out, &out.sum, cat_y, cat_T,
                  rc ? NULL : Py_BuildValue("{s:d,s:d}", "c", out.c, "x_vertex", out.x_vertex));
}

PyObject *pyctn_ecatenary(PyObject *module, PyObject *args)
{
    ctn_ecatenary_in in;
    ctn_ecatenary out;
    ctn_ctx *ctx = NULL;
    PyObject *xs;
    if (!PyArg_ParseTuple(args, "dddddO", &in.l, &in.h, &in.w, &in.EA, &in.L0, &xs)) return NULL;
    if (ctn_ctx_create(&ctx)) return PyErr_NoMemory();
    int rc = ctn_ecatenary_solve(ctx, &in, &out);
    return finish(pyctn_state_of(module), ctx, rc, xs, &out, &out.sum, ecat_y, ecat_T,
                  rc ? NULL : Py_BuildValue("{s:d,s:d}", "V_left", out.V_left, "V_right", out.V_right));
}

PyObject *pyctn_parabola(PyObject *module, PyObject *args)
{
    ctn_parabola_in in;
    ctn_parabola out;
    ctn_ctx *ctx = NULL;
    PyObject *xs;
    if (!PyArg_ParseTuple(args, "dddddO", &in.l, &in.h, &in.q, &in.L0, &in.EA, &xs)) return NULL;
    if (ctn_ctx_create(&ctx)) return PyErr_NoMemory();
    int rc = ctn_parabola_solve(ctx, &in, &out);
    return finish(pyctn_state_of(module), ctx, rc, xs, &out, &out.sum, par_y, par_T, NULL);
}
