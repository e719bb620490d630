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
struct ctn_pattern;
struct ctn_eigen_info;

typedef struct ctn_comm_ops {
    const char *name;                                  /* "serial", "mpi" */
    int (*rank)(const void *impl);
    int (*size)(const void *impl);
    /* v[0 .. n-1] <- op over the processes of their v, in place (every process gets it);
     * the result must not depend on the process (a fixed order of summation) */
    int (*allreduce)(void *impl, double *v, size_t n, ctn_reduce_op op);
    /* the ghost entries of v (after the owned ones, lay's order) <- their owners' values */
    int (*ghosts)(void *impl, const ctn_layout *lay, double *v);
    /* v[lo .. hi - 1] of every process into every process's v (the ranges of the processes
     * in rank order, consecutive, covering v): a vector each process computed its share of */
    int (*allgather)(void *impl, double *v, size_t lo, size_t hi);
    /* the linear solvers that run over this communicator's processes (NULL-terminated;
     * NULL: none beyond the registry's, linalg/linsolve.c) */
    const struct ctn_linsolve_ops *const *solvers;
    /* Optional (NULL: the library's eigen-solvers, linalg/eigen/eigen.h): the nev
     * (1 <= nev < n) eigenpairs of K x = lambda M x nearest sigma, solved over this
     * communicator's processes (K and M on the replicated pattern p, in its order):
     * lambda ascending, *vecs a new n x (nev + 1) array (ctn_free), the first nev
     * columns the eigenvectors, the same on every process. The MPI module's: SLEPc. */
    int (*eigen)(void *impl, ctn_ctx *ctx, const struct ctn_pattern *p, const double *Kx, const double *Mx,
                 int nev, double sigma, double *lambda, double **vecs, struct ctn_eigen_info *info);
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
