/* Atomic file output: write a temporary file beside the target, then rename. */
#include "io/atomic.h"
#include "catena/io.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int ctn_atomic_stage(ctn_ctx *ctx, const char *path, const char *data, size_t len, char **out)
{
    *out = NULL;
    size_t pl = strlen(path);
    char *tmp = ctn_malloc(ctx, pl + 16, 1);
    if (!tmp) return CTN_ERR_NOMEM;
    snprintf(tmp, pl + 16, "%s.tmp.XXXXXX", path);
    int fd = mkstemp(tmp), rc = CTN_OK;
    if (fd < 0) {
        rc = ctn_error(ctx, CTN_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
        ctn_free(tmp);
        return rc;
    }
    if (fchmod(fd, 0644)) rc = ctn_error(ctx, CTN_ERR_IO, "%s: chmod failed: %s", path, strerror(errno));
    size_t done = 0;
    while (!rc && done < len) {
        ssize_t k = write(fd, data + done, len - done);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) { rc = ctn_error(ctx, CTN_ERR_IO, "%s: write failed: %s", path, strerror(errno)); break; }
        done += (size_t)k;
    }
    if (!rc && fsync(fd)) rc = ctn_error(ctx, CTN_ERR_IO, "%s: fsync failed: %s", path, strerror(errno));
    if (close(fd) && !rc) rc = ctn_error(ctx, CTN_ERR_IO, "%s: close failed: %s", path, strerror(errno));
    if (rc) {
        ctn_atomic_abort(tmp);
        return rc;
    }
    *out = tmp;
    return CTN_OK;
}

int ctn_atomic_commit(ctn_ctx *ctx, char *tmp, const char *path)
{
    int rc = CTN_OK;
    if (rename(tmp, path)) {
        rc = ctn_error(ctx, CTN_ERR_IO, "%s: rename failed: %s", path, strerror(errno));
        unlink(tmp);
    }
    ctn_free(tmp);
    return rc;
}

void ctn_atomic_abort(char *tmp)
{
    if (!tmp) return;
    unlink(tmp);
    ctn_free(tmp);
}

int ctn_write_file_atomic(ctn_ctx *ctx, const char *path, const char *data, size_t len)
{
    if (!path || (!data && len)) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_write_file_atomic: bad arguments");
    char *tmp = NULL;
    int rc = ctn_atomic_stage(ctx, path, data, len, &tmp);
    return rc ? rc : ctn_atomic_commit(ctx, tmp, path);
}
