/* A beam's end forces rebuilt from a step's displacements and rotations (the public
 * accessor ctn_solution_beam, for the writers). */
#include "element/beam3.h"
#include "problem/solution.h"

#include <math.h>
#include <string.h>

int ctn_solution_beam(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, ctn_beam_result *out)
{
    ctn_beam_props p;
    double X[6], u[12], f[12];
    if (!out || out->size < sizeof *out || !m || !s || k >= s->nsteps || i >= m->elements.n || i >= s->ne ||
        m->nodes.n != s->nn || ctn_element_family(m->elements.v[i].type) != &ctn_beam3_ops || !s->steps[k].rot)
        return CTN_ERR_INVALID;
    const int *nd = ctn_elem_nodes(m, i);
    for (int a = 0; a < 2; a++)
        for (int j = 0; j < 3; j++) {
            X[3 * a + j] = m->nodes.v[nd[a]].X[j];
            u[6 * a + j] = s->steps[k].d[3 * (size_t)nd[a] + (size_t)j];
            u[6 * a + 3 + j] = s->steps[k].rot[3 * (size_t)nd[a] + (size_t)j];
        }
    ctn_beam3_ops.setup(m, i, &p);
    if (ctn_beam_end_forces(&p, X, u, f)) return CTN_ERR_NOCONV;
    memset(out, 0, sizeof *out);
    out->size = sizeof *out;
    memcpy(out->end[0], f, 6 * sizeof *f);
    memcpy(out->end[1], f + 6, 6 * sizeof *f);
    out->N = f[6];
    out->T = f[9];
    out->M_max = fmax(hypot(f[4], f[5]), hypot(f[10], f[11]));
    return CTN_OK;
}
