/* A Model built piece by piece in the order of its .cable text: text through the reader
 * (ctn_read_string_into), node and element rows from arrays through the bulk calls
 * (ctn_model_add_nodes, ctn_model_add_elements), each piece numbered by its first line
 * in the text, so that messages name the line of Model.to_cable(). The arrays come in
 * through the buffer protocol (contiguous int32 'i' or float64 'd'), read in place. */
#include "pycatena.h"

#include <string.h>

/* A contiguous buffer of n items of format fmt ('i' or 'd') of obj; n < 0: any count,
 * set in *n. -1 with an exception set when it is not one. */
static int take(PyObject *obj, Py_buffer *b, char fmt, Py_ssize_t *n, const char *what)
{
    if (PyObject_GetBuffer(obj, b, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT)) return -1;
    size_t fl = b->format ? strlen(b->format) : 0;
    Py_ssize_t size = fmt == 'i' ? (Py_ssize_t)sizeof(int) : (Py_ssize_t)sizeof(double);
    int ok = fl && b->format[fl - 1] == fmt && b->itemsize == size && (*n < 0 || b->len == *n * size);
    if (ok && *n < 0) *n = b->len / size;
    if (ok) return 0;
    PyBuffer_Release(b);
    b->obj = NULL;
    PyErr_Format(PyExc_TypeError, "%s: a contiguous array of %s%s was expected", what,
                 fmt == 'i' ? "int32" : "float64", *n < 0 ? "" : " of the right length");
    return -1;
}

static void release(Py_buffer *b, int count)
{
    for (int k = 0; k < count; k++)
        if (b[k].obj) PyBuffer_Release(&b[k]);
}

/* new_model(name) -> Model: an empty model (its `solve` options the defaults). */
PyObject *pyctn_new_model(PyObject *module, PyObject *args)
{
    const char *name;
    if (!PyArg_ParseTuple(args, "s", &name)) return NULL;
    pyctn_model *self = pyctn_model_alloc(module);
    if (!self) return NULL;
    ctn_solve_options_default(&self->opt);
    int rc = ctn_model_create(self->ctx, &self->m);
    if (!rc) rc = ctn_model_set_origin(self->m, name, 0);
    if (rc) {
        pyctn_raise(pyctn_state_of(module), self->ctx, rc);
        Py_DECREF(self);
        return NULL;
    }
    return (PyObject *)self;
}

/* read_more(name, first_line, text, interruptible): more .cable text into the model. */
PyObject *pyctn_model_read_more(PyObject *op, PyObject *args)
{
    pyctn_model *self = (pyctn_model *)op;
    const char *name, *text;
    Py_ssize_t len;
    int line, irq_on = 0, rc;
    if (!PyArg_ParseTuple(args, "sis#|p", &name, &line, &text, &len, &irq_on)) return NULL;
    pyctn_irq q;
    pyctn_model_lock(self);
    pyctn_irq_begin(&q, self->ctx, irq_on);
    Py_BEGIN_ALLOW_THREADS
    rc = ctn_read_string_into(self->m, name, line, text, (size_t)len, &self->opt);
    Py_END_ALLOW_THREADS
    int hit = pyctn_irq_end(&q, self->ctx);
    PyThread_release_lock(self->lock);
    if (hit || rc) return PyErr_Occurred() ? NULL : pyctn_raise(pyctn_state_of(self->module), self->ctx, rc);
    Py_RETURN_NONE;
}

/* The masses of the rows that have one (the reader sets a node's mass after adding it). */
static int node_masses(ctn_model *m, const char *name, int line, Py_ssize_t n, const int *ids, const double *mass)
{
    int rc = CTN_OK;
    for (Py_ssize_t i = 0; i < n && !rc; i++) {
        if (mass[i] == 0) continue;
        rc = ctn_model_set_origin(m, name, line + (int)i);
        if (!rc) rc = ctn_model_set_node_mass(m, ids[i], mass[i]);
    }
    return rc;
}

/* add_nodes(name, first_line, ids int32 (n,), X float64 (n, 3), fix int32 (n,) | None,
 * mass float64 (n,) | None). */
PyObject *pyctn_model_add_nodes(PyObject *op, PyObject *args)
{
    pyctn_model *self = (pyctn_model *)op;
    const char *name;
    int line, rc;
    PyObject *o[4];
    Py_buffer b[4];
    memset(b, 0, sizeof b);
    if (!PyArg_ParseTuple(args, "siOOOO", &name, &line, &o[0], &o[1], &o[2], &o[3])) return NULL;
    Py_ssize_t n = -1, n3;
    if (take(o[0], &b[0], 'i', &n, "ids") || (n3 = 3 * n, take(o[1], &b[1], 'd', &n3, "X")) ||
        (o[2] != Py_None && take(o[2], &b[2], 'i', &n, "fix")) || (o[3] != Py_None && take(o[3], &b[3], 'd', &n, "mass"))) {
        release(b, 4);
        return NULL;
    }
    pyctn_model_lock(self);
    Py_BEGIN_ALLOW_THREADS
    rc = ctn_model_set_origin(self->m, name, line);
    if (!rc) rc = ctn_model_add_nodes(self->m, (size_t)n, b[0].buf, b[1].buf, b[2].buf);   /* fix: int as unsigned */
    if (!rc && b[3].buf) rc = node_masses(self->m, name, line, n, b[0].buf, b[3].buf);
    ctn_model_set_origin(self->m, name, 0);
    Py_END_ALLOW_THREADS
    PyThread_release_lock(self->lock);
    release(b, 4);
    if (rc) return pyctn_raise(pyctn_state_of(self->module), self->ctx, rc);
    Py_RETURN_NONE;
}

/* A column of add_elements: None (the spec's default), a number (the spec's value for
 * all) or a float64 array of n (*col). */
static int column(PyObject *o, Py_buffer *b, Py_ssize_t n, double *spec_value, const double **col, const char *what)
{
    *col = NULL;
    if (o == Py_None) return 0;
    if (PyFloat_Check(o)) {
        *spec_value = PyFloat_AS_DOUBLE(o);
        return 0;
    }
    if (take(o, b, 'd', &n, what)) return -1;
    *col = b->buf;
    return 0;
}

enum { C_IDS, C_CONN, C_L0, C_VALUE, C_K, C_Q, C_FORCE, C_TARGET, C_ORIENT, C_RELEASE, C_SEGMENTS, C_COUNT };

/* An optional array column of n * per items of format fmt: None or the array (*col). */
static int column_of(PyObject *o, Py_buffer *b, Py_ssize_t n, char fmt, const void **col, const char *what)
{
    *col = NULL;
    if (o == Py_None) return 0;
    if (take(o, b, fmt, &n, what)) return -1;
    *col = b->buf;
    return 0;
}

/* add_elements(name, first_line, type, ids int32 (n,), conn int32 (n, nnodes), nnodes,
 * section | None, group | None, prestress kind (0 none, 1 N0, 2 s0, 3 eps0), l0, value,
 * k, q, force, target kind (0 none, 1 H, 2 sag, 3 tension), target value, orient,
 * release, segments): l0 .. force and the target value each None, a float, or a float64
 * array (n,); orient None or float64 (n, 3); release and segments None or int32 (n,). */
PyObject *pyctn_model_add_elements(PyObject *op, PyObject *args)
{
    pyctn_model *self = (pyctn_model *)op;
    const char *name, *type, *section, *group;
    int line, nnodes, kind, target, rc;
    PyObject *o[C_COUNT];
    Py_buffer b[C_COUNT];
    memset(b, 0, sizeof b);
    o[C_TARGET] = o[C_ORIENT] = o[C_RELEASE] = o[C_SEGMENTS] = Py_None;
    target = 0;
    if (!PyArg_ParseTuple(args, "sisOOizziOOOOO|iOOOO", &name, &line, &type, &o[C_IDS], &o[C_CONN], &nnodes, &section,
                          &group, &kind, &o[C_L0], &o[C_VALUE], &o[C_K], &o[C_Q], &o[C_FORCE], &target, &o[C_TARGET],
                          &o[C_ORIENT], &o[C_RELEASE], &o[C_SEGMENTS]))
        return NULL;
    if (target < 0 || target > 3) {
        PyErr_SetString(PyExc_ValueError, "add_elements: target kind 0..3");
        return NULL;
    }
    ctn_element_spec spec;
    ctn_element_rows rows;
    ctn_element_spec_init(&spec);
    ctn_element_rows_init(&rows);
    spec.type = type;
    spec.nnodes = nnodes;
    spec.section = section;
    spec.group = group;
    spec.prestress = (ctn_prestress)kind;
    spec.target = (ctn_cable_target)target;
    const void *orient = NULL, *rel = NULL, *seg = NULL;
    Py_ssize_t n = -1, nc;
    int bad = take(o[C_IDS], &b[C_IDS], 'i', &n, "ids") ||
              (nc = n * nnodes, take(o[C_CONN], &b[C_CONN], 'i', &nc, "conn")) ||
              column(o[C_L0], &b[C_L0], n, &spec.l0, &rows.l0, "l0") ||
              column(o[C_VALUE], &b[C_VALUE], n, &spec.prestress_value, &rows.prestress_value, "prestress") ||
              column(o[C_K], &b[C_K], n, &spec.k, &rows.k, "k") || column(o[C_Q], &b[C_Q], n, &spec.q, &rows.q, "q") ||
              column(o[C_FORCE], &b[C_FORCE], n, &spec.force, &rows.force, "force") ||
              column(o[C_TARGET], &b[C_TARGET], n, &spec.target_value, &rows.target_value, "target") ||
              column_of(o[C_ORIENT], &b[C_ORIENT], 3 * n, 'd', &orient, "orient") ||
              column_of(o[C_RELEASE], &b[C_RELEASE], n, 'i', &rel, "release") ||
              column_of(o[C_SEGMENTS], &b[C_SEGMENTS], n, 'i', &seg, "segments");
    if (bad) {
        release(b, C_COUNT);
        return NULL;
    }
    rows.orient = orient;
    rows.release = rel;                      /* int32 bits, read as unsigned (the same size) */
    rows.segments = seg;
    rows.n = (size_t)n;
    rows.ids = b[C_IDS].buf;
    rows.nodes = b[C_CONN].buf;
    pyctn_model_lock(self);
    Py_BEGIN_ALLOW_THREADS
    rc = ctn_model_set_origin(self->m, name, line);
    if (!rc) rc = ctn_model_add_elements(self->m, &spec, &rows);
    ctn_model_set_origin(self->m, name, 0);
    Py_END_ALLOW_THREADS
    PyThread_release_lock(self->lock);
    release(b, C_COUNT);
    if (rc) return pyctn_raise(pyctn_state_of(self->module), self->ctx, rc);
    Py_RETURN_NONE;
}

/* add_loads(name, first_line, nodes int32 (n,), F float64 (n, 3)): a `load` line a row,
 * each through ctn_model_add_load as the reader adds it (the public call is per load). */
PyObject *pyctn_model_add_loads(PyObject *op, PyObject *args)
{
    pyctn_model *self = (pyctn_model *)op;
    const char *name;
    int line, rc = CTN_OK;
    PyObject *o[2];
    Py_buffer b[2];
    memset(b, 0, sizeof b);
    if (!PyArg_ParseTuple(args, "siOO", &name, &line, &o[0], &o[1])) return NULL;
    Py_ssize_t n = -1, n3;
    if (take(o[0], &b[0], 'i', &n, "nodes") || (n3 = 3 * n, take(o[1], &b[1], 'd', &n3, "F"))) {
        release(b, 2);
        return NULL;
    }
    const int *ids = b[0].buf;
    const double *F = b[1].buf;
    pyctn_model_lock(self);
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t i = 0; i < n && !rc; i++) {
        rc = ctn_model_set_origin(self->m, name, line + (int)i);
        if (!rc) rc = ctn_model_add_load(self->m, ids[i], F + 3 * i);
    }
    ctn_model_set_origin(self->m, name, 0);
    Py_END_ALLOW_THREADS
    PyThread_release_lock(self->lock);
    release(b, 2);
    if (rc) return pyctn_raise(pyctn_state_of(self->module), self->ctx, rc);
    Py_RETURN_NONE;
}
