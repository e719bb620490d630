/* _catena.Array: numbers exposed through the buffer protocol (read-only), so that
 * numpy.asarray(a) is a view of them with no copy. */
#include "pycatena.h"

#include <string.h>

pyctn_array *pyctn_array_new(pyctn_state *st, PyObject *owner, void *data, const char *format,
                             int ndim, const Py_ssize_t *shape)
{
    pyctn_array *a = PyObject_GC_New(pyctn_array, st->array_type);
    if (!a) return NULL;
    a->owner = NULL;
    a->data = NULL;
    a->format[0] = format[0];
    a->format[1] = '\0';
    a->itemsize = format[0] == 'd' ? (Py_ssize_t)sizeof(double)
                : format[0] == 'i' ? (Py_ssize_t)sizeof(int) : 1;
    a->ndim = ndim;
    Py_ssize_t count = 1;
    for (int k = ndim - 1; k >= 0; k--) {
        a->shape[k] = shape[k];
        a->strides[k] = k == ndim - 1 ? a->itemsize : a->strides[k + 1] * shape[k + 1];
        count *= shape[k];
    }
    if (data) {
        Py_XINCREF(owner);
        a->owner = owner;
        a->data = data;
    } else {
        size_t bytes = (size_t)(count > 0 ? count : 1) * (size_t)a->itemsize;
        a->data = PyMem_RawCalloc(1, bytes);
        if (!a->data) {
            PyObject_GC_Del(a);
            return (pyctn_array *)PyErr_NoMemory();
        }
    }
    PyObject_GC_Track(a);
    return a;
}

static int array_getbuffer(PyObject *self, Py_buffer *view, int flags)
{
    pyctn_array *a = (pyctn_array *)self;
    if (flags & PyBUF_WRITABLE) {
        PyErr_SetString(PyExc_BufferError, "catena arrays are read-only");
        return -1;
    }
    Py_ssize_t count = 1;
    for (int k = 0; k < a->ndim; k++) count *= a->shape[k];
    Py_INCREF(self);
    view->obj = self;
    view->buf = a->data;
    view->len = count * a->itemsize;
    view->readonly = 1;
    view->itemsize = a->itemsize;
    view->format = (flags & PyBUF_FORMAT) ? a->format : NULL;
    view->ndim = a->ndim;
    view->shape = (flags & PyBUF_ND) ? a->shape : NULL;
    view->strides = (flags & PyBUF_STRIDES) == PyBUF_STRIDES ? a->strides : NULL;
    view->suboffsets = NULL;
    view->internal = NULL;
    return 0;
}

static int array_traverse(PyObject *self, visitproc visit, void *arg)
{
    Py_VISIT(((pyctn_array *)self)->owner);
    Py_VISIT(Py_TYPE(self));
    return 0;
}

static int array_clear(PyObject *self)
{
    Py_CLEAR(((pyctn_array *)self)->owner);
    return 0;
}

static void array_dealloc(PyObject *self)
{
    pyctn_array *a = (pyctn_array *)self;
    PyTypeObject *type = Py_TYPE(self);
    PyObject_GC_UnTrack(self);
    if (!a->owner) PyMem_RawFree(a->data);
    array_clear(self);
    PyObject_GC_Del(self);
    Py_DECREF(type);
}

static PyObject *array_shape(PyObject *self, void *closure)
{
    (void)closure;
    pyctn_array *a = (pyctn_array *)self;
    PyObject *t = PyTuple_New(a->ndim);
    for (int k = 0; t && k < a->ndim; k++) PyTuple_SET_ITEM(t, k, PyLong_FromSsize_t(a->shape[k]));
    return t;
}

static PyGetSetDef array_getset[] = {
    { "shape", array_shape, NULL, "the array's shape", NULL },
    { NULL, NULL, NULL, NULL, NULL }
};

static PyType_Slot array_slots[] = {
    { Py_tp_dealloc, (void *)array_dealloc },
    { Py_tp_traverse, (void *)array_traverse },
    { Py_tp_clear, (void *)array_clear },
    { Py_tp_getset, array_getset },
    { Py_bf_getbuffer, (void *)array_getbuffer },
    { Py_tp_doc, (void *)"Numbers of a catena result, read-only, for numpy.asarray (no copy)." },
    { 0, NULL }
};

PyType_Spec pyctn_array_spec = {
    "catena._catena.Array", sizeof(pyctn_array), 0,
    Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC | PYCTN_NOINIT, array_slots
};
