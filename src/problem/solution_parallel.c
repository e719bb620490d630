/* The processes and the linear solver of a solution (catena/parallel.h). */
#include "catena/parallel.h"

#include "problem/solution.h"

int ctn_solution_ranks(const ctn_solution *s) { return s && s->ranks > 1 ? s->ranks : 1; }

int ctn_solution_by_columns(const ctn_solution *s) { return s && s->by_columns; }

const char *ctn_solution_linear_solver(const ctn_solution *s) { return s ? s->linsolver : ""; }
