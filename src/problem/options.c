/* Solver options, defaults and reason names. */
#include "problem/problem.h"
#include "problem/buckling_options.h"
#include "problem/dynamics_options.h"

#include "core/versioned.h"
#include "dist/plugin.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void ctn_modal_options_default(ctn_modal_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->size = sizeof *opt;
    opt->count = 0;
    opt->mass = CTN_MASS_CONSISTENT;
    opt->shift = 0;
    opt->line = 0;
    opt->solver = CTN_EIGEN_AUTO;
}

void ctn_stability_options_default(ctn_stability_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->size = sizeof *opt;
}

void ctn_solve_options_default(ctn_solve_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->size = sizeof *opt;
    opt->tol = 1e-10;
    opt->dtol = 1e-8;
    opt->maxit = 50;
    opt->ordering = CTN_ORDER_AUTO;
    opt->method = CTN_METHOD_AUTO;
    opt->linesearch = 0;
    opt->steps = 1;
    opt->maxcuts = -1;
    opt->arclength = 0;
    opt->arcsteps = 200;
    opt->lambda_max = 1;
    opt->monitor = NULL;
    opt->monitor_data = NULL;
    opt->linear_solver = NULL;
    ctn_modal_options_default(&opt->modal);
    opt->threads = 0;
    opt->reuse = 1;
    ctn_buckling_options_default(&opt->buckling);
    ctn_dynamics_options_default(&opt->dynamics);
}

int ctn_modal_options_fault(const ctn_modal_options *o, char *msg, size_t size)
{
    if (o->count < 0)
        return snprintf(msg, size, "modes: count must be >= 1 (got %d)", o->count), 1;
    if (o->mass != CTN_MASS_CONSISTENT && o->mass != CTN_MASS_LUMPED)
        return snprintf(msg, size, "modes: unknown mass matrix"), 1;
    if (o->solver != CTN_EIGEN_BLOCK && o->solver != CTN_EIGEN_ARPACK && o->solver != CTN_EIGEN_AUTO)
        return snprintf(msg, size, "modes: unknown eigen-solver"), 1;
    if (!(isfinite(o->shift) && o->shift >= 0))
        return snprintf(msg, size, "modes: shift must be >= 0 and finite (got %g)", o->shift), 1;
    double w = 6.28318530717958647692 * o->shift;
    if (!isfinite(w * w))
        return snprintf(msg, size, "modes: shift=%g Hz is beyond double precision ((2 pi shift)^2 overflows)", o->shift), 1;
    return 0;
}

const char *ctn_ordering_name(ctn_ordering o)
{
    static const char *const names[] = { "auto", "natural", "amd", "metis" };
    return o >= CTN_ORDER_AUTO && o <= CTN_ORDER_METIS ? names[o] : "?";
}

int ctn_solve_options_fault(const ctn_solve_options *opt, char *msg, size_t size)
{
    if (!(opt->tol > 0) || !isfinite(opt->tol) || !(opt->dtol > 0) || !isfinite(opt->dtol))
        return snprintf(msg, size, "solve: tolerances must be positive and finite"), 1;
    if (opt->maxit < 1 || opt->maxit > 100000)
        return snprintf(msg, size, "solve: maxit must be between 1 and 100000 (got %d)", opt->maxit), 1;
    if (opt->ordering < CTN_ORDER_AUTO || opt->ordering > CTN_ORDER_METIS)
        return snprintf(msg, size, "solve: unknown ordering"), 1;
    if (!ctn_strategy_of(opt->method))
        return snprintf(msg, size, "solve: unknown method"), 1;
    if (opt->steps < 1 || opt->steps > 100000)
        return snprintf(msg, size, "solve: steps must be between 1 and 100000 (got %d)", opt->steps), 1;
    if (opt->maxcuts < -1 || opt->maxcuts > 60)
        return snprintf(msg, size, "solve: cutbacks must be between 0 and 60 (got %d)", opt->maxcuts), 1;
    if (!isfinite(opt->arclength) || opt->arclength < 0)
        return snprintf(msg, size, "solve: arclength must be >= 0 and finite"), 1;
    if (opt->arcsteps < 1 || opt->arcsteps > 1000000)
        return snprintf(msg, size, "solve: arcsteps must be between 1 and 1000000 (got %d)", opt->arcsteps), 1;
    if (!isfinite(opt->lambda_max) || opt->lambda_max == 0)
        return snprintf(msg, size, "solve: lambda must be finite and non-zero"), 1;
    if (opt->threads < 0 || opt->threads > 1024)
        return snprintf(msg, size, "solve: threads must be between 0 and 1024 (got %d)", opt->threads), 1;
    if (opt->reuse != 0 && opt->reuse != 1)
        return snprintf(msg, size, "solve: reuse must be 0 or 1 (got %d)", opt->reuse), 1;
    int module = ctn_linsolve_module_name(opt->linear_solver);
    if (module && !ctn_mpi_module_built())
        return snprintf(msg, size, "solve: linear solver '%.40s' needs catena built with PETSc and MPI (docs/parallel.md)",
                        opt->linear_solver), 1;
    if (opt->linear_solver && !module && !ctn_linsolve_find(opt->linear_solver))
        return snprintf(msg, size, "solve: unknown linear solver '%.40s' (expected cholmod or cholmod-ldl)", opt->linear_solver), 1;
    if (ctn_buckling_options_fault(&opt->buckling, msg, size)) return 1;
    if (ctn_dynamics_options_fault(&opt->dynamics, msg, size)) return 1;
    return ctn_modal_options_fault(&opt->modal, msg, size);
}

int ctn_solve_options_check(ctn_ctx *ctx, const ctn_solve_options *opt)
{
    char msg[256];
    if (!opt) return ctn_error(ctx, CTN_ERR_INVALID, "solve options are NULL");
    ctn_solve_options o;
    int rc = ctn_solve_options_take(ctx, &o, opt);
    if (rc) return rc;
    return ctn_solve_options_fault(&o, msg, sizeof msg) ? ctn_error(ctx, CTN_ERR_INVALID, "%s", msg) : CTN_OK;
}

int ctn_solve_options_take(ctn_ctx *ctx, ctn_solve_options *dst, const ctn_solve_options *src)
{
    ctn_solve_options_default(dst);
    if (!src) return CTN_OK;
    int rc = ctn_versioned_take(ctx, dst, sizeof *dst, src, "solve options");
    dst->modal.size = sizeof dst->modal;   /* the same layout as the caller's, or defaults */
    dst->buckling.size = sizeof dst->buckling;
    dst->dynamics.size = sizeof dst->dynamics;
    return rc;
}

int ctn_modal_options_check(ctn_ctx *ctx, const ctn_modal_options *opt)
{
    char msg[256];
    if (!opt) return ctn_error(ctx, CTN_ERR_INVALID, "modal options are NULL");
    ctn_modal_options o;
    int rc = ctn_modal_options_take(ctx, &o, opt);
    if (rc) return rc;
    return ctn_modal_options_fault(&o, msg, sizeof msg) ? ctn_error(ctx, CTN_ERR_INVALID, "%s", msg) : CTN_OK;
}

int ctn_modal_options_take(ctn_ctx *ctx, ctn_modal_options *dst, const ctn_modal_options *src)
{
    ctn_modal_options_default(dst);
    return src ? ctn_versioned_take(ctx, dst, sizeof *dst, src, "modal options") : CTN_OK;
}

const char *ctn_reason_name(ctn_reason r)
{
    switch (r) {
    case CTN_CONVERGED: return "converged";
    case CTN_DIVERGED_MAXIT: return "maximum iterations reached";
    case CTN_DIVERGED_NANORINF: return "NaN or Inf in the iteration";
    case CTN_DIVERGED_INDEFINITE: return "tangent not positive definite";
    case CTN_DIVERGED_LINESEARCH: return "line search failed";
    case CTN_DIVERGED_ARCLENGTH: return "arc-length step failed";
    case CTN_DIVERGED_ROUNDOFF: return "residual above its round-off floor";
    case CTN_DIVERGED_MECHANISM: return "no equilibrium (a mechanism)";
    default: return "not solved";
    }
}

const char *ctn_dof_name(int dir)
{
    static const char *const names[6] = { "x", "y", "z", "rx", "ry", "rz" };
    return dir >= 0 && dir < 6 ? names[dir] : "?";
}
