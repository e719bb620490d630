/* A beam member meshed into n elements (ctn_model_add_beam): n - 1 nodes evenly spaced
 * on the chord, numbered after the largest node id; the first element takes the spec's
 * id, the others are numbered from CTN_BEAM_GEN_ID + 1 on (after the largest element id
 * once it is there), out of the way of the ids of the members that follow, in order
 * from the first node to the second. The member's end releases go to its end elements. */
#include "model/model.h"

#include <string.h>

int ctn_model_add_beam(ctn_model *m, const ctn_element_spec *spec, int n)
{
    int ia, ib, rc;
    if (!m || !spec || !spec->nodes || spec->nnodes != 2) return CTN_ERR_INVALID;
    if (n < 1 || n > CTN_BEAM_MAX_N)
        return ctn_model_error(m, CTN_ERR_MODEL, "beam %d: n must be an integer from 1 to %d (got %d)", spec->id,
                               CTN_BEAM_MAX_N, n);
    if ((rc = ctn_model_node_lookup(m, spec->nodes[0], &ia)) || (rc = ctn_model_node_lookup(m, spec->nodes[1], &ib)))
        return rc;
    if (m->max_node_id > 0x7fffffff - n || m->max_element_id > 0x7fffffff - n - CTN_BEAM_GEN_ID)
        return ctn_model_error(m, CTN_ERR_MODEL, "beam %d: generated ids would overflow", spec->id);
    double A[3], B[3];
    memcpy(A, m->nodes.v[ia].X, sizeof A);
    memcpy(B, m->nodes.v[ib].X, sizeof B);
    ctn_element_spec s = *spec;
    s.type = "beam";
    int nodes[2] = { spec->nodes[0], 0 };
    s.nodes = nodes;
    for (int k = 1; k <= n; k++) {
        nodes[1] = spec->nodes[1];
        if (k < n) {
            double X[3], t = (double)k / n;
            for (int j = 0; j < 3; j++) X[j] = A[j] + t * (B[j] - A[j]);
            nodes[1] = m->max_node_id + 1;
            if ((rc = ctn_model_add_node(m, nodes[1], X, 0))) return rc;
        }
        if (k > 1) s.id = (m->max_element_id > CTN_BEAM_GEN_ID ? m->max_element_id : CTN_BEAM_GEN_ID) + 1;
        s.release = spec->release & ((k == 1 ? 7u : 0u) | (k == n ? 56u : 0u));   /* the member's ends */
        if ((rc = ctn_model_add_element_spec(m, &s))) return rc;
        nodes[0] = nodes[1];
    }
    return CTN_OK;
}
