/*
 * catena/solve.h - static analysis of a model and its results.
 *
 * A problem (ctn_problem) is the analysis of one model with one set of options: it
 * validates the model and does the symbolic work once (DOF map, sparsity pattern,
 * element properties, the linear solver's ordering and analysis). ctn_problem_solve()
 * then runs the static analysis by the options' method (Newton-Raphson on
 * K_T(d) dd = f_ext - f_int(d) in load steps, globalized or pure, or arc-length), and
 * the same problem can be asked for the stability of a solution (the tangent at its
 * state) afterwards. ctn_solve() is create + solve + destroy in one call.
 * Non-convergence is an outcome, not an error: the solve returns CTN_OK with a solution
 * whose reason says why it stopped (ctn_reason). Errors (out of memory, invalid model,
 * backend failure) return a status and no solution.
 */
#ifndef CATENA_SOLVE_H
#define CATENA_SOLVE_H

#include <stddef.h>

#include "catena/core.h"
#include "catena/model.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* Fill-reducing ordering of the tangent's factorization. */
typedef enum ctn_ordering {
    CTN_ORDER_AUTO = 0,    /* natural if it makes no fill; else analyze natural, AMD and
                              METIS and keep the one with the fewest flops (natural on ties
                              within 10 %: it keeps memory access local); an ordering whose
                              analysis fails (e.g. a factor too large to index) is skipped */
    CTN_ORDER_NATURAL = 1, /* the model's DOF order */
    CTN_ORDER_AMD = 2,     /* approximate minimum degree */
    CTN_ORDER_METIS = 3    /* METIS nested dissection */
} ctn_ordering;
/* "auto", "natural", "amd", "metis" ("?" if none). */
const char *ctn_ordering_name(ctn_ordering o);

/* Solution strategy. */
typedef enum ctn_method {
    CTN_METHOD_AUTO = 0,      /* globalized Newton: full Newton steps while they lower the
                                 total potential, else a diagonal shift of the tangent
                                 (Levenberg-Marquardt) and a backtracking line search on the
                                 potential; load increments cut back on failure. Solves from
                                 straight or zero-tension starts and with slack members */
    CTN_METHOD_NEWTON = 1,    /* pure Newton-Raphson (the paper's): d <- d + dd */
    CTN_METHOD_ARCLENGTH = 2  /* Crisfield's cylindrical arc-length: traces limit points */
} ctn_method;

/* One Newton iteration, as the monitor sees it. */
typedef struct ctn_iterate {
    int iteration;        /* 1, 2, ... over the whole run */
    double residual;      /* |f_ext - f_int| after the iteration (a rejected one: at the
                             state kept, its start) [force] */
    double increment;     /* |alpha dd| of the step taken; of the trial step when rejected
                             [length] */
    int rejected;         /* 1: the step was tried and not taken (globalized Newton raises
                             its shift and tries again) */
    double shift;         /* Levenberg-Marquardt shift of the tangent used (0: Newton's) */
} ctn_iterate;
/* Called after every Newton iteration (the iteration log). */
typedef void (*ctn_monitor_fn)(void *data, const ctn_iterate *it);

/* The mass matrix of a modal analysis (docs/theory.md, "Modal analysis"). */
typedef enum ctn_mass_matrix {
    CTN_MASS_CONSISTENT = 0, /* the elements' consistent mass (linear interpolation of the
                                motion along each element; the default: its frequencies
                                converge from above at O(h^2) with a smaller constant) */
    CTN_MASS_LUMPED = 1      /* half of each element's mass at each of its nodes */
} ctn_mass_matrix;

/* The eigen-solver of a modal analysis (docs/theory.md, "Modal analysis"). */
typedef enum ctn_eigen_solver {
    CTN_EIGEN_BLOCK = 0,     /* shift-invert block Lanczos: blocks of 4 vectors, each one
                                multi-right-hand-side solve with the factor (fewer passes
                                over the factor), full re-orthogonalization by BLAS-3 */
    CTN_EIGEN_ARPACK = 1,    /* ARPACK's implicitly restarted Lanczos, one vector per solve */
    CTN_EIGEN_AUTO = 2,      /* ARPACK below CTN_EIGEN_BLOCK_DOFS free DOFs, block Lanczos
                                from there (measured: ARPACK as fast or faster on the nets
                                up to 29k DOFs, block 1.6x faster at 478k) */
    CTN_EIGEN_SLEPC = 3      /* reported, not asked for: SLEPc's Krylov-Schur, shift-invert
                                on MUMPS, over the ranks of an MPI job (docs/parallel.md) */
} ctn_eigen_solver;
#define CTN_EIGEN_BLOCK_DOFS 100000

/* A modal analysis about a converged state: K_T phi = omega^2 M phi. */
typedef struct ctn_modal_options {
    size_t size;          /* sizeof(ctn_modal_options): ctn_modal_options_default sets it
                             (catena/analysis.h); keys are only ever added at the end */
    int count;            /* the number of modes N >= 1, at most the free DOFs that carry
                             mass (0: no modal analysis; the default) */
    ctn_mass_matrix mass; /* default CTN_MASS_CONSISTENT */
    double shift;         /* >= 0 [Hz]: the N modes whose frequencies are nearest it
                             (default 0: the N lowest) */
    int line;             /* the model file's `modes` line, named by its errors (0: none) */
    ctn_eigen_solver solver; /* default CTN_EIGEN_AUTO */
} ctn_modal_options;

/* Linear buckling about a converged state (catena/analysis.h, docs/theory.md "Linear
 * buckling"): the load factors lambda on the last step's loads at which the tangent,
 * extrapolated linearly in lambda, becomes singular. */
typedef struct ctn_buckling_options {
    size_t size;          /* sizeof(ctn_buckling_options): ctn_buckling_options_default sets
                             it (catena/analysis.h); keys are only ever added at the end */
    int count;            /* the number of buckling factors N >= 1, the lowest positive
                             (0: no buckling analysis; the default) */
    int line;             /* the model file's `buckling` line, named by its errors (0: none) */
    int check;            /* 1: the non-linear check beside the linear factors: the load
                             path from the solved state with an imperfection in the first
                             mode, its limit or Southwell's factor (0: none; the default) */
} ctn_buckling_options;

/* The time integration of a dynamics analysis (catena/analysis.h, docs/theory.md
 * "Dynamics"). The implicit methods are one family, the generalized-alpha method of
 * Chung and Hulbert: M a(n+1-am) + C v(n+1-af) + f_int(n+1-af) = f_ext(n+1-af), the
 * forces averaged between t_n and t_n+1 (x(n+1-a) = (1 - a) x(n+1) + a x(n)), Newmark's
 * update with gamma, beta; a Newton solve per step on K_T + c1 M + c2 C. */
typedef enum ctn_dyn_method {
    CTN_DYN_GENALPHA = 0,    /* am = (2 rho - 1)/(rho + 1), af = rho/(rho + 1), gamma = 1/2 -
                                am + af, beta = (1 - am + af)^2 / 4 from rho_inf */
    CTN_DYN_HHT = 1,         /* Hilber-Hughes-Taylor: am = 0, af = -alpha (alpha in
                                [-1/3, 0], or from rho_inf in [1/2, 1]), gamma = 1/2 + af,
                                beta = (1 + af)^2 / 4 */
    CTN_DYN_NEWMARK = 2,     /* am = af = 0, the options' gamma and beta */
    CTN_DYN_CENTRAL = 3      /* explicit central differences on the lumped mass; dt at most
                                the stable step of the mesh */
} ctn_dyn_method;

/* The most modes modal damping takes (ctn_dynamics_options.modal_count). */
#define CTN_DYN_MODAL_MAX 64

/* A dynamics analysis: time integration from t = 0 to t_end in steps dt. */
typedef struct ctn_dynamics_options {
    size_t size;          /* sizeof(ctn_dynamics_options): ctn_dynamics_options_default sets
                             it (catena/analysis.h); keys are only ever added at the end */
    double dt;            /* time step [s] > 0 (0 with t_end 0: no dynamics; the default) */
    double t_end;         /* end time [s] > 0 */
    ctn_dyn_method method;/* default CTN_DYN_GENALPHA */
    double rho_inf;       /* spectral radius at infinite frequency, [0, 1] (default 0.9;
                             1: no algorithmic damping) */
    double alpha;         /* HHT's alpha in [-1/3, 0]; NAN (default): from rho_inf */
    double gamma, beta;   /* NEWMARK: default 1/2, 1/4 (average acceleration) */
    ctn_mass_matrix mass; /* implicit methods: default CTN_MASS_CONSISTENT; CENTRAL: lumped */
    double damping_alpha; /* Rayleigh damping C = damping_alpha M + damping_beta K_0, K_0 the */
    double damping_beta;  /* tangent at the start of the analysis [1/s], [s] (default 0, 0) */
    double tol;           /* a step converges when |R| <= tol (|f_ext| + |f_int| + |M a|) ... */
    double dtol;          /* ... or its Newton correction |dd| <= dtol (|d| + L_ref)
                             (defaults 1e-8, 1e-12) */
    int maxit;            /* most Newton iterations of a step (default 20) */
    int maxcuts;          /* halvings of dt on a failed step before it stops (default 10) */
    int from_rest;        /* 1: from rest at the start geometry, the loads of every step
                             applied at t = 0 (no static analysis first); 0: from the
                             equilibrium of the last static step, its loads held */
    int line;             /* the model file's `dynamics` line, named by its errors (0: none) */
    int steps_before;     /* the `step` lines before the `dynamics` line (the reader's) */
    int output_every;     /* a row of the histories (and a frame) every K-th step of dt, K
                             >= 1; t = 0 and the last step always (default 1) */
    int frames;           /* 1: keep the state at every row (ctn_solution_frame: the
                             displacements, velocities, reactions and element forces) for
                             the VTU series of ctn_write_results; 0 (default): none */
    int modal_count;      /* modal damping: the N lowest modes about the start state damped,
                             C = M Phi diag(2 zeta_i omega_i) Phi^T M (0: none; the default) */
    int modal_nzeta;      /* ratios given in modal_zeta: 1 (every mode's) or modal_count */
    double modal_zeta[CTN_DYN_MODAL_MAX]; /* the modes' damping ratios, [0, 1) */
    int relative_wind;    /* 1: `wind` loads drag on the velocity of the air relative to the
                             element, 0.5 rho Cd d |v_n| v_n per length with v_n the normal
                             part of v_wind - v_structure (aerodynamic damping); 0
                             (default): wind is refused in a dynamics analysis */
} ctn_dynamics_options;

/* Solver options; ctn_solve_options_default() fills the defaults. */
typedef struct ctn_solve_options {
    size_t size;          /* sizeof(ctn_solve_options): ctn_solve_options_default sets it;
                             keys are only ever added at the end, so a program built
                             against an older header passes a smaller size and the
                             library takes the defaults for the keys it does not know */
    double tol;           /* residual test |r| <= tol * |f_ext| (default 1e-10) */
    double dtol;          /* increment test |dd| <= dtol * (|d| + L_ref), L_ref the
                             diagonal of the model's bounding box (default 1e-8).
                             Both tests must hold, except that the residual test is
                             waived once |dd| <= 1e3 eps (|d| + L_ref): the Newton
                             correction is then at the resolution of the coordinates and
                             the residual at its round-off floor (reported: `floor`) */
    int maxit;            /* most Newton iterations (default 50) */
    ctn_ordering ordering;
    ctn_method method;    /* default CTN_METHOD_AUTO */
    int linesearch;       /* CTN_METHOD_NEWTON: backtracking on |r| (default 0) */
    int steps;            /* load increments per load step (default 1) */
    int maxcuts;          /* halvings of a failed increment (default -1: 10 for AUTO,
                             0 for NEWTON) */
    double arclength;     /* ARCLENGTH: arc radius (displacement norm) per step; 0: that
                             of the first increment 1/steps of the load (default 0) */
    int arcsteps;         /* ARCLENGTH: most arc-length steps (default 200) */
    double lambda_max;    /* ARCLENGTH: stop once the load factor reaches this (default 1) */
    ctn_monitor_fn monitor;  /* NULL: no log */
    void *monitor_data;
    const char *linear_solver; /* NULL: the method's own ("cholmod", LL'; arc-length:
                                  "cholmod-ldl", LDL' for indefinite tangents) */
    ctn_modal_options modal;   /* after a converged solve, ctn_problem_solve runs
                                  ctn_problem_modes with these when modal.count > 0 (the
                                  file's `modes` line) */
    int threads;          /* threads of the numeric factorization (OpenMP, shared by CHOLMOD
                             and an OpenMP OpenBLAS); 0 (default): one, the fastest measured
                             (docs/solver.md "Threads"); at most the context's limit
                             (ctn_ctx_set_threads, by default 1). 1: no thread at all; else
                             large parts of the solve may use a helper thread where the
                             context allows it */
    int reuse;            /* CTN_METHOD_AUTO: once Newton converges quadratically, take the
                             next step with the last factorization (conjugate gradients on
                             the current tangent, preconditioned by it) instead of factoring
                             again (default 1; 0: factor every iteration). Pure Newton
                             always factors */
    ctn_buckling_options buckling; /* after a converged solve (and its modes), the static
                             analysis runs the buckling analysis with these when
                             buckling.count > 0 (the file's `buckling` line) */
    ctn_dynamics_options dynamics; /* when dynamics.t_end > 0 (the file's `dynamics` line):
                             from rest instead of the static analysis (from_rest), or
                             after its converged last step */
} ctn_solve_options;

/* Fill the defaults (and size). Options belong to a solve, not to a model: a model file's `solve`
 * line is read into options by ctn_read_file (catena/io.h). */
void ctn_solve_options_default(ctn_solve_options *opt);
/* CTN_OK, or CTN_ERR_INVALID with a message naming the option out of range. */
int ctn_solve_options_check(ctn_ctx *ctx, const ctn_solve_options *opt);

/* Why the Newton iteration stopped. Positive: converged; negative: diverged. */
typedef enum ctn_reason {
    CTN_CONVERGED = 1,              /* both residual and increment tests met */
    CTN_DIVERGED_MAXIT = -1,        /* maxit iterations without convergence */
    CTN_DIVERGED_NANORINF = -2,     /* a NaN or Inf appeared; the last finite state is kept */
    CTN_DIVERGED_INDEFINITE = -3,   /* tangent not positive definite (compressed or
                                       unrestrained DOF); see fail_node, fail_dir */
    CTN_DIVERGED_LINESEARCH = -4,   /* no step lowered the potential or the residual */
    CTN_DIVERGED_ARCLENGTH = -5,    /* arc-length: no real root for the load factor after
                                       cutting the arc */
    CTN_DIVERGED_ROUNDOFF = -6,     /* the Newton correction reached the resolution of the
                                       coordinates with the residual above its round-off
                                       floor, or that floor is above 1e-4 of the forces
                                       meeting at the nodes: the stiffness is too large for
                                       the loads to be resolved in double precision (see
                                       residual_floor, force_scale) */
    CTN_DIVERGED_MECHANISM = -7     /* no equilibrium: the loads move a free node without
                                       bound along a direction nothing restrains (a
                                       mechanism); see fail_node, fail_dir */
} ctn_reason;

/* Name of a reason, e.g. "converged", "tangent not positive definite". */
const char *ctn_reason_name(ctn_reason r);
/* Name of a DOF direction (fail_dir, ctn_stability.dir): "x", "y", "z", and "rx", "ry",
 * "rz" for the rotations of a 6-DOF node; "?" for anything else. */
const char *ctn_dof_name(int dir);

typedef struct ctn_solution ctn_solution;

/* Summary of a solution. */
typedef struct ctn_solve_summary {
    ctn_reason reason;
    int iterations;       /* Newton steps taken */
    double residual;      /* final |f_ext - f_int| over free DOFs [force] */
    double increment;     /* last |dd| [length] */
    double fext_norm;     /* |f_ext| over free DOFs [force] */
    int fail_node;        /* CTN_DIVERGED_INDEFINITE: user id of the node whose DOF had
                             a non-positive pivot, else 0 */
    int fail_dir;         /* its direction 0 = x, 1 = y, 2 = z, 3..5 = rx, ry, rz (a node
                             with rotations; ctn_dof_name), -1 if none */
    ctn_ordering ordering;/* the ordering used (never AUTO) */
    size_t step;          /* index of the last load step attempted (0-based) */
    double load_factor;   /* t reached in that step: 1 when it converged, else the last
                             converged fraction (arc-length: the load factor) */
    int cuts;             /* increment halvings over the run */
    int floor;            /* 1 if convergence was declared with the residual at its
                             round-off floor, above tol |f_ext| (see dtol) */
    double residual_floor;/* the computed round-off floor of the residual [force] where
                             it was needed (floor, CTN_DIVERGED_ROUNDOFF), else 0: the
                             bound of the force errors of the elements at a node, from
                             the resolution of their chords, over the free DOFs */
    double force_scale;   /* with residual_floor: the force that meets at the nodes (norm
                             over the free DOFs of the sum of the members' |N| and |f_ext|);
                             a floor above 1e-4 of it resolves no equilibrium */
    size_t floor_step;    /* floor: the load step (0-based) where it was declared */
    int stable;           /* converged: 1 if the tangent at the solution is positive
                             definite, 0 if not (ctn_solution_stability says why); -1 when
                             not checked (not converged) */
    int preshaped;        /* slack chains placed on the arc of their unstressed length
                             before the first step (CTN_METHOD_AUTO), plus 1 when the
                             junction start placed meshed cables meeting at free nodes */
    int relaxed;          /* increments that began with a compression-free relaxation
                             (CTN_METHOD_AUTO from a start with compressed members) */
    size_t ndof;          /* free DOFs */
    size_t nnz_factor;    /* non-zeros of the Cholesky factor */
    int factorizations;   /* numeric factorizations of the tangent */
    int solves;           /* triangular solves (right-hand sides) */
    double t_setup;       /* wall seconds: DOF map, pattern, scatter map, ordering and
                             symbolic analysis (once per model) */
    double t_assemble;    /* wall seconds in all iterations: internal forces, tangent
                             values and residual (pure Newton on a chain runs the
                             factorization beside it: the two then overlap in time) */
    double t_factor;      /* wall seconds in all numeric factorizations */
    double t_solve;       /* wall seconds in all triangular solves */
    int fail_element;     /* not converged: user id of the element that could not be
                             evaluated at the last state tried (a chord of zero length,
                             or a catenary whose forces are beyond double precision),
                             else 0 */
    double flops_factor;  /* floating-point operations of one numeric factorization, from
                             the symbolic analysis */
    double t_factor_cpu;  /* CPU seconds (all threads) in all numeric factorizations:
                             against t_factor it shows how the threads were used */
    int threads;          /* threads of the last numeric factorization */
    char blas[64];        /* the BLAS loaded, e.g. "OpenBLAS 0.3.21 (OpenMP)" */
    int reused;           /* iterations that reused the last factorization (cg steps) */
    int solve_threads;    /* threads of the triangular solves: 2 for a supernodal factor
                             of 50 000 DOFs or more on a machine of two CPUs or more
                             (not under threads=1), else 1 */
    int fdensity;         /* 1 if the free nodes of a net started on the equilibrium of
                             its start forces held as force densities (CTN_METHOD_AUTO) */
} ctn_solve_summary;

/* Element state at the solution. */
typedef struct ctn_element_state {
    double length;        /* current length l [length] */
    double strain;        /* strain of the element's measure (Green-Lagrange or engineering) */
    double force;         /* axial tension N (true force, >= 0 in tension) [force] */
    double stress;        /* N / A, A the unstressed area [force/length^2] */
    int slack;            /* 1 if a tension-only element carries no force */
} ctn_element_state;

/* Cables and catenary elements set by a target (ctn_cable_spec.target,
 * ctn_element_spec.target: H, sag or tension): find the unstressed lengths that meet
 * every target at the end of the first load step, under the loads acting in it, to 1e-10
 * relative, all together, by Newton's method on the lengths with sensitivities from the
 * FE tangent (docs/theory.md). The model is changed in place: the cables' elements and
 * the catenaries get the lengths found (ctn_model_cable and ctn_model_element_target
 * report them with the value reached) and the nodes' starting displacements become the
 * first step's solution. *outer (may be NULL) gets the outer iterations. A target no
 * length can reach is CTN_ERR_MODEL naming the cable's or catenary's line and the
 * closest value reached. No-op without targets. Until it has run, ctn_problem_create
 * refuses a model with targets. */
int ctn_model_resolve_targets(ctn_ctx *ctx, ctn_model *m, const ctn_solve_options *opt, int *outer);

/* The analysis of model m with options opt (NULL: the defaults), set up once. The model
 * must outlive the problem and not change while it exists. On CTN_OK *out owns it. */
typedef struct ctn_problem ctn_problem;
int ctn_problem_create(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt,
                       ctn_problem **out);
/* NULL or *p == NULL is a harmless no-op; sets *p to NULL. */
void ctn_problem_destroy(ctn_problem **p);
/* Static analysis: every load step by the options' method. On CTN_OK *out owns a new
 * solution (free it with ctn_solution_destroy), whatever the reason. May be called again
 * (the same problem solved afresh). */
int ctn_problem_solve(ctn_problem *p, ctn_solution **out);

/* Stability of an equilibrium: the inertia of the tangent stiffness (free DOFs) at the
 * state of a solution's last step. */
typedef struct ctn_stability {
    int stable;           /* 1: the tangent is positive definite */
    int semidefinite;     /* 1: not stable because of a zero pivot (a DOF with no
                             stiffness, e.g. a node held only by slack members) */
    long negative;        /* negative eigenvalues of the tangent (0 when semidefinite
                             stopped the count) */
    int node;             /* not stable: user id of the node whose DOF failed first */
    int dir;              /* its direction 0 = x, 1 = y, 2 = z, 3..5 = rx, ry, rz, -1 if none */
    int by_tension;       /* stable, shown without a factorization: every member in
                             tension or slack and every free DOF tied to a support by
                             members in tension (docs/theory.md); 0: by LL' */
} ctn_stability;
int ctn_problem_stability(ctn_problem *p, const ctn_solution *s, ctn_stability *out);
/* The stability of a converged solution, checked by ctn_problem_solve (free when the
 * last Newton iteration's LL' factorization succeeded; else, unless a modal analysis
 * follows, without a factorization when the tangent is definite by its structure
 * (by_tension); else by ctn_problem_stability).
 * CTN_ERR_INVALID when not checked (the solve did not converge). */
int ctn_solution_stability(const ctn_solution *s, ctn_stability *out);

/* Modal analysis about the state of a converged solution's last step: the opt->count
 * natural modes of K_T phi = omega^2 M phi nearest opt->shift (the lowest by default),
 * K_T the tangent there (geometric stiffness included; slack members add none), M the
 * mass (sections' mass per unstressed length, conserved under stretch; nodes' point
 * masses). Sparse shift-invert Lanczos whose solves are the problem's linear solver on
 * K_T - sigma M, factored once (not at all when opt->shift is 0 and the stability check
 * of the solve has just factored K_T at s: that factor serves, with sigma = 0):
 * opt->solver CTN_EIGEN_AUTO (the default: ARPACK below CTN_EIGEN_BLOCK_DOFS free
 * DOFs, block above), CTN_EIGEN_BLOCK (block Lanczos, 4 vectors per multi-right-hand-side
 * solve; ARPACK takes over when it does not converge) or CTN_EIGEN_ARPACK (ARPACK's
 * implicitly restarted Lanczos, mode 3). The summary says which ran.
 * The modes are stored in s (replacing earlier ones) and read back with
 * ctn_solution_mode; the writers add them to the results.
 * Modes of zero frequency (a mechanism: a node held only by slack members; a part that
 * can turn) are results, not errors: CTN_MODE_ZERO with the nodes that move.
 * Errors: CTN_ERR_MODEL (message at opt->line of the model's file) when the count is
 * out of range, the model has no mass, or a section's mass cannot be told (a weight and
 * no units); CTN_ERR_INVALID for a solution that did not converge or is not of this
 * problem's model; CTN_ERR_LINALG when the eigen-solver fails or does not converge (its message says why).
 * ARPACK keeps state between its calls (Fortran SAVE variables, process-wide): do not
 * run two modal analyses at once in two threads. */
int ctn_problem_modes(ctn_problem *p, ctn_solution *s, const ctn_modal_options *opt);

/* What a mode is. */
typedef enum ctn_mode_kind {
    CTN_MODE_VIBRATION = 0,   /* omega^2 > 0: a natural vibration */
    CTN_MODE_ZERO = 1,        /* |omega^2| within the round-off of the tangent: a
                                 mechanism or rigid-body motion (frequency 0) */
    CTN_MODE_UNSTABLE = 2     /* omega^2 < 0: the equilibrium is unstable along it
                                 (frequency 0; the growth rate is sqrt(-omega^2)) */
} ctn_mode_kind;

/* Name of a mode kind: "vibration", "zero", "unstable" (as the results spell it). */
const char *ctn_mode_kind_name(ctn_mode_kind k);

#define CTN_MODE_MAX_NODES 8  /* nodes a zero mode names */

/* Mode k of a solution (k = 0 .. count - 1, by increasing omega^2). */
typedef struct ctn_mode {
    ctn_mode_kind kind;
    double eigenvalue;        /* omega^2 [1/s^2] */
    double angular_frequency; /* omega = sqrt(omega^2) [rad/s], 0 unless VIBRATION */
    double frequency;         /* f = omega / (2 pi) [Hz] */
    double period;            /* T = 1 / f [s]; 0 when f is 0 (no period) */
    const double *shape;      /* phi, 3 per node in model node order (0 on fixed DOFs),
                                 mass-normalized: phi^T M phi = 1 [1/sqrt(mass)]. Owned
                                 by the solution */
    double participation[3];  /* Gamma_j = phi^T M r_j, r_j the unit translation along
                                 x, y, z of the free DOFs [sqrt(mass)] */
    double effective_mass[3]; /* Gamma_j^2 [mass]; over all modes they sum to the total
                                 moving mass (ctn_modal_summary.total_mass) */
    int node;                 /* user id of the node that moves most */
    int nnodes;               /* ZERO: how many nodes move (amplitude >= 1e-3 of the
                                 largest), else 0 */
    int nodes[CTN_MODE_MAX_NODES]; /* ZERO: the first min(nnodes, 8) of them, user ids,
                                 largest amplitude first */
} ctn_mode;

/* The modal analysis of a solution, as a whole. */
typedef struct ctn_modal_summary {
    int count;                /* modes stored (0: none was run) */
    ctn_mass_matrix mass;
    double shift;             /* [Hz] as asked */
    double sigma;             /* the shift of K_T - sigma M that was factored [1/s^2] */
    double total_mass[3];     /* mass that moves with the free DOFs along x, y, z: r^T M r,
                                 r their unit translation, M the analysis' mass matrix */
    int zero_modes;           /* modes of kind ZERO */
    int unstable_modes;       /* modes of kind UNSTABLE */
    int lanczos_restarts;     /* ARPACK's implicit restarts, or the block solver's thick
                                 restarts */
    int factorizations;       /* numeric factorizations (1, 2 when LL' failed and LDL'
                                 took over) */
    int solves;               /* shift-invert solves (right-hand sides) */
    double max_residual;      /* max over the modes of |K phi - omega^2 M phi| / |K phi| */
    double t_assemble;        /* wall seconds: tangent and mass values */
    double t_factor;          /* wall seconds in the factorization(s) */
    double t_solve;           /* wall seconds in the shift-invert solves */
    double t_total;           /* wall seconds of the whole modal analysis */
    ctn_eigen_solver solver;  /* the eigen-solver used */
    int block_size;           /* BLOCK: columns of a block (0 for ARPACK) */
    int block_solves;         /* BLOCK: multi-right-hand-side solves (solves counts their
                                 columns). When the block solver did not converge (a shift
                                 within about 1e-8 of an eigenvalue) ARPACK takes over:
                                 solver is then ARPACK and block_solves what the block
                                 solver spent */
    double max_floor;         /* BLOCK: the largest rounding bound eps | |K||phi| +
                                 omega^2 |M||phi| | / |K phi| of a mode whose residual is
                                 above 1e-10 (0 if none): what double precision can show */
    int reused_factor;        /* 1: no factorization: the static solve's stability check
                                 had factored K_T at this state (LL', so K_T is positive
                                 definite) and, without a shift, it served with sigma = 0 */
    double t_solve_cpu;       /* CPU seconds of the process in the shift-invert solves */
    double t_cpu;             /* CPU seconds of the process in the whole modal analysis */
} ctn_modal_summary;

/* Modes of a solution: the count (0 if no modal analysis was run) and mode k;
 * CTN_ERR_INVALID for k out of range. */
size_t ctn_solution_mode_count(const ctn_solution *s);
int ctn_solution_mode(const ctn_solution *s, size_t k, ctn_mode *out);
/* CTN_ERR_INVALID when no modal analysis was run on s. */
int ctn_solution_modal_summary(const ctn_solution *s, ctn_modal_summary *out);

/* Solve the model: ctn_problem_create + ctn_problem_solve + destroy. opt NULL: defaults. */
int ctn_solve(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *opt,
              ctn_solution **out);
void ctn_solution_destroy(ctn_solution **s);

void ctn_solution_summary(const ctn_solution *s, ctn_solve_summary *out);
/* Residual norm history over all iterations of all increments: the norm after each
 * Newton iteration, preceded, for each increment, by its starting residual. *n gets
 * the count. Owned by the solution. */
const double *ctn_solution_residual_history(const ctn_solution *s, size_t *n);
/* Increment norm history: |alpha dd| of each Newton iteration; *n gets iterations. */
const double *ctn_solution_increment_history(const ctn_solution *s, size_t *n);
/* Displacements, 3 per node in model node order. Owned by the solution. */
const double *ctn_solution_displacements(const ctn_solution *s);
/* Support reactions, 3 per node: f_int - f_ext on fixed DOFs, 0 on free ones. */
const double *ctn_solution_reactions(const ctn_solution *s);
/* Rotations [rad] about x, y, z, 3 per node in model node order (0 on a node without
 * rotations), and the support reaction moments (f_int - f_ext on fixed rotations, 0 on
 * free ones), of the last step; NULL when no node of the model has rotations
 * (ctn_model_has_rotations). Owned by the solution. */
const double *ctn_solution_rotations(const ctn_solution *s);
const double *ctn_solution_reaction_moments(const ctn_solution *s);
/* The threads= option of the solve that made it (0 auto, 1 one thread, n): what the
 * result writers ask the thread policy with. */
int ctn_solution_threads(const ctn_solution *s);
/* Whether the solution holds rotations (its model has a node with 6 DOFs). */
int ctn_solution_has_rotations(const ctn_solution *s);
/* The same at the end of step k (either out-pointer may be NULL; both get NULL when the
 * model has no rotations); CTN_ERR_INVALID if k is out of range. */
int ctn_solution_step_rotations(const ctn_solution *s, size_t k, const double **rot, const double **moment);
/* State of element i (model element order). */
int ctn_solution_element(const ctn_solution *s, size_t i, ctn_element_state *out);

CTN_API_END
#ifdef __cplusplus
}
#endif

#include "catena/results.h"   /* the results per step (types above) */
#endif
