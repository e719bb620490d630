/* Solve options from and to a dict whose keys are the `solve` and `modes` lines' keys
 * (docs/format.md): tol, dtol, maxit, method, ordering, linesearch, linear_solver, reuse,
 * threads, steps, cutbacks, arclength, arcsteps, lambda; modes (count), mass, shift,
 * eigen_solver. */
#include "pycatena.h"

#include <string.h>

typedef enum { K_DOUBLE, K_INT, K_BOOL, K_WORD } kind;

typedef struct key {
    const char *name;
    kind k;
    size_t off;                      /* in ctn_solve_options */
    const char *const *words;        /* K_WORD: the names of 0, 1, ... */
    int nwords;
} key;

static const char *const orderings[] = { "auto", "natural", "amd", "metis" };
static const char *const methods[] = { "auto", "newton", "arclength" };
static const char *const masses[] = { "consistent", "lumped" };
static const char *const eigens[] = { "block", "arpack", "auto" };
static const char *const linear[] = { "cholmod", "cholmod-ldl" };

#define OFF(f) offsetof(ctn_solve_options, f)
static const key keys[] = {
    { "tol", K_DOUBLE, OFF(tol), NULL, 0 },
    { "dtol", K_DOUBLE, OFF(dtol), NULL, 0 },
    { "maxit", K_INT, OFF(maxit), NULL, 0 },
    { "ordering", K_WORD, OFF(ordering), orderings, 4 },
    { "method", K_WORD, OFF(method), methods, 3 },
    { "linesearch", K_BOOL, OFF(linesearch), NULL, 0 },
    { "reuse", K_BOOL, OFF(reuse), NULL, 0 },
    { "threads", K_INT, OFF(threads), NULL, 0 },
    { "steps", K_INT, OFF(steps), NULL, 0 },
    { "cutbacks", K_INT, OFF(maxcuts), NULL, 0 },
    { "arclength", K_DOUBLE, OFF(arclength), NULL, 0 },
    { "arcsteps", K_INT, OFF(arcsteps), NULL, 0 },
    { "lambda", K_DOUBLE, OFF(lambda_max), NULL, 0 },
    { "modes", K_INT, OFF(modal.count), NULL, 0 },
    { "mass", K_WORD, OFF(modal.mass), masses, 2 },
    { "shift", K_DOUBLE, OFF(modal.shift), NULL, 0 },
    { "eigen_solver", K_WORD, OFF(modal.solver), eigens, 3 },
};
#define NKEYS (sizeof keys / sizeof keys[0])

static int set_word(const key *k, PyObject *v, char *field)
{
    const char *w = PyUnicode_Check(v) ? PyUnicode_AsUTF8(v) : NULL;
    for (int i = 0; w && i < k->nwords; i++)
        if (!strcmp(w, k->words[i])) {
            int e = i;                       /* every such field is an enum (int-sized) */
            memcpy(field, &e, sizeof e);
            return 0;
        }
    if (!PyErr_Occurred()) PyErr_Format(PyExc_ValueError, "solve option %s=%R: not one of the names it takes", k->name, v);
    return -1;
}

static int set_key(const key *k, PyObject *v, ctn_solve_options *opt)
{
    char *field = (char *)opt + k->off;
    if (k->k == K_WORD) return set_word(k, v, field);
    if (k->k == K_DOUBLE) {
        double d = PyFloat_AsDouble(v);
        if (d == -1.0 && PyErr_Occurred()) return -1;
        memcpy(field, &d, sizeof d);
        return 0;
    }
    int i;
    if (k->k == K_BOOL) {
        if ((i = PyObject_IsTrue(v)) < 0) return -1;
    } else {
        long l = PyLong_AsLong(v);
        if (l == -1 && PyErr_Occurred()) return -1;
        if (l < -0x7fffffffL || l > 0x7fffffffL) {
            PyErr_Format(PyExc_OverflowError, "solve option %s=%ld is out of range", k->name, l);
            return -1;
        }
        i = (int)l;
    }
    memcpy(field, &i, sizeof i);
    return 0;
}

static int set_linear(PyObject *v, ctn_solve_options *opt)
{
    const char *w = v == Py_None ? NULL : PyUnicode_Check(v) ? PyUnicode_AsUTF8(v) : "";
    if (!w) {
        if (PyErr_Occurred()) return -1;
        opt->linear_solver = NULL;
        return 0;
    }
    for (int i = 0; i < 2; i++)
        if (!strcmp(w, linear[i])) {
            opt->linear_solver = linear[i];          /* static: outlives the solve */
            return 0;
        }
    PyErr_Format(PyExc_ValueError, "solve option linear_solver=%R: not 'cholmod' or 'cholmod-ldl'", v);
    return -1;
}

int pyctn_options_parse(pyctn_state *st, PyObject *dict, ctn_ctx *ctx, ctn_solve_options *opt)
{
    PyObject *name, *v;
    Py_ssize_t pos = 0;
    while (PyDict_Next(dict, &pos, &name, &v)) {
        const char *n = PyUnicode_Check(name) ? PyUnicode_AsUTF8(name) : NULL;
        if (!n) {
            if (!PyErr_Occurred()) PyErr_SetString(PyExc_TypeError, "solve option names are strings");
            return -1;
        }
        if (!strcmp(n, "linear_solver")) {
            if (set_linear(v, opt)) return -1;
            continue;
        }
        size_t i = 0;
        while (i < NKEYS && strcmp(n, keys[i].name)) i++;
        if (i == NKEYS) {
            PyErr_Format(PyExc_TypeError, "unknown solve option '%s'", n);
            return -1;
        }
        if (set_key(&keys[i], v, opt)) return -1;
    }
    int rc = ctn_solve_options_check(ctx, opt);
    if (rc) {
        pyctn_raise_msg(st, CTN_ERR_INVALID, ctn_ctx_message(ctx));
        return -1;
    }
    return 0;
}

static int put(PyObject *d, const char *name, PyObject *v)
{
    int rc = v ? PyDict_SetItemString(d, name, v) : -1;
    Py_XDECREF(v);
    return rc;
}

PyObject *pyctn_options_dict(const ctn_solve_options *opt)
{
    PyObject *d = PyDict_New();
    for (size_t i = 0; d && i < NKEYS; i++) {
        const key *k = &keys[i];
        const char *field = (const char *)opt + k->off;
        PyObject *v;
        double x;
        int n;
        if (k->k == K_DOUBLE) {
            memcpy(&x, field, sizeof x);
            v = PyFloat_FromDouble(x);
        } else {
            memcpy(&n, field, sizeof n);
            v = k->k == K_BOOL ? PyBool_FromLong(n)
              : k->k == K_INT ? PyLong_FromLong(n)
              : PyUnicode_FromString(n >= 0 && n < k->nwords ? k->words[n] : "?");
        }
        if (put(d, k->name, v)) Py_CLEAR(d);
    }
    if (d && put(d, "linear_solver", opt->linear_solver ? PyUnicode_FromString(opt->linear_solver) : Py_NewRef(Py_None)))
        Py_CLEAR(d);
    return d;
}
