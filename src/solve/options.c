/* Solver options, defaults and reason names. */
#include "model/model.h"

#include <math.h>

void ctn_solve_options_default(ctn_solve_options *opt)
{
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
}

void ctn_model_solve_options(const ctn_model *m, ctn_solve_options *opt)
{
    if (m) *opt = m->options;
    else ctn_solve_options_default(opt);
}

int ctn_model_set_solve_options(ctn_model *m, const ctn_solve_options *opt)
{
    if (!m || !opt) return CTN_ERR_INVALID;
    if (!(opt->tol > 0) || !isfinite(opt->tol) || !(opt->dtol > 0) || !isfinite(opt->dtol))
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: tolerances must be positive and finite");
    if (opt->maxit < 1 || opt->maxit > 100000)
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: maxit must be between 1 and 100000 (got %d)", opt->maxit);
    if (opt->ordering < CTN_ORDER_AUTO || opt->ordering > CTN_ORDER_AMD)
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: unknown ordering");
    if (opt->method < CTN_METHOD_AUTO || opt->method > CTN_METHOD_ARCLENGTH)
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: unknown method");
    if (opt->steps < 1 || opt->steps > 100000)
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: steps must be between 1 and 100000 (got %d)", opt->steps);
    if (opt->maxcuts < -1 || opt->maxcuts > 60)
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: cutbacks must be between 0 and 60 (got %d)", opt->maxcuts);
    if (!isfinite(opt->arclength) || opt->arclength < 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: arclength must be >= 0 and finite");
    if (opt->arcsteps < 1 || opt->arcsteps > 1000000)
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: arcsteps must be between 1 and 1000000 (got %d)", opt->arcsteps);
    if (!isfinite(opt->lambda_max) || opt->lambda_max == 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "solve: lambda must be finite and non-zero");
    m->options = *opt;
    return CTN_OK;
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
    default: return "not solved";
    }
}
