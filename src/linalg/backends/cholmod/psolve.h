/* Internal to linalg/: the triangular solves of a CHOLMOD supernodal LL' factor on two
 * threads (cholmod_psolve.c). CHOLMOD solves on one thread; this is catena's own
 * schedule of the same sweeps over CHOLMOD's factor, read only.
 *
 * The plan splits the supernodal elimination tree into two sets of whole subtrees of
 * about equal work and a "top" (the ancestors of the split, solved on one thread):
 * forward, each thread solves its subtrees (updates to top rows go to a private buffer,
 * summed after the join), then the top; backward, the top, then both subtree sets. The
 * plan depends on the factor's structure only (fixed by the symbolic analysis), so it
 * serves every numeric factorization of that structure. */
#ifndef CTN_LINALG_PSOLVE_H
#define CTN_LINALG_PSOLVE_H

#include "core/ctx.h"

#include <cholmod.h>

typedef struct ctn_psolve ctn_psolve;

/* The plan for factor L (supernodal LL', symbolic part only). *out is NULL (status
 * CTN_OK) when L is not a supernodal LL' factor or its tree has no useful split
 * (the subtree sets would hold less than half of the work). Owned by the caller. */
int ctn_psolve_create(ctn_ctx *ctx, const cholmod_factor *L, ctn_psolve **out);
void ctn_psolve_destroy(ctn_psolve **p);
/* X = A \ B for the n x k block B (columns, leading dimension n) with L L' = P A P'
 * (CHOLMOD's factor of A, numerically valid): X may be B (all of B is read before X is
written). threads: 2 runs
 * the subtree sets on two threads, 1 one after the other (the same arithmetic: the
 * results are identical). Workspace grows with k (CTN_ERR_NOMEM if it cannot). */
int ctn_psolve_solve(ctn_psolve *p, const cholmod_factor *L, const double *B, double *X, size_t k, int threads);
/* Shares of the factor's entries: in the two subtree sets and the top (sum 1). */
void ctn_psolve_shares(const ctn_psolve *p, double share[3]);

#endif
