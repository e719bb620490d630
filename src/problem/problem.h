/* Internal: the problem of an analysis, shared by every strategy (pure and globalized
 * Newton, load stepping, arc-length) and by the checks after a solve (stability, and
 * later modal analysis). It owns the symbolic work done once per model (DOF map,
 * pattern, scatter map, element properties, the linear solver's analysis), the tangent's
 * values and the work vectors, so that no strategy allocates inside its iteration loop,
 * and it outlives one solve.
 *
 * Vectors named "state" hold every DOF of every node (ctn_dofmap); "ndof" vectors hold
 * the free DOFs (equations). Within one load step the external state is parametrized by
 * t in [0, 1]:  f_ext(t) = f0 + t (f1 - f0),  d_fixed(t) = p0 + t (p1 - p0). */
#ifndef CTN_SOLVE_PROBLEM_H
#define CTN_SOLVE_PROBLEM_H

#include "assemble/asm.h"
#include "dist/layout.h"
#include "dist/matrix.h"
#include "linalg/gmres.h"
#include "linalg/linsolve.h"
#include "problem/overlap.h"
#include "problem/solution.h"

#include "catena/analysis.h"

/* A solution strategy (static analysis), registered by its ctn_method. */
typedef struct ctn_strategy_ops {
    const char *name;          /* "auto", "newton", "arclength" */
    const char *linear_solver; /* the linear solver it needs */
    int globalized;            /* corrector: Levenberg-Marquardt shift, acceptance on the
                                  potential, relaxation of compressed starts */
    int preshape;              /* place slack chains on arcs before the first step */
    int maxcuts;               /* default halvings of a failed increment */
    int (*run)(ctn_problem *p, ctn_solution *s, double *d);
} ctn_strategy_ops;

/* Loads that follow the geometry (follow.c): hload on the deformed projection. */
typedef struct ctn_follow ctn_follow;
/* Moments on nodes of composed rotations (spin.c). */
typedef struct ctn_spin ctn_spin;

extern const ctn_strategy_ops ctn_strategy_auto, ctn_strategy_newton, ctn_strategy_arclength;
/* The strategy of a method, NULL if none. */
const ctn_strategy_ops *ctn_strategy_of(ctn_method method);

struct ctn_problem {
    ctn_ctx *ctx;
    const ctn_model *m;
    ctn_solve_options opt;
    const ctn_strategy_ops *strategy;
    ctn_asm *a;
    ctn_linsolve *ls;
    const char *ls_name;       /* the linear solver's name (none created without DOFs) */
    double *Kx;                /* nnz: the tangent's values, pattern order */
    size_t ns, ndof;           /* state length, equations */
    ctn_layout eq, st;         /* the layouts of the equations (free DOFs) and of the state
                                  over the processes (dist/layout.h): every reduction over
                                  an ndof or state vector goes through them */
    ctn_dvec vr, vdd, vw;      /* the ndof vectors r, dd, w below (their storage) */
    ctn_dmat K;                /* the tangent over eq: the assembly's pattern, values Kx */
    unsigned mode;             /* CTN_EVAL_* passed to the elements */
    double *fint;              /* state: internal forces at the last residual() */
    double *fext;              /* state: external forces at the current t */
    double *f0, *f1, *p0, *p1; /* state: step start and end loads / prescribed displacements */
    double *r, *dd, *w;        /* ndof: residual, increment, work */
    double *dsave;             /* state: saved state for line searches and cut-backs */
    double *react;             /* state: reactions being stored */
    double *wd;                /* state: the globalized corrector's watchdog checkpoint
                                  (correct.c), NULL without finite rotations */
    double *v3;                /* 3 nn: model-side scratch (loads, results) */
    double lref;               /* bounding-box diagonal of the reference geometry */
    double kscale;             /* largest element stiffness scale */
    double t_setup;            /* wall seconds of the setup */
    int last_definite;         /* the last factorization was LL' of K itself (no shift)
                                  and succeeded: K was positive definite there */
    double shift;              /* of the last factorization */
    ctn_follow *fl;            /* loads that follow the geometry, NULL if none */
    ctn_spin *sp;              /* moments on nodes of composed rotations, NULL if none:
                                  the tangent is not symmetric there (spin.c) */
    unsigned char *in_chain;   /* ne: 1 for a two-node member with a free node that joins
                                  exactly two members (a cable's), the members a relaxation
                                  may free of compression; bars between joints are not */
    size_t max_steps;          /* solve at most this many model steps (0: all) */
    double *dT0, *dT1, *dT;    /* ne: temperature changes at the step's start, end and at
                                  t; NULL when the model has no temperature load */
    ctn_solve_summary *sum;    /* where timings accumulate (the current solution's) */
    int spd_factor;            /* the factorization held is LL' of a tangent (no shift) */
    double *cg;                /* 4 ndof: conjugate-gradient workspace (reuse of the last
                                  factorization), NULL when the strategy does not reuse */
    const ctn_solution *factored_at; /* the factor held is LL' of the tangent at this
                                  solution's converged state (the stability check's),
                                  which a modal analysis without a shift reuses; NULL
                                  when it is of anything else */
    int mech_node, mech_dir;   /* the junction start found no equilibrium: the loads move
                                  this node (index) in this direction without bound; -1 */
    int overlap;               /* pure Newton: each residual with K also starts K's
                                  factorization beside its assembly (overlap.c) */
    ctn_overlap ovl;           /* that factorization, while it runs */
    int dist;                  /* the tangent distributed by columns over the ranks of an
                                  MPI job (dist.c): Kx holds this rank's columns only */
    size_t q0, q1;             /* dist: this rank's nodes */
    size_t c0, c1;             /* dist: their columns (free DOFs), consecutive */
    int *lcolptr;              /* dist: c1 - c0 + 1, those columns' positions from 0 */
    int *lrowind;              /* dist: their row indices, the assembly's a->rowind then
                                  released (NULL); NULL when they are every column */
};

/* ctn_problem_create without the check that every cable target is resolved (for the
 * root find that resolves them, target.c). */
int ctn_problem_create_any(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt, ctn_problem **out);

/* Set t: fext and the fixed entries of d. */
void ctn_problem_set_t(ctn_problem *p, double t, double *d);
/* Load the totals of model step k into f1 / p1 (state layout). */
void ctn_problem_step_loads(ctn_problem *p, size_t k);
/* The same for the loads of a selection (a case or a combination). */
void ctn_problem_sel_loads(ctn_problem *p, const ctn_loadsel *sel);
/* f_int (and K if with_K) at d; r = f_ext - f_int on free DOFs, |r| in *rnorm; if pi is
 * not NULL, the total potential (stored energy - f_ext . d over free DOFs) from the same
 * pass. *valid = 0 if an element collapsed or a result is not finite (an outcome). */
int ctn_problem_residual(ctn_problem *p, const double *d, int with_K, double *rnorm, double *pi,
                         int *valid);
/* Force scale of the residual test: |f_ext| on free DOFs, or where that is zero (pure
 * prescribed displacement) |f_int| on fixed DOFs, or 1. */
double ctn_problem_fref(const ctn_problem *p);
/* Newton step dd = K^-1 r on the current tangent (p->Kx) by conjugate gradients
 * preconditioned by the last factorization (of K + 0 I at an earlier state), to
 * |K dd - r| <= target; *ok = 0 (nothing to use) if it did not reach rmax, met negative
 * curvature or no factorization can be reused (reuse.c). */
int ctn_problem_reuse_step(ctn_problem *p, double target, double rmax, int *ok);
/* Factorize K + shift I; *posdef = 0 when the factorization failed on a pivot, with its
 * equation in *fail_col. Without a shift, the factorization the last residual started
 * beside its assembly (p->overlap) is the one waited for. */
int ctn_problem_factor(ctn_problem *p, double shift, int *posdef, long *fail_col);
/* The column where CHOLMOD's LL' of K + shift I fails (-1 if it does not, or on an
 * error, which is not recorded): for a solver that names none (locate.c). */
long ctn_problem_fail_col(ctn_problem *p, double shift);
/* Drop the factorization the last residual started, if it runs (no factorization
 * wanted: a converged state, a shifted one): the factor held is then of no matrix. Every
 * use of p->Kx or p->ls but ctn_problem_factor settles first. */
void ctn_problem_settle(ctn_problem *p);
/* x = K \ b (ndof vectors). */
int ctn_problem_linsolve(ctn_problem *p, const double *b, double *x);
/* Largest diagonal entry of the assembled tangent. */
double ctn_problem_max_diag(const ctn_problem *p);

/* The tangent distributed by columns (dist.c). Set up once the follower loads are known:
 * p->dist decided for linear solver `name`, p->Kx allocated (this rank's columns, or
 * the whole pattern's values), p->K set. */
int ctn_problem_dist_setup(ctn_problem *p, const char *name);
/* A solver of that name on p's tangent: this rank's columns when p->dist. */
int ctn_problem_solver_create(ctn_problem *p, const char *name, ctn_la_ordering ord, ctn_linsolve **out);
/* ctn_asm_eval over this rank's nodes, their columns into Kx (if not NULL), the internal
 * forces p->fint gathered whole, the energy (U if not NULL) summed over the ranks, the
 * first collapsed element over them in *bad (returns 1) */
int ctn_problem_dist_eval(ctn_problem *p, const double *d, unsigned mode, double *Kx, double *U, size_t *bad);
double ctn_problem_dist_max_diag(const ctn_problem *p);
void ctn_problem_dist_symv(const ctn_problem *p, const double *Ax, const double *x, double *y);
/* The whole tangent on every rank, its pattern in *pat and values (pattern order) in
 * *Kx: the assembly's and p->Kx, or when p->dist new arrays gathered from the ranks (the
 * rare paths that name a node by CHOLMOD), to be released by ctn_problem_whole_K_done. */
int ctn_problem_whole_K(ctn_problem *p, ctn_pattern *pat, double **Kx);
void ctn_problem_whole_K_done(const ctn_problem *p, const ctn_pattern *pat, double *Kx);
/* The tangent at state d, assembled (the whole of it or this rank's columns, p->Kx),
 * and f_int; 1 if an element collapsed there. */
int ctn_problem_eval_tangent(ctn_problem *p, const double *d);
/* d (state) += alpha * v (ndof) on free DOFs: a vector sum (a mode shape, a perturbation). */
void ctn_problem_axpy(const ctn_problem *p, double *d, double alpha, const double *v);
/* The state update of an iteration, d <- d (+) alpha v: the translations added, the
 * rotations through the DOF map's rot_update (ctn_dofmap_update; the plain sum when the
 * model has no rotations). */
void ctn_problem_update(const ctn_problem *p, double *d, double alpha, const double *v);
/* Store d, its reactions (f_int - f_ext at the current f_ext) and element states in step
 * k of the solution. */
int ctn_problem_fill_step(ctn_problem *p, ctn_solution *s, size_t k, const double *d);
/* Record an iteration in the solution's history (grows it; CTN_ERR_NOMEM) and tell the
 * monitor. _ex: a rejected trial step (dnorm its norm; the history keeps 0) and the
 * tangent's shift. */
int ctn_problem_record(ctn_problem *p, ctn_solution *s, double rnorm, double dnorm);
int ctn_problem_record_ex(ctn_problem *p, ctn_solution *s, double rnorm, double dnorm, int rejected,
                          double shift);

/* One load step of the solution (its index k) from d to the loads in f1/p1/dT1, in
 * `sub` increments (0: the options' steps), with cut-back (drive.c). dstep: state
 * scratch. */
int ctn_problem_run_step(ctn_problem *p, ctn_solution *s, size_t k, int sub, double *d, double *dstep);
/* Solve every load case and combination of the model from its installed state (a
 * converged step of s), each non-linearly; the results go into s (cases.c). */
int ctn_problem_cases(ctn_problem *p, ctn_solution *s);

/* Newton corrector at fixed t from d (modified in place). On return *reason is
 * CTN_CONVERGED or why it stopped; the state d is the last accepted iterate. */
int ctn_newton_correct(ctn_problem *p, ctn_solution *s, double *d, ctn_reason *reason);
/* The round-off floor of |f_ext - f_int| at state d (floor.c), and in *scale the force
 * that meets at the nodes it is judged against; INFINITY if an element collapsed. */
double ctn_problem_residual_floor(ctn_problem *p, const double *d, double *scale);
/* Crisfield's cylindrical arc-length continuation (single load pattern). */
int ctn_arclength_run(ctn_problem *p, ctn_solution *s, double *d);
/* Place slack chains on the arc of their unstressed length (see preshape.c); *count
 * gets the number of chains placed. */
int ctn_preshape(ctn_problem *p, double *d, int *count);
/* The start of a later load step or of a load case taken in one increment (its loads in
 * f0/f1/dT0/dT1, its selections from and to): a chain between two supports that the
 * step's temperature leaves slack, or whose loads turn (a wind), placed on its funicular
 * under the end's loads (preshape.c); *count gets the number of chains placed. */
int ctn_preshape_step(ctn_problem *p, const ctn_loadsel *from, const ctn_loadsel *to, double *d, int *count);
/* Place the free anchors of meshed cables meeting at a free node on the equilibrium of
 * the model with each chain as one elastic catenary, and the chains on their catenaries
 * (junction.c); loads: the first step's dead loads (3 per node); the elements placed are
 * marked in seen; *placed = 1 if it did. */
int ctn_junction_place(ctn_problem *p, const double *loads, double *d, unsigned char *seen, int *placed);

/* The model fits a dynamics analysis with options o (analysis/dynamics/dynamics.c): no
 * rotations, no follower loads, the `dynamics` line after the last step, mass (every
 * free DOF's for the explicit method); CTN_ERR_MODEL at the `dynamics` line. */
int ctn_dynamics_check(ctn_problem *p, const ctn_dynamics_options *o);

/* dst = the defaults overwritten by the keys of the caller's src (by its size; NULL:
 * the defaults); CTN_ERR_INVALID, recorded, for a size not set or too large. */
int ctn_solve_options_take(ctn_ctx *ctx, ctn_solve_options *dst, const ctn_solve_options *src);
int ctn_modal_options_take(ctn_ctx *ctx, ctn_modal_options *dst, const ctn_modal_options *src);
/* 1 with a message if an option is out of range, else 0 (options.c). */
int ctn_solve_options_fault(const ctn_solve_options *opt, char *msg, size_t size);
int ctn_modal_options_fault(const ctn_modal_options *opt, char *msg, size_t size);

/* Follower loads (follow.c). create: NULL p->fl when the model has none. step: the q of
 * model step k becomes the target (the previous one the start); reset: before the first
 * step; set_t: q at t; forces: the loads (state layout) at d, kept for the tangent;
 * solve: x = (K + shift I - L)^-1 b by GMRES preconditioned by the factorization. */
int ctn_follow_create(ctn_problem *p);
void ctn_follow_destroy(ctn_follow **f);
void ctn_follow_reset(ctn_problem *p);
void ctn_follow_step(ctn_problem *p, size_t k);
/* The same for the loads of a selection (a case or a combination). */
void ctn_follow_sel(ctn_problem *p, const ctn_loadsel *sel);
void ctn_follow_set_t(ctn_problem *p, double t);
const double *ctn_follow_forces(ctn_problem *p, const double *d);
/* The loads of selection sel at state d into out (state layout; zero without follower
 * loads), the follower's own state unchanged (the start heuristics). */
void ctn_follow_forces_sel(const ctn_problem *p, const double *d, const ctn_loadsel *sel, double *out);
/* The loads of the last ctn_follow_forces (state layout). */
const double *ctn_follow_loads(const ctn_follow *f);
int ctn_follow_solve(ctn_problem *p, const double *b, double *x);
/* y = (K + shift I - L) x: the operator GMRES solves with. */
int ctn_follow_apply(ctn_problem *p, const double *x, double *y);
/* The dynamics' follower loads (analysis/dynamics): the segments under a deformed-
 * projection hload (0: none, the dynamics drops p->fl); the winds' segments set to no
 * load at every t (a dynamics takes winds on the relative velocity instead). */
size_t ctn_follow_hload_count(const ctn_follow *f);
void ctn_follow_drop_winds(ctn_problem *p);

/* Moments on nodes of composed rotations (spin.c). create: NULL p->sp when no node
 * with three free composed rotations carries a moment (after the linear solver);
 * solve: x = (K + shift I (- L) - [g]x / 2)^-1 b by GMRES preconditioned by the
 * factorization, g the internal moments of the last residual. */
int ctn_spin_create(ctn_problem *p);
/* 1 if the model has such moments (ctn_spin_create will make p->sp): their tangent's
 * symmetric part may be indefinite on a stable path, so the default factorization of
 * the preconditioner is LDL' (problem.c). Needs p->a only. */
int ctn_spin_wanted(const ctn_problem *p);
void ctn_spin_destroy(ctn_spin **s);
int ctn_spin_solve(ctn_problem *p, const double *b, double *x);
/* The sign (1, -1; 0 if singular) of det(K - [g]x / 2 at the spun nodes), the whole
 * non-symmetric tangent, from f, a factorization of K (p->Kx, g in p->fint at the same
 * state) with neg negative pivots: det(K) det(I + S E^T K^-1 E) (the matrix determinant
 * lemma; E selects the spun nodes' rotations, S their blocks), 3 solves per spun node.
 * Needs p->sp. */
int ctn_spin_det_sign(ctn_problem *p, ctn_linsolve *f, long neg, int *sign);
/* The largest |g| over the spun nodes (the 2-norm of the skew part is half of it). */
double ctn_spin_moment_max(const ctn_problem *p);

/* The right-hand side -g (ndof) of the stretch correction of a step dd (ndof) from d to
 * dtrial (states) in the members of the families of finite rotations (stretch.c);
 * 1 if there is any such member, else 0. */
int ctn_problem_stretch_rhs(ctn_problem *p, const double *d, const double *dtrial, const double *dd, double *g);

/* The tangent's values (p->Kx, mode 0: the materials' own laws) and p->fint at the state
 * d (state layout) of the solution's last step; CTN_ERR_INVALID, naming who, for a
 * solution of another model or a collapsed element (stability.c). */
int ctn_problem_tangent_at(ctn_problem *p, const ctn_solution *s, double *d, const char *who);
/* 1 in *ok when the tangent at s's state is positive definite by its structure: axial
 * members in tension or slack only, and every free DOF tied to a support by members in
 * tension (stability_tension.c); 0 when that cannot be shown (a factorization can). */
int ctn_problem_stable_by_tension(ctn_problem *p, const ctn_solution *s, int *ok);
/* a . b over the equations' layout (p->eq), for the Krylov solvers (data: the problem). */
double ctn_problem_dot(void *p, const double *a, const double *b);
/* y = A x (ndof), A symmetric with values Ax in the pattern's order (upper triangle). */
void ctn_problem_symv(const ctn_problem *p, const double *Ax, const double *x, double *y);

/* Small vector helpers for the local systems of one process (vec.c): a vector of the
 * problem's equations or state is reduced through its layout (p->eq, p->st). */
double ctn_vec_norm(const double *v, size_t n);      /* 2-norm, without overflow */
double ctn_vec_dot(const double *a, const double *b, size_t n);
/* Monotonic wall clock in seconds. */
double ctn_clock(void);
/* CPU seconds of the process (every thread). */
double ctn_cpu_clock(void);

#endif
