/* Internal: how the entries of a vector (or the rows and columns of a matrix) are laid
 * out over the processes of an analysis. A process owns the global entries [lo, hi),
 * stored first (local index i - lo), and keeps copies of nghost entries owned by other
 * processes after them (ghosts: the DOFs of the elements it assembles that it does not
 * own). One process: it owns everything, no ghosts (ctn_layout_serial).
 *
 * Every reduction over a vector (dot products, norms, sums over masked entries) goes
 * through its layout: the process's partial over its owned entries, then the
 * communicator's allreduce. In one process that is the plain loop, to the bit. */
#ifndef CTN_DIST_LAYOUT_H
#define CTN_DIST_LAYOUT_H

#include "dist/comm.h"

struct ctn_layout {
    size_t n;                  /* global entries */
    size_t lo, hi;             /* the owned ones: [lo, hi) */
    size_t nghost;             /* copies of entries owned elsewhere, after the owned */
    const size_t *ghost;       /* their global indices, ascending (NULL when none) */
    const ctn_comm *comm;
};

/* One process: owns [0, n), no ghosts. */
void ctn_layout_serial(ctn_layout *l, size_t n, const ctn_comm *comm);
/* Entries owned, and stored (owned + ghosts). */
static inline size_t ctn_layout_owned(const ctn_layout *l) { return l->hi - l->lo; }
static inline size_t ctn_layout_local(const ctn_layout *l) { return l->hi - l->lo + l->nghost; }

/* sum over the processes of x (a process's partial), and the largest. */
double ctn_layout_sum(const ctn_layout *l, double x);
double ctn_layout_max(const ctn_layout *l, double x);
/* a . b over the owned entries of every process. */
double ctn_layout_dot(const ctn_layout *l, const double *a, const double *b);
/* |a| (2-norm) over every process's owned entries, without overflow or underflow. */
double ctn_layout_norm(const ctn_layout *l, const double *a);
/* One entry of a vector that is not stored as one (0 where it does not count), by its
 * local index. */
typedef double (*ctn_entry_fn)(const void *ud, size_t i);
/* sqrt(ss) for ss the sum over the processes of the squares of entry(ud, i) over their
 * owned entries (ss: already reduced, ctn_layout_sum), recomputed scaled by the largest
 * entry when that overflowed or underflowed. */
double ctn_layout_norm_ss(const ctn_layout *l, double ss, ctn_entry_fn entry, const void *ud);
/* The ghost entries of v from their owners (one process: nothing to do). */
int ctn_layout_ghosts(const ctn_layout *l, double *v);

/* A vector over a layout: its local entries (owned, then ghosts). */
typedef struct ctn_dvec {
    const ctn_layout *lay;
    double *v;
} ctn_dvec;
/* Zeroed; at least one entry is allocated (an empty layout too). */
int ctn_dvec_create(ctn_ctx *ctx, const ctn_layout *lay, ctn_dvec *x);
void ctn_dvec_destroy(ctn_dvec *x);

#endif
