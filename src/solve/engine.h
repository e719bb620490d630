/* Internal: the solution engine shared by every strategy (pure and globalized Newton,
 * load stepping, arc-length). It owns the symbolic work done once per model (DOF map,
 * pattern, scatter map, ordering, analysis) and the work vectors, so that no strategy
 * allocates inside its iteration loop.
 *
 * The external state is parametrized by t in [0, 1] within one load step:
 *   f_ext(t) = f0 + t (f1 - f0),   d_fixed(t) = p0 + t (p1 - p0). */
#ifndef CTN_SOLVE_ENGINE_H
#define CTN_SOLVE_ENGINE_H

#include "assemble/asm.h"
#include "linalg/chol.h"
#include "solve/solution.h"

typedef struct ctn_engine {
    ctn_ctx *ctx;
    const ctn_model *m;
    ctn_solve_options opt;
    ctn_asm *a;
    ctn_chol *ch;
    size_t n3, ndof;
    double *fint;              /* 3 nn: internal forces at the last residual() */
    double *fext;              /* 3 nn: external forces at the current t */
    double *f0, *f1, *p0, *p1; /* 3 nn: step start and end loads / prescribed displacements */
    double *r, *dd, *w;        /* ndof: residual, increment, work */
    double *dsave;             /* 3 nn: saved state for line searches and cut-backs */
    double lref;               /* bounding-box diagonal of the reference geometry */
    double kscale;             /* max EA/l0 of the elements: stiffness scale */
    ctn_solve_summary *sum;    /* where timings accumulate */
} ctn_engine;

int ctn_engine_setup(ctn_engine *e, ctn_ctx *ctx, const ctn_model *m,
                     const ctn_solve_options *opt, ctn_solve_summary *sum);
void ctn_engine_teardown(ctn_engine *e);

/* Set t: fext and the fixed entries of d. */
void ctn_engine_set_t(ctn_engine *e, double t, double *d);
/* f_int (and K if with_K) at d; r = f_ext - f_int on free DOFs, |r| in *rnorm; if pi is
 * not NULL, the total potential (strain energy - f_ext . d over free DOFs) from the same
 * pass. CTN_ERR_DOMAIN if an element collapsed or a result is not finite. */
int ctn_engine_residual(ctn_engine *e, const double *d, int with_K, double *rnorm, double *pi);
/* Force scale of the residual test: |f_ext| on free DOFs, or where that is zero (pure
 * prescribed displacement) |f_int| on fixed DOFs, or 1. */
double ctn_engine_fref(const ctn_engine *e);
/* Factorize K + shift I. Returns a status (backend failure); *posdef = 0 when the
 * matrix is not positive definite, with the equation of the failing pivot in
 * *fail_col. */
int ctn_engine_factor(ctn_engine *e, double shift, int *posdef, long *fail_col);
/* x = K \ b (ndof vectors). */
int ctn_engine_solve(ctn_engine *e, const double *b, double *x);
/* d (3 nn) += alpha * v (ndof) on free DOFs. */
void ctn_engine_axpy(const ctn_engine *e, double *d, double alpha, const double *v);
/* Euclidean norms. */
double ctn_norm(const double *v, size_t n);
double ctn_dot(const double *a, const double *b, size_t n);
/* Monotonic wall clock in seconds. */
double ctn_now(void);

/* Store d, its reactions (f_int - f_ext at the engine's current f_ext) and element
 * states in step k of the solution. */
void ctn_engine_fill_step(ctn_engine *e, ctn_solution *s, size_t k, const double *d);

/* Record an iteration in the solution's history (grows it; CTN_ERR_NOMEM). */
int ctn_engine_record(ctn_engine *e, ctn_solution *s, double rnorm, double dnorm);

/* Newton corrector at fixed t from d (modified in place). On return *reason is
 * CTN_CONVERGED or why it stopped; the state d is the last accepted iterate. */
int ctn_newton_correct(ctn_engine *e, ctn_solution *s, double *d, ctn_reason *reason);
/* Place slack chains on the arc of their unstressed length (see preshape.c); *count
 * gets the number of chains placed. */
int ctn_preshape(ctn_engine *e, double *d, int *count);
/* Crisfield's cylindrical arc-length continuation (single load pattern). */
int ctn_arclength_run(ctn_engine *e, ctn_solution *s, double *d);

#endif
