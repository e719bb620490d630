/* Mass: point masses at nodes, the mass per length of a section, standard gravity in
 * the model's units. Mass is in the consistent unit force s^2 / length (docs/format.md). */
#include "model/model.h"

#include <math.h>
#include <string.h>

#define CTN_G0 9.80665          /* standard gravity [m/s^2] */

double ctn_model_standard_gravity(const ctn_model *m)
{
    if (!m || !m->length_unit[0] || !(m->lconv > 0)) return 0.0;
    return CTN_G0 / m->lconv;                        /* m/s^2 -> length/s^2 */
}

int ctn_model_set_node_mass(ctn_model *m, int id, double mass)
{
    int i;
    if (!m) return CTN_ERR_INVALID;
    int rc = ctn_model_node_lookup(m, id, &i);
    if (rc) return rc;
    if (!(isfinite(mass) && mass >= 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "node %d: mass must be >= 0 and finite (got %g)", id, mass);
    m->nodes.v[i].mass = mass;
    return CTN_OK;
}

double ctn_model_section_mass(const ctn_model *m, int i)
{
    const ctn_section *s = &m->sections.v[i];
    double g = ctn_model_standard_gravity(m);
    if (s->mass >= 0) return s->mass;
    if (s->w == 0) return 0.0;
    return g > 0 ? s->w / g : NAN;                   /* m' = w / g */
}
