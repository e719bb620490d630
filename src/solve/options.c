/* Solver options, defaults and reason names. */
#include "model/model.h"

#include <math.h>

void ctn_solve_options_default(ctn_solve_options *opt)
{
    opt->tol = 1e-10;
    opt->dtol = 1e-8;
    opt->maxit = 50;
    opt->ordering = CTN_ORDER_AUTO;
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
    default: return "not solved";
    }
}
