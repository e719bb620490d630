/* The dynamics analysis's options: defaults, range check, versioned copy. */
#include "problem/dynamics_options.h"

#include "core/ctx.h"
#include "core/versioned.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void ctn_dynamics_options_default(ctn_dynamics_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->size = sizeof *opt;
    opt->method = CTN_DYN_GENALPHA;
    opt->rho_inf = 0.9;
    opt->alpha = NAN;
    opt->gamma = 0.5;
    opt->beta = 0.25;
    opt->mass = CTN_MASS_CONSISTENT;
    opt->tol = 1e-8;
    opt->dtol = 1e-12;
    opt->maxit = 20;
    opt->maxcuts = 10;
    opt->from_rest = 1;
    opt->output_every = 1;
}

const char *ctn_dyn_method_name(ctn_dyn_method m)
{
    static const char *const names[] = { "genalpha", "hht", "newmark", "central" };
    return m >= CTN_DYN_GENALPHA && m <= CTN_DYN_CENTRAL ? names[m] : "?";
}

static int fault(char *msg, size_t size, const char *what)
{
    snprintf(msg, size, "dynamics: %s", what);
    return 1;
}

/* The Newmark parameters: gamma >= 1/2 and beta >= (gamma + 1/2)^2 / 4 (unconditional
 * stability of the linear method), or the explicit beta = 0 is the central method's. */
static int newmark_fault(const ctn_dynamics_options *o, char *msg, size_t size)
{
    if (!(isfinite(o->gamma) && o->gamma >= 0.5 && o->gamma <= 1))
        return snprintf(msg, size, "dynamics: gamma must be from 0.5 to 1 (got %g)", o->gamma), 1;
    double lo = 0.25 * (o->gamma + 0.5) * (o->gamma + 0.5);
    if (!(isfinite(o->beta) && o->beta >= lo - 1e-15 && o->beta <= 0.5))
        return snprintf(msg, size, "dynamics: beta must be from (gamma + 1/2)^2 / 4 = %g to 0.5 (got %g)", lo, o->beta), 1;
    return 0;
}

/* Modal damping: a count within CTN_DYN_MODAL_MAX, 1 or count ratios in [0, 1). */
static int modal_fault(const ctn_dynamics_options *o, char *msg, size_t size)
{
    if (o->modal_count < 0 || o->modal_count > CTN_DYN_MODAL_MAX)
        return snprintf(msg, size, "dynamics: modal damping takes 1 to %d modes (got %d)", CTN_DYN_MODAL_MAX, o->modal_count), 1;
    if (!o->modal_count) return 0;
    if (o->modal_nzeta != 1 && o->modal_nzeta != o->modal_count)
        return snprintf(msg, size, "dynamics: modal damping needs 1 ratio or one per mode (%d), got %d", o->modal_count,
                        o->modal_nzeta), 1;
    for (int i = 0; i < o->modal_nzeta; i++)
        if (!(o->modal_zeta[i] >= 0 && o->modal_zeta[i] < 1))
            return snprintf(msg, size, "dynamics: modal damping ratio %d must be from 0 to below 1 (got %g)", i + 1,
                            o->modal_zeta[i]), 1;
    return 0;
}

int ctn_dynamics_options_fault(const ctn_dynamics_options *o, char *msg, size_t size)
{
    if (o->dt == 0 && o->t_end == 0) return 0;                     /* no dynamics */
    if (!(isfinite(o->dt) && o->dt > 0)) return snprintf(msg, size, "dynamics: dt must be > 0 and finite (got %g)", o->dt), 1;
    if (!(isfinite(o->t_end) && o->t_end > 0))
        return snprintf(msg, size, "dynamics: t_end must be after the start t = 0 (got %g)", o->t_end), 1;
    if (o->t_end / o->dt > 1e9) return snprintf(msg, size, "dynamics: t_end / dt is more than 1e9 steps (%g)", o->t_end / o->dt), 1;
    if (o->method < CTN_DYN_GENALPHA || o->method > CTN_DYN_CENTRAL) return fault(msg, size, "unknown method");
    if (!(o->rho_inf >= 0 && o->rho_inf <= 1))
        return snprintf(msg, size, "dynamics: rho_inf must be from 0 to 1 (got %g)", o->rho_inf), 1;
    if (o->method == CTN_DYN_HHT && isnan(o->alpha) && o->rho_inf < 0.5)
        return snprintf(msg, size, "dynamics: method=hht takes rho_inf from 0.5 to 1 (got %g; genalpha goes lower)", o->rho_inf), 1;
    if (!isnan(o->alpha) && !(o->alpha >= -1.0 / 3 && o->alpha <= 0))
        return snprintf(msg, size, "dynamics: alpha (HHT) must be from -1/3 to 0 (got %g)", o->alpha), 1;
    if (o->method == CTN_DYN_NEWMARK && newmark_fault(o, msg, size)) return 1;
    if (o->mass != CTN_MASS_CONSISTENT && o->mass != CTN_MASS_LUMPED) return fault(msg, size, "unknown mass matrix");
    if (!(isfinite(o->damping_alpha) && o->damping_alpha >= 0 && isfinite(o->damping_beta) && o->damping_beta >= 0))
        return snprintf(msg, size, "dynamics: damping alpha and beta must be >= 0 and finite (got %g, %g)",
                        o->damping_alpha, o->damping_beta), 1;
    if (!(o->tol > 0 && isfinite(o->tol) && o->dtol > 0 && isfinite(o->dtol)))
        return fault(msg, size, "tolerances must be positive and finite");
    if (o->maxit < 1 || o->maxit > 1000) return snprintf(msg, size, "dynamics: maxit must be from 1 to 1000 (got %d)", o->maxit), 1;
    if (o->maxcuts < 0 || o->maxcuts > 40)
        return snprintf(msg, size, "dynamics: cutbacks must be from 0 to 40 (got %d)", o->maxcuts), 1;
    if (o->output_every < 1) return snprintf(msg, size, "dynamics: output_every must be >= 1 (got %d)", o->output_every), 1;
    if (o->frames != 0 && o->frames != 1) return fault(msg, size, "frames must be 0 or 1");
    if (o->relative_wind != 0 && o->relative_wind != 1) return fault(msg, size, "relative_wind must be 0 or 1");
    return modal_fault(o, msg, size);
}

int ctn_dynamics_options_take(ctn_ctx *ctx, ctn_dynamics_options *dst, const ctn_dynamics_options *src)
{
    ctn_dynamics_options_default(dst);
    return src ? ctn_versioned_take(ctx, dst, sizeof *dst, src, "dynamics options") : CTN_OK;
}

int ctn_dynamics_options_check(ctn_ctx *ctx, const ctn_dynamics_options *opt)
{
    char msg[256];
    if (!opt) return ctn_error(ctx, CTN_ERR_INVALID, "dynamics options are NULL");
    ctn_dynamics_options o;
    int rc = ctn_dynamics_options_take(ctx, &o, opt);
    if (rc) return rc;
    return ctn_dynamics_options_fault(&o, msg, sizeof msg) ? ctn_error(ctx, CTN_ERR_INVALID, "%s", msg) : CTN_OK;
}
