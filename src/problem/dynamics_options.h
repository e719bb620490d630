/* Internal: the dynamics analysis's options (dynamics_options.c), part of the solve
 * options (ctn_solve_options.dynamics) like the modal and buckling analyses'. */
#ifndef CTN_PROBLEM_DYNAMICS_OPTIONS_H
#define CTN_PROBLEM_DYNAMICS_OPTIONS_H

#include "catena/analysis.h"

/* dst = the defaults overwritten by the caller's src (by its size; NULL: the defaults);
 * CTN_ERR_INVALID, recorded, for a size not set or too large. */
int ctn_dynamics_options_take(ctn_ctx *ctx, ctn_dynamics_options *dst, const ctn_dynamics_options *src);
/* 1 with a message if an option is out of range, else 0. */
int ctn_dynamics_options_fault(const ctn_dynamics_options *opt, char *msg, size_t size);
/* Whether the options ask for a dynamics analysis (t_end > 0). */
static inline int ctn_dynamics_asked(const ctn_dynamics_options *o) { return o->t_end > 0; }

#endif
