/* Internal: atomic file output in two phases, so that a set of files is written
 * completely before any of them replaces an older one. A staged file is a temporary
 * beside the target (path.tmp.XXXXXX, mode 0644), written through its sink, synced and
 * closed, then renamed onto the target (commit) or removed (abort). */
#ifndef CTN_IO_ATOMIC_H
#define CTN_IO_ATOMIC_H

#include "io/sink.h"

typedef struct ctn_atomic_file {
    ctn_ctx *ctx;
    char *path;       /* the target (a copy, owned) */
    char *tmp;        /* the temporary, owned; NULL once committed or aborted */
    int fd;           /* open while staging, else -1 */
} ctn_atomic_file;

/* An unopened file: commit and abort are harmless no-ops on it. */
#define CTN_ATOMIC_FILE_INIT { NULL, NULL, NULL, -1 }

/* CTN_OK when a write to path may replace what is there: nothing, a regular file, or a
 * link to one (written through); else CTN_ERR_IO naming path (a device, directory, pipe
 * or socket, a link to nothing, a file this context has read). ctn_atomic_open makes
 * the same check; a set of files makes it for every file before staging any. */
int ctn_atomic_check(ctn_ctx *ctx, const char *path);
/* Create the temporary beside path. On failure f holds nothing to release. */
int ctn_atomic_open(ctn_ctx *ctx, const char *path, ctn_atomic_file *f);
/* The sink writing to the open temporary. */
ctn_sink ctn_atomic_sink(ctn_atomic_file *f);
/* fsync and close the temporary: its bytes are on disk. */
int ctn_atomic_close(ctn_atomic_file *f);
/* Rename the closed temporary onto the target and release f. On failure the
 * temporary is removed. */
int ctn_atomic_commit(ctn_atomic_file *f);
/* Close and remove the temporary, release f. */
void ctn_atomic_abort(ctn_atomic_file *f);

#endif
