/* Internal: analyses as objects (catena/analysis.h). An analysis kind is an ops table:
 * its name, the size of its options struct (size_t size first) and their defaults and
 * check, and run. The kinds are listed once, in analysis.c's registry; each lives in
 * its folder (static/, stability/, modal/, buckling/, dynamics/) and uses the problem (problem/problem.h) the
 * analyses share. */
#ifndef CTN_ANALYSIS_ANALYSIS_H
#define CTN_ANALYSIS_ANALYSIS_H

#include "problem/problem.h"

typedef struct ctn_analysis_ops {
    const char *name;          /* "static", "stability", "modal", "buckling", "dynamics" */
    size_t options_size;       /* sizeof its options struct */
    int needs_solution;        /* 1: runs about the last step of a converged solution */
    /* the defaults (the problem's own where it has them) */
    void (*defaults)(const ctn_problem *p, void *opt);
    /* CTN_ERR_INVALID (recorded) when an option is out of range or does not fit p */
    int (*check)(ctn_problem *p, const void *opt);
    /* the computation: a new *s (static) or results stored in *s */
    int (*run)(ctn_problem *p, const void *opt, ctn_solution **s);
} ctn_analysis_ops;

extern const ctn_analysis_ops ctn_analysis_static, ctn_analysis_stability, ctn_analysis_modal;
extern const ctn_analysis_ops ctn_analysis_buckling;   /* buckling/buckling.c */
extern const ctn_analysis_ops ctn_analysis_dynamics;   /* dynamics/dynamics.c */

/* The dynamics analysis with options o into s (dynamics/dynamics.c): from rest at the
 * start geometry when s has no step, else from its last step's state; a step "dynamics"
 * (the state reached) and the histories added to s. A failed time step is an outcome
 * (s->sum.reason, the dynamics summary's t_fail), not an error. */
int ctn_dynamics_run(ctn_problem *p, ctn_solution *s, const ctn_dynamics_options *o);

/* The registered kind of a name, NULL if none. */
const ctn_analysis_ops *ctn_analysis_find(const char *name);

/* The static analysis of p with options o (static/static.c): a new solution in *out. */
int ctn_static_run(ctn_problem *p, const ctn_solve_options *o, ctn_solution **out);

#endif
