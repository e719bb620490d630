/* Internal: the writers take the results of the nodes a piece at a time: a range of
 * nodes [lo, hi) with their displacements, reactions, rotations and moments, asked of a
 * source in node order. One process: the solution's own arrays, cut into pieces of
 * CTN_PIECE_NODES (ctn_pieces_local). A distributed run passes a source that brings each
 * process's owned nodes in turn (dist/layout.h), so no writer needs the whole arrays at
 * once. */
#ifndef CTN_IO_PIECE_H
#define CTN_IO_PIECE_H

#include "catena/solve.h"

#define CTN_PIECE_NODES 4096

typedef struct ctn_node_piece {
    size_t lo, hi;             /* the nodes (model order) */
    const double *d, *react;   /* 3 per node, node lo first */
    const double *rot, *mom;   /* the same, NULL when the model has no rotations */
} ctn_node_piece;

typedef struct ctn_pieces {
    /* the piece of step k that starts at node lo < n (n the model's nodes): out->hi > lo;
       CTN_ERR_INVALID for a step the solution does not have */
    int (*nodes)(void *ud, const ctn_solution *s, size_t k, size_t lo, size_t n, ctn_node_piece *out);
    void *ud;
} ctn_pieces;

extern const ctn_pieces ctn_pieces_local;

/* Node i of a piece (lo <= i < hi): its 3 displacements, reactions, rotations, moments
 * (the last two NULL without rotations). */
static inline const double *ctn_piece_d(const ctn_node_piece *p, size_t i) { return p->d + 3 * (i - p->lo); }
static inline const double *ctn_piece_react(const ctn_node_piece *p, size_t i) { return p->react + 3 * (i - p->lo); }
static inline const double *ctn_piece_rot(const ctn_node_piece *p, size_t i)
{
    return p->rot ? p->rot + 3 * (i - p->lo) : NULL;
}
static inline const double *ctn_piece_mom(const ctn_node_piece *p, size_t i)
{
    return p->mom ? p->mom + 3 * (i - p->lo) : NULL;
}

#endif
