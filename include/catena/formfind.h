/*
 * catena/formfind.h - form finding by the force density method (Schek 1974).
 *
 * Every member of the model carries a force density q = N / l (q= in the file,
 * ctn_element_spec.q) or a target force (force=, ctn_element_spec.force); fixed DOFs
 * are anchors, free DOFs go where the members and the loads of the first step balance.
 * For fixed densities the equilibrium of the free nodes is linear, one system per
 * coordinate with the same matrix:
 *
 *     C_f' Q C_f x_f = p_f - C_f' Q C_x x_x          (Q = diag(q), C the branch-node matrix)
 *
 * solved by the sparse Cholesky factorization (CHOLMOD LL'), once per density set, three
 * right-hand sides. Targeted members iterate q <- force / l until every force matches
 * its target; loads that depend on the shape (self-weight w l0, where l0 realises the
 * member's force by its own strain law; hload) are recomputed from the shape found until
 * they no longer change. The found model is then complete: node positions, and for each
 * member the unstressed length that carries N = q l in the found geometry, so that a
 * static solve of it (ctn_solve, or `catena solve` of the written file) stays where it
 * is and returns the forces q l to round-off.
 *
 * ctn_solve ignores q and force (the member's l0 governs, as without them).
 */
#ifndef CATENA_FORMFIND_H
#define CATENA_FORMFIND_H

#include <stddef.h>

#include "catena/core.h"
#include "catena/model.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* Force density q [force/length] or target force [force] of the elements with ids
 * first..last (inclusive; at least one must exist), e.g. the range of a generated
 * cable: exactly one of q and force positive, the other 0. */
int ctn_model_set_force_density(ctn_model *m, int first, int last, double q, double force);
/* The force density and target force of element i (index), 0 where none. */
int ctn_model_force_density(const ctn_model *m, size_t i, double *q, double *force);
/* Number of elements that carry q or force (for a warning that ctn_solve ignores them). */
size_t ctn_model_force_density_count(const ctn_model *m);

/* One iteration of the form finding, as the monitor sees it. */
typedef struct ctn_formfind_iterate {
    int iteration;          /* 1, 2, ...: one linear solve (3 right-hand sides) each */
    double force_mismatch;  /* largest |q l - force| / force over targeted members after
                               the solve (0 without targets) */
    double load_change;     /* largest change of a nodal load recomputed from the shape
                               found, over the force scale (0 when loads do not depend on
                               the shape) */
} ctn_formfind_iterate;
typedef void (*ctn_formfind_monitor_fn)(void *data, const ctn_formfind_iterate *it);

/* Options; ctn_formfind_options_init() sets the defaults. */
typedef struct ctn_formfind_options {
    size_t size;            /* sizeof(ctn_formfind_options) (set by init) */
    double tol;             /* stop when the force mismatch and the load change are both
                               <= tol (default 1e-10), > 0 */
    int maxit;              /* most iterations (default 1000), >= 1 */
    ctn_formfind_monitor_fn monitor;  /* called after every iteration, or NULL */
    void *monitor_data;
} ctn_formfind_options;
void ctn_formfind_options_init(ctn_formfind_options *o);

/* Why the iteration stopped (an outcome, not an error). */
typedef enum ctn_formfind_reason {
    CTN_FF_CONVERGED = 0,   /* forces on target and loads settled, to tol */
    CTN_FF_MAXIT = 1,       /* maxit iterations without meeting tol */
    CTN_FF_STALLED = 2      /* the mismatch stopped falling (no better value in the last
                               100 iterations): the targets are probably not compatible
                               with equilibrium */
} ctn_formfind_reason;

typedef struct ctn_formfind_report {
    ctn_formfind_reason reason;
    int iterations;         /* linear solves */
    int factorizations;     /* numeric factorizations (one per density set and free-node set) */
    size_t free_nodes;      /* nodes with at least one free DOF */
    size_t targets;         /* members with a target force */
    double force_mismatch;  /* the last iteration's largest relative force mismatch */
    size_t worst;           /* index of the member with that mismatch (0 without targets) */
    double load_change;     /* the last iteration's relative load change */
    double residual;        /* equilibrium of the found state: largest |sum of member
                               forces + loads| at a free DOF, over the force scale */
    double force_min, force_max;   /* member forces q l [force] */
} ctn_formfind_report;

/* Find the shape of m in place. On CTN_OK with rep->reason == CTN_FF_CONVERGED, m is the
 * found model: free node coordinates moved to the found shape, every member's l0 set to
 * the unstressed length that carries its force q l there (the member family's own law;
 * springs: l0 = l - N/k), Newton starts reset to the reference (a generated cable keeps
 * its record but starts where it is). On any other outcome m is unchanged. Errors
 * (CTN_ERR_MODEL with file:line): a member without q or force, a member of more than two
 * nodes, a free DOF not connected to an anchor of that direction, a prescribed
 * displacement in the first step, targets that no shape can reach at a node (one force
 * larger than all the others and the load there together), a member of zero length in the
 * found shape, no unstressed length giving a member its force; and the checks of
 * ctn_model_validate. Errors are recorded in the model's context (ctx: the same one).
 * opt may be NULL (defaults); rep may be NULL. */
int ctn_formfind(ctn_ctx *ctx, ctn_model *m, const ctn_formfind_options *opt, ctn_formfind_report *rep);

/* Write the found model m as a .cable file at path, atomically (a temporary renamed on
 * success; nothing is left on failure): the source text (the bytes m was read from, len
 * of them, as ctn_read_string took them) line by line, with node lines of moved nodes
 * given their found coordinates, element and spring lines their l0= in place of q=,
 * force=, and each `cable` line expanded into its nodes and elements; every other line
 * (units, materials, sections, loads, steps, solve, comments) is copied as it is.
 * Numbers are written with 17 significant digits (they read back to the same double). */
int ctn_formfind_write(ctn_ctx *ctx, const ctn_model *m, const char *text, size_t len,
                       const char *path);

/* Read the model file in, find its shape (ctn_formfind) and, when it converged and out
 * is not NULL, write the found model to out (ctn_formfind_write). *found (may be NULL)
 * receives the found model (ctn_model_destroy), NULL on error. */
int ctn_formfind_file(ctn_ctx *ctx, const char *in, const char *out, const ctn_formfind_options *opt,
                      ctn_formfind_report *rep, ctn_model **found);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
