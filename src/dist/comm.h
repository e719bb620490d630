/* Internal: the communicator of the processes that share one analysis. Everything that
 * crosses processes goes through its ops: reductions of the partial sums each process
 * computes over the entries it owns, and the values of the ghost entries (owned by
 * another process, read by this one). One process today: the serial communicator,
 * whose reductions return their input and whose processes have no ghosts. A distributed
 * engine (MPI) sets its own on the context (ctn_ctx_set_comm). */
#ifndef CTN_DIST_COMM_H
#define CTN_DIST_COMM_H

#include "catena/core.h"

#include <stddef.h>

typedef enum ctn_reduce_op { CTN_REDUCE_SUM = 0, CTN_REDUCE_MAX = 1, CTN_REDUCE_MIN = 2 } ctn_reduce_op;

typedef struct ctn_layout ctn_layout;
struct ctn_linsolve_ops;

typedef struct ctn_comm_ops {
    const char *name;                                  /* "serial", "mpi" */
    int (*rank)(const void *impl);
    int (*size)(const void *impl);
    /* v[0 .. n-1] <- op over the processes of their v, in place (every process gets it);
     * the result must not depend on the process (a fixed order of summation) */
    int (*allreduce)(void *impl, double *v, size_t n, ctn_reduce_op op);
    /* the ghost entries of v (after the owned ones, lay's order) <- their owners' values */
    int (*ghosts)(void *impl, const ctn_layout *lay, double *v);
    /* the linear solvers that run over this communicator's processes (NULL-terminated;
     * NULL: none beyond the registry's, linalg/linsolve.c) */
    const struct ctn_linsolve_ops *const *solvers;
} ctn_comm_ops;

typedef struct ctn_comm {
    const ctn_comm_ops *ops;
    void *impl;
} ctn_comm;

/* The communicator of one process (constant: no state). */
extern const ctn_comm ctn_comm_serial;

/* The context's communicator (the serial one unless set). */
const ctn_comm *ctn_ctx_comm(const ctn_ctx *ctx);
/* Set it (NULL: the serial one); the comm must outlive the context's analyses. */
void ctn_ctx_set_comm(ctn_ctx *ctx, const ctn_comm *comm);

static inline int ctn_comm_rank(const ctn_comm *c) { return c->ops->rank(c->impl); }
static inline int ctn_comm_size(const ctn_comm *c) { return c->ops->size(c->impl); }

#endif
