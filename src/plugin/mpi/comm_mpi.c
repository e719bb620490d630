/* The MPI communicator (comm_mpi.h) and the module's handle that sets it on a context
 * (the library's ctn_parallel_create, dist/parallel.c, calls it through plugin.h). Reductions gather every process's values and combine them in rank
 * order on every process: the same bits everywhere, whatever MPI's own reduction tree
 * would have done, so that a decision taken on a reduced value (a converged residual) is
 * the same decision on every rank. */
#include "plugin/mpi/comm_mpi.h"

#include "core/ctx.h"
#include "plugin/mpi/petsc/petsc.h"
#ifdef CTN_HAVE_SLEPC
#include "plugin/mpi/slepc/slepc_eigen.h"
#endif

#include <limits.h>
#include <math.h>

typedef struct mpi_comm {
    MPI_Comm comm;             /* a duplicate of the caller's: our messages are ours */
    int rank, size;
    double *buf;               /* size * CTN_MPI_REDUCE_MAX gathered values */
    long long *ranges;         /* 2 size: every rank's [lo, hi) of an allgather */
    int *counts;               /* 2 size: their lengths and offsets */
} mpi_comm;

#define CTN_MPI_REDUCE_MAX 4096  /* values per reduction in one exchange */

typedef struct mpi_handle {
    ctn_ctx *ctx;
    ctn_comm comm;
    mpi_comm impl;
    const ctn_comm *before;    /* the context's communicator before (restored) */
} mpi_handle;

static int mpi_rank(const void *impl) { return ((const mpi_comm *)impl)->rank; }

static int mpi_size(const void *impl) { return ((const mpi_comm *)impl)->size; }

static double combine(double a, double b, ctn_reduce_op op)
{
    if (op == CTN_REDUCE_SUM || isnan(a) || isnan(b)) return a + b;   /* NaN stays NaN */
    if (op == CTN_REDUCE_MAX) return a > b ? a : b;
    return a < b ? a : b;
}

/* v <- op over the ranks, in rank order (a NaN anywhere stays NaN) */
static int mpi_allreduce(void *impl, double *v, size_t n, ctn_reduce_op op)
{
    mpi_comm *c = impl;
    for (size_t k0 = 0; k0 < n; k0 += CTN_MPI_REDUCE_MAX) {
        int m = (int)(n - k0 < CTN_MPI_REDUCE_MAX ? n - k0 : CTN_MPI_REDUCE_MAX);
        if (MPI_Allgather(v + k0, m, MPI_DOUBLE, c->buf, m, MPI_DOUBLE, c->comm) != MPI_SUCCESS) return CTN_ERR_IO;
        for (int i = 0; i < m; i++) {
            double x = c->buf[i];
            for (int r = 1; r < c->size; r++) x = combine(x, c->buf[(size_t)r * (size_t)m + (size_t)i], op);
            v[k0 + (size_t)i] = x;
        }
    }
    return CTN_OK;
}

/* The replicated engine keeps no ghosts (every rank holds every entry): an exchange
 * asked for is a layout this engine does not make. */
static int mpi_ghosts(void *impl, const ctn_layout *lay, double *v)
{
    (void)impl;
    (void)lay;
    (void)v;
    return CTN_ERR_INVALID;
}

/* every rank's [lo, hi) of v to every rank (in place) */
static int mpi_allgather(void *impl, double *v, size_t lo, size_t hi)
{
    mpi_comm *c = impl;
    long long mine[2] = { (long long)lo, (long long)hi }, *all = c->ranges;
    int *count = c->counts, rc = CTN_OK;
    if (MPI_Allgather(mine, 2, MPI_LONG_LONG, all, 2, MPI_LONG_LONG, c->comm) != MPI_SUCCESS) rc = CTN_ERR_IO;
    for (int r = 0; !rc && r < c->size; r++) {
        if (all[2 * r + 1] - all[2 * r] > INT_MAX || all[2 * r] > INT_MAX) rc = CTN_ERR_INVALID;
        count[r] = (int)(all[2 * r + 1] - all[2 * r]);
        count[c->size + r] = (int)all[2 * r];
    }
    if (!rc && MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DOUBLE, v, count, count + c->size, MPI_DOUBLE, c->comm) != MPI_SUCCESS)
        rc = CTN_ERR_IO;
    return rc;
}

/* the PETSc solvers: over this communicator's processes */
static const ctn_linsolve_ops *const mpi_solvers[] = {
    &ctn_petsc_mumps_ops, &ctn_petsc_ldl_ops, &ctn_petsc_cg_ops, &ctn_petsc_inertia_ops, NULL,
};

#ifdef CTN_HAVE_SLEPC
/* the modal analysis's eigenproblem: SLEPc over this communicator's processes */
static int mpi_eigen(void *impl, ctn_ctx *ctx, const ctn_pattern *p, const double *Kx, const double *Mx, int nev,
                     double sigma, double *lambda, double **vecs, ctn_eigen_info *info)
{
    return ctn_slepc_eigen(((mpi_comm *)impl)->comm, ctx, p, Kx, Mx, nev, sigma, lambda, vecs, info);
}
#define CTN_MPI_EIGEN mpi_eigen
#else
#define CTN_MPI_EIGEN NULL
#endif

const ctn_comm_ops ctn_comm_mpi_ops = { "mpi", mpi_rank, mpi_size, mpi_allreduce, mpi_ghosts, mpi_allgather, mpi_solvers, CTN_MPI_EIGEN };

MPI_Comm ctn_comm_mpi_handle(const ctn_comm *c)
{
    return c && c->ops == &ctn_comm_mpi_ops ? ((const mpi_comm *)c->impl)->comm : MPI_COMM_SELF;
}

int ctn_mpi_handle_create(ctn_ctx *ctx, const void *mpi_comm_ptr, void **out)
{
    int init = 0;
    *out = NULL;
    if (MPI_Initialized(&init) != MPI_SUCCESS || !init)
        return ctn_error(ctx, CTN_ERR_INVALID, "ctn_parallel_create: MPI is not initialised (the caller initialises it)");
    mpi_handle *p = ctn_calloc(ctx, 1, sizeof *p);
    if (!p) return CTN_ERR_NOMEM;
    MPI_Comm given = mpi_comm_ptr ? *(const MPI_Comm *)mpi_comm_ptr : MPI_COMM_WORLD;
    if (MPI_Comm_dup(given, &p->impl.comm) != MPI_SUCCESS) {
        ctn_free(p);
        return ctn_error(ctx, CTN_ERR_IO, "ctn_parallel_create: MPI_Comm_dup failed");
    }
    MPI_Comm_rank(p->impl.comm, &p->impl.rank);
    MPI_Comm_size(p->impl.comm, &p->impl.size);
    p->impl.buf = ctn_calloc(ctx, (size_t)p->impl.size * CTN_MPI_REDUCE_MAX, sizeof(double));
    p->impl.ranges = ctn_calloc(ctx, 2 * (size_t)p->impl.size, sizeof(long long));
    p->impl.counts = ctn_calloc(ctx, 2 * (size_t)p->impl.size, sizeof(int));
    if (!p->impl.buf || !p->impl.ranges || !p->impl.counts) {
        ctn_free(p->impl.buf);
        ctn_free(p->impl.ranges);
        ctn_free(p->impl.counts);
        MPI_Comm_free(&p->impl.comm);
        ctn_free(p);
        return CTN_ERR_NOMEM;
    }
    p->ctx = ctx;
    p->comm = (ctn_comm){ &ctn_comm_mpi_ops, &p->impl };
    p->before = ctx->comm;
    ctn_ctx_set_comm(ctx, &p->comm);
    *out = p;
    return CTN_OK;
}

int ctn_mpi_handle_attach(void *h, ctn_ctx *ctx)
{
    mpi_handle *p = h;
    ctn_ctx_set_comm(ctx, &p->comm);
    return CTN_OK;
}

void ctn_mpi_handle_destroy(void *h)
{
    mpi_handle *p = h;
    if (p->ctx->comm == &p->comm) ctn_ctx_set_comm(p->ctx, p->before);
    int fin = 0;
    MPI_Finalized(&fin);
    if (!fin) MPI_Comm_free(&p->impl.comm);
    ctn_free(p->impl.buf);
    ctn_free(p->impl.ranges);
    ctn_free(p->impl.counts);
    ctn_free(p);
}

int ctn_mpi_handle_rank(const void *h) { return ((const mpi_handle *)h)->impl.rank; }

int ctn_mpi_handle_size(const void *h) { return ((const mpi_handle *)h)->impl.size; }

int ctn_mpi_handle_max(void *h, int *v)
{
    mpi_handle *p = h;
    int in = *v;
    if (MPI_Allreduce(&in, v, 1, MPI_INT, MPI_MAX, p->impl.comm) != MPI_SUCCESS) return CTN_ERR_IO;
    return CTN_OK;
}
