/* Form finding by force density: the iteration. Each pass solves the linear equilibrium
 * of the free nodes for the current densities and loads, measures the members, gives
 * each the unstressed length that carries N = q l (its family's prestress_l0), recomputes
 * the loads from that state, and updates the densities of targeted members, q <- force / l.
 * It stops when the largest relative force mismatch and the load change are both <= tol
 * and the loads have stopped changing (their change no longer halves: round-off). */
#include "design/formfind/ff.h"
#include "element/element.h"

#include <math.h>
#include <string.h>

static int ff_alloc(ctn_ff *f)
{
    size_t nn = f->nn ? f->nn : 1, ne = f->ne ? f->ne : 1;
    f->q = ctn_malloc(f->ctx, ne, sizeof(double));
    f->len = ctn_malloc(f->ctx, ne, sizeof(double));
    f->l00 = ctn_malloc(f->ctx, ne, sizeof(double));
    f->p = ctn_malloc(f->ctx, 3 * nn, sizeof(double));
    f->pnew = ctn_malloc(f->ctx, 3 * nn, sizeof(double));
    f->X0 = ctn_malloc(f->ctx, 3 * nn, sizeof(double));
    f->b = ctn_malloc(f->ctx, nn, sizeof(double));
    return f->q && f->len && f->l00 && f->p && f->pnew && f->X0 && f->b ? CTN_OK : CTN_ERR_NOMEM;
}

static void ff_free(ctn_ff *f)
{
    ctn_ff_systems_destroy(f);
    ctn_free(f->q);
    ctn_free(f->len);
    ctn_free(f->l00);
    ctn_free(f->p);
    ctn_free(f->pnew);
    ctn_free(f->X0);
    ctn_free(f->b);
}

/* Keep (save = 1) or put back (0) the coordinates and unstressed lengths as given. */
static void keep_model(ctn_ff *f, int save)
{
    ctn_model *m = f->m;
    for (size_t i = 0; i < f->nn; i++) {
        if (save) memcpy(f->X0 + 3 * i, m->nodes.v[i].X, 3 * sizeof(double));
        else memcpy(m->nodes.v[i].X, f->X0 + 3 * i, 3 * sizeof(double));
    }
    for (size_t e = 0; e < f->ne; e++) {
        if (save) f->l00[e] = m->elements.v[e].l0;
        else m->elements.v[e].l0 = f->l00[e];
    }
    f->saved = 1;
}

/* Lengths of the shape found and the unstressed lengths that carry N = q l there. */
static int measure(ctn_ff *f, double *scale)
{
    ctn_model *m = f->m;
    int rc = CTN_OK, line = m->line;
    for (size_t e = 0; e < f->ne && !rc; e++) {
        ctn_element *el = &m->elements.v[e];
        double l = f->len[e] = ctn_ff_length(m, e), N = f->q[e] * l, l0 = 0;
        if (!(l > 0) || !isfinite(N)) {
            const int *nd = ctn_elem_nodes(m, e);
            return ctn_error_at(f->ctx, CTN_ERR_MODEL, m->file, el->line, "element %d shrank to zero length (nodes %d and "
                                "%d met) %s", el->id, m->nodes.v[nd[0]].id, m->nodes.v[nd[1]].id, f->targets ?
                                "while the densities followed the target forces: no shape gives these targets" :
                                "in the shape of these force densities and loads");
        }
        *scale = fmax(*scale, N);
        m->line = el->line;                              /* messages at the member's line */
        rc = ctn_element_family(el->type)->prestress_l0(m, el, CTN_PRESTRESS_FORCE, N, l, &l0);
        if (!rc) el->l0 = l0;
    }
    m->line = line;
    return rc;
}

/* Loads of the first step recomputed from the state; the largest change over scale. */
static double reload(ctn_ff *f, double scale)
{
    double change = 0, *t = f->p;
    ctn_model_step_loads(f->m, 0, f->pnew, NULL);
    for (size_t i = 0; i < 3 * f->nn; i++) scale = fmax(scale, fabs(f->pnew[i]));
    for (size_t i = 0; i < 3 * f->nn; i++) change = fmax(change, fabs(f->pnew[i] - f->p[i]));
    f->p = f->pnew;
    f->pnew = t;
    return scale > 0 ? change / scale : change;
}

static double mismatch(const ctn_ff *f, size_t *worst)
{
    double r = 0;
    *worst = 0;
    for (size_t k = 0; k < f->m->densities.n; k++) {
        const ctn_density *dn = &f->m->densities.v[k];
        if (!(dn->force > 0)) continue;
        double d = fabs(f->q[dn->e] * f->len[dn->e] - dn->force) / dn->force;
        if (d > r) r = d, *worst = dn->e;
    }
    return r;
}

/* q <- force / l for the targeted members; the factorizations are then stale. */
static void update_densities(ctn_ff *f)
{
    for (size_t k = 0; k < f->m->densities.n; k++) {
        const ctn_density *dn = &f->m->densities.v[k];
        if (dn->force > 0) {
            f->q[dn->e] = dn->force / f->len[dn->e];
            f->factored = 0;
        }
    }
}

/* Largest |p + sum of member forces| at a free DOF over the force scale. */
static double residual(const ctn_ff *f, double scale)
{
    const ctn_model *m = f->m;
    double *r = f->pnew, worst = 0;
    memcpy(r, f->p, 3 * f->nn * sizeof(double));
    for (size_t e = 0; e < f->ne; e++) {
        const int *nd = ctn_elem_nodes(m, e);
        const double *a = m->nodes.v[nd[0]].X, *b = m->nodes.v[nd[1]].X;
        for (int k = 0; k < 3; k++) {
            double t = f->q[e] * (b[k] - a[k]);            /* N (x_b - x_a) / l */
            r[3 * (size_t)nd[0] + (size_t)k] += t;
            r[3 * (size_t)nd[1] + (size_t)k] -= t;
        }
    }
    for (size_t i = 0; i < f->nn; i++)
        for (int k = 0; k < 3; k++)
            if (!(m->nodes.v[i].fix & (1u << k))) worst = fmax(worst, fabs(r[3 * i + (size_t)k]));
    return scale > 0 ? worst / scale : worst;
}

static int iterate(ctn_ff *f, const ctn_formfind_options *o, ctn_formfind_report *rep)
{
    double best = INFINITY, scale = 0, last_change = INFINITY;
    int best_it = 0, rc = CTN_OK;
    rep->reason = CTN_FF_MAXIT;
    for (int it = 1; it <= o->maxit && !rc; it++) {
        scale = 0;
        if ((rc = ctn_ff_solve_shape(f, &rep->factorizations)) || (rc = measure(f, &scale))) break;
        ctn_formfind_iterate log = { it, mismatch(f, &rep->worst), reload(f, scale) };
        rep->iterations = it;
        rep->force_mismatch = log.force_mismatch;
        rep->load_change = log.load_change;
        if (o->monitor) o->monitor(o->monitor_data, &log);
        int settled = log.load_change == 0 || log.load_change > 0.5 * last_change;   /* at round-off */
        last_change = log.load_change;
        if (log.force_mismatch <= o->tol && log.load_change <= o->tol && settled) {
            rep->reason = CTN_FF_CONVERGED;
            break;
        }
        double worst = fmax(log.force_mismatch, log.load_change);
        if (worst < best) best = worst, best_it = it;
        if (it - best_it >= 100) {
            rep->reason = CTN_FF_STALLED;
            break;
        }
        update_densities(f);
    }
    if (!rc) rep->residual = residual(f, fmax(scale, 0));
    return rc;
}

static void report_forces(const ctn_ff *f, ctn_formfind_report *rep)
{
    rep->force_min = INFINITY;
    rep->force_max = 0;
    for (size_t e = 0; e < f->ne; e++) {
        rep->force_min = fmin(rep->force_min, f->q[e] * f->len[e]);
        rep->force_max = fmax(rep->force_max, f->q[e] * f->len[e]);
    }
    for (size_t i = 0; i < f->nn; i++) rep->free_nodes += f->m->nodes.v[i].fix != CTN_FIX_ALL;
}

/* The found model starts where it is: no Newton start guesses, generated cables not
 * moved onto their catenary. */
static void start_in_place(ctn_model *m)
{
    for (size_t i = 0; i < m->nodes.n; i++) memset(m->nodes.v[i].guess, 0, sizeof m->nodes.v[i].guess);
    for (size_t c = 0; c < m->cables.n; c++) m->cables.v[c].start = CTN_START_ARC;
}

static int setup(ctn_ff *f, ctn_formfind_report *rep)
{
    int rc = ff_alloc(f);
    if (rc) return rc;
    keep_model(f, 1);
    if ((rc = ctn_ff_check_model(f))) return rc;
    for (size_t k = 0; k < f->m->densities.n; k++) {       /* every member has one (checked) */
        const ctn_density *dn = &f->m->densities.v[k];
        f->q[dn->e] = dn->q > 0 ? dn->q : dn->force / ctn_ff_length(f->m, dn->e);
        rep->targets += dn->force > 0;
    }
    f->targets = rep->targets;
    ctn_model_step_loads(f->m, 0, f->p, NULL);
    if ((rc = ctn_ff_check_targets(f))) return rc;
    return ctn_ff_systems_create(f);
}

int ctn_formfind(ctn_ctx *ctx, ctn_model *m, const ctn_formfind_options *opt, ctn_formfind_report *rep)
{
    ctn_formfind_options o;
    ctn_formfind_report own;
    ctn_formfind_options_init(&o);
    if (opt) ctn_spec_copy(&o, sizeof o, opt);
    if (!rep) rep = &own;
    memset(rep, 0, sizeof *rep);
    if (!m || (opt && opt->size < sizeof(size_t)) || !(o.tol > 0) || !isfinite(o.tol) || o.maxit < 1)
        return ctn_error(ctx, CTN_ERR_INVALID, "ctn_formfind: bad arguments (tol must be positive, maxit >= 1)");
    int rc = ctn_model_validate(m);
    if (rc) return rc;
    ctn_ff f;
    memset(&f, 0, sizeof f);
    f.ctx = m->ctx;
    f.m = m;
    f.nn = m->nodes.n;
    f.ne = m->elements.n;
    rc = setup(&f, rep);
    if (!rc) rc = iterate(&f, &o, rep);
    if (!rc) report_forces(&f, rep);
    if (!rc && rep->reason == CTN_FF_CONVERGED) start_in_place(m);
    else if (f.saved) keep_model(&f, 0);
    ff_free(&f);
    return rc;
}
