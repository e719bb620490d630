/* Result files: result.json, nodes.csv and elements.csv in a directory (and modes.csv
 * when the solution has modes). Each is
 * streamed by its writer (io/writer.h) into a staged temporary (io/atomic.h), synced;
 * only when all three are staged is any renamed onto its target. */
#include "io/atomic.h"
#include "io/writer.h"
#include "catena/io.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#define NFILES 4

static const ctn_writer_ops *const writers[NFILES] = {
    &ctn_writer_json, &ctn_writer_nodes_csv, &ctn_writer_elements_csv, &ctn_writer_modes_csv
};

/* Whether the set holds the file of writer ops for solution s. */
static int wanted(const ctn_writer_ops *ops, const ctn_solution *s)
{
    return ops != &ctn_writer_modes_csv || ctn_solution_mode_count(s) > 0;
}

static int target(ctn_ctx *ctx, const char *dir, const char *name, char *path, size_t size)
{
    if ((size_t)snprintf(path, size, "%s/%s", dir, name) < size) return CTN_OK;
    return ctn_error(ctx, CTN_ERR_IO, "%s: path too long", dir);
}

/* A target that exists must be a regular file (checked before anything is written). */
static int check_targets(ctn_ctx *ctx, const char *dir)
{
    for (int i = 0; i < NFILES; i++) {
        char path[4096];
        struct stat st;
        int rc = target(ctx, dir, writers[i]->name, path, sizeof path);
        if (rc) return rc;
        if (!stat(path, &st) && !S_ISREG(st.st_mode))
            return ctn_error(ctx, CTN_ERR_IO, "%s: exists and is not a regular file", path);
    }
    return CTN_OK;
}

/* Stream one file into its temporary beside dir/name and sync it. On failure the
 * caller aborts f. */
static int stage(ctn_ctx *ctx, const char *dir, const ctn_writer_ops *ops, const ctn_model *m,
                 const ctn_solution *s, ctn_atomic_file *f)
{
    char path[4096];
    int rc = target(ctx, dir, ops->name, path, sizeof path);
    if (!rc) rc = ctn_atomic_open(ctx, path, f);
    if (rc) return rc;
    ctn_sink sink = ctn_atomic_sink(f);
    rc = ctn_writer_run(ctx, ops, 1, &sink, m, s);
    return rc ? rc : ctn_atomic_close(f);
}

/* All the files are staged before any replaces an older one, so a failure leaves the
 * previous set (or nothing) in place, never a mix. */
int ctn_write_results(ctn_ctx *ctx, const char *dir, const ctn_model *m,
                      const ctn_solution *s)
{
    ctn_atomic_file f[NFILES] = { CTN_ATOMIC_FILE_INIT, CTN_ATOMIC_FILE_INIT, CTN_ATOMIC_FILE_INIT, CTN_ATOMIC_FILE_INIT };
    if (!dir || !m || !s) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_write_results: bad arguments");
    int rc = ctn_result_check(ctx, m, s);
    if (rc) return rc;
    if (mkdir(dir, 0755) && errno != EEXIST)
        return ctn_error(ctx, CTN_ERR_IO, "%s: cannot create directory: %s", dir, strerror(errno));
    rc = check_targets(ctx, dir);
    for (int i = 0; i < NFILES && !rc; i++)
        if (wanted(writers[i], s)) rc = stage(ctx, dir, writers[i], m, s, &f[i]);
    for (int i = 0; i < NFILES; i++) {
        if (!wanted(writers[i], s)) continue;
        if (!rc) rc = ctn_atomic_commit(&f[i]);
        else ctn_atomic_abort(&f[i]);
    }
    return rc;
}
