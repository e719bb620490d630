/* Atomic file output: a temporary file beside the target, written through a sink,
 * synced, then renamed. */
#define _DEFAULT_SOURCE                  /* realpath, lstat */
#include "io/atomic.h"
#include "catena/io.h"
#include "core/ctx.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void release(ctn_atomic_file *f)
{
    ctn_free(f->path);
    ctn_free(f->tmp);
    *f = (ctn_atomic_file)CTN_ATOMIC_FILE_INIT;
}

/* The file a write to path must replace: path itself when nothing is there or a regular
 * file is, the file a symbolic link leads to (written through, not replaced), never a
 * device, a directory, a pipe or a socket, nor a file this context has read. *target is
 * allocated (path's copy or the link's resolution); target NULL: the checks only. */
static int resolve_target(ctn_ctx *ctx, const char *path, char **target)
{
    struct stat st;
    char *real = NULL;
    const char *t = path;
    if (lstat(path, &st)) {
        if (errno != ENOENT) return ctn_error(ctx, CTN_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    } else {
        if (S_ISLNK(st.st_mode)) {
            real = realpath(path, NULL);
            if (!real || stat(real, &st)) {
                int rc = ctn_error(ctx, CTN_ERR_IO, "%s: a symbolic link to a missing file; not written", path);
                free(real);
                return rc;
            }
            t = real;
        }
        int rc = CTN_OK;
        if (!S_ISREG(st.st_mode))
            rc = ctn_error(ctx, CTN_ERR_IO, "%s: not a regular file (a device, directory, pipe or socket); "
                           "catena replaces only regular files", path);
        else if (ctn_ctx_is_input(ctx, (unsigned long long)st.st_dev, (unsigned long long)st.st_ino))
            rc = ctn_error(ctx, CTN_ERR_IO, "%s: is the input being read; write the output elsewhere", path);
        if (rc) {
            free(real);
            return rc;
        }
    }
    if (!target) {
        free(real);
        return CTN_OK;
    }
    size_t n = strlen(t) + 1;
    *target = ctn_malloc(ctx, n, 1);
    if (*target) memcpy(*target, t, n);
    free(real);
    return *target ? CTN_OK : CTN_ERR_NOMEM;
}

int ctn_atomic_check(ctn_ctx *ctx, const char *path) { return resolve_target(ctx, path, NULL); }

int ctn_atomic_open(ctn_ctx *ctx, const char *path, ctn_atomic_file *f)
{
    *f = (ctn_atomic_file)CTN_ATOMIC_FILE_INIT;
    f->ctx = ctx;
    int rc = resolve_target(ctx, path, &f->path);
    if (rc) return rc;
    size_t pl = strlen(f->path);
    f->tmp = ctn_malloc(ctx, pl + 16, 1);
    if (!f->tmp) {
        release(f);
        return CTN_ERR_NOMEM;
    }
    snprintf(f->tmp, pl + 16, "%s.tmp.XXXXXX", f->path);
    f->fd = mkstemp(f->tmp);
    if (f->fd < 0) {
        rc = ctn_error(ctx, CTN_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
        release(f);
        return rc;
    }
    if (!fchmod(f->fd, 0644)) return CTN_OK;
    rc = ctn_error(ctx, CTN_ERR_IO, "%s: chmod failed: %s", path, strerror(errno));
    ctn_atomic_abort(f);
    return rc;
}

static int fd_write(void *ud, const char *p, size_t n)
{
    ctn_atomic_file *f = ud;
    while (n) {
        ssize_t k = write(f->fd, p, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0)
            return ctn_error(f->ctx, CTN_ERR_IO, "%s: write failed: %s", f->path,
                             k < 0 ? strerror(errno) : "no progress");
        p += k;
        n -= (size_t)k;
    }
    return CTN_OK;
}

ctn_sink ctn_atomic_sink(ctn_atomic_file *f) { return (ctn_sink){ fd_write, f }; }

int ctn_atomic_close(ctn_atomic_file *f)
{
    int rc = CTN_OK;
    if (fsync(f->fd)) rc = ctn_error(f->ctx, CTN_ERR_IO, "%s: fsync failed: %s", f->path, strerror(errno));
    if (close(f->fd) && !rc) rc = ctn_error(f->ctx, CTN_ERR_IO, "%s: close failed: %s", f->path, strerror(errno));
    f->fd = -1;
    return rc;
}

int ctn_atomic_commit(ctn_atomic_file *f)
{
    int rc = CTN_OK;
    if (!f->tmp) return rc;
    if (rename(f->tmp, f->path)) {
        rc = ctn_error(f->ctx, CTN_ERR_IO, "%s: rename failed: %s", f->path, strerror(errno));
        unlink(f->tmp);
    }
    release(f);
    return rc;
}

void ctn_atomic_abort(ctn_atomic_file *f)
{
    if (f->fd >= 0) close(f->fd);
    if (f->tmp) unlink(f->tmp);
    release(f);
}

int ctn_write_file_atomic(ctn_ctx *ctx, const char *path, const char *data, size_t len)
{
    if (!path || (!data && len)) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_write_file_atomic: bad arguments");
    ctn_atomic_file f;
    int rc = ctn_atomic_open(ctx, path, &f);
    if (!rc && len) rc = fd_write(&f, data, len);
    if (!rc) rc = ctn_atomic_close(&f);
    if (rc) {
        ctn_atomic_abort(&f);
        return rc;
    }
    return ctn_atomic_commit(&f);
}
