/*
 * catena/analysis.h - analyses as objects over a problem.
 *
 * A problem (ctn_problem, catena/solve.h) holds what every analysis of a model shares:
 * the DOF map, the sparsity pattern, the element properties, the linear solver's
 * symbolic analysis, the tangent's values and the state vectors. An analysis is one
 * kind of computation on it, registered by name, with options of its own:
 *
 *   "static"     the static analysis by the options' method (newton, auto, arclength):
 *                options ctn_solve_options; makes a new solution
 *   "stability"  the inertia of the tangent at a solution's last step: options
 *                ctn_stability_options; its result is read with ctn_solution_stability
 *   "modal"      the natural modes about a converged solution: options
 *                ctn_modal_options; read with ctn_solution_mode
 *   "buckling"   the linear buckling factors about a converged solution: options
 *                ctn_buckling_options; read with ctn_solution_buckling
 *   "dynamics"   time integration (ctn_dynamics_options): from rest at the start
 *                geometry when *s is NULL (a new solution), else from the converged last
 *                step of *s with its loads held (a step "dynamics" added to it); read
 *                with ctn_solution_history, ctn_solution_dynamics_summary
 *
 * Every options struct starts with its size (set by its _default function), so that a
 * program built against this header keeps working when later versions add keys at the
 * end: the library reads the keys the caller's size covers and takes the defaults for
 * the rest. A size of 0 (options not initialised by their _default function) is refused.
 *
 *   ctn_analysis *a;
 *   ctn_modal_options mo;
 *   ctn_modal_options_default(&mo);
 *   mo.count = 6;
 *   ctn_analysis_create(problem, "modal", &mo, &a);
 *   ctn_analysis_run(a, &solution);         (solution: a converged static solution)
 *   ctn_analysis_destroy(&a);
 */
#ifndef CATENA_ANALYSIS_H
#define CATENA_ANALYSIS_H

#include <stddef.h>

#include "catena/core.h"
#include "catena/solve.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* Options of the stability analysis: nothing to choose yet but the size. */
typedef struct ctn_stability_options {
    size_t size;          /* sizeof(ctn_stability_options), set by the _default function */
} ctn_stability_options;
void ctn_stability_options_default(ctn_stability_options *opt);
/* The defaults of the modal analysis (count 0: set it to the modes wanted). */
void ctn_modal_options_default(ctn_modal_options *opt);
/* CTN_OK, or CTN_ERR_INVALID with a message naming the option out of range (a count of
 * 0 is in range: no modal analysis). */
int ctn_modal_options_check(ctn_ctx *ctx, const ctn_modal_options *opt);

/* The defaults of the buckling analysis (count 0: set it to the factors wanted). */
void ctn_buckling_options_default(ctn_buckling_options *opt);
/* CTN_OK, or CTN_ERR_INVALID with a message naming the option out of range (a count of
 * 0 is in range: no buckling analysis). */
int ctn_buckling_options_check(ctn_ctx *ctx, const ctn_buckling_options *opt);

/* The buckling analysis works on dense matrices of the free DOFs (LAPACK's dsygv): at
 * most this many free DOFs; beyond, CTN_ERR_MODEL naming the limit. */
#define CTN_BUCKLING_MAX_DOFS 2000

/* Linear buckling about the converged state d of a solution's last step, with f that
 * step's total external loads (dead loads and moments, on the free DOFs): K_T the
 * tangent at d (it must be positive definite), u' = K_T^-1 f the tangent of the load
 * path, K' = dK_T/dlambda along it (a central difference of the tangent at d +- h u'),
 * and the factors lambda of the pencil K_T + (lambda - 1) K' singular: -K' phi = theta
 * K_T phi, lambda = 1 + 1/theta. On a linear pre-buckling path (K_T = K_M + K_G,
 * K_G linear in the load) this is the classical (K_M + lambda K_G^(f)) phi = 0 exactly.
 * docs/theory.md, "Linear buckling". */
typedef struct ctn_buckling_mode {
    double factor;            /* lambda > 0: the load factor on the step's loads */
    const double *shape;      /* phi, 3 translations per node in model node order (0 on
                                 fixed DOFs), scaled so that the largest |component| is 1
                                 and positive. Owned by the solution */
    int node;                 /* user id of the node that moves most */
    double residual;          /* |K(lambda) phi| / (|K_T phi| + |lambda - 1| |K' phi|),
                                 K(lambda) = K_T + (lambda - 1) K' */
} ctn_buckling_mode;

typedef struct ctn_buckling_summary {
    int count;                /* factors stored: the lowest positive ones, at most the
                                 count asked (fewer when the pencil has fewer) */
    int asked;                /* the count asked */
    int ndof;                 /* free DOFs of the dense problem */
    double h;                 /* the central difference's step along u' (h max|u'| is
                                 1e-5 of the model's size) */
    double load_norm;         /* |f| on the free DOFs */
    double t_total;           /* wall seconds of the buckling analysis */
    /* The non-linear check (check=1; docs/format.md "buckling"), 0 when not run: */
    int nl_kind;              /* 1: a limit, the largest load factor of a converged stable
                                 state on the imperfect path (the path fails or loses its
                                 stability past it, below lambda_1 - 0.0115 (lambda_1 - 1));
                                 2: the path stays stable to there (a stable bifurcation):
                                 Southwell's factor, the slope of a / lambda against a (a
                                 the path's amplitude in the mode) */
    double nl_factor;         /* that load factor on the step's loads */
    double nl_imperfection;   /* the imperfection's amplitude [length]: the largest
                                 translation of the mode's shape times this, from a
                                 perturbing load growing with lambda */
    int nl_increments;        /* the path's increments solved */
} ctn_buckling_summary;

/* Buckling factors of a solution: the count (0 if no buckling analysis was run) and
 * factor k, lowest first; CTN_ERR_INVALID for k out of range. */
size_t ctn_solution_buckling_count(const ctn_solution *s);
int ctn_solution_buckling(const ctn_solution *s, size_t k, ctn_buckling_mode *out);
/* CTN_ERR_INVALID when no buckling analysis was run on s. */
int ctn_solution_buckling_summary(const ctn_solution *s, ctn_buckling_summary *out);

/* The defaults of the dynamics analysis (t_end 0: set dt and t_end). */
void ctn_dynamics_options_default(ctn_dynamics_options *opt);
/* CTN_OK, or CTN_ERR_INVALID with a message naming the option out of range (dt and t_end
 * both 0 are in range: no dynamics analysis). */
int ctn_dynamics_options_check(ctn_ctx *ctx, const ctn_dynamics_options *opt);

/* A dynamics analysis as a whole (docs/theory.md "Dynamics"). */
typedef struct ctn_dynamics_summary {
    ctn_dyn_method method;
    double dt, t_end;         /* as asked [s] */
    double t_reached;         /* the time of the last converged state [s] (t_end when done) */
    size_t steps;             /* time steps of dt taken (rows of the history - 1 with
                                 output_every 1) */
    double alpha_m, alpha_f, gamma, beta; /* the method's parameters */
    double rho_inf;           /* as asked (genalpha, hht) */
    ctn_mass_matrix mass;     /* the mass matrix used */
    double damping_alpha, damping_beta;   /* Rayleigh's, as used */
    int iterations;           /* Newton iterations (implicit) over every step */
    int factorizations;       /* numeric factorizations of the effective tangent */
    int cuts;                 /* halvings of dt on failed steps */
    int substeps;             /* steps taken (more than steps when dt was cut) */
    double dt_stable;         /* CENTRAL: the stable step of the mesh [s]; else 0 */
    double energy_error;      /* max over the rows of |E_k + U - W + D - (E_k0 + U_0)| /
                                 max(E_k + U + |W| + D, over the rows) */
    double t_total;           /* wall seconds of the dynamics analysis */
    ctn_reason reason;        /* CTN_CONVERGED when t_end was reached; else why the step
                                 after t_reached failed with dt cut maxcuts times */
    double t_fail;            /* not converged: the time the failed step started [s] */
    int output_every;         /* a row every this many steps (t = 0 and the last too) */
    int modal_count;          /* modes under modal damping (0: none) */
    size_t frames;            /* frames kept for the VTU series (0: none) */
    int relative_wind;        /* elements under a relative-velocity wind drag (0: none) */
} ctn_dynamics_summary;

/* CTN_ERR_INVALID when no dynamics analysis was run on s. */
int ctn_solution_dynamics_summary(const ctn_solution *s, ctn_dynamics_summary *out);
/* The recorded time histories (ctn_model_record_node, ctn_model_record_element): rows
 * 1 + steps (t = 0 first, then every dt; with output_every K every K-th step and the
 * last), each 1 + columns numbers: t [s], then one per
 * column (a node's displacement from the start geometry, an element's axial force);
 * NULL (0, 0) without a dynamics analysis. Owned by the solution. */
const double *ctn_solution_history(const ctn_solution *s, size_t *rows, size_t *columns);
/* The name of column j (0-based, after t): "ID.ux", "ID.uy", "ID.uz" for node ID,
 * "ID.force" for element ID; NULL when out of range. */
const char *ctn_solution_history_name(const ctn_solution *s, size_t j);
/* The energy balance at every row: 4 numbers each, kinetic energy E_k, strain energy U,
 * work of the external loads since t = 0 W, energy dissipated by damping D [force
 * length]; NULL without a dynamics analysis. Owned by the solution. */
const double *ctn_solution_energy(const ctn_solution *s, size_t *rows);
/* The state at a row of the histories, kept when the options asked for frames
 * (ctn_dynamics_options.frames; the model file's `dynamics ... vtu=1`): arrays owned by
 * the solution, 3 numbers per node in model order, one per element. */
typedef struct ctn_dyn_frame {
    double t;                 /* its time [s] (the row's) */
    const double *d;          /* displacements from the start geometry [L] */
    const double *v;          /* velocities [L/s] (a moving support's from its function) */
    const double *react;      /* reactions at the supports f_int + M a + C v - f_ext [F]
                                 (inertia and damping included), 0 elsewhere */
    const double *force;      /* the elements' axial forces N [F] */
    size_t nodes, elements;   /* the arrays' sizes: 3 nodes, elements */
} ctn_dyn_frame;
/* The frames kept (0 without), and frame k < that count (CTN_ERR_INVALID otherwise). */
size_t ctn_solution_frame_count(const ctn_solution *s);
int ctn_solution_frame(const ctn_solution *s, size_t k, ctn_dyn_frame *out);
/* The name of a method: "genalpha", "hht", "newmark", "central" ("?" if none). */
const char *ctn_dyn_method_name(ctn_dyn_method m);

typedef struct ctn_analysis ctn_analysis;

/* The registered analyses: their count and the name of the i-th ("static",
 * "stability", "modal", "buckling", "dynamics"); NULL for i out of range. */
size_t ctn_analysis_count(void);
const char *ctn_analysis_type(size_t i);

/* An analysis of kind name on problem p, with options (the kind's options struct, its
 * size first; NULL: the defaults, for "static" the problem's own options). The options
 * are checked and copied: the caller's struct may go. CTN_ERR_INVALID for an unknown
 * name (the message lists the known ones), options out of range or not initialised, or
 * static options whose method needs another linear solver than the problem's (create
 * the problem with them). The problem must outlive the analysis. */
int ctn_analysis_create(ctn_problem *p, const char *name, const void *options, ctn_analysis **out);
/* Run it. "static": *s gets a new solution (any earlier *s is left to its owner);
 * the others run about the last step of the converged solution *s and store their
 * results in it. Non-convergence is an outcome (the solution's reason), not an error. */
int ctn_analysis_run(ctn_analysis *a, ctn_solution **s);
const char *ctn_analysis_name(const ctn_analysis *a);
/* NULL or *a == NULL is a harmless no-op; sets *a to NULL. */
void ctn_analysis_destroy(ctn_analysis **a);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
