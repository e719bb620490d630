/* The pieces of one process: the solution's arrays (piece.h). */
#include "io/piece.h"

static int local_nodes(void *ud, const ctn_solution *s, size_t k, size_t lo, size_t n, ctn_node_piece *out)
{
    (void)ud;
    ctn_step_result st;
    const double *rot = NULL, *mom = NULL;
    if (lo >= n || ctn_solution_step(s, k, &st) || ctn_solution_step_rotations(s, k, &rot, &mom))
        return CTN_ERR_INVALID;
    out->lo = lo;
    out->hi = n - lo > CTN_PIECE_NODES ? lo + CTN_PIECE_NODES : n;
    out->d = st.d + 3 * lo;
    out->react = st.react + 3 * lo;
    out->rot = rot ? rot + 3 * lo : NULL;
    out->mom = mom ? mom + 3 * lo : NULL;
    return CTN_OK;
}

const ctn_pieces ctn_pieces_local = { local_nodes, NULL };
