/* Internal: the solution object. */
#ifndef CTN_SOLVE_SOLUTION_H
#define CTN_SOLVE_SOLUTION_H

#include "catena/solve.h"
#include "core/ctx.h"

struct ctn_solution {
    ctn_solve_summary sum;
    size_t nn, ne;
    double *d;                 /* 3 nn displacements */
    double *react;             /* 3 nn reactions */
    ctn_element_state *elem;   /* ne */
    double *rhist, *dhist;     /* maxit + 1 and maxit entries */
    size_t nhist;              /* iterations recorded */
};

int ctn_solution_alloc(ctn_ctx *ctx, size_t nn, size_t ne, int maxit, ctn_solution **out);

#endif
