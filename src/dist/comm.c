/* The serial communicator and the context's (comm.h). */
#include "dist/comm.h"

#include "core/ctx.h"

static int serial_rank(const void *impl)
{
    (void)impl;
    return 0;
}

static int serial_size(const void *impl)
{
    (void)impl;
    return 1;
}

static int serial_allreduce(void *impl, double *v, size_t n, ctn_reduce_op op)
{
    (void)impl;
    (void)v;
    (void)n;
    (void)op;
    return CTN_OK;                               /* one process: its values are the result */
}

static int serial_ghosts(void *impl, const ctn_layout *lay, double *v)
{
    (void)impl;
    (void)lay;
    (void)v;
    return CTN_OK;                               /* one process owns everything */
}

static int serial_allgather(void *impl, double *v, size_t lo, size_t hi)
{
    (void)impl;
    (void)v;
    (void)lo;
    (void)hi;
    return CTN_OK;                               /* one process holds every range */
}

static const ctn_comm_ops serial_ops = { "serial", serial_rank, serial_size, serial_allreduce, serial_ghosts,
                                         serial_allgather, NULL, NULL };

const ctn_comm ctn_comm_serial = { &serial_ops, NULL };

const ctn_comm *ctn_ctx_comm(const ctn_ctx *ctx) { return ctx && ctx->comm ? ctx->comm : &ctn_comm_serial; }

void ctn_ctx_set_comm(ctn_ctx *ctx, const ctn_comm *comm)
{
    if (ctx) ctx->comm = comm;
}
