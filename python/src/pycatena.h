/* Internal to the Python extension catena._catena: the types and helpers its files share.
 *
 * The extension is a thin layer over the public C API (include/catena.h): a Model owns a
 * context and a model; a Solution owns a solution and a reference to its Model (which
 * outlives it); an Array exposes a block of numbers through the buffer protocol, so
 * numpy reads it in place (numpy.asarray) without a copy and without numpy's C API at
 * build time. Errors raise _catena.Error(code, message); the Python layer
 * (catena/errors.py) turns them into the catena.CatenaError hierarchy. */
#ifndef PYCATENA_H
#define PYCATENA_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <pythread.h>

#include <catena.h>

/* Types made only by the module, never by calling them from Python. */
#ifdef Py_TPFLAGS_DISALLOW_INSTANTIATION
#define PYCTN_NOINIT Py_TPFLAGS_DISALLOW_INSTANTIATION
#else
#define PYCTN_NOINIT 0
#endif

/* The module's state: its exception and types (no process-wide C state). */
typedef struct pyctn_state {
    PyObject *error;          /* _catena.Error(code, message) */
    PyTypeObject *array_type;
    PyTypeObject *model_type;
    PyTypeObject *solution_type;
} pyctn_state;

pyctn_state *pyctn_state_of(PyObject *module);
/* The module's state from a type defined in it (its methods' defining class). */
pyctn_state *pyctn_state_from_type(PyTypeObject *type);

/* A Model: the context it is bound to, the model, the options of its file's `solve` line,
 * and a lock that one solve (or a change) holds at a time (a context is not
 * thread-safe; two Python threads may share a Model object). */
typedef struct pyctn_model {
    PyObject_HEAD
    ctn_ctx *ctx;
    ctn_model *m;
    ctn_solve_options opt;
    int resolved;             /* ctn_model_resolve_targets has run */
    PyThread_type_lock lock;
    PyObject *module;         /* for the state (types, error) */
} pyctn_model;

/* A new Model object with its context (no model yet); NULL with an exception set. */
pyctn_model *pyctn_model_alloc(PyObject *module);
/* Take the model's lock, waiting with the GIL released. */
void pyctn_model_lock(pyctn_model *self);
/* Building a model in pieces (build.c): new_model(name) of the module; the Model's
 * read_more, add_nodes and add_elements methods. */
PyObject *pyctn_new_model(PyObject *module, PyObject *args);
PyObject *pyctn_model_read_more(PyObject *op, PyObject *args);
PyObject *pyctn_model_add_nodes(PyObject *op, PyObject *args);
PyObject *pyctn_model_add_elements(PyObject *op, PyObject *args);
PyObject *pyctn_model_add_loads(PyObject *op, PyObject *args);

typedef struct pyctn_solution {
    PyObject_HEAD
    pyctn_model *model;       /* a reference: the model outlives its solution */
    ctn_solution *s;
} pyctn_solution;

/* An Array: n-dimensional doubles ('d'), ints ('i') or bytes ('b'), either lent by owner
 * (data points into it, owner keeps it alive) or owned (allocated here, freed with it). */
#define PYCTN_MAXDIM 3
typedef struct pyctn_array {
    PyObject_HEAD
    PyObject *owner;          /* NULL when data is owned */
    void *data;
    char format[2];
    Py_ssize_t itemsize;
    int ndim;
    Py_ssize_t shape[PYCTN_MAXDIM];
    Py_ssize_t strides[PYCTN_MAXDIM];
} pyctn_array;

/* A new Array of shape (ndim entries); data NULL: allocated, zeroed and owned; else lent
 * by owner. format "d", "i" or "b". NULL with an exception set on failure. */
pyctn_array *pyctn_array_new(pyctn_state *st, PyObject *owner, void *data, const char *format,
                             int ndim, const Py_ssize_t *shape);

/* Raise _catena.Error(status, the context's message or the status's name); NULL. */
PyObject *pyctn_raise(pyctn_state *st, ctn_ctx *ctx, int status);
/* Raise for status when the context has no message (ctx NULL). */
PyObject *pyctn_raise_msg(pyctn_state *st, int status, const char *msg);

/* Interruption by Ctrl-C: while the library runs with the GIL released on the main
 * thread, its interrupt callback takes the GIL and runs Python's signal handlers
 * (PyErr_CheckSignals); an exception they raise (KeyboardInterrupt) stops the library
 * and is raised when the call returns. Off the main thread there is nothing to poll. */
typedef struct pyctn_irq {
    unsigned long thread;     /* the thread that polls (the main thread), or 0: none */
    volatile int hit;
    PyObject *type, *value, *tb;   /* the handler's exception */
} pyctn_irq;
void pyctn_irq_begin(pyctn_irq *q, ctn_ctx *ctx, int enabled);
/* Remove the callback; restore the handler's exception (returns 1) if there was one. */
int pyctn_irq_end(pyctn_irq *q, ctn_ctx *ctx);

extern PyType_Spec pyctn_array_spec, pyctn_model_spec, pyctn_solution_spec;

/* Solution from a solve of model (steals s). */
PyObject *pyctn_solution_wrap(pyctn_model *model, ctn_solution *s);
/* Solve options from a dict of the `solve` line's keys (on top of base). */
int pyctn_options_parse(pyctn_state *st, PyObject *dict, ctn_ctx *ctx, ctn_solve_options *opt);
/* The options as such a dict. */
PyObject *pyctn_options_dict(const ctn_solve_options *opt);

#endif
