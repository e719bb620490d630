/* catena/parallel.h: the public handle of an MPI communicator on a context, over the
 * MPI module (plugin.h), which this opens for each handle. */
#include "catena/parallel.h"

#include "core/ctx.h"
#include "dist/plugin.h"

struct ctn_parallel {
    ctn_mpi_module mod;
    void *impl;                /* the module's communicator */
};

int ctn_parallel_create(ctn_ctx *ctx, const void *mpi_comm, ctn_parallel **out)
{
    if (!ctx || !out) return CTN_ERR_INVALID;
    *out = NULL;
    ctn_parallel *p = ctn_calloc(ctx, 1, sizeof *p);
    if (!p) return CTN_ERR_NOMEM;
    int rc = ctn_mpi_module_open(ctx, &p->mod);
    if (!rc) rc = p->mod.ops->create(ctx, mpi_comm, &p->impl);
    if (rc) {
        ctn_mpi_module_close(&p->mod);
        ctn_free(p);
        return rc;
    }
    *out = p;
    return CTN_OK;
}

int ctn_parallel_attach(ctn_parallel *p, ctn_ctx *ctx)
{
    if (!p || !ctx) return CTN_ERR_INVALID;
    return p->mod.ops->attach(p->impl, ctx);
}

void ctn_parallel_destroy(ctn_parallel **pp)
{
    if (!pp || !*pp) return;
    ctn_parallel *p = *pp;
    p->mod.ops->destroy(p->impl);
    ctn_mpi_module_close(&p->mod);
    ctn_free(p);
    *pp = NULL;
}

int ctn_parallel_rank(const ctn_parallel *p) { return p ? p->mod.ops->rank(p->impl) : 0; }

int ctn_parallel_size(const ctn_parallel *p) { return p ? p->mod.ops->size(p->impl) : 1; }

int ctn_parallel_max(ctn_parallel *p, int *v) { return p ? p->mod.ops->max(p->impl, v) : CTN_OK; }

int ctn_parallel_available(void)
{
    ctn_ctx *ctx = NULL;
    ctn_mpi_module m;
    if (!ctn_mpi_module_built() || ctn_ctx_create(&ctx)) return 0;
    int ok = !ctn_mpi_module_open(ctx, &m);
    ctn_mpi_module_close(&m);
    ctn_ctx_destroy(&ctx);
    return ok;
}

struct ctn_parallel_job {
    ctn_mpi_module mod;
};

int ctn_parallel_job_init(ctn_ctx *ctx, int argc, char **argv, ctn_parallel_job **out)
{
    char msg[256] = "";
    if (!ctx || !out || argc < 1 || !argv) return CTN_ERR_INVALID;
    *out = NULL;
    ctn_parallel_job *j = ctn_calloc(ctx, 1, sizeof *j);
    if (!j) return CTN_ERR_NOMEM;
    int rc = ctn_mpi_module_open(ctx, &j->mod);
    if (!rc && j->mod.ops->job_init(argc, argv, msg, sizeof msg)) rc = ctn_error(ctx, CTN_ERR_IO, "%s", msg);
    if (rc) {
        ctn_mpi_module_close(&j->mod);
        ctn_free(j);
        return rc;
    }
    *out = j;
    return CTN_OK;
}

void ctn_parallel_job_finalize(ctn_parallel_job **jp)
{
    if (!jp || !*jp) return;
    (*jp)->mod.ops->job_finalize();
    ctn_mpi_module_close(&(*jp)->mod);
    ctn_free(*jp);
    *jp = NULL;
}
