/* ctn_write_vtu: one step of a solution as one ParaView .vtu file, by the writer of
 * result.vtu (io/vtu.c), staged and renamed (atomic). */
#include "catena/io.h"

#include "core/ctx.h"
#include "io/atomic.h"
#include "io/writer.h"

int ctn_write_vtu(ctn_ctx *ctx, const char *path, const ctn_model *m, const ctn_solution *s, size_t step)
{
    if (!ctx || !path || !m || !s) return CTN_ERR_INVALID;
    if (step >= ctn_solution_step_count(s))
        return ctn_error(ctx, CTN_ERR_INVALID, "write_vtu: step %zu out of range (the solution has %zu)",
                         step, ctn_solution_step_count(s));
    int rc = ctn_result_check(ctx, m, s);
    if (rc) return rc;
    ctn_atomic_file f = CTN_ATOMIC_FILE_INIT;
    rc = ctn_atomic_open(ctx, path, &f);
    if (rc) return rc;
    ctn_sink sink = ctn_atomic_sink(&f);
    rc = ctn_writer_run_step(ctx, &ctn_writer_vtu, 1, step, &sink, m, s);
    if (!rc) rc = ctn_atomic_close(&f);
    if (!rc) return ctn_atomic_commit(&f);
    ctn_atomic_abort(&f);
    return rc;
}
