/* Layouts, reductions through the communicator, vectors (layout.h). */
#include "dist/layout.h"

#include "core/ctx.h"

#include <math.h>

void ctn_layout_serial(ctn_layout *l, size_t n, const ctn_comm *comm)
{
    l->n = n;
    l->lo = 0;
    l->hi = n;
    l->nghost = 0;
    l->ghost = NULL;
    l->comm = comm ? comm : &ctn_comm_serial;
}

static double reduce(const ctn_layout *l, double x, ctn_reduce_op op)
{
    if (l->comm->ops->allreduce(l->comm->impl, &x, 1, op)) return NAN;   /* a failed exchange
                                                    poisons the result: the caller's test of
                                                    finiteness stops the iteration */
    return x;
}

double ctn_layout_sum(const ctn_layout *l, double x) { return reduce(l, x, CTN_REDUCE_SUM); }

double ctn_layout_max(const ctn_layout *l, double x) { return reduce(l, x, CTN_REDUCE_MAX); }

double ctn_layout_dot(const ctn_layout *l, const double *a, const double *b)
{
    double s = 0;
    size_t n = ctn_layout_owned(l);
    for (size_t i = 0; i < n; i++) s += a[i] * b[i];
    return ctn_layout_sum(l, s);
}

/* sqrt(ss) as it is when ss is a normal number (every Newton iteration's case), else the
 * sum again scaled by the largest entry, so that a load of 1e300 has the norm 1e300, not
 * Inf, and 1e-200 not 0. A NaN stays NaN. */
double ctn_layout_norm_ss(const ctn_layout *l, double ss, ctn_entry_fn entry, const void *ud)
{
    if (isnan(ss) || (ss > 0x1p-900 && ss < 0x1p+900)) return sqrt(ss);
    size_t n = ctn_layout_owned(l);
    double big = 0;
    for (size_t i = 0; i < n; i++) big = fmax(big, fabs(entry(ud, i)));
    big = ctn_layout_max(l, big);
    if (!(big > 0) || isinf(big)) return big;
    double t = 0;
    for (size_t i = 0; i < n; i++) {
        double x = entry(ud, i) / big;
        t += x * x;
    }
    return big * sqrt(ctn_layout_sum(l, t));
}

static double plain_entry(const void *ud, size_t i) { return ((const double *)ud)[i]; }

double ctn_layout_norm(const ctn_layout *l, const double *a)
{
    double s = 0;
    size_t n = ctn_layout_owned(l);
    for (size_t i = 0; i < n; i++) s += a[i] * a[i];
    return ctn_layout_norm_ss(l, ctn_layout_sum(l, s), plain_entry, a);
}

int ctn_layout_ghosts(const ctn_layout *l, double *v)
{
    return l->nghost ? l->comm->ops->ghosts(l->comm->impl, l, v) : CTN_OK;
}

int ctn_dvec_create(ctn_ctx *ctx, const ctn_layout *lay, ctn_dvec *x)
{
    size_t n = ctn_layout_local(lay);
    x->lay = lay;
    x->v = ctn_calloc(ctx, n ? n : 1, sizeof(double));
    return x->v ? CTN_OK : CTN_ERR_NOMEM;
}

void ctn_dvec_destroy(ctn_dvec *x)
{
    ctn_free(x->v);
    x->v = NULL;
}
