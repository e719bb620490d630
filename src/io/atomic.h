/* Internal: two-phase atomic output, so that a set of files is written completely before
 * any of them replaces an older one. */
#ifndef CTN_IO_ATOMIC_H
#define CTN_IO_ATOMIC_H

#include "core/ctx.h"

/* Write data to a new temporary file beside path (synced); *tmp gets its name. */
int ctn_atomic_stage(ctn_ctx *ctx, const char *path, const char *data, size_t len, char **tmp);
/* Rename the staged file onto path; frees tmp. On failure the temporary is removed. */
int ctn_atomic_commit(ctn_ctx *ctx, char *tmp, const char *path);
/* Remove a staged file that will not be committed; frees tmp; NULL is a no-op. */
void ctn_atomic_abort(char *tmp);

#endif
