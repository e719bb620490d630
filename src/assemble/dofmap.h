/* Internal: the DOF map. Each node carries the DOFs of the element families that reach
 * it (3 translations today; a beam family would give its nodes 6). A state vector (the
 * displacements d, forces f) holds the DOFs of every node in node order; eq numbers the
 * free ones (the equations). The model speaks in translations, 3 per node (loads,
 * supports, results): ctn_dofmap_from3 / _to3 convert. Nothing outside this map assumes
 * how many DOFs a node has. */
#ifndef CTN_ASSEMBLE_DOFMAP_H
#define CTN_ASSEMBLE_DOFMAP_H

#include "model/model.h"

typedef struct ctn_dofmap {
    size_t nn;          /* nodes */
    size_t nstate;      /* entries of a state vector */
    size_t ndof;        /* free DOFs (equations) */
    int uniform;        /* > 0: every node has this many DOFs (first[i] = uniform i) */
    size_t *first;      /* nn + 1: node i's DOFs are state[first[i] .. first[i + 1]) */
    int *eq;            /* nstate: equation number, -1 if fixed */
    int *dof_node;      /* ndof: node index of each equation */
    int *dof_dir;       /* ndof: its direction (0 x, 1 y, 2 z, 3.. rotations) */
} ctn_dofmap;

/* Build the map for nodes with ndof_node[i] DOFs each (>= 3: the first three are the
 * translations x, y, z, fixed by the node's fix flags; the others are free). */
int ctn_dofmap_build(ctn_ctx *ctx, const ctn_model *m, const unsigned char *ndof_node,
                     ctn_dofmap *map);
void ctn_dofmap_free(ctn_dofmap *map);

/* First state entry of node i. */
static inline size_t ctn_dofmap_node(const ctn_dofmap *map, size_t i)
{
    return map->uniform ? i * (size_t)map->uniform : map->first[i];
}
/* DOFs of node i. */
static inline int ctn_dofmap_count(const ctn_dofmap *map, size_t i)
{
    return map->uniform ? map->uniform : (int)(map->first[i + 1] - map->first[i]);
}

/* state = v3 (3 per node) on the translations, 0 on the other DOFs. */
void ctn_dofmap_from3(const ctn_dofmap *map, const double *v3, double *state);
/* v3 (3 per node) = the translations of state. */
void ctn_dofmap_to3(const ctn_dofmap *map, const double *state, double *v3);

#endif
