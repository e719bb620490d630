/* Cables and catenary elements set by a target (H=, sag=, tension=; the quantities in
 * target_q.c): the unstressed lengths that meet every target in the solved first load
 * step, by Newton's method on the lengths (outer loop) with the sensitivities from the FE
 * tangent (docs/theory.md, "Cables set by a target"):
 *   F(u, L) = f_ext(L) - f_int(u, L) = 0  =>  du/dL_j = K^-1 dF/dL_j,
 *   dQ_i/dL_j = d/dh Q_i(u + h du/dL_j, L + h e_j) at h = 0,
 * dF/dL_j and the directional derivative of Q by central differences (the partial
 * derivatives of closed-form element quantities; the solution's sensitivity itself comes
 * from the tangent). Each outer step is a full non-linear solve started from the last. */
#include "design/targets/target.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define TARGET_MAXIT 60
#define TARGET_RTOL 1e-10
#define TARGET_MAX_STRAIN 0.1   /* the largest strain a target may ask of its cable */

typedef struct targets {
    ctn_ctx *ctx;
    ctn_model *m;
    ctn_problem *p;
    size_t nt, ncab;         /* targets; the first ncab are cables, the rest catenaries */
    ctn_cable **rec;         /* [nt] their records (m->cables, then m->etargets) */
    double *L, *Q, *J, *dL, *Lold;
    double *rs;                /* nt: the Jacobian's row scales (dense_solve) */
    size_t *perm;              /* nt: its row order (dense_solve) */
    double *d, *dp, *u3, *f, *fm, *b, *v;   /* state, state, 3 nn, state, state, ndof, ndof */
    int outer;               /* outer iterations */
    ctn_solve_summary sum;   /* where the sensitivity solves count */
} targets;

static const char *const target_key[] = { "length", "H", "sag", "tension" };

static double quantity(const targets *tg, const double *u3, size_t j)
{
    return ctn_target_quantity(tg->p, tg->rec[j], u3);
}

/* How messages name target j: "cable 1-2" or "catenary 7". */
static const char *name_of(const targets *tg, size_t j, char *buf, size_t size)
{
    const ctn_model *m = tg->m;
    const ctn_cable *c = tg->rec[j];
    if (j >= tg->ncab) snprintf(buf, size, "catenary %d", m->elements.v[c->first].id);
    else snprintf(buf, size, "cable %d-%d", m->nodes.v[c->node[0]].id, m->nodes.v[c->node[1]].id);
    return buf;
}

/* ---- lengths, solves, sensitivities ---- */

/* The length of target j (its elements keep the temperature the last solve left them at:
 * the sensitivities are those of the heated or cooled cable). */
static void set_length(targets *tg, size_t j, double L)
{
    ctn_cable *c = tg->rec[j];
    const double *dT = tg->p->dT;
    for (size_t e = c->first; e < c->first + c->count; e++) {
        tg->m->elements.v[e].l0 = L / (double)c->count;
        ctn_asm_setup_element(tg->p->a, e, dT ? dT[e] : 0.0);
    }
    c->length = L;
}

/* Solve the first step at the current lengths from the model's start; on convergence the
 * state goes to tg->d (state layout) and tg->u3, and becomes the next start. */
static int solve_at(targets *tg, int *ok)
{
    ctn_solution *s = NULL;
    int rc = ctn_problem_solve(tg->p, &s);
    if (rc) return rc;
    ctn_solve_summary sum;
    ctn_solution_summary(s, &sum);
    *ok = sum.reason == CTN_CONVERGED;
    if (*ok) {
        memcpy(tg->u3, ctn_solution_displacements(s), 3 * tg->m->nodes.n * sizeof(double));
        for (size_t i = 0; i < tg->m->nodes.n; i++) memcpy(tg->m->nodes.v[i].guess, tg->u3 + 3 * i, 3 * sizeof(double));
        ctn_dofmap_from3(&tg->p->a->map, tg->u3, tg->d);
    }
    ctn_solution_destroy(&s);
    return CTN_OK;
}

/* f_ext (dead loads of step 1) - f_int at state d, into f (state layout). */
static void residual_at(targets *tg, const double *d, double *f)
{
    ctn_problem *p = tg->p;
    ctn_model_step_loads_ex(tg->m, 0, 1, p->v3, NULL);
    ctn_dofmap_from3(&p->a->map, p->v3, f);
    ctn_asm_eval(p->a, d, 0, p->fint, NULL, NULL, NULL);
    for (size_t i = 0; i < p->ns; i++) f[i] -= p->fint[i];
}

/* Q_i at (d + h v, L + h e_j) for every i, into q. */
static void quantities_along(targets *tg, size_t j, double h, double *q)
{
    ctn_problem *p = tg->p;
    memcpy(tg->dp, tg->d, p->ns * sizeof(double));
    ctn_problem_axpy(p, tg->dp, h, tg->v);
    set_length(tg, j, tg->L[j] + h);
    double *u3 = p->v3;
    ctn_dofmap_to3(&p->a->map, tg->dp, u3);
    for (size_t i = 0; i < tg->nt; i++) q[i] = quantity(tg, u3, i);
    set_length(tg, j, tg->L[j]);
}

/* The Jacobian dQ/dL at the converged state (tangent factored there). */
static int jacobian(targets *tg, int *ok)
{
    ctn_problem *p = tg->p;
    double rn;
    int valid = 0, posdef = 0;
    long col = -1;
    p->sum = &tg->sum;
    int rc = ctn_problem_residual(p, tg->d, 1, &rn, NULL, &valid);
    if (!rc && valid) rc = ctn_problem_factor(p, 0, &posdef, &col);
    *ok = !rc && valid && posdef;
    if (!*ok) {
        p->sum = NULL;
        return rc;
    }
    double qp[64], qm[64];
    for (size_t j = 0; j < tg->nt && !rc; j++) {
        double h = 1e-6 * tg->L[j];
        set_length(tg, j, tg->L[j] + h);
        residual_at(tg, tg->d, tg->f);
        set_length(tg, j, tg->L[j] - h);
        residual_at(tg, tg->d, tg->fm);
        set_length(tg, j, tg->L[j]);
        for (size_t i = 0; i < p->ns; i++) {
            int q = p->a->map.eq[i];
            if (q >= 0) tg->b[q] = (tg->f[i] - tg->fm[i]) / (2 * h);
        }
        if (p->ndof) rc = ctn_problem_linsolve(p, tg->b, tg->v);
        quantities_along(tg, j, h, qp);
        quantities_along(tg, j, -h, qm);
        for (size_t i = 0; i < tg->nt; i++) tg->J[i * tg->nt + j] = (qp[i] - qm[i]) / (2 * h);
    }
    p->sum = NULL;
    return rc;
}

/* Solve J x = b (n x n, row-major, overwritten) by elimination with partial pivoting,
 * rs and perm n of scratch. -1 when solved; else the target (row) that the others
 * determine: its pivot is 0, or at below TARGET_PIVOT_RTOL of its row's scale, so the lengths
 * that meet the targets are not unique (two cables in line at a free node, both set by
 * H=, carry the same H whatever their lengths share). The Jacobian is made by central
 * differences to about 1e-7 of its rows (measured on that ring: its two rows, equal in
 * exact arithmetic, differ by 8e-8), so a pivot below 1e-6 of its row is zero. */
#define TARGET_PIVOT_RTOL 1e-6
static long dense_solve(size_t n, double *J, double *b, double *rs, size_t *perm)
{
    for (size_t i = 0; i < n; i++) {
        rs[i] = 0;
        perm[i] = i;
        for (size_t c = 0; c < n; c++) rs[i] = fmax(rs[i], fabs(J[i * n + c]));
    }
    for (size_t k = 0; k < n; k++) {
        size_t piv = k;
        for (size_t i = k + 1; i < n; i++)
            if (fabs(J[i * n + k]) > fabs(J[piv * n + k])) piv = i;
        if (!(fabs(J[piv * n + k]) > TARGET_PIVOT_RTOL * rs[piv])) return (long)perm[piv];
        for (size_t c = 0; c < n; c++) {
            double t = J[k * n + c];
            J[k * n + c] = J[piv * n + c];
            J[piv * n + c] = t;
        }
        double t = b[k], r = rs[k];
        size_t q = perm[k];
        b[k] = b[piv];
        b[piv] = t;
        rs[k] = rs[piv];
        rs[piv] = r;
        perm[k] = perm[piv];
        perm[piv] = q;
        for (size_t i = k + 1; i < n; i++) {
            double f = J[i * n + k] / J[k * n + k];
            for (size_t c = k; c < n; c++) J[i * n + c] -= f * J[k * n + c];
            b[i] -= f * b[k];
        }
    }
    for (size_t k = n; k-- > 0;) {
        for (size_t c = k + 1; c < n; c++) b[k] -= J[k * n + c] * b[c];
        b[k] /= J[k * n + k];
    }
    return -1;
}

static double misfit(const targets *tg)
{
    double worst = 0;
    for (size_t i = 0; i < tg->nt; i++) {
        const ctn_cable *c = tg->rec[i];
        worst = fmax(worst, fabs(tg->Q[i] - c->target_value) / c->target_value);
    }
    return isfinite(worst) ? worst : INFINITY;
}

static void evaluate(targets *tg)
{
    for (size_t i = 0; i < tg->nt; i++) tg->Q[i] = quantity(tg, tg->u3, i);
}

/* The error when the targets are not met: which record, what it asked, what was reached. */
static int not_met(targets *tg, const char *why)
{
    size_t worst = 0;
    double w = -1;
    char name[48];
    for (size_t i = 0; i < tg->nt; i++) {
        const ctn_cable *c = tg->rec[i];
        double e = fabs(tg->Q[i] - c->target_value) / c->target_value;
        if (!(e <= w)) {
            w = e;
            worst = i;
        }
    }
    const ctn_cable *c = tg->rec[worst];
    return ctn_error_at(tg->ctx, CTN_ERR_MODEL, tg->m->file, c->line, "%s: no unstressed length gives %s=%g: %s",
                        name_of(tg, worst, name, sizeof name), target_key[c->target], c->target_value, why);
}

/* Targets that the others determine: the lengths that meet them are not unique. */
static int not_unique(targets *tg, size_t k)
{
    char name[48];
    const ctn_cable *c = tg->rec[k];
    return ctn_error_at(tg->ctx, CTN_ERR_MODEL, tg->m->file, c->line, "%s: %s=%g does not fix its length: the other "
                        "targets already determine it (e.g. two cables in line at a free node, both set by H=, "
                        "carry the same H whatever lengths they share), so the lengths are not unique; give one "
                        "of them length=", name_of(tg, k, name, sizeof name), target_key[c->target], c->target_value);
}

/* The extremum of the target between lengths a < b that bracket it (sign 1: the
 * minimum, -1: the maximum), by golden-section search to 1e-9 of the length; *L and *q
 * improved when it finds a better one. */
static int refine(targets *tg, double a, double b, double sign, double *L, double *q)
{
    const double r = 0.5 * (sqrt(5.0) - 1);
    double x[2] = { b - r * (b - a), a + r * (b - a) }, f[2];
    for (int i = 0; i < 2; i++) {
        int ok = 0, rc;
        set_length(tg, 0, x[i]);
        if ((rc = solve_at(tg, &ok))) return rc;
        if (!ok) return CTN_OK;                          /* keep the sampled value */
        f[i] = sign * quantity(tg, tg->u3, 0);
    }
    for (int it = 0; it < 80 && b - a > 1e-9 * b; it++) {
        int lo = f[0] < f[1], k = lo ? 0 : 1, ok = 0, rc;   /* keep the better half */
        if (lo) { b = x[1]; x[1] = x[0]; f[1] = f[0]; x[0] = b - r * (b - a); }
        else    { a = x[0]; x[0] = x[1]; f[0] = f[1]; x[1] = a + r * (b - a); }
        set_length(tg, 0, x[k]);
        if ((rc = solve_at(tg, &ok))) return rc;
        if (!ok) break;
        f[k] = sign * quantity(tg, tg->u3, 0);
    }
    int k = f[0] < f[1] ? 0 : 1;
    if (f[k] < sign * *q) {                             /* f = sign q: minimized */
        *q = sign * f[k];
        *L = x[k];
    }
    return CTN_OK;
}

/* For one target not met: the range of the target over unstressed lengths from just
 * below the chord to four chords (solved in order, each from the last), into msg; an
 * extremum inside the range is then found to 1e-9 of its length (refine). */
static int reachable(targets *tg, char *msg, size_t size)
{
    static const double s[] = { -2e-3, -1e-3, -3e-4, 0, 1e-4, 3e-4, 1e-3, 3e-3, 0.01, 0.02, 0.05, 0.1,
                                0.2, 0.35, 0.5, 0.75, 1, 1.5, 2, 3 };
    enum { NS = sizeof s / sizeof *s };
    const ctn_cable *c = tg->rec[0];
    const double *A = tg->m->nodes.v[c->node[0]].X, *B = tg->m->nodes.v[c->node[1]].X;
    double chord = sqrt((B[0] - A[0]) * (B[0] - A[0]) + (B[1] - A[1]) * (B[1] - A[1]) + (B[2] - A[2]) * (B[2] - A[2]));
    double lo = INFINITY, hi = -INFINITY, Llo = 0, Lhi = 0, L0 = INFINITY, L1 = 0;
    int conv[NS], klo = -1, khi = -1, rc;
    for (int k = 0; k < NS; k++) {
        double L = chord * (1 + s[k]);
        conv[k] = 0;
        set_length(tg, 0, L);
        if ((rc = solve_at(tg, &conv[k]))) return rc;
        if (!conv[k]) continue;
        double q = quantity(tg, tg->u3, 0);
        L0 = fmin(L0, L);
        L1 = fmax(L1, L);
        if (q < lo) { lo = q; Llo = L; klo = k; }
        if (q > hi) { hi = q; Lhi = L; khi = k; }
    }
    if (klo > 0 && klo + 1 < NS && conv[klo - 1] && conv[klo + 1] &&
        (rc = refine(tg, chord * (1 + s[klo - 1]), chord * (1 + s[klo + 1]), 1, &Llo, &lo)))
        return rc;
    if (khi > 0 && khi + 1 < NS && conv[khi - 1] && conv[khi + 1] &&
        (rc = refine(tg, chord * (1 + s[khi - 1]), chord * (1 + s[khi + 1]), -1, &Lhi, &hi)))
        return rc;
    tg->L[0] = Llo;
    set_length(tg, 0, tg->L[0]);
    if (!(L1 > 0)) snprintf(msg, size, "the model converges with none of the lengths tried");
    else
        snprintf(msg, size, "over unstressed lengths %.6g to %.6g it ranges from %.6g (length %.6g) to %.6g (length %.6g)",
                 L0, L1, lo, Llo, hi, Lhi);
    return CTN_OK;
}

/* A target met only by stretching its cable beyond TARGET_MAX_STRAIN (the strain the
 * summary calls far beyond an elastic cable) is out of reach: for one target, the value
 * at that strain (bisection on the length) bounds the reachable range. */
static int elastic_range(targets *tg)
{
    size_t worst = 0;
    double eps = -INFINITY;
    for (size_t j = 0; j < tg->nt; j++) {
        double e = ctn_target_strain(tg->p, tg->rec[j], tg->u3);
        if (e > eps) { eps = e; worst = j; }
    }
    if (!(eps > TARGET_MAX_STRAIN)) return CTN_OK;
    const ctn_cable *c = tg->rec[worst];
    double Lbad = tg->L[worst], found = Lbad, q = NAN;
    char msg[320], name[48];
    if (tg->nt == 1) {
        double Lok = Lbad * (1 + eps) / (1 + 0.5 * TARGET_MAX_STRAIN);   /* about half the limit strain */
        for (int it = 0; it < 60 && Lok - Lbad > 1e-9 * Lok; it++) {
            double mid = 0.5 * (Lbad + Lok);
            int ok = 0, rc;
            set_length(tg, 0, mid);
            if ((rc = solve_at(tg, &ok))) return rc;
            if (ok && ctn_target_strain(tg->p, tg->rec[0], tg->u3) <= TARGET_MAX_STRAIN) {
                Lok = mid;
                q = quantity(tg, tg->u3, 0);
            } else {
                Lbad = mid;
            }
        }
    }
    if (isfinite(q))
        snprintf(msg, sizeof msg, "it needs a strain of %.3g (length %.6g); the reachable range ends at %s=%.6g, the most "
                 "taut cable with strains up to %g", eps, found, target_key[c->target], q, TARGET_MAX_STRAIN);
    else
        snprintf(msg, sizeof msg, "it needs a strain of %.3g (length %.6g), beyond the %g an elastic cable takes", eps, found,
                 TARGET_MAX_STRAIN);
    return ctn_error_at(tg->ctx, CTN_ERR_MODEL, tg->m->file, c->line, "%s: no unstressed length gives %s=%g within "
                        "the elastic range: %s", name_of(tg, worst, name, sizeof name), target_key[c->target],
                        c->target_value, msg);
}

/* Outer Newton on the lengths. */
static int find_lengths(targets *tg)
{
    int ok = 0, rc = solve_at(tg, &ok);
    if (rc) return rc;
    if (!ok) {
        evaluate(tg);
        return not_met(tg, "the model does not converge with the first lengths tried");
    }
    evaluate(tg);
    double best = misfit(tg);
    for (tg->outer = 0; best > TARGET_RTOL; tg->outer++) {
        if (tg->outer == TARGET_MAXIT || (tg->nt == 1 && tg->outer >= 12 && best > 1e-3)) {
            char msg[256] = "the root find does not converge";
            if (tg->nt == 1 && (rc = reachable(tg, msg, sizeof msg))) return rc;
            return not_met(tg, msg);
        }
        if ((rc = jacobian(tg, &ok))) return rc;
        if (!ok) return not_met(tg, "the equilibrium reached is not stable");
        for (size_t i = 0; i < tg->nt; i++) tg->dL[i] = tg->rec[i]->target_value - tg->Q[i];
        long dep = dense_solve(tg->nt, tg->J, tg->dL, tg->rs, tg->perm);
        if (dep >= 0 && tg->nt == 1)
            return not_met(tg, "the target does not change with the length there (a slack or straight cable?)");
        if (dep >= 0) return not_unique(tg, (size_t)dep);
        memcpy(tg->Lold, tg->L, tg->nt * sizeof(double));
        double scale = 1;                           /* at most halve or double a length */
        for (size_t i = 0; i < tg->nt; i++) {
            double r = tg->dL[i] / tg->L[i];
            if (r < -0.5) scale = fmin(scale, -0.5 / r);
            if (r > 1) scale = fmin(scale, 1 / r);
        }
        int accepted = 0;
        for (int cut = 0; cut < 30 && !accepted; cut++, scale *= 0.5) {
            for (size_t i = 0; i < tg->nt; i++) {
                tg->L[i] = tg->Lold[i] + scale * tg->dL[i];
                set_length(tg, i, tg->L[i]);
            }
            if ((rc = solve_at(tg, &ok))) return rc;
            if (!ok) continue;
            evaluate(tg);
            double mis = misfit(tg);
            accepted = mis < best || mis <= TARGET_RTOL || cut >= 8;
            if (accepted) best = mis;
        }
        if (!accepted) return not_met(tg, "the model does not converge near the lengths that the target needs");
    }
    return elastic_range(tg);
}

static int alloc_targets(targets *tg)
{
    ctn_ctx *ctx = tg->ctx;
    size_t nt = tg->nt ? tg->nt : 1, ns = tg->p->ns, nd = tg->p->ndof ? tg->p->ndof : 1;
    double **small[] = { &tg->L, &tg->Q, &tg->dL, &tg->Lold };
    double **state[] = { &tg->d, &tg->dp, &tg->f, &tg->fm };
    if (!(tg->rec = ctn_calloc(ctx, nt, sizeof(ctn_cable *))) || !(tg->J = ctn_calloc(ctx, nt * nt, sizeof(double))) ||
        !(tg->rs = ctn_calloc(ctx, nt, sizeof(double))) || !(tg->perm = ctn_calloc(ctx, nt, sizeof(size_t))))
        return CTN_ERR_NOMEM;
    for (size_t i = 0; i < 4; i++)
        if (!(*small[i] = ctn_calloc(ctx, nt, sizeof(double))) || !(*state[i] = ctn_calloc(ctx, ns, sizeof(double))))
            return CTN_ERR_NOMEM;
    if (!(tg->u3 = ctn_calloc(ctx, 3 * tg->m->nodes.n, sizeof(double))) || !(tg->b = ctn_calloc(ctx, nd, sizeof(double))) ||
        !(tg->v = ctn_calloc(ctx, nd, sizeof(double))))
        return CTN_ERR_NOMEM;
    return CTN_OK;
}

static void free_targets(targets *tg)
{
    double *v[] = { tg->L, tg->Q, tg->dL, tg->Lold, tg->d, tg->dp, tg->f, tg->fm, tg->u3, tg->b, tg->v, tg->J };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
    ctn_free(tg->rec);
    ctn_free(tg->rs);
    ctn_free(tg->perm);
    ctn_problem_destroy(&tg->p);
}

/* The records still to resolve, cables first, into tg->rec (NULL: count only). */
static size_t collect(ctn_model *m, ctn_cable **rec, size_t *ncab)
{
    size_t n = 0;
    for (size_t i = 0; i < m->cables.n; i++)
        if (m->cables.v[i].target != CTN_TARGET_NONE && !m->cables.v[i].resolved) {
            if (rec) rec[n] = &m->cables.v[i];
            n++;
        }
    *ncab = n;
    for (size_t i = 0; i < m->etargets.n; i++)
        if (!m->etargets.v[i].resolved) {
            if (rec) rec[n] = &m->etargets.v[i];
            n++;
        }
    return n;
}

int ctn_model_resolve_targets(ctn_ctx *ctx, ctn_model *m, const ctn_solve_options *opt, int *outer)
{
    if (!m) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_model_resolve_targets: model is NULL");
    if (outer) *outer = 0;
    size_t ncab, nt = collect(m, NULL, &ncab);
    if (!nt) return CTN_OK;
    if (nt > 64)
        return ctn_error(ctx, CTN_ERR_MODEL, "%s%smore than 64 cables and catenaries set by a target (%zu)", m->file,
                         *m->file ? ": " : "", nt);
    ctn_solve_options o;
    if (opt) o = *opt;
    else ctn_solve_options_default(&o);
    if (o.method == CTN_METHOD_ARCLENGTH) o.method = CTN_METHOD_AUTO;   /* the lengths are found under the full loads */
    o.tol = fmin(o.tol, 1e-12);
    o.monitor = NULL;
    o.modal.count = 0;                      /* the modes come with the final solve */
    targets tg;
    memset(&tg, 0, sizeof tg);
    tg.ctx = ctx;
    tg.m = m;
    tg.nt = nt;
    tg.ncab = ncab;
    for (size_t i = 0; i < m->cables.n; i++) m->cables.v[i].resolved |= m->cables.v[i].target == CTN_TARGET_NONE;
    int rc = ctn_problem_create_any(ctx, m, &o, &tg.p);
    if (!rc) rc = alloc_targets(&tg);
    if (!rc) {
        tg.p->max_steps = 1;
        collect(m, tg.rec, &ncab);
        for (size_t j = 0; j < nt; j++) tg.L[j] = tg.rec[j]->length;
        rc = find_lengths(&tg);
    }
    for (size_t j = 0; !rc && j < nt; j++) {
        ctn_cable *c = tg.rec[j];
        c->resolved = 1;
        c->target_achieved = tg.Q[j];
        c->target_iterations = tg.outer;
    }
    if (outer) *outer = tg.outer;
    free_targets(&tg);
    return rc;
}
