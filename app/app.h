/* The catena command: shared declarations of the sub-commands. */
#ifndef CTN_APP_APP_H
#define CTN_APP_APP_H

#include <stdio.h>

#include "catena.h"

/* Exit codes of the catena command (docs/cli.md). */
enum {
    CTN_EXIT_OK = 0,         /* converged / success */
    CTN_EXIT_USAGE = 1,      /* bad command line */
    CTN_EXIT_MODEL = 2,      /* bad model file */
    CTN_EXIT_NOCONV = 3,     /* the solution did not converge */
    CTN_EXIT_IO = 4,         /* a file could not be read or written, or another failure */
};

int ctn_cmd_solve(int argc, char **argv);

/* Exit code for a failed library call, after printing its message to stderr. */
int ctn_app_fail(ctn_ctx *ctx, int status);

/* Human-readable result summary. */
void ctn_print_summary(FILE *out, const ctn_model *m, const ctn_solution *s);
/* Iteration log state: the monitor prints one line per Newton iteration with the
 * observed order log(r_k/r_k-1) / log(r_k-1/r_k-2) (2 for quadratic convergence). */
typedef struct ctn_iter_log {
    FILE *out;
    double r[2];   /* the two previous residual norms, 0 if none */
} ctn_iter_log;
void ctn_print_iteration(void *data, int it, double rnorm, double dnorm);

#endif
