/* Loads that follow the geometry: `hload` on the deformed horizontal projection, and
 * `wind` drag on the chord projected on the plane normal to the wind (the same load with
 * the wind's direction in place of gravity's: each segment has its own direction g).
 *
 * A segment a-b of an element under q per unit horizontal length carries
 * P = q |h| / 2 at each of its nodes along g (unit gravity), h = the current chord
 * x_b - x_a less its component along g. The load depends on the state:
 *   dP/dx_b = -dP/dx_a = (q/2) h^T/|h|,
 * so the tangent is K - L with L's rows at a and b equal to (q/2) g (h/|h|)^T [-I I]: not
 * symmetric (the load has no potential). The step solves (K + mu I - L) dd = r by GMRES,
 * preconditioned by the Cholesky factor of K + mu I, which the Newton iteration makes
 * anyway: L is small beside K and a few Krylov iterations reach round-off, so Newton stays
 * quadratic. */
#include "problem/problem.h"

#include <math.h>
#include <string.h>

#define CTN_GMRES_M 30        /* Krylov vectors per cycle */
#define CTN_GMRES_CYCLES 4
#define CTN_GMRES_RTOL 1e-13

struct ctn_follow {
    size_t n;                 /* segments */
    int *a, *b, *elem;        /* per segment: its nodes, its element (model index) */
    int *src;                 /* per segment: -1 for the hloads, else its wind's index in
                                 m->lloads */
    double *dir;              /* 3 per segment: the unit direction of its load */
    double *qa, *qb, *qt;     /* per segment: q at the start and end of the step, at t */
    double *hhat;             /* 3 per segment: h / |h| at the last evaluation */
    double *fh;               /* state: the loads at the last evaluation */
    ctn_gmres gm;
    double *work;
    double *tmp;              /* ndof */
};

/* Total q of the deformed-projection hloads of a selection on element e. */
static double element_q_sel(const ctn_model *m, size_t e, const ctn_loadsel *sel)
{
    double q = 0;
    for (size_t h = 0; h < m->hloads.n; h++) {
        const ctn_hload *hl = &m->hloads.v[h];
        double w = ctn_loadsel_weight(sel, hl->step);
        if (!hl->reference && w != 0 && ctn_hload_on(m, hl, e)) q += w * hl->q;
    }
    return q;
}

/* q of a segment in a selection: its hloads', or its wind's. */
static double segment_q(const ctn_model *m, const struct ctn_follow *f, size_t s, const ctn_loadsel *sel)
{
    if (f->src[s] < 0) return element_q_sel(m, (size_t)f->elem[s], sel);
    const ctn_lload *l = &m->lloads.v[f->src[s]];
    double w = ctn_loadsel_weight(sel, l->step);
    return w == 0 ? 0 : w * ctn_model_drag_q(m, l, sel, (size_t)f->elem[s]);
}

/* The same at the end of model step k, or (k >= the step count) in case k - steps alone. */
static double element_q(const ctn_model *m, size_t e, size_t k)
{
    size_t ns = ctn_model_step_count(m);
    int tag = CTN_CASE_TAG0 + (int)(k - ns);
    double one = 1.0;
    ctn_loadsel sel = k < ns ? ctn_loadsel_step(k) : (ctn_loadsel){ -1, 1, &tag, &one };
    return element_q_sel(m, e, &sel);
}

/* One segment a-b of element e under source src along dir (fill when f). */
static void put_segment(struct ctn_follow *f, size_t n, int a, int b, size_t e, int src, const double *dir)
{
    if (!f) return;
    f->a[n] = a;
    f->b[n] = b;
    f->elem[n] = (int)e;
    f->src[n] = src;
    for (int k = 0; k < 3; k++) f->dir[3 * n + (size_t)k] = dir[k];
}

/* Segments under a deformed-projection hload in some step or case, then under each wind
 * (count, or fill when f); g: unit gravity, NULL when there is none. */
static size_t scan(const ctn_model *m, struct ctn_follow *f, const double *g)
{
    size_t n = 0, last = ctn_model_step_count(m) - 1 + m->cases.n;
    for (size_t e = 0; e < m->elements.n && g && m->hloads.n; e++) {
        int hit = 0;
        for (size_t k = 0; k <= last && !hit; k++) hit = element_q(m, e, k) != 0;
        if (!hit) continue;
        const int *nd = ctn_elem_nodes(m, e);
        for (int s = 0; s + 1 < m->elements.v[e].nnodes; s++, n++) put_segment(f, n, nd[s], nd[s + 1], e, -1, g);
    }
    for (size_t j = 0; j < m->lloads.n; j++) {
        const ctn_lload *l = &m->lloads.v[j];
        double u[3];
        if (!l->drag || !(l->cdp > 0)) continue;
        ctn_lload_dir(l, u);
        for (size_t e = 0; e < m->elements.n; e++) {
            if (!ctn_lload_on(m, l, e)) continue;
            const int *nd = ctn_elem_nodes(m, e);
            for (int s = 0; s + 1 < m->elements.v[e].nnodes; s++, n++) put_segment(f, n, nd[s], nd[s + 1], e, (int)j, u);
        }
    }
    return n;
}

static int alloc_follow(ctn_problem *p, struct ctn_follow *f)
{
    ctn_ctx *ctx = p->ctx;
    size_t n = f->n, nd = p->ndof ? p->ndof : 1;
    f->a = ctn_malloc(ctx, n, sizeof(int));
    f->b = ctn_malloc(ctx, n, sizeof(int));
    f->elem = ctn_malloc(ctx, n, sizeof(int));
    f->src = ctn_malloc(ctx, n, sizeof(int));
    f->dir = ctn_malloc(ctx, 3 * n, sizeof(double));
    f->qa = ctn_calloc(ctx, n, sizeof(double));
    f->qb = ctn_calloc(ctx, n, sizeof(double));
    f->qt = ctn_calloc(ctx, n, sizeof(double));
    f->hhat = ctn_calloc(ctx, 3 * n, sizeof(double));
    f->fh = ctn_calloc(ctx, p->ns, sizeof(double));
    f->tmp = ctn_calloc(ctx, nd, sizeof(double));
    f->work = ctn_calloc(ctx, ctn_gmres_work_size(nd, CTN_GMRES_M), sizeof(double));
    return f->a && f->b && f->elem && f->src && f->dir && f->qa && f->qb && f->qt && f->hhat && f->fh && f->tmp && f->work
               ? CTN_OK : CTN_ERR_NOMEM;
}

void ctn_follow_destroy(ctn_follow **pf)
{
    if (!pf || !*pf) return;
    struct ctn_follow *f = *pf;
    void *v[] = { f->a, f->b, f->elem, f->src, f->dir, f->qa, f->qb, f->qt, f->hhat, f->fh, f->tmp, f->work };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
    ctn_free(f);
    *pf = NULL;
}

/* y = (K + shift I) x - L x on the equations. */
static int apply(void *data, const double *x, double *y)
{
    ctn_problem *p = data;
    const struct ctn_follow *f = p->fl;
    const int *cp = p->a->colptr, *ri = p->a->rowind, *eq = p->a->map.eq;
    for (size_t c = 0; c < p->ndof; c++) y[c] = p->shift * x[c];
    for (size_t c = 0; c < p->ndof; c++)
        for (int k = cp[c]; k < cp[c + 1]; k++) {
            size_t r = (size_t)ri[k];
            y[r] += p->Kx[k] * x[c];
            if (r != c) y[c] += p->Kx[k] * x[r];
        }
    for (size_t s = 0; s < f->n; s++) {
        size_t sa = ctn_dofmap_node(&p->a->map, (size_t)f->a[s]), sb = ctn_dofmap_node(&p->a->map, (size_t)f->b[s]);
        double dx = 0;
        for (int k = 0; k < 3; k++) {
            int qa = eq[sa + (size_t)k], qb = eq[sb + (size_t)k];
            dx += f->hhat[3 * s + (size_t)k] * ((qb >= 0 ? x[qb] : 0) - (qa >= 0 ? x[qa] : 0));
        }
        double c = 0.5 * f->qt[s] * dx;
        for (int k = 0; k < 3; k++) {
            int qa = eq[sa + (size_t)k], qb = eq[sb + (size_t)k];
            if (qa >= 0) y[qa] -= c * f->dir[3 * s + (size_t)k];
            if (qb >= 0) y[qb] -= c * f->dir[3 * s + (size_t)k];
        }
    }
    return CTN_OK;
}

int ctn_follow_apply(ctn_problem *p, const double *x, double *y)
{
    return apply(p, x, y);
}

static int precond(void *data, const double *x, double *y)
{
    ctn_problem *p = data;
    return ctn_linsolve_solve(p->ls, x, y);
}

int ctn_follow_create(ctn_problem *p)
{
    const ctn_model *m = p->m;
    double gn = sqrt(m->gravity[0] * m->gravity[0] + m->gravity[1] * m->gravity[1] + m->gravity[2] * m->gravity[2]);
    double g[3] = { m->gravity[0] / gn, m->gravity[1] / gn, m->gravity[2] / gn };
    const double *gp = gn > 0 ? g : NULL;
    size_t n = m->hloads.n || m->lloads.n ? scan(m, NULL, gp) : 0;
    if (!n) return CTN_OK;
    struct ctn_follow *f = ctn_calloc(p->ctx, 1, sizeof *f);
    if (!f) return CTN_ERR_NOMEM;
    p->fl = f;
    f->n = n;
    int rc = alloc_follow(p, f);
    if (rc) return rc;
    scan(m, f, gp);
    ctn_gmres_init(&f->gm, p->ndof, CTN_GMRES_M, f->work);
    f->gm.apply = apply;
    f->gm.precond = precond;
    f->gm.data = p;
    f->gm.dot = ctn_problem_dot;
    return CTN_OK;
}

void ctn_follow_step(ctn_problem *p, size_t k)
{
    ctn_loadsel sel = ctn_loadsel_step(k);
    ctn_follow_sel(p, &sel);
}

void ctn_follow_sel(ctn_problem *p, const ctn_loadsel *sel)
{
    struct ctn_follow *f = p->fl;
    if (!f) return;
    for (size_t s = 0; s < f->n; s++) {
        f->qa[s] = f->qb[s];
        f->qb[s] = segment_q(p->m, f, s, sel);
    }
}

void ctn_follow_reset(ctn_problem *p)
{
    if (p->fl) memset(p->fl->qb, 0, p->fl->n * sizeof(double));
}

void ctn_follow_set_t(ctn_problem *p, double t)
{
    struct ctn_follow *f = p->fl;
    if (!f) return;
    for (size_t s = 0; s < f->n; s++) f->qt[s] = f->qa[s] + t * (f->qb[s] - f->qa[s]);
}

/* Segment s's load P = q |h| / 2 at each of its nodes along its direction, added to out
 * (state layout) at state d; its h / |h| into hhat when not NULL. */
static void segment_load(const ctn_problem *p, const struct ctn_follow *f, size_t s, double q, const double *d,
                         double *out, double *hhat)
{
    const ctn_model *m = p->m;
    size_t sa = ctn_dofmap_node(&p->a->map, (size_t)f->a[s]), sb = ctn_dofmap_node(&p->a->map, (size_t)f->b[s]);
    const double *Xa = m->nodes.v[f->a[s]].X, *Xb = m->nodes.v[f->b[s]].X;
    double h[3], along = 0, hn = 0;
    for (int k = 0; k < 3; k++) {
        h[k] = (Xb[k] - Xa[k]) + (d[sb + (size_t)k] - d[sa + (size_t)k]);
        along += h[k] * f->dir[3 * s + (size_t)k];
    }
    for (int k = 0; k < 3; k++) {
        h[k] -= along * f->dir[3 * s + (size_t)k];
        hn += h[k] * h[k];
    }
    hn = sqrt(hn);
    double P = 0.5 * q * hn;
    for (int k = 0; k < 3; k++) {
        if (hhat) hhat[k] = hn > 0 ? h[k] / hn : 0.0;
        out[sa + (size_t)k] += P * f->dir[3 * s + (size_t)k];
        out[sb + (size_t)k] += P * f->dir[3 * s + (size_t)k];
    }
}

const double *ctn_follow_forces(ctn_problem *p, const double *d)
{
    struct ctn_follow *f = p->fl;
    memset(f->fh, 0, p->ns * sizeof(double));
    for (size_t s = 0; s < f->n; s++) segment_load(p, f, s, f->qt[s], d, f->fh, f->hhat + 3 * s);
    return f->fh;
}

void ctn_follow_forces_sel(const ctn_problem *p, const double *d, const ctn_loadsel *sel, double *out)
{
    const struct ctn_follow *f = p->fl;
    memset(out, 0, p->ns * sizeof(double));
    for (size_t s = 0; f && s < f->n; s++) segment_load(p, f, s, segment_q(p->m, f, s, sel), d, out, NULL);
}

int ctn_follow_solve(ctn_problem *p, const double *b, double *x)
{
    double rel;
    int iters;
    int rc = ctn_gmres_solve(&p->fl->gm, b, x, CTN_GMRES_RTOL, CTN_GMRES_CYCLES, &rel, &iters);
    p->sum->solves += iters + 1;
    return rc;
}

const double *ctn_follow_loads(const ctn_follow *f) { return f->fh; }

size_t ctn_follow_hload_count(const ctn_follow *f)
{
    size_t n = 0;
    for (size_t s = 0; f && s < f->n; s++) n += f->src[s] < 0;
    return n;
}

void ctn_follow_drop_winds(ctn_problem *p)
{
    struct ctn_follow *f = p->fl;
    for (size_t s = 0; f && s < f->n; s++)
        if (f->src[s] >= 0) f->qa[s] = f->qb[s] = f->qt[s] = 0.0;
}
