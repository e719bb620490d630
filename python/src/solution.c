/* _catena.Solution: a solution and its model; its numbers as Arrays (the solution's own
 * arrays lent without a copy: displacements, reactions, histories; element states and
 * mode shapes copied by one C loop each). */
#include "pycatena.h"

#include <string.h>

PyObject *pyctn_solution_wrap(pyctn_model *model, ctn_solution *s)
{
    pyctn_state *st = pyctn_state_of(model->module);
    pyctn_solution *self = PyObject_GC_New(pyctn_solution, st->solution_type);
    if (!self) {
        ctn_solution_destroy(&s);
        return NULL;
    }
    self->model = (pyctn_model *)Py_NewRef((PyObject *)model);
    self->s = s;
    PyObject_GC_Track(self);
    return (PyObject *)self;
}

static pyctn_state *sol_state(pyctn_solution *self) { return pyctn_state_of(self->model->module); }

static Py_ssize_t node_count(pyctn_solution *self) { return (Py_ssize_t)ctn_model_node_count(self->model->m); }

/* A step index: k < 0 counts from the end, as Python does. */
static int step_index(pyctn_solution *self, Py_ssize_t k, size_t *out)
{
    Py_ssize_t n = (Py_ssize_t)ctn_solution_step_count(self->s);
    if (k < 0) k += n;
    if (k < 0 || k >= n) {
        PyErr_Format(PyExc_IndexError, "step %zd out of range (the solution has %zd)", k, n);
        return -1;
    }
    *out = (size_t)k;
    return 0;
}

static PyObject *lend(pyctn_solution *self, const double *p, int ndim, const Py_ssize_t *shape)
{
    if (!p) Py_RETURN_NONE;
    return (PyObject *)pyctn_array_new(sol_state(self), (PyObject *)self, (void *)p, "d", ndim, shape);
}

/* step(k) -> (name, reason, load_factor, iterations, displacements, reactions,
 *             rotations or None, moments or None) */
static PyObject *sol_step(PyObject *op, PyObject *args)
{
    pyctn_solution *self = (pyctn_solution *)op;
    Py_ssize_t k;
    size_t j;
    ctn_step_result r;
    if (!PyArg_ParseTuple(args, "n", &k) || step_index(self, k, &j)) return NULL;
    if (ctn_solution_step(self->s, j, &r)) return pyctn_raise_msg(sol_state(self), CTN_ERR_INVALID, "no such step");
    const double *rot = NULL, *mom = NULL;
    ctn_solution_step_rotations(self->s, j, &rot, &mom);
    Py_ssize_t shape[2] = { node_count(self), 3 };
    return Py_BuildValue("(sidiNNNN)", r.name, (int)r.reason, r.load_factor, r.iterations, lend(self, r.d, 2, shape),
                         lend(self, r.react, 2, shape), lend(self, rot, 2, shape), lend(self, mom, 2, shape));
}

static PyObject *sol_step_count(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    return PyLong_FromSize_t(ctn_solution_step_count(((pyctn_solution *)op)->s));
}

/* elements(k) -> (force, stress, strain, length, slack, utilisation) at the end of step
 * k, one C loop over the elements. */
enum { S_FORCE, S_STRESS, S_STRAIN, S_LENGTH, S_UTIL, S_NDOUBLE };

static PyObject *sol_elements(PyObject *op, PyObject *args)
{
    pyctn_solution *self = (pyctn_solution *)op;
    pyctn_state *st = sol_state(self);
    Py_ssize_t k, n = (Py_ssize_t)ctn_model_element_count(self->model->m);
    size_t j;
    if (!PyArg_ParseTuple(args, "n", &k) || step_index(self, k, &j)) return NULL;
    pyctn_array *v[S_NDOUBLE] = { 0 }, *slack = pyctn_array_new(st, NULL, NULL, "?", 1, &n);
    int ok = slack != NULL;
    for (int c = 0; ok && c < S_NDOUBLE; c++) ok = (v[c] = pyctn_array_new(st, NULL, NULL, "d", 1, &n)) != NULL;
    if (ok) {
        int rc = 0;
        Py_BEGIN_ALLOW_THREADS
        for (Py_ssize_t i = 0; !rc && i < n; i++) {
            ctn_element_state es;
            ctn_element_info ei;
            rc = ctn_solution_step_element(self->s, j, (size_t)i, &es);
            if (!rc) rc = ctn_model_element(self->model->m, (size_t)i, &ei);
            if (rc) break;
            ((double *)v[S_FORCE]->data)[i] = es.force;
            ((double *)v[S_STRESS]->data)[i] = es.stress;
            ((double *)v[S_STRAIN]->data)[i] = es.strain;
            ((double *)v[S_LENGTH]->data)[i] = es.length;
            ((double *)v[S_UTIL]->data)[i] = ctn_utilisation(&ei, &es);
            ((unsigned char *)slack->data)[i] = es.slack ? 1 : 0;
        }
        Py_END_ALLOW_THREADS
        if (rc) {
            pyctn_raise_msg(st, CTN_ERR_INVALID, "an element state could not be read");
            ok = 0;
        }
    }
    if (ok) return Py_BuildValue("(NNNNNN)", v[S_FORCE], v[S_STRESS], v[S_STRAIN], v[S_LENGTH], slack, v[S_UTIL]);
    Py_XDECREF(slack);
    for (int c = 0; c < S_NDOUBLE; c++) Py_XDECREF(v[c]);
    return NULL;
}

/* histories() -> (residual, increment), lent. */
static PyObject *sol_histories(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    pyctn_solution *self = (pyctn_solution *)op;
    size_t nr = 0, ni = 0;
    const double *r = ctn_solution_residual_history(self->s, &nr), *i = ctn_solution_increment_history(self->s, &ni);
    Py_ssize_t sr = (Py_ssize_t)nr, si = (Py_ssize_t)ni;
    static const double none = 0;
    return Py_BuildValue("(NN)", lend(self, r ? r : &none, 1, &sr), lend(self, i ? i : &none, 1, &si));
}

#define PUT(d, key, v) do { PyObject *v_ = (v); if (!v_ || PyDict_SetItemString(d, key, v_)) { Py_XDECREF(v_); Py_DECREF(d); return NULL; } Py_DECREF(v_); } while (0)

static PyObject *sol_summary(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    pyctn_solution *self = (pyctn_solution *)op;
    ctn_solve_summary s;
    ctn_solution_summary(self->s, &s);
    PyObject *d = PyDict_New();
    if (!d) return NULL;
    PUT(d, "reason", PyLong_FromLong(s.reason));
    PUT(d, "reason_name", PyUnicode_FromString(ctn_reason_name(s.reason)));
    PUT(d, "iterations", PyLong_FromLong(s.iterations));
    PUT(d, "residual", PyFloat_FromDouble(s.residual));
    PUT(d, "increment", PyFloat_FromDouble(s.increment));
    PUT(d, "fext_norm", PyFloat_FromDouble(s.fext_norm));
    PUT(d, "fail_node", PyLong_FromLong(s.fail_node));
    PUT(d, "fail_dir", PyUnicode_FromString(s.fail_dir >= 0 ? ctn_dof_name(s.fail_dir) : ""));
    PUT(d, "fail_element", PyLong_FromLong(s.fail_element));
    PUT(d, "ordering", PyUnicode_FromString(ctn_ordering_name(s.ordering)));
    PUT(d, "step", PyLong_FromSize_t(s.step));
    PUT(d, "load_factor", PyFloat_FromDouble(s.load_factor));
    PUT(d, "cuts", PyLong_FromLong(s.cuts));
    PUT(d, "floor", PyBool_FromLong(s.floor));
    PUT(d, "residual_floor", PyFloat_FromDouble(s.residual_floor));
    PUT(d, "stable", PyLong_FromLong(s.stable));
    PUT(d, "ndof", PyLong_FromSize_t(s.ndof));
    PUT(d, "nnz_factor", PyLong_FromSize_t(s.nnz_factor));
    PUT(d, "factorizations", PyLong_FromLong(s.factorizations));
    PUT(d, "solves", PyLong_FromLong(s.solves));
    PUT(d, "reused", PyLong_FromLong(s.reused));
    PUT(d, "t_setup", PyFloat_FromDouble(s.t_setup));
    PUT(d, "t_assemble", PyFloat_FromDouble(s.t_assemble));
    PUT(d, "t_factor", PyFloat_FromDouble(s.t_factor));
    PUT(d, "t_solve", PyFloat_FromDouble(s.t_solve));
    PUT(d, "threads", PyLong_FromLong(s.threads));
    PUT(d, "blas", PyUnicode_FromString(s.blas));
    return d;
}

static PyObject *sol_stability(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    ctn_stability s;
    if (ctn_solution_stability(((pyctn_solution *)op)->s, &s)) Py_RETURN_NONE;
    return Py_BuildValue("{s:O,s:O,s:l,s:i,s:s,s:O}", "stable", s.stable ? Py_True : Py_False, "semidefinite",
                         s.semidefinite ? Py_True : Py_False, "negative", s.negative, "node", s.node, "dir",
                         s.dir >= 0 ? ctn_dof_name(s.dir) : "", "by_tension", s.by_tension ? Py_True : Py_False);
}

PyObject *pyctn_solution_modes(PyObject *op, PyObject *noargs);

/* groups(k) -> list of dicts (ctn_group_result), one per group (few: not per element). */
static PyObject *sol_groups(PyObject *op, PyObject *args)
{
    pyctn_solution *self = (pyctn_solution *)op;
    Py_ssize_t k;
    size_t j, n = ctn_model_group_count(self->model->m);
    if (!PyArg_ParseTuple(args, "n", &k) || step_index(self, k, &j)) return NULL;
    PyObject *list = PyList_New(0);
    for (size_t g = 0; list && g < n; g++) {
        ctn_group_result r;
        if (ctn_solution_group(self->model->m, self->s, j, g, &r)) {
            Py_DECREF(list);
            return pyctn_raise_msg(sol_state(self), CTN_ERR_INVALID, "a group could not be read");
        }
        PyObject *d = Py_BuildValue("{s:s,s:n,s:d,s:d,s:d,s:d,s:O,s:d,s:i,s:n,s:d,s:d,s:d}", "name", r.name,
                                    "elements", (Py_ssize_t)r.elements, "max_force", r.max_force, "min_force",
                                    r.min_force, "max_stress", r.max_stress, "max_strain", r.max_strain,
                                    "has_capacity", r.has_capacity ? Py_True : Py_False, "max_utilisation",
                                    r.max_utilisation, "worst_element", r.worst_element, "slack", (Py_ssize_t)r.slack,
                                    "length", r.length, "stressed_length", r.stressed_length, "weight", r.weight);
        if (!d || PyList_Append(list, d)) Py_CLEAR(list);
        Py_XDECREF(d);
    }
    return list;
}

/* catenary(k, i) -> dict: catenary element i at the end of step k (ctn_solution_catenary). */
static PyObject *sol_catenary(PyObject *op, PyObject *args)
{
    pyctn_solution *self = (pyctn_solution *)op;
    Py_ssize_t k, i;
    size_t j;
    if (!PyArg_ParseTuple(args, "nn", &k, &i) || step_index(self, k, &j)) return NULL;
    ctn_catenary_result r;
    r.size = sizeof r;
    int rc = i < 0 ? CTN_ERR_INVALID : ctn_solution_catenary(self->model->m, self->s, j, (size_t)i, &r);
    if (rc) return pyctn_raise_msg(sol_state(self), rc, "not a catenary element, or its state has no solution");
    return Py_BuildValue("{s:d,s:(dd),s:((ddd)(ddd)),s:(dd),s:d,s:d}", "H", r.H, "tension", r.tension[0], r.tension[1],
                         "end_forces", r.force[0][0], r.force[0][1], r.force[0][2], r.force[1][0], r.force[1][1],
                         r.force[1][2], "V", r.V[0], r.V[1], "sag", r.sag, "stretched_length", r.length);
}

/* element_shape(k, i, n) -> Array (n, 3): the deformed shape of element i at step k. */
static PyObject *sol_element_shape(PyObject *op, PyObject *args)
{
    pyctn_solution *self = (pyctn_solution *)op;
    Py_ssize_t k, i, n;
    size_t j;
    if (!PyArg_ParseTuple(args, "nnn", &k, &i, &n) || step_index(self, k, &j)) return NULL;
    if (n < 2 || n > 1000000 || i < 0) {
        PyErr_SetString(PyExc_ValueError, "element_shape: n must be 2 to 1e6 and the element an index");
        return NULL;
    }
    Py_ssize_t shape[2] = { n, 3 };
    pyctn_array *a = pyctn_array_new(sol_state(self), NULL, NULL, "d", 2, shape);
    if (!a) return NULL;
    int rc = ctn_solution_element_shape(self->model->m, self->s, j, (size_t)i, (int)n, a->data);
    if (rc) {
        Py_DECREF(a);
        return pyctn_raise_msg(sol_state(self), rc, "element_shape: no such element");
    }
    return (PyObject *)a;
}

/* cables() -> list of dicts, one per generated cable: ends, elements, length, sag, target. */
static PyObject *sol_cables(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    pyctn_solution *self = (pyctn_solution *)op;
    const ctn_model *m = self->model->m;
    size_t n = ctn_model_cable_count(m);
    static const char *const kinds[] = { "", "H", "sag", "tension" };
    PyObject *list = PyList_New(0);
    for (size_t i = 0; list && i < n; i++) {
        ctn_cable_info c;
        double sag = 0, far = 0;
        if (ctn_model_cable(m, i, &c)) break;
        int has_sag = ctn_solution_cable_sag(m, self->s, i, &sag) == CTN_OK;
        ctn_solution_cable_max_sag_from_chord(m, self->s, i, &far);
        int t = (int)c.target;
        PyObject *d = Py_BuildValue("{s:(ii),s:n,s:n,s:d,s:d,s:d,s:s,s:d,s:d,s:i}", "nodes", c.node[0], c.node[1],
                                    "first_element", (Py_ssize_t)c.first, "count", (Py_ssize_t)c.count, "length",
                                    c.length, "sag", has_sag ? sag : Py_NAN, "max_sag_from_chord", far, "target",
                                    t >= 0 && t < 4 ? kinds[t] : "?", "target_value", c.target_value,
                                    "target_achieved", c.target_achieved, "target_iterations", c.target_iterations);
        if (!d || PyList_Append(list, d)) Py_CLEAR(list);
        Py_XDECREF(d);
    }
    return list;
}

/* Calls that record errors in the model's context hold the model's lock. */
static void lock(pyctn_solution *self)
{
    if (PyThread_acquire_lock(self->model->lock, NOWAIT_LOCK)) return;
    Py_BEGIN_ALLOW_THREADS
    PyThread_acquire_lock(self->model->lock, WAIT_LOCK);
    Py_END_ALLOW_THREADS
}

static PyObject *finish(pyctn_solution *self, int rc, PyObject *ok)
{
    PyObject *r = rc ? pyctn_raise(sol_state(self), self->model->ctx, rc) : ok;
    if (rc) Py_XDECREF(ok);
    PyThread_release_lock(self->model->lock);
    return r;
}

/* write_vtu(path, step): the C writer (ctn_write_vtu), atomic. */
static PyObject *sol_write_vtu(PyObject *op, PyObject *args)
{
    pyctn_solution *self = (pyctn_solution *)op;
    PyObject *path;
    Py_ssize_t k = -1;
    size_t j;
    if (!PyArg_ParseTuple(args, "O&|n", PyUnicode_FSConverter, &path, &k)) return NULL;
    if (step_index(self, k, &j)) {
        Py_DECREF(path);
        return NULL;
    }
    int rc;
    lock(self);
    Py_BEGIN_ALLOW_THREADS
    rc = ctn_write_vtu(self->model->ctx, PyBytes_AS_STRING(path), self->model->m, self->s, j);
    Py_END_ALLOW_THREADS
    Py_DECREF(path);
    return finish(self, rc, Py_NewRef(Py_None));
}

/* write_results(dir): result.json, nodes.csv, elements.csv, result.vtu (ctn_write_results). */
static PyObject *sol_write_results(PyObject *op, PyObject *args)
{
    pyctn_solution *self = (pyctn_solution *)op;
    PyObject *path;
    if (!PyArg_ParseTuple(args, "O&", PyUnicode_FSConverter, &path)) return NULL;
    int rc;
    lock(self);
    Py_BEGIN_ALLOW_THREADS
    rc = ctn_write_results(self->model->ctx, PyBytes_AS_STRING(path), self->model->m, self->s);
    Py_END_ALLOW_THREADS
    Py_DECREF(path);
    return finish(self, rc, Py_NewRef(Py_None));
}

/* json(pretty) -> str: the text of `catena solve --json` (ctn_result_json). */
static PyObject *sol_json(PyObject *op, PyObject *args)
{
    pyctn_solution *self = (pyctn_solution *)op;
    int pretty = 1, rc;
    char *text = NULL;
    if (!PyArg_ParseTuple(args, "|p", &pretty)) return NULL;
    lock(self);
    Py_BEGIN_ALLOW_THREADS
    rc = ctn_result_json(self->model->ctx, self->model->m, self->s, pretty, &text);
    Py_END_ALLOW_THREADS
    PyObject *r = rc ? NULL : PyUnicode_FromString(text);
    ctn_json_free(text);
    if (!rc && !r) {
        PyThread_release_lock(self->model->lock);
        return NULL;
    }
    return finish(self, rc, r);
}

static PyMethodDef sol_methods[] = {
    { "summary", sol_summary, METH_NOARGS, "summary() -> dict (ctn_solve_summary)" },
    { "step_count", sol_step_count, METH_NOARGS, "step_count() -> int" },
    { "step", sol_step, METH_VARARGS, "step(k) -> (name, reason, load_factor, iterations, d, reactions, rotations, moments)" },
    { "elements", sol_elements, METH_VARARGS, "elements(k) -> (force, stress, strain, length, slack, utilisation)" },
    { "groups", sol_groups, METH_VARARGS, "groups(k) -> list of dicts" },
    { "cables", sol_cables, METH_NOARGS, "cables() -> list of dicts" },
    { "catenary", sol_catenary, METH_VARARGS, "catenary(k, i) -> dict" },
    { "element_shape", sol_element_shape, METH_VARARGS, "element_shape(k, i, n) -> Array (n, 3)" },
    { "histories", sol_histories, METH_NOARGS, "histories() -> (residual, increment)" },
    { "stability", sol_stability, METH_NOARGS, "stability() -> dict or None" },
    { "modes", pyctn_solution_modes, METH_NOARGS, "modes() -> None or dict of arrays" },
    { "write_vtu", sol_write_vtu, METH_VARARGS, "write_vtu(path, step=-1)" },
    { "write_results", sol_write_results, METH_VARARGS, "write_results(dir)" },
    { "json", sol_json, METH_VARARGS, "json(pretty=True) -> str" },
    { NULL, NULL, 0, NULL }
};

static int sol_traverse(PyObject *op, visitproc visit, void *arg)
{
    Py_VISIT(((pyctn_solution *)op)->model);
    Py_VISIT(Py_TYPE(op));
    return 0;
}

static void sol_dealloc(PyObject *op)
{
    pyctn_solution *self = (pyctn_solution *)op;
    PyTypeObject *type = Py_TYPE(op);
    PyObject_GC_UnTrack(op);
    ctn_solution_destroy(&self->s);
    Py_CLEAR(self->model);
    PyObject_GC_Del(op);
    Py_DECREF(type);
}

static PyType_Slot sol_slots[] = {
    { Py_tp_dealloc, (void *)sol_dealloc },
    { Py_tp_traverse, (void *)sol_traverse },
    { Py_tp_methods, sol_methods },
    { Py_tp_doc, (void *)"A catena solution (use catena.Solution)." },
    { 0, NULL }
};

PyType_Spec pyctn_solution_spec = {
    "catena._catena.Solution", sizeof(pyctn_solution), 0, Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC | PYCTN_NOINIT, sol_slots
};
