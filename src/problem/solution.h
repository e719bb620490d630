/* Internal: the solution object: per-step states and the iteration history. */
#ifndef CTN_SOLVE_SOLUTION_H
#define CTN_SOLVE_SOLUTION_H

#include "catena/analysis.h"
#include "catena/solve.h"
#include "core/ctx.h"

typedef struct ctn_step_state {
    char name[64];
    ctn_reason reason;
    double t;                  /* load fraction reached, or arc-length load factor */
    int iterations;
    double *d;                 /* 3 nn displacements */
    double *react;             /* 3 nn reactions */
    double *rot;               /* 3 nn rotations [rad], NULL when no node has rotations */
    double *moment;            /* 3 nn reaction moments, NULL likewise */
    ctn_element_state *elem;   /* ne */
} ctn_step_state;

/* The modes of a modal analysis (modes_result.c). */
typedef struct ctn_modes {
    ctn_modal_summary sum;
    ctn_mode *mode;            /* sum.count, by increasing omega^2 */
    double *shapes;            /* 3 nn per mode; mode[k].shape points into it */
    double *rshapes;           /* 3 nn per mode: the rotations (spins) of the shapes, NULL
                                  when no node has rotations (a dynamics' modal damping) */
} ctn_modes;

/* The factors of a buckling analysis (analysis/buckling/buckling_result.c). */
typedef struct ctn_buckles {
    ctn_buckling_summary sum;
    ctn_buckling_mode *mode;   /* sum.count, lowest factor first */
    double *shapes;            /* 3 nn per mode; mode[k].shape points into it */
} ctn_buckles;

/* The histories of a dynamics analysis (analysis/dynamics/dyn_record.c). */
#define CTN_DYN_NAME_MAX 24
typedef struct ctn_dyn_result {
    ctn_dynamics_summary sum;
    size_t ncol;               /* columns after t */
    char (*names)[CTN_DYN_NAME_MAX]; /* ncol: "ID.ux", "ID.force" */
    size_t nrow, cap;          /* rows stored, room */
    double *rows;              /* nrow x (1 + ncol): t, then the columns */
    double *energy;            /* nrow x 4: kinetic, strain, work, damping */
    size_t nn, ne;             /* the model's nodes and elements (a frame's size) */
    size_t nframe, fcap;       /* frames stored (one per row when asked), room */
    double *frames;            /* nframe x (1 + 9 nn + ne): t, d, v, react (3 per node),
                                  the elements' axial forces */
} ctn_dyn_result;
void ctn_dyn_result_destroy(ctn_dyn_result **r);

struct ctn_solution {
    ctn_ctx *ctx;
    ctn_solve_summary sum;
    size_t nn, ne;
    ctn_step_state *steps;
    size_t nsteps, capsteps;
    ctn_stability stability;   /* of the last step's state, when checked */
    double *rhist, *dhist;     /* residual and increment norms */
    size_t nr, nd, capr, capd;
    ctn_modes *modes;          /* the last modal analysis, NULL if none */
    ctn_buckles *buckling;     /* the last buckling analysis, NULL if none */
    ctn_dyn_result *dyn;       /* the last dynamics analysis, NULL if none */
    int rot;                   /* some node has rotations: the steps keep rot and moment */
    struct ctn_solution **cases; /* the load cases then combinations of the model, one
                                  solution of one step each (cases.c); NULL if none */
    size_t ncases;
    size_t of_case;            /* a case's solution: 1 + the case's index (its loads and
                                  temperatures are the case's), else 0 */
    int threads;               /* the threads= option of the solve that made it (0 auto,
                                  1, n): the writers ask the thread policy with it */
    int ranks;                 /* the processes it was solved on (catena/parallel.h) */
    int by_columns;            /* its tangent was held by columns over the ranks (each its
                                  own nodes' columns: problem/dist.c), not whole on each */
    char linsolver[48];        /* the linear solver's label (ctn_linsolve_label), "" none */
};

int ctn_solution_create(ctn_ctx *ctx, size_t nn, size_t ne, ctn_solution **out);
/* Set rot before the first step is added when some node has rotations. */
/* Append a step state (arrays zeroed); *k gets its index. */
int ctn_solution_add_step(ctn_solution *s, const char *name, size_t *k);
/* Remove the last step (a strategy replaces it). */
void ctn_solution_drop_step(ctn_solution *s);
int ctn_solution_push_residual(ctn_solution *s, double r);
int ctn_solution_push_increment(ctn_solution *s, double d);
/* A zeroed set of count modes for nn nodes (shape pointers set); NULL when out of memory. */
ctn_modes *ctn_modes_create(ctn_ctx *ctx, size_t count, size_t nn);
void ctn_modes_destroy(ctn_modes **m);
/* A zeroed set of count buckling modes for nn nodes; NULL when out of memory. */
ctn_buckles *ctn_buckles_create(ctn_ctx *ctx, size_t count, size_t nn);
void ctn_buckles_destroy(ctn_buckles **b);

#endif
