/* Internal: the DOF map. Each node carries the DOFs of the element families that reach
 * it: 3 (translations x, y, z), or 6 (and rotations rx, ry, rz) when a family of 6 DOFs
 * per node reaches it (the most over its families; a 3-DOF family attaches to the
 * translations). A state vector (the displacements d, forces f) holds the DOFs of every
 * node in node order; eq numbers the free ones (the equations). The model speaks in
 * vectors of 3 per node (loads, supports, results), translations and rotations apart:
 * ctn_dofmap_from3 / _to3 and ctn_dofmap_rot_from3 / _rot_to3 convert. Nothing outside
 * this map assumes how many DOFs a node has.
 *
 * The state update. Translations are updated by addition, d += alpha dd. Rotations go
 * through the map's rot_update op, node by node: the default adds the rotation vectors
 * (right for small rotations, the rspring family, and for the corotational beam, whose
 * DOFs are the nodes' total rotation vectors: its tangent is the Hessian in them); a
 * family of spin increments would set it to compose them (R = exp(alpha dtheta) R) when
 * the problem is built. A model without rotations never calls it (ctn_problem_update keeps its plain
 * loop). */
#ifndef CTN_ASSEMBLE_DOFMAP_H
#define CTN_ASSEMBLE_DOFMAP_H

#include "model/model.h"

/* Update the rotations theta (3) of one node by the increment dtheta (3, alpha folded in;
 * 0 on its fixed rotations). */
typedef void (*ctn_rot_update_fn)(double *theta, const double *dtheta);
/* The default: theta += dtheta. */
void ctn_rot_update_add(double *theta, const double *dtheta);
/* A family of finite rotations' (rot_compose.c): theta is the node's rotation vector
 * psi, dtheta a spin: exp(psi) <- exp(dtheta) exp(psi), psi kept continuous (past 2 pi).
 * The map then adds the rotations of a node with some fixed and some free. */
void ctn_rot_update_compose(double *theta, const double *dtheta);

typedef struct ctn_dofmap {
    size_t nn;          /* nodes */
    size_t nstate;      /* entries of a state vector */
    size_t ndof;        /* free DOFs (equations) */
    int uniform;        /* > 0: every node has this many DOFs (first[i] = uniform i) */
    size_t *first;      /* nn + 1: node i's DOFs are state[first[i] .. first[i + 1]) */
    int *eq;            /* nstate: equation number, -1 if fixed */
    int *dof_node;      /* ndof: node index of each equation */
    int *dof_dir;       /* ndof: its direction (0 x, 1 y, 2 z, 3.. rotations) */
    size_t rot;         /* nodes with rotations (6 DOFs); 0: translations only */
    ctn_rot_update_fn rot_update;  /* the update of a node's rotations (ctn_rot_update_add) */
} ctn_dofmap;

/* Build the map for nodes with ndof_node[i] DOFs each (3 or 6: the translations x, y, z
 * and the rotations rx, ry, rz, each fixed by its bit of the node's fix flags). */
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

/* state = v3 (3 per node) on the rotations of the nodes that have them. */
void ctn_dofmap_rot_from3(const ctn_dofmap *map, const double *v3, double *state);
/* v3 (3 per node) = the rotations of state, 0 for a node without. */
void ctn_dofmap_rot_to3(const ctn_dofmap *map, const double *state, double *v3);
/* d (state) += alpha v (ndof) on the free DOFs: a sum of vectors. */
void ctn_dofmap_axpy(const ctn_dofmap *map, double *d, double alpha, const double *v);
/* The state update: d (state) += alpha v (ndof) on the free translations, the free
 * rotations through rot_update; ctn_dofmap_axpy when the model has no rotations. */
void ctn_dofmap_update(const ctn_dofmap *map, double *d, double alpha, const double *v);

#endif
