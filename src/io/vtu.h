/* Internal: the VTU writer's parts shared with the pieces of an MPI job (vtu_pieces.c):
 * a piece of the model (a range of elements and the nodes they reference), written as
 * result.vtu is, and the arrays a .pvtu declares. */
#ifndef CTN_IO_VTU_H
#define CTN_IO_VTU_H

#include "io/writer.h"

/* A piece: the elements [e0, e1) and its points, points[0 .. npoints - 1] the model's
 * nodes in model order; local[node] a node's point in the piece (nodes not in it:
 * unused). */
typedef struct ctn_vtu_subset {
    size_t e0, e1;
    size_t npoints;
    const size_t *points;
    const size_t *local;
} ctn_vtu_subset;

/* <FieldData> and <Piece> of step k (sub NULL: the whole model), as result.vtu's. */
int ctn_vtu_put_piece(ctn_writer *w, const ctn_solution *s, size_t k, const ctn_vtu_subset *sub);
/* <PPointData> and <PCellData>: the arrays of a piece of step k. */
int ctn_vtu_put_parrays(ctn_writer *w, const ctn_solution *s, size_t k);
/* begin and end of a VTK file: open the output and print text; print text. */
int ctn_vtu_begin_with(void *w, const ctn_model *m, ctn_sink *sink, const char *text);
int ctn_vtu_end_with(void *w, const char *text);
/* result.vtu's begin and end (an UnstructuredGrid file). */
int ctn_vtu_begin(void *w, const ctn_model *m, ctn_sink *sink);
int ctn_vtu_end(void *w);

/* The pieces of an MPI job (vtu_pieces.c), each process of the context's communicator
 * writing its own: the elements split evenly by index, rank r's piece holding
 * [ne r / N, ne (r + 1) / N) and the nodes they reference, nodes of no element with the
 * piece of their own even share; result.pvtu lists them (written by rank 0). */
extern const ctn_writer_ops ctn_writer_vtu_piece;     /* result_rR.vtu (R the rank) */
extern const ctn_writer_ops ctn_writer_pvtu;          /* result.pvtu */
/* The piece file of rank r, in name[CTN_VTU_NAME_MAX]. */
void ctn_vtu_piece_name(char *name, int rank);
/* After a set of size ranks' files is in place in dir: the pieces of an earlier run
 * with more ranks (result_rR.vtu, R >= size) removed, and with one process (no pieces)
 * every piece and result.pvtu. */
int ctn_vtu_pieces_remove_stale(ctn_ctx *ctx, const char *dir, int size);

#endif
