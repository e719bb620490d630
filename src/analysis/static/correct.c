/* Newton corrector at a fixed load parameter.
 *   pure (CTN_METHOD_NEWTON):  K dd = r, d <- d + dd (the paper's), optionally with a
 *                              backtracking line search on |r|;
 *   globalized (CTN_METHOD_AUTO): (K + mu I) dd = r with mu = 0 while K is positive
 *                              definite and full steps lower the total potential;
 *                              otherwise mu grows (Levenberg-Marquardt) and a
 *                              backtracking (Armijo) line search on the potential picks
 *                              the step. The residual is never modified, so the converged
 *                              equilibrium does not depend on mu or the path. */
#include "problem/problem.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define LS_HALVINGS 30
#define ARMIJO 1e-4
#define CTN_NONMONOTONE 16   /* memory of the non-monotone acceptance test */
#define CTN_FLOOR (1e3 * DBL_EPSILON)  /* |dd| / (|d| + L_ref) below which the
                                         correction is at the coordinates' resolution */
#define CTN_FLOOR_MAX 1e-4             /* largest round-off floor accepted, relative to
                                         the force that meets at the nodes */
#define CTN_STALLS 3                   /* iterations at resolution above the floor */
#define CTN_LM_AGREE 0.75             /* gain ratio at which the quadratic model is
                                         trusted: the shift falls by CTN_LM_FALL, not by
                                         Nielsen's 1/3 at most (docs/solver.md) */
#define CTN_LM_FALL 0.1
#define CTN_QUADRATIC 0.1              /* |r| fell at least this much in a full Newton
                                         step: the next may reuse the factorization */
#define CTN_WATCHDOG 12                /* Newton steps taken on trust from a checkpoint */

typedef struct corrector {
    ctn_problem *e;
    ctn_solution *s;
    double *d;
    double rn;          /* |r| at d */
    double pi;          /* potential at d (globalized only) */
    double mu, nu;      /* Levenberg-Marquardt shift and its growth factor */
    double past[CTN_NONMONOTONE]; /* potentials of the last accepted iterates */
    int npast;
    int globalized;
    int accepted;       /* the last iteration moved d */
    double dmax;        /* an upper bound of |d| (triangle inequality), for the increment
                           test: |d| itself is computed only when the test can pass */
    double fref;        /* force scale of the residual test */
    int quadratic;      /* the last step was a full Newton step that cut |r| by
                           CTN_QUADRATIC: the next one reuses the factorization */
    double cut;         /* |r| after / before that step */
    int wd_left;        /* watchdog (finite rotations): Newton steps still taken on trust
                           from the checkpoint e->wd; 0 when none is open */
    int wd_spent;       /* a watchdog failed from this state: none until an acceptance */
    double wd_rn, wd_pi, wd_ref;  /* the checkpoint's |r|, merit and reference */
} corrector;

/* Raise the shift after a failure (Nielsen: mu *= nu, nu *= 2). */
static void raise_mu(corrector *c)
{
    if (c->mu == 0) {
        c->mu = 1e-6 * ctn_problem_max_diag(c->e);
        c->nu = 2;
    } else {
        c->mu *= c->nu;
        c->nu *= 2;
    }
}

/* A watchdog (lm_step) that failed at a state taken on trust where the tangent is not
 * definite: back to its checkpoint (d, its residual and tangent), the shift raised from
 * 0 there as after a rejected step. */
static int watchdog_back(corrector *c)
{
    ctn_problem *e = c->e;
    int valid;
    memcpy(c->d, e->wd, e->ns * sizeof(double));
    int rc = ctn_problem_residual(e, c->d, 1, &c->rn, NULL, &valid);
    if (rc) return rc;
    c->pi = c->wd_pi;
    c->wd_left = 0;
    c->wd_spent = 1;
    c->mu = 0;
    raise_mu(c);
    return CTN_OK;
}

/* Factorize K + mu I; the globalized corrector raises mu until it is definite. */
static int factor(corrector *c, int *ok)
{
    for (;;) {
        long col;
        int rc = ctn_problem_factor(c->e, c->mu, ok, &col);
        if (rc || *ok) return rc;
        if (!c->globalized || c->mu > 1e12 * c->e->kscale) {
            if (col < 0) col = ctn_problem_fail_col(c->e, c->mu);   /* a solver that pivots */
            if (col < 0) return CTN_OK;
            c->s->sum.fail_node = c->e->m->nodes.v[c->e->a->map.dof_node[col]].id;
            c->s->sum.fail_dir = c->e->a->map.dof_dir[col];
            return CTN_OK;
        }
        if (c->wd_left) {                        /* on trust, the tangent not definite */
            if ((rc = watchdog_back(c))) return rc;
            continue;
        }
        raise_mu(c);
    }
}

/* d = dsave + alpha dd, its residual (with K) and, if pi != NULL, its potential;
 * *ok = 0 if an element collapsed. d equals dsave on entry when fresh is set. */
static int trial(corrector *c, double alpha, int fresh, double *rn, double *pi, int *ok)
{
    ctn_problem *e = c->e;
    if (!fresh) memcpy(c->d, e->dsave, e->ns * sizeof(double));
    ctn_problem_update(e, c->d, alpha, e->dd);
    int rc = ctn_problem_residual(e, c->d, 1, rn, pi, ok);
    if (pi && (e->fl || e->sp)) *pi = 0.5 * *rn * *rn;          /* no potential: the residual's merit */
    return rc;
}

/* Pure Newton, optionally with backtracking on |r|: the accepted alpha, or 0. */
static int newton_search(corrector *c, double *alpha, double *rn)
{
    int ok, rc, halvings = c->e->opt.linesearch ? LS_HALVINGS : 0;
    *alpha = 1;
    for (int h = 0; h <= halvings; h++, *alpha *= 0.5) {
        if ((rc = trial(c, *alpha, h == 0, rn, NULL, &ok))) return rc;
        if (ok && (!c->e->opt.linesearch || *rn <= (1 - ARMIJO * *alpha) * c->rn)) return CTN_OK;
    }
    *alpha = 0;
    return CTN_OK;
}

/* Remember an accepted potential (ring buffer) and return the reference: the largest
 * of the last CTN_NONMONOTONE (Grippo-Lampariello-Lucidi), so that Newton's natural
 * non-monotone first steps are not rejected. */
static void remember(corrector *c, double pi)
{
    c->past[c->npast++ % CTN_NONMONOTONE] = pi;
}

static double reference(const corrector *c)
{
    double r = c->pi;
    int n = c->npast < CTN_NONMONOTONE ? c->npast : CTN_NONMONOTONE;
    for (int i = 0; i < n; i++) r = fmax(r, c->past[i]);
    return r;
}

/* A trial state (|r| rn, merit pi) lowers the merit enough to be accepted: below the
 * non-monotone reference, or, at round-off, |r| not larger and the merit not higher
 * than at the start; while a watchdog is open (below), than at its checkpoint. */
static int acceptable(const corrector *c, double rn, double pi)
{
    int wd = c->wd_left > 0;
    double ref = wd ? c->wd_ref : reference(c), rn0 = wd ? c->wd_rn : c->rn, pi0 = wd ? c->wd_pi : c->pi;
    /* the potential falls below the reference; or, at round-off, |r| falls while the
     * potential does not rise, or the step lands within the residual test (a start
     * already in equilibrium, whose steps are round-off noise) */
    double noise = 1e-12 * fabs(pi0);
    return pi < ref || (rn <= rn0 && pi <= pi0 + noise) || (rn <= c->e->opt.tol * c->fref && pi <= pi0 + noise);
}

/* A watchdog is open, or would open on this step if it were rejected (below). */
static int trusting(const corrector *c)
{
    return c->wd_left > 0 || (c->e->wd && c->mu == 0 && !c->wd_spent);
}

/* The step of a model of finite rotations (beams: the DOF map composes the rotations)
 * with its stretch correction (stretch.c: a mechanism swung by straight-line steps
 * stretches its members by the square of the turn): where the forces g of the stretch
 * the step did not predict exceed the residual at its start (a swing, not Newton's
 * quadratic end game), dc = (K + mu I)^-1 (-g) on the step's factorization, and
 * d + dd + dc kept when its potential is the lower; but where the watchdog would take
 * the step on trust, only when that makes it acceptable (a correction that does not
 * cure the step spoils Newton's next one: the roll-up's residual then fell by 2 per
 * two steps instead of converging). c->d, *rn, *pi: the state kept and its residual. */
static int second_order(corrector *c, double *rn, double *pi)
{
    ctn_problem *e = c->e;
    int valid, rc;
    double rn2, pi2;
    if (e->a->map.rot_update != ctn_rot_update_compose) return CTN_OK;
    if (!ctn_problem_stretch_rhs(e, e->dsave, c->d, e->dd, e->w)) return CTN_OK;
    if (!(ctn_layout_norm(&e->eq, e->w) > c->rn)) return CTN_OK;   /* not the stretch's step */
    if ((rc = ctn_problem_linsolve(e, e->w, e->r))) return rc;     /* dc, in r (recomputed) */
    memcpy(e->react, c->d, e->ns * sizeof(double));      /* the trial state, kept */
    if (isfinite(ctn_layout_norm(&e->eq, e->r))) {
        ctn_problem_update(e, c->d, 1.0, e->r);
        if ((rc = ctn_problem_residual(e, c->d, 1, &rn2, &pi2, &valid))) return rc;
        if (e->fl || e->sp) pi2 = 0.5 * rn2 * rn2;          /* no potential: the merit */
        if (valid && pi2 < *pi && (!trusting(c) || acceptable(c, *rn, *pi) || acceptable(c, rn2, pi2))) {
            *rn = rn2;
            *pi = pi2;
            return CTN_OK;
        }
    }
    memcpy(c->d, e->react, e->ns * sizeof(double));       /* back to the trial */
    if ((rc = ctn_problem_residual(e, c->d, 1, rn, pi, &valid))) return rc;
    if (e->fl || e->sp) *pi = 0.5 * *rn * *rn;
    return CTN_OK;
}

/* The watchdog (Chamberlain, Powell, Lemarechal and Pedersen 1982) for a model of
 * finite rotations, where the merit rejects the Newton steps that converge: a node
 * turned by a spin moves its neighbours along the tangents of their circles, and the
 * members stretch by the square of the turn (stretch.c); the potential (or |r|^2)
 * at the full step then rises, by the members' axial stiffness, and the corrector
 * crawls on a raised shift (the cantilever rolled into a circle, the helix: not
 * converged in 580 iterations), where Newton's next step takes the stretch back at
 * once (the Maratos effect of constrained optimization). So a rejected full Newton step
 * (no shift) is taken on trust from a checkpoint, as are up to CTN_WATCHDOG - 1 more
 * Newton steps (a tangent that is not definite on the way fails the watchdog at once,
 * factor() above: a cantilever loaded at once to a large deflection crawled on shifted
 * steps on trust, 45 iterations against 25); the first whose merit falls below the
 * checkpoint's reference closes the watchdog, and if none does the corrector returns
 * to the checkpoint and raises the shift there.
 * 1: the step is taken on trust. */
static int watchdog(corrector *c)
{
    ctn_problem *e = c->e;
    if (c->wd_left > 1) {
        c->wd_left--;
        return 1;
    }
    if (c->wd_left == 1) {                       /* failed: back to the checkpoint */
        c->wd_left = 0;
        c->wd_spent = 1;
        memcpy(e->dsave, e->wd, e->ns * sizeof(double));
        c->pi = c->wd_pi;
        return 0;
    }
    if (!e->wd || c->mu != 0 || c->wd_spent) return 0;
    memcpy(e->wd, e->dsave, e->ns * sizeof(double));
    c->wd_rn = c->rn;
    c->wd_pi = c->pi;
    c->wd_ref = reference(c);
    c->wd_left = CTN_WATCHDOG;
    return 1;
}

/* Levenberg-Marquardt step with the gain ratio rho = actual / predicted decrease of the
 * potential, predicted = (dd.r + mu |dd|^2) / 2. Accept if the potential falls below the
 * non-monotone reference (or, at round-off, if |r| falls while the potential does not
 * rise); mu follows Nielsen's rule on the monotone ratio, except that where the model
 * agrees (rho >= CTN_LM_AGREE) it falls ten times, so that a first rejected step does not
 * condemn a dozen cautious ones (issue 29: the 1e4-element B1 cable 17 -> 12 iterations).
 * While a watchdog is open the test is against its checkpoint. */
static int lm_step(corrector *c, double *alpha, double *rn, double *pi)
{
    ctn_problem *e = c->e;
    double dd2 = ctn_layout_dot(&e->eq, e->dd, e->dd);
    double pred = e->fl || e->sp ? 0.5 * (c->rn * c->rn - c->mu * c->mu * dd2)       /* |r|^2 / 2 */
                        : 0.5 * (ctn_layout_dot(&e->eq, e->r, e->dd) + c->mu * dd2);
    int ok, rc = trial(c, 1.0, 1, rn, pi, &ok);
    *alpha = 0;
    if (rc) return rc;
    if (!ok) {
        if (c->wd_left) {                        /* an element collapsed: back at once */
            c->wd_left = 1;
            watchdog(c);
        }
        return CTN_OK;
    }
    if ((rc = second_order(c, rn, pi))) return rc;
    double rho = pred > 0 ? (c->pi - *pi) / pred : -1;
    if (acceptable(c, *rn, *pi)) {
        /* A plateau: the model predicts no decrease and none came (a slack state under
         * loads without a potential, where the merit |r|^2 / 2 cannot fall until members
         * take up their slack): the step did no harm and says nothing, so it may grow as
         * if the model agreed, instead of creeping at the shift of the last rejection. */
        int plateau = e->fl && pred <= 1e-12 * 0.5 * c->rn * c->rn && *rn >= (1 - 1e-12) * c->rn;
        if (rho > 0 || plateau) {
            double f = 1 - pow(2 * fmin(rho, 1) - 1, 3);
            c->mu *= plateau || rho >= CTN_LM_AGREE ? CTN_LM_FALL : f > 1.0 / 3 ? f : 1.0 / 3;
            if (c->mu < 1e-14 * e->kscale) c->mu = 0; /* plain Newton from here */
            c->nu = 2;
        }
        c->wd_left = 0;
        c->wd_spent = 0;
        remember(c, *pi);
        *alpha = 1;
    } else if (watchdog(c)) {
        *alpha = 1;                              /* on trust: not remembered */
    }
    return CTN_OK;
}

/* The Newton step dd = K^-1 r: with the last factorization while Newton converges
 * quadratically (reuse.c: to the forcing term below, or at least a tenth of |r|),
 * else by a new one. */
static int newton_step(corrector *c, ctn_reason *why)
{
    ctn_problem *e = c->e;
    int ok = 0, rc = CTN_OK;
    if (c->quadratic && c->mu == 0) {
        /* Solved to the accuracy the next iterate can use: with |r| cut by q in the
         * last step, Newton's next residual is about q^2 |r|, so the step's own error
         * is kept below that (Eisenstat and Walker's forcing term q^2), not below
         * 1e-8 |r|: quadratic convergence is kept with fewer solves. */
        double eta = fmin(1e-2, fmax(1e-8, c->cut * c->cut));
        double target = fmax(0.1 * e->opt.tol * c->fref, eta * c->rn);
        if ((rc = ctn_problem_reuse_step(e, target, 0.1 * c->rn, &ok)) || ok) return rc;
    }
    if ((rc = factor(c, &ok))) return rc;
    if (!ok) { *why = CTN_DIVERGED_INDEFINITE; return CTN_OK; }
    return ctn_problem_linsolve(e, e->r, e->dd);
}

/* One Newton iteration: factor, solve, accept or reject. *why: 0 or a stop reason. */
static int iteration(corrector *c, ctn_reason *why)
{
    ctn_problem *e = c->e;
    double alpha, rn = 0, pi = 0, r0 = c->rn;
    *why = 0;
    c->accepted = 0;
    int rc = newton_step(c, why);
    c->quadratic = 0;
    if (rc || *why) return rc;
    if (!isfinite(ctn_layout_norm(&e->eq, e->dd))) { *why = CTN_DIVERGED_NANORINF; return CTN_OK; }
    int keep = c->globalized || e->opt.linesearch;   /* a step may be rejected */
    if (keep) memcpy(e->dsave, c->d, e->ns * sizeof(double));
    rc = c->globalized ? lm_step(c, &alpha, &rn, &pi) : newton_search(c, &alpha, &rn);
    if (rc) return rc;
    double shift = c->mu;
    if (alpha == 0) {                            /* back to the start of the iteration */
        double tried = ctn_layout_norm(&e->eq, e->dd);
        if (keep) memcpy(c->d, e->dsave, e->ns * sizeof(double));
        else ctn_problem_update(e, c->d, -1.0, e->dd); /* pure Newton: undo the step */
        int valid;
        if ((rc = ctn_problem_residual(e, c->d, 1, &c->rn, NULL, &valid)) || !valid) return rc;
        if (!c->globalized) { *why = e->opt.linesearch ? CTN_DIVERGED_LINESEARCH : CTN_DIVERGED_NANORINF; return CTN_OK; }
        raise_mu(c);
        return ctn_problem_record_ex(e, c->s, c->rn, tried, 1, shift);
    }
    c->rn = rn;
    c->pi = pi;
    c->accepted = 1;
    c->quadratic = c->globalized && shift == 0 && alpha == 1 && rn <= CTN_QUADRATIC * r0;
    c->cut = r0 > 0 ? rn / r0 : 0;
    return ctn_problem_record_ex(e, c->s, rn, alpha * ctn_layout_norm(&e->eq, e->dd), 0, shift);
}

/* The Newton correction is at the resolution of the coordinates with |r| above tol |f_ext|:
 * converged if |r| is within the computed round-off floor and that floor resolves the
 * forces that meet at the nodes (at most CTN_FLOOR_MAX of them); else, after CTN_STALLS
 * such iterations, the residual will not fall: CTN_DIVERGED_ROUNDOFF. 1 when decided. */
static int at_floor(ctn_problem *e, ctn_solution *s, const double *d, double rn, int *stalls,
                    ctn_reason *reason)
{
    double scale, F = ctn_problem_residual_floor(e, d, &scale);
    s->sum.residual_floor = F;
    s->sum.force_scale = scale;
    if (rn <= F && F <= CTN_FLOOR_MAX * scale) {
        *reason = CTN_CONVERGED;
        s->sum.floor = 1;
        s->sum.floor_step = s->nsteps ? s->nsteps - 1 : 0;
        return 1;
    }
    if (F > CTN_FLOOR_MAX * scale || ++*stalls >= CTN_STALLS) {
        *reason = CTN_DIVERGED_ROUNDOFF;
        return 1;
    }
    return 0;
}

static int correct(ctn_problem *e, ctn_solution *s, double *d, ctn_reason *reason)
{
    corrector c;
    memset(&c, 0, sizeof c);
    c.e = e;
    c.s = s;
    c.d = d;
    c.nu = 2;
    c.globalized = e->strategy->globalized;
    *reason = CTN_DIVERGED_NANORINF;
    int valid, rc = ctn_problem_residual(e, d, 1, &c.rn, c.globalized ? &c.pi : NULL, &valid);
    if (c.globalized && (e->fl || e->sp)) c.pi = 0.5 * c.rn * c.rn;
    if (!rc && valid && c.globalized) remember(&c, c.pi);
    if (rc || !valid) return rc;
    if ((rc = ctn_solution_push_residual(s, c.rn))) return rc;
    s->sum.residual = c.rn;
    if (e->ndof == 0) {                              /* determinate: nothing moves */
        *reason = CTN_CONVERGED;
        return CTN_OK;
    }
    double fref = ctn_problem_fref(e);                /* once per increment */
    c.fref = fref;
    int stalls = 0;
    c.dmax = ctn_layout_norm(&e->st, d);
    for (int it = 1; it <= e->opt.maxit; it++) {
        ctn_reason why;
        if ((rc = iteration(&c, &why))) return rc;
        if (why) { *reason = why; return CTN_OK; }
        double dnorm = s->dhist[s->nd - 1];
        if (!c.accepted) continue;
        c.dmax += dnorm;                                 /* |d + a dd| <= |d| + |a dd| */
        if (dnorm > e->opt.dtol * (c.dmax + e->lref)) continue;
        double size = ctn_layout_norm(&e->st, d) + e->lref;     /* only when it can matter */
        c.dmax = size - e->lref;
        if (dnorm > e->opt.dtol * size) continue;
        if (c.rn <= e->opt.tol * fref) {
            *reason = CTN_CONVERGED;
            return CTN_OK;
        }
        if (dnorm > CTN_FLOOR * size) continue;          /* dd above coordinate resolution */
        if (at_floor(e, s, d, c.rn, &stalls, reason)) return CTN_OK;
    }
    *reason = CTN_DIVERGED_MAXIT;
    return CTN_OK;
}

/* Globalized: a start with compressed two-way members of cables (members of a chain: a
 * free node joins exactly two members; a straight or unstressed start of a cable longer
 * than its chord) is first relaxed with compression cut off, so no
 * compression energy barrier holds it on the chord; then the real materials take over
 * from that state. The final iterations use the true residual, so the equilibrium is
 * not biased by the first phase. */
int ctn_newton_correct(ctn_problem *e, ctn_solution *s, double *d, ctn_reason *reason)
{
    if (!e->strategy->globalized || !ctn_asm_count_compressed(e->a, d, e->in_chain)) {
        int rc = correct(e, s, d, reason);
        ctn_problem_settle(e);                      /* the converged state's is not wanted */
        return rc;
    }
    e->mode = CTN_EVAL_CUT_COMPRESSION;
    int rc = correct(e, s, d, reason);
    e->mode = 0;
    if (rc) return rc;
    s->sum.relaxed++;
    return correct(e, s, d, reason);
}
