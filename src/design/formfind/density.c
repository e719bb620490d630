/* Force densities and target forces on a model's elements, and the options' defaults. */
#include "design/formfind/ff.h"

#include <math.h>
#include <string.h>

int ctn_model_set_force_density(ctn_model *m, int first, int last, double q, double force)
{
    if (!m) return CTN_ERR_INVALID;
    if (!isfinite(q) || !isfinite(force) || q < 0 || force < 0 || (q > 0) == (force > 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "form finding: give one positive q or force (got q = %g, force = %g)", q, force);
    size_t hit = 0;
    for (size_t e = 0; e < m->elements.n; e++) hit += m->elements.v[e].id >= first && m->elements.v[e].id <= last;
    if (!hit) return ctn_model_error(m, CTN_ERR_MODEL, "form finding: no element with id in %d-%d", first, last);
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->densities, hit);        /* then nothing fails */
    for (size_t e = 0; e < m->elements.n && !rc; e++)
        if (m->elements.v[e].id >= first && m->elements.v[e].id <= last) rc = ctn_model_put_density(m, e, q, force);
    return rc;
}

int ctn_model_force_density(const ctn_model *m, size_t i, double *q, double *force)
{
    if (!m || i >= m->elements.n) return CTN_ERR_INVALID;
    const ctn_density *d = ctn_model_density_of(m, i);
    if (q) *q = d ? d->q : 0;
    if (force) *force = d ? d->force : 0;
    return CTN_OK;
}

size_t ctn_model_force_density_count(const ctn_model *m)
{
    return m ? m->densities.n : 0;
}

void ctn_formfind_options_init(ctn_formfind_options *o)
{
    if (!o) return;
    memset(o, 0, sizeof *o);
    o->size = sizeof *o;
    o->tol = 1e-10;
    o->maxit = 1000;
}

double ctn_ff_length(const ctn_model *m, size_t e)
{
    const int *nd = ctn_elem_nodes(m, e);
    const double *a = m->nodes.v[nd[0]].X, *b = m->nodes.v[nd[1]].X;
    double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);      /* as ctn_axial_chord */
}
