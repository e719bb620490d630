/* The DOF map: state layout per node and the numbering of the free DOFs, node by node. */
#include "assemble/dofmap.h"

#include <string.h>

static int layout(ctn_ctx *ctx, ctn_dofmap *map, const unsigned char *ndof_node)
{
    int u = map->nn ? ndof_node[0] : 3;
    for (size_t i = 1; i < map->nn && u; i++)
        if (ndof_node[i] != u) u = 0;
    map->uniform = u;
    map->first = ctn_malloc(ctx, map->nn + 1, sizeof(size_t));
    if (!map->first) return CTN_ERR_NOMEM;
    map->first[0] = 0;
    for (size_t i = 0; i < map->nn; i++) map->first[i + 1] = map->first[i] + ndof_node[i];
    map->nstate = map->first[map->nn];
    if (u) {                                      /* the formula serves: drop the table */
        ctn_free(map->first);
        map->first = NULL;
    }
    return CTN_OK;
}

int ctn_dofmap_build(ctn_ctx *ctx, const ctn_model *m, const unsigned char *ndof_node,
                     ctn_dofmap *map)
{
    memset(map, 0, sizeof *map);
    map->nn = m->nodes.n;
    int rc = layout(ctx, map, ndof_node);
    if (rc) return rc;
    if (map->nstate > 0x7fffffff) return ctn_error(ctx, CTN_ERR_MODEL, "model too large: %zu degrees of freedom", map->nstate);
    map->eq = ctn_malloc(ctx, map->nstate ? map->nstate : 1, sizeof(int));
    if (!map->eq) return CTN_ERR_NOMEM;
    size_t n = 0;
    for (size_t i = 0; i < map->nn; i++) {
        size_t s = ctn_dofmap_node(map, i);
        for (int k = 0; k < ctn_dofmap_count(map, i); k++)
            map->eq[s + (size_t)k] = (m->nodes.v[i].fix >> k) & 1u ? -1 : (int)n++;
        map->rot += ctn_dofmap_count(map, i) == 6;
    }
    map->rot_update = ctn_rot_update_add;
    map->ndof = n;
    map->dof_node = ctn_malloc(ctx, n ? n : 1, sizeof(int));
    map->dof_dir = ctn_malloc(ctx, n ? n : 1, sizeof(int));
    if (!map->dof_node || !map->dof_dir) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < map->nn; i++) {
        size_t s = ctn_dofmap_node(map, i);
        for (int k = 0; k < ctn_dofmap_count(map, i); k++) {
            int q = map->eq[s + (size_t)k];
            if (q < 0) continue;
            map->dof_node[q] = (int)i;
            map->dof_dir[q] = k;
        }
    }
    return CTN_OK;
}

void ctn_dofmap_free(ctn_dofmap *map)
{
    ctn_free(map->first);
    ctn_free(map->eq);
    ctn_free(map->dof_node);
    ctn_free(map->dof_dir);
    memset(map, 0, sizeof *map);
}

void ctn_dofmap_from3(const ctn_dofmap *map, const double *v3, double *state)
{
    if (map->uniform == 3) {
        memcpy(state, v3, map->nstate * sizeof(double));
        return;
    }
    memset(state, 0, map->nstate * sizeof(double));
    for (size_t i = 0; i < map->nn; i++)
        memcpy(state + ctn_dofmap_node(map, i), v3 + 3 * i, 3 * sizeof(double));
}

void ctn_dofmap_to3(const ctn_dofmap *map, const double *state, double *v3)
{
    if (map->uniform == 3) {
        memcpy(v3, state, map->nstate * sizeof(double));
        return;
    }
    for (size_t i = 0; i < map->nn; i++)
        memcpy(v3 + 3 * i, state + ctn_dofmap_node(map, i), 3 * sizeof(double));
}

void ctn_dofmap_rot_from3(const ctn_dofmap *map, const double *v3, double *state)
{
    for (size_t i = 0; map->rot && i < map->nn; i++)
        if (ctn_dofmap_count(map, i) == 6) memcpy(state + ctn_dofmap_node(map, i) + 3, v3 + 3 * i, 3 * sizeof(double));
}

void ctn_dofmap_rot_to3(const ctn_dofmap *map, const double *state, double *v3)
{
    memset(v3, 0, 3 * map->nn * sizeof(double));
    for (size_t i = 0; map->rot && i < map->nn; i++)
        if (ctn_dofmap_count(map, i) == 6) memcpy(v3 + 3 * i, state + ctn_dofmap_node(map, i) + 3, 3 * sizeof(double));
}

void ctn_rot_update_add(double *theta, const double *dtheta)
{
    for (int j = 0; j < 3; j++) theta[j] += dtheta[j];
}

/* The update of a model with rotations: node by node, each node's kind. */
static void update_nodes(const ctn_dofmap *map, double *d, double alpha, const double *v)
{
    for (size_t i = 0; i < map->nn; i++) {
        size_t s = ctn_dofmap_node(map, i);
        for (int k = 0; k < 3; k++)
            if (map->eq[s + (size_t)k] >= 0) d[s + (size_t)k] += alpha * v[map->eq[s + (size_t)k]];
        if (ctn_dofmap_count(map, i) != 6) continue;
        double dt[3];
        int nfree = 0;
        for (int k = 0; k < 3; k++) {
            int q = map->eq[s + 3 + (size_t)k];
            dt[k] = q >= 0 ? alpha * v[q] : 0.0;
            nfree += q >= 0;
        }
        if (nfree == 3) map->rot_update(d + s + 3, dt);
        else ctn_rot_update_add(d + s + 3, dt);        /* a plane model's: psi's own components */
    }
}

void ctn_dofmap_axpy(const ctn_dofmap *map, double *d, double alpha, const double *v)
{
    for (size_t i = 0; i < map->nstate; i++) {
        int q = map->eq[i];
        if (q >= 0) d[i] += alpha * v[q];
    }
}

void ctn_dofmap_update(const ctn_dofmap *map, double *d, double alpha, const double *v)
{
    if (map->rot) update_nodes(map, d, alpha, v);
    else ctn_dofmap_axpy(map, d, alpha, v);                    /* translations only */
}
