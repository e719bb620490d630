/* Internal: the buckling analysis's options (buckling_options.c), part of the solve
 * options (ctn_solve_options.buckling) like the modal analysis's. */
#ifndef CTN_PROBLEM_BUCKLING_OPTIONS_H
#define CTN_PROBLEM_BUCKLING_OPTIONS_H

#include "catena/analysis.h"

/* dst = the defaults overwritten by the caller's src (by its size; NULL: the defaults);
 * CTN_ERR_INVALID, recorded, for a size not set or too large. */
int ctn_buckling_options_take(ctn_ctx *ctx, ctn_buckling_options *dst, const ctn_buckling_options *src);
/* 1 with a message if an option is out of range, else 0. */
int ctn_buckling_options_fault(const ctn_buckling_options *opt, char *msg, size_t size);

#endif
