/* Form-finding parameters of members (a force density q= or a target force force=), kept
 * beside the elements rather than in every element's record: the few members that have
 * them, by increasing element index. */
#include "model/model.h"

#include <string.h>

/* Position of element e's record, or where it would go. */
static size_t find(const ctn_model *m, size_t e)
{
    size_t lo = 0, hi = m->densities.n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (m->densities.v[mid].e < e) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

const ctn_density *ctn_model_density_of(const ctn_model *m, size_t e)
{
    size_t k = find(m, e);
    return k < m->densities.n && m->densities.v[k].e == e ? &m->densities.v[k] : NULL;
}

int ctn_model_put_density(ctn_model *m, size_t e, double q, double force)
{
    size_t k = find(m, e);
    if (k < m->densities.n && m->densities.v[k].e == e) {
        m->densities.v[k].q = q;
        m->densities.v[k].force = force;
        return CTN_OK;
    }
    int rc = CTN_ARRAY_RESERVE(m->ctx, m->densities, 1);
    if (rc) return rc;
    memmove(m->densities.v + k + 1, m->densities.v + k, (m->densities.n - k) * sizeof *m->densities.v);
    m->densities.v[k] = (ctn_density){ e, q, force };
    m->densities.n++;
    return CTN_OK;
}
