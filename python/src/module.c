/* catena._catena: the module, its error, and Ctrl-C while the library runs. */
#include "pycatena.h"

pyctn_state *pyctn_state_of(PyObject *module) { return (pyctn_state *)PyModule_GetState(module); }

pyctn_state *pyctn_state_from_type(PyTypeObject *type) { return (pyctn_state *)PyType_GetModuleState(type); }

PyObject *pyctn_raise_msg(pyctn_state *st, int status, const char *msg)
{
    PyObject *args = Py_BuildValue("(is)", status, msg && *msg ? msg : ctn_strerror(status));
    if (args) {
        PyErr_SetObject(st->error, args);
        Py_DECREF(args);
    }
    return NULL;
}

PyObject *pyctn_raise(pyctn_state *st, ctn_ctx *ctx, int status)
{
    if (status == CTN_ERR_NOMEM) return PyErr_NoMemory();
    return pyctn_raise_msg(st, status, ctx ? ctn_ctx_message(ctx) : NULL);
}

/* ---- Ctrl-C ---- */

static int irq_poll(void *data)
{
    pyctn_irq *q = data;
    if (q->hit) return 1;
    if (PyThread_get_thread_ident() != q->thread) return 0;   /* a helper thread */
    PyGILState_STATE g = PyGILState_Ensure();
    if (PyErr_CheckSignals() < 0) {
        PyErr_Fetch(&q->type, &q->value, &q->tb);
        q->hit = 1;
    }
    PyGILState_Release(g);
    return q->hit;
}

void pyctn_irq_begin(pyctn_irq *q, ctn_ctx *ctx, int enabled)
{
    q->thread = enabled ? PyThread_get_thread_ident() : 0;
    q->hit = 0;
    q->type = q->value = q->tb = NULL;
    if (enabled) ctn_ctx_set_interrupt(ctx, irq_poll, q);
}

int pyctn_irq_end(pyctn_irq *q, ctn_ctx *ctx)
{
    if (q->thread) ctn_ctx_set_interrupt(ctx, NULL, NULL);
    if (!q->type) return 0;
    PyErr_Restore(q->type, q->value, q->tb);
    return 1;
}

/* ---- module ---- */

static PyObject *mod_version(PyObject *self, PyObject *noargs)
{
    (void)self;
    (void)noargs;
    return PyUnicode_FromString(ctn_version());
}

PyObject *pyctn_read(PyObject *module, PyObject *args);
PyObject *pyctn_read_string(PyObject *module, PyObject *args);
PyObject *pyctn_formfind(PyObject *module, PyObject *args);
PyObject *pyctn_use_cli_heap(PyObject *module, PyObject *noargs);
PyObject *pyctn_catenary(PyObject *module, PyObject *args);
PyObject *pyctn_ecatenary(PyObject *module, PyObject *args);
PyObject *pyctn_parabola(PyObject *module, PyObject *args);

static PyMethodDef mod_methods[] = {
    { "version", mod_version, METH_NOARGS, "version() -> str: the library's version (ctn_version)." },
    { "read", pyctn_read, METH_VARARGS,
      "read(path, interruptible) -> Model: read a .cable file (ctn_read_file)." },
    { "read_string", pyctn_read_string, METH_VARARGS,
      "read_string(name, text, interruptible) -> Model: read .cable text; name stands for the file in messages." },
    { "use_cli_heap", pyctn_use_cli_heap, METH_NOARGS,
      "use_cli_heap() -> bool: the catena command's process-wide heap settings (see catena.use_cli_heap)." },
    { "new_model", pyctn_new_model, METH_VARARGS,
      "new_model(name) -> Model: an empty model to build (read_more, add_nodes, add_elements)." },
    { "formfind", pyctn_formfind, METH_VARARGS,
      "formfind(name, text, out, tol, maxit, interruptible) -> report: find the shape, write it to out." },
    { "catenary", pyctn_catenary, METH_VARARGS, "catenary(l, h, w, S, x) -> dict (ctn_catenary_solve)" },
    { "ecatenary", pyctn_ecatenary, METH_VARARGS, "ecatenary(l, h, w, EA, L0, x) -> dict (ctn_ecatenary_solve)" },
    { "parabola", pyctn_parabola, METH_VARARGS, "parabola(l, h, q, L0, EA, x) -> dict (ctn_parabola_solve)" },
    { NULL, NULL, 0, NULL }
};

static int mod_exec(PyObject *module)
{
    pyctn_state *st = pyctn_state_of(module);
    st->error = PyErr_NewExceptionWithDoc("catena._catena.Error",
                                          "Error(code, message): a catena status and its message.", NULL, NULL);
    if (!st->error || PyModule_AddObjectRef(module, "Error", st->error)) return -1;
    st->array_type = (PyTypeObject *)PyType_FromModuleAndSpec(module, &pyctn_array_spec, NULL);
    st->model_type = (PyTypeObject *)PyType_FromModuleAndSpec(module, &pyctn_model_spec, NULL);
    st->solution_type = (PyTypeObject *)PyType_FromModuleAndSpec(module, &pyctn_solution_spec, NULL);
    if (!st->array_type || !st->model_type || !st->solution_type) return -1;
    if (PyModule_AddObjectRef(module, "Array", (PyObject *)st->array_type) ||
        PyModule_AddObjectRef(module, "Model", (PyObject *)st->model_type) ||
        PyModule_AddObjectRef(module, "Solution", (PyObject *)st->solution_type))
        return -1;
    return 0;
}

static int mod_traverse(PyObject *module, visitproc visit, void *arg)
{
    pyctn_state *st = pyctn_state_of(module);
    Py_VISIT(st->error);
    Py_VISIT(st->array_type);
    Py_VISIT(st->model_type);
    Py_VISIT(st->solution_type);
    return 0;
}

static int mod_clear(PyObject *module)
{
    pyctn_state *st = pyctn_state_of(module);
    Py_CLEAR(st->error);
    Py_CLEAR(st->array_type);
    Py_CLEAR(st->model_type);
    Py_CLEAR(st->solution_type);
    return 0;
}

static void mod_free(void *module) { mod_clear((PyObject *)module); }

static PyModuleDef_Slot mod_slots[] = {
    { Py_mod_exec, (void *)mod_exec },
    { 0, NULL }
};

static struct PyModuleDef mod_def = {
    PyModuleDef_HEAD_INIT, "_catena",
    "The C layer of the catena package over libcatena (include/catena.h); use the catena package.",
    sizeof(pyctn_state), mod_methods, mod_slots, mod_traverse, mod_clear, mod_free
};

PyMODINIT_FUNC PyInit__catena(void) { return PyModuleDef_Init(&mod_def); }
