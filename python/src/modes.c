/* Solution.modes(): the modal analysis of a solution as arrays (copies, one C loop). */
#include "pycatena.h"

#include <string.h>

enum { M_EIG, M_OMEGA, M_FREQ, M_PERIOD, M_NDOUBLE };

typedef struct mode_arrays {
    pyctn_array *v[M_NDOUBLE], *kind, *node, *part, *meff, *shape;
} mode_arrays;

static void release(mode_arrays *a)
{
    for (int c = 0; c < M_NDOUBLE; c++) Py_XDECREF(a->v[c]);
    Py_XDECREF(a->kind);
    Py_XDECREF(a->node);
    Py_XDECREF(a->part);
    Py_XDECREF(a->meff);
    Py_XDECREF(a->shape);
}

static int alloc(pyctn_state *st, mode_arrays *a, Py_ssize_t k, Py_ssize_t n)
{
    Py_ssize_t s3[2] = { k, 3 }, sh[3] = { k, n, 3 };
    memset(a, 0, sizeof *a);
    for (int c = 0; c < M_NDOUBLE; c++)
        if (!(a->v[c] = pyctn_array_new(st, NULL, NULL, "d", 1, &k))) return -1;
    return (a->kind = pyctn_array_new(st, NULL, NULL, "i", 1, &k)) && (a->node = pyctn_array_new(st, NULL, NULL, "i", 1, &k)) &&
           (a->part = pyctn_array_new(st, NULL, NULL, "d", 2, s3)) && (a->meff = pyctn_array_new(st, NULL, NULL, "d", 2, s3)) &&
           (a->shape = pyctn_array_new(st, NULL, NULL, "d", 3, sh)) ? 0 : -1;
}

static void fill(mode_arrays *a, size_t j, const ctn_mode *md, size_t n)
{
    ((double *)a->v[M_EIG]->data)[j] = md->eigenvalue;
    ((double *)a->v[M_OMEGA]->data)[j] = md->angular_frequency;
    ((double *)a->v[M_FREQ]->data)[j] = md->frequency;
    ((double *)a->v[M_PERIOD]->data)[j] = md->period;
    ((int *)a->kind->data)[j] = (int)md->kind;
    ((int *)a->node->data)[j] = md->node;
    memcpy((double *)a->part->data + 3 * j, md->participation, sizeof md->participation);
    memcpy((double *)a->meff->data + 3 * j, md->effective_mass, sizeof md->effective_mass);
    memcpy((double *)a->shape->data + 3 * n * j, md->shape, 3 * n * sizeof(double));
}

PyObject *pyctn_solution_modes(PyObject *op, PyObject *noargs)
{
    (void)noargs;
    pyctn_solution *self = (pyctn_solution *)op;
    pyctn_state *st = pyctn_state_of(self->model->module);
    size_t k = ctn_solution_mode_count(self->s), n = ctn_model_node_count(self->model->m);
    if (!k) Py_RETURN_NONE;
    mode_arrays a;
    if (alloc(st, &a, (Py_ssize_t)k, (Py_ssize_t)n)) {
        release(&a);
        return NULL;
    }
    for (size_t j = 0; j < k; j++) {
        ctn_mode md;
        if (ctn_solution_mode(self->s, j, &md)) {
            release(&a);
            return pyctn_raise_msg(st, CTN_ERR_INVALID, "a mode could not be read");
        }
        fill(&a, j, &md, n);
    }
    ctn_modal_summary ms;
    ctn_solution_modal_summary(self->s, &ms);
    return Py_BuildValue("{s:N,s:N,s:N,s:N,s:N,s:N,s:N,s:N,s:N,s:(ddd),s:s,s:d}",
                         "eigenvalues", a.v[M_EIG], "angular_frequencies", a.v[M_OMEGA], "frequencies", a.v[M_FREQ],
                         "periods", a.v[M_PERIOD], "kinds", a.kind, "nodes", a.node, "participation", a.part,
                         "effective_mass", a.meff, "shapes", a.shape, "total_mass", ms.total_mass[0],
                         ms.total_mass[1], ms.total_mass[2], "mass", ms.mass == CTN_MASS_LUMPED ? "lumped" : "consistent",
                         "max_residual", ms.max_residual);
}
