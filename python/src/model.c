/* _catena.Model: a context and the model bound to it, read from a .cable file or text;
 * its solve (the GIL released) and its tables as Arrays. */
#include "pycatena.h"

#include <string.h>

pyctn_model *pyctn_model_alloc(PyObject *module)
{
    pyctn_state *st = pyctn_state_of(module);
    pyctn_model *self = PyObject_GC_New(pyctn_model, st->model_type);
    if (!self) return NULL;
    self->ctx = NULL;
    self->m = NULL;
    self->resolved = 0;
    self->module = Py_NewRef(module);
    self->lock = PyThread_allocate_lock();
    PyObject_GC_Track(self);
    if (!self->lock || ctn_ctx_create(&self->ctx)) {
        Py_DECREF(self);
        return (pyctn_model *)PyErr_NoMemory();
    }
    return self;
}

void pyctn_model_lock(pyctn_model *self)
{
    if (PyThread_acquire_lock(self->lock, NOWAIT_LOCK)) return;
    Py_BEGIN_ALLOW_THREADS
    PyThread_acquire_lock(self->lock, WAIT_LOCK);
    Py_END_ALLOW_THREADS
}

/* read(path, interruptible) and read_string(name, text, interruptible). */
static PyObject *read_any(PyObject *module, const char *name, const char *text, Py_ssize_t len, int irq_on)
{
    pyctn_model *self = pyctn_model_alloc(module);
    if (!self) return NULL;
    pyctn_irq q;
    int rc;
    pyctn_irq_begin(&q, self->ctx, irq_on);
    Py_BEGIN_ALLOW_THREADS
    rc = text ? ctn_read_string(self->ctx, name, text, (size_t)len, &self->m, &self->opt)
              : ctn_read_file(self->ctx, name, &self->m, &self->opt);
    Py_END_ALLOW_THREADS
    if (pyctn_irq_end(&q, self->ctx) || rc) {
        if (!PyErr_Occurred()) pyctn_raise(pyctn_state_of(module), self->ctx, rc);
        Py_DECREF(self);
        return NULL;
    }
    return (PyObject *)self;
}

PyObject *pyctn_read(PyObject *module, PyObject *args)
{
    PyObject *path;
    int irq_on = 0;
    if (!PyArg_ParseTuple(args, "O&|p", PyUnicode_FSConverter, &path, &irq_on)) return NULL;
    PyObject *r = read_any(module, PyBytes_AS_STRING(path), NULL, 0, irq_on);
    Py_DECREF(path);
    return r;
}

PyObject *pyctn_read_string(PyObject *module, PyObject *args)
{
    const char *name, *text;
    Py_ssize_t len;
    int irq_on = 0;
    if (!PyArg_ParseTuple(args, "ss#|p", &name, &text, &len, &irq_on)) return NULL;
    return read_any(module, name, text, len, irq_on);
}

/* solve(options: dict, interruptible: bool) -> Solution. As `catena solve` does: the
 * model is validated, its targets resolved (once: that changes the model), then solved. */
static PyObject *model_solve(PyObject *op, PyObject *args)
{
    pyctn_model *self = (pyctn_model *)op;
    pyctn_state *st = pyctn_state_of(self->module);
    PyObject *dict;
    int irq_on = 0;
    if (!PyArg_ParseTuple(args, "O!|p", &PyDict_Type, &dict, &irq_on)) return NULL;
    pyctn_model_lock(self);
    ctn_solve_options opt = self->opt;
    ctn_solution *s = NULL;
    if (pyctn_options_parse(st, dict, self->ctx, &opt)) {
        PyThread_release_lock(self->lock);
        return NULL;
    }
    /* The context's limit is the catena command's (0: the solve's threads= and the machine
     * decide): the same helper threads, results and timings as `catena solve`; threads=1
     * runs the solve on the caller's thread alone. */
    int rc;
    pyctn_irq q;
    pyctn_irq_begin(&q, self->ctx, irq_on);
    Py_BEGIN_ALLOW_THREADS
    rc = ctn_ctx_set_threads(self->ctx, 0);
    if (!rc) rc = ctn_model_validate(self->m);
    if (!rc && !self->resolved) rc = ctn_model_resolve_targets(self->ctx, self->m, &opt, NULL);
    if (!rc) self->resolved = 1;
    if (!rc) rc = ctn_solve(self->ctx, self->m, &opt, &s);
    Py_END_ALLOW_THREADS
    PyObject *r = NULL;
    if (pyctn_irq_end(&q, self->ctx) || rc) {
        if (!PyErr_Occurred()) pyctn_raise(st, self->ctx, rc);
        ctn_solution_destroy(&s);
    } else {
        r = pyctn_solution_wrap(self, s);
    }
    PyThread_release_lock(self->lock);
    return r;
}

static PyObject *model_options(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    return pyctn_options_dict(&((pyctn_model *)op)->opt);
}

static PyObject *model_counts(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    pyctn_model *self = (pyctn_model *)op;
    return Py_BuildValue("(nn)", (Py_ssize_t)ctn_model_node_count(self->m), (Py_ssize_t)ctn_model_element_count(self->m));
}

/* nodes() -> (ids, X (n, 3), fix): copies, one C loop. */
static PyObject *model_nodes(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    pyctn_model *self = (pyctn_model *)op;
    pyctn_state *st = pyctn_state_of(self->module);
    Py_ssize_t n = (Py_ssize_t)ctn_model_node_count(self->m), s3[2] = { n, 3 };
    pyctn_array *ids = pyctn_array_new(st, NULL, NULL, "i", 1, &n);
    pyctn_array *X = ids ? pyctn_array_new(st, NULL, NULL, "d", 2, s3) : NULL;
    pyctn_array *fix = X ? pyctn_array_new(st, NULL, NULL, "i", 1, &n) : NULL;
    if (!fix) goto fail;
    for (Py_ssize_t i = 0; i < n; i++) {
        ctn_node_info ni;
        if (ctn_model_node(self->m, (size_t)i, &ni)) {
            pyctn_raise(st, self->ctx, CTN_ERR_INVALID);
            goto fail;
        }
        ((int *)ids->data)[i] = ni.id;
        memcpy((double *)X->data + 3 * i, ni.X, sizeof ni.X);
        ((int *)fix->data)[i] = (int)ni.fix;
    }
    return Py_BuildValue("(NNN)", ids, X, fix);
fail:
    Py_XDECREF(ids);
    Py_XDECREF(X);
    Py_XDECREF(fix);
    return NULL;
}

/* elements() -> (ids, ends (ne, 2) node indices, l0, A, E, w, family codes, family names):
 * copies in one C loop; a family is named once, codes index the list of names. */
enum { E_L0, E_A, E_E, E_W, E_NDOUBLE };

static int family_code(PyObject *names, const char *type)
{
    Py_ssize_t n = PyList_GET_SIZE(names);
    for (Py_ssize_t k = 0; k < n; k++)
        if (!strcmp(PyUnicode_AsUTF8(PyList_GET_ITEM(names, k)), type)) return (int)k;
    PyObject *s = PyUnicode_FromString(type);
    int rc = s ? PyList_Append(names, s) : -1;
    Py_XDECREF(s);
    return rc ? -1 : (int)n;
}

static PyObject *model_elements(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    pyctn_model *self = (pyctn_model *)op;
    pyctn_state *st = pyctn_state_of(self->module);
    Py_ssize_t n = (Py_ssize_t)ctn_model_element_count(self->m), s2[2] = { n, 2 };
    pyctn_array *ids = pyctn_array_new(st, NULL, NULL, "i", 1, &n), *ends = NULL, *fam = NULL, *v[E_NDOUBLE] = { 0 };
    PyObject *names = PyList_New(0);
    int ok = ids && names && (ends = pyctn_array_new(st, NULL, NULL, "i", 2, s2)) &&
             (fam = pyctn_array_new(st, NULL, NULL, "i", 1, &n));
    for (int k = 0; ok && k < E_NDOUBLE; k++) ok = (v[k] = pyctn_array_new(st, NULL, NULL, "d", 1, &n)) != NULL;
    for (Py_ssize_t i = 0; ok && i < n; i++) {
        ctn_element_info e;
        if (ctn_model_element(self->m, (size_t)i, &e)) {
            pyctn_raise(st, self->ctx, CTN_ERR_INVALID);
            ok = 0;
            break;
        }
        int code = family_code(names, e.type);
        ok = code >= 0;
        ((int *)ids->data)[i] = e.id;
        ((int *)ends->data)[2 * i] = e.node[0];
        ((int *)ends->data)[2 * i + 1] = e.node[1];
        ((int *)fam->data)[i] = code;
        ((double *)v[E_L0]->data)[i] = e.l0;
        ((double *)v[E_A]->data)[i] = e.A;
        ((double *)v[E_E]->data)[i] = e.E;
        ((double *)v[E_W]->data)[i] = e.w;
    }
    if (ok) return Py_BuildValue("(NNNNNNNN)", ids, ends, v[E_L0], v[E_A], v[E_E], v[E_W], fam, names);
    Py_XDECREF(ids);
    Py_XDECREF(ends);
    Py_XDECREF(fam);
    Py_XDECREF(names);
    for (int k = 0; k < E_NDOUBLE; k++) Py_XDECREF(v[k]);
    return NULL;
}

static PyMethodDef model_methods[] = {
    { "solve", model_solve, METH_VARARGS, "solve(options: dict, interruptible: bool) -> Solution" },
    { "options", model_options, METH_NOARGS, "options() -> dict: the file's solve options" },
    { "counts", model_counts, METH_NOARGS, "counts() -> (nodes, elements)" },
    { "nodes", model_nodes, METH_NOARGS, "nodes() -> (ids, X, fix)" },
    { "elements", model_elements, METH_NOARGS, "elements() -> (ids, ends, l0, A, E, w, family, family_names)" },
    { "read_more", pyctn_model_read_more, METH_VARARGS, "read_more(name, first_line, text, interruptible): more .cable text" },
    { "add_nodes", pyctn_model_add_nodes, METH_VARARGS, "add_nodes(name, first_line, ids, X, fix, mass): node rows" },
    { "add_loads", pyctn_model_add_loads, METH_VARARGS, "add_loads(name, first_line, nodes, F): load rows" },
    { "add_elements", pyctn_model_add_elements, METH_VARARGS,
      "add_elements(name, first_line, type, ids, conn, nnodes, section, group, kind, l0, value, k, q, force): element rows" },
    { NULL, NULL, 0, NULL }
};

static int model_traverse(PyObject *op, visitproc visit, void *arg)
{
    Py_VISIT(((pyctn_model *)op)->module);
    Py_VISIT(Py_TYPE(op));
    return 0;
}

static void model_dealloc(PyObject *op)
{
    pyctn_model *self = (pyctn_model *)op;
    PyTypeObject *type = Py_TYPE(op);
    PyObject_GC_UnTrack(op);
    ctn_model_destroy(&self->m);
    ctn_ctx_destroy(&self->ctx);
    if (self->lock) PyThread_free_lock(self->lock);
    Py_CLEAR(self->module);
    PyObject_GC_Del(op);
    Py_DECREF(type);
}

static PyType_Slot model_slots[] = {
    { Py_tp_dealloc, (void *)model_dealloc },
    { Py_tp_traverse, (void *)model_traverse },
    { Py_tp_methods, model_methods },
    { Py_tp_doc, (void *)"A catena model and its context (use catena.Model)." },
    { 0, NULL }
};

PyType_Spec pyctn_model_spec = {
    "catena._catena.Model", sizeof(pyctn_model), 0, Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC | PYCTN_NOINIT, model_slots
};
