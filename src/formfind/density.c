/* Force densities and target forces on a model's elements, and the options' defaults. */
#include "formfind/ff.h"

#include <math.h>
#include <string.h>

int ctn_model_set_force_density(ctn_model *m, int first, int last, double q, double force)
{
    if (!m) return CTN_ERR_INVALID;
    if (!isfinite(q) || !isfinite(force) || q < 0 || force < 0 || (q > 0) == (force > 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "form finding: give one positive q or force (got q = %g, force = %g)", q, force);
    size_t hit = 0;
    for (size_t e = 0; e < m->elements.n; e++) {
        ctn_element *el = &m->elements.v[e];
        if (el->id < first || el->id > last) continue;
        el->ff_q = q;
        el->ff_force = force;
        hit++;
    }
    return hit ? CTN_OK : ctn_model_error(m, CTN_ERR_MODEL, "form finding: no element with id in %d-%d", first, last);
}

int ctn_model_force_density(const ctn_model *m, size_t i, double *q, double *force)
{
    if (!m || i >= m->elements.n) return CTN_ERR_INVALID;
    if (q) *q = m->elements.v[i].ff_q;
    if (force) *force = m->elements.v[i].ff_force;
    return CTN_OK;
}

size_t ctn_model_force_density_count(const ctn_model *m)
{
    size_t n = 0;
    for (size_t e = 0; m && e < m->elements.n; e++) n += m->elements.v[e].ff_q > 0 || m->elements.v[e].ff_force > 0;
    return n;
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
