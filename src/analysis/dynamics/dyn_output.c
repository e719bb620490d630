/* What a dynamics analysis keeps beside the histories: the support reactions with their
 * inertia and damping, R = f_int + M a + C v - f_ext at the fixed DOFs, and the frames
 * (the state at a row, for the VTU series). The fixed DOFs' rows of M and C reach only
 * the elements with a fixed DOF (the "support elements"): their element mass and, for
 * Rayleigh's beta, their tangent at the start are kept, so a reaction costs an element
 * loop and no global matrix. A moving support's velocity and acceleration are its
 * function's derivatives (a ramp's or table's kinks and a step's jump carry no impulse
 * here). A model with rotations: the velocities are the spatial ones (a rotation's R W),
 * the rotary inertia is dyn_rot.c's (lumped at each node, R (J A + W x J W) and alpha
 * R J W at a node's fixed rotations while others turn). docs/theory.md "Dynamics". */
#include "analysis/dynamics/dynamics.h"

#include <math.h>
#include <string.h>

/* d^order f / dt^order of function i at t (order 1 or 2). */
static double fn_rate(const ctn_model *m, int i, double t, int order)
{
    const ctn_fn *f = &m->fns.v[i];
    double w = 6.28318530717958647692 * f->par[1];
    switch (f->kind) {
    case CTN_FN_RAMP: return order == 1 && t > f->par[0] && t < f->par[1] ? 1.0 / (f->par[1] - f->par[0]) : 0.0;
    case CTN_FN_STEP: return 0.0;
    case CTN_FN_HARMONIC:
        return order == 1 ? f->par[0] * w * cos(w * t + f->par[2]) : -f->par[0] * w * w * sin(w * t + f->par[2]);
    default: break;
    }
    if (order == 2 || t < f->t[0] || t >= f->t[f->n - 1]) return 0.0;
    size_t lo = 0, hi = f->n - 1;                        /* t[lo] <= t < t[hi] */
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (f->t[mid] <= t) lo = mid;
        else hi = mid;
    }
    return (f->v[hi] - f->v[lo]) / (f->t[hi] - f->t[lo]);
}

void ctn_dyn_rates(const ctn_dyn *dy, double t, const double *vq, const double *aq, double *vs, double *as)
{
    const ctn_problem *p = dy->p;
    const ctn_model *m = p->m;
    const int *eq = p->a->map.eq;
    for (size_t i = 0; i < p->ns; i++) {
        vs[i] = eq[i] >= 0 ? vq[eq[i]] : 0.0;
        if (as) as[i] = eq[i] >= 0 ? aq[eq[i]] : 0.0;
    }
    for (size_t j = 0; j < m->dloads.n; j++) {
        const ctn_dload *dl = &m->dloads.v[j];
        size_t at = ctn_dofmap_node(&p->a->map, (size_t)dl->node);
        double f1 = dl->dofs ? fn_rate(m, dl->fn, t, 1) : 0, f2 = dl->dofs && as ? fn_rate(m, dl->fn, t, 2) : 0;
        for (int k = 0; k < 3; k++)
            if (dl->dofs >> k & 1) {
                vs[at + (size_t)k] += f1 * dl->F[k];
                if (as) as[at + (size_t)k] += f2 * dl->F[k];
            }
    }
}

/* Whether element el has a fixed DOF. */
static int touches_support(const ctn_asm *a, const ctn_asm_elem *el)
{
    int nd = el->b->ops->ndof_node;
    for (int i = 0; i < el->b->nnodes; i++)
        for (int c = 0; c < nd; c++)
            if (a->map.eq[ctn_dofmap_node(&a->map, (size_t)el->nodes[i]) + (size_t)c] < 0) return 1;
    return 0;
}

/* The support elements: counted (store NULL), then stored with their packed mass and
 * start tangent. */
typedef struct sup_pass {
    ctn_dyn *dy;
    int store;
    size_t n, nv;          /* elements, values (packed entries) */
} sup_pass;

static void sup_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    sup_pass *sp = data;
    ctn_dyn *dy = sp->dy;
    if (!touches_support(a, el)) return;
    int ns = el->b->nslots;
    if (sp->store) {
        double *X = dy->ework, *Me = dy->sup_M + sp->nv;
        for (int i = 0; i < el->b->nnodes; i++) memcpy(X + 3 * i, a->m->nodes.v[el->nodes[i]].X, 3 * sizeof(double));
        memset(Me, 0, (size_t)ns * sizeof(double));
        if (el->b->ops->mass) el->b->ops->mass(el->props, X, dy->lumped, Me);
        for (int u = 0; u < el->b->nedof && el->b->ops->ndof_node == 6; u++)   /* rotary inertia: */
            for (int v = u; v < el->b->nedof; v++)                            /* dyn_rot.c's own */
                if (u % 6 >= 3 || v % 6 >= 3) Me[ctn_packed_index(el->b->nedof, u, v)] = 0.0;
        if (dy->sup_K) memcpy(dy->sup_K + sp->nv, el->Ke, (size_t)ns * sizeof(double));
        dy->sup_e[sp->n] = el->e;
        dy->sup_off[sp->n] = sp->nv;
    }
    sp->n++;
    sp->nv += (size_t)ns;
}

int ctn_dyn_output_begin(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    const ctn_model *m = p->m;
    int need = dy->o->frames, moves = 0;
    for (size_t i = 0; i < m->records.n; i++) need |= m->records.v[i].reaction;
    for (size_t j = 0; j < m->dloads.n; j++) moves |= m->dloads.v[j].dofs != 0;
    if (!need && !moves) return CTN_OK;
    if (moves && !(dy->fsup = ctn_calloc(p->ctx, p->ndof, sizeof(double)))) return CTN_ERR_NOMEM;
    dy->react = ctn_calloc(p->ctx, p->ns, sizeof(double));
    dy->vs = ctn_calloc(p->ctx, p->ns, sizeof(double));
    dy->as = ctn_calloc(p->ctx, p->ns, sizeof(double));
    if (!dy->react || !dy->vs || !dy->as) return CTN_ERR_NOMEM;
    sup_pass sp = { dy, 0, 0, 0 };
    ctn_asm_loop(p->a, NULL, 0, 0, sup_visit, &sp, NULL);
    dy->nsup = sp.n;
    dy->sup_e = ctn_malloc(p->ctx, sp.n + 1, sizeof(size_t));
    dy->sup_off = ctn_malloc(p->ctx, sp.n + 1, sizeof(size_t));
    dy->sup_M = ctn_malloc(p->ctx, sp.nv + 1, sizeof(double));
    dy->sup_idx = ctn_malloc(p->ctx, (size_t)p->a->maxdof + 1, sizeof(size_t));
    if (!dy->sup_e || !dy->sup_off || !dy->sup_M || !dy->sup_idx) return CTN_ERR_NOMEM;
    if ((dy->o->damping_beta > 0 || (moves && dy->mr)) && !(dy->sup_K = ctn_malloc(p->ctx, sp.nv + 1, sizeof(double)))) return CTN_ERR_NOMEM;
    sp = (sup_pass){ dy, 1, 0, 0 };
    size_t bad = 0;
    if (ctn_asm_loop(p->a, dy->d0, 0, dy->sup_K != NULL, sup_visit, &sp, &bad))
        return ctn_dyn_error(p, dy->o, "dynamics: an element cannot be evaluated in the start state");
    dy->sup_off[sp.n] = sp.nv;
    return CTN_OK;
}

/* P x over element e's rows of one kind (P packed, x the state layout), times scale:
 * free = 0: the fixed DOFs' rows, added to y (the state layout); free = 1: the free
 * DOFs' rows, added to y (the equations' layout). */
static void packed_rows(ctn_dyn *dy, size_t e, const double *P, double scale, const double *x, double *y, int free)
{
    const ctn_asm *a = dy->p->a;
    const ctn_asm_block *b = ctn_asm_block_of(a, e);
    const int *nodes = ctn_elem_nodes(a->m, e);
    int n = b->nedof, nd = b->ops->ndof_node;
    size_t *idx = dy->sup_idx;
    for (int i = 0; i < n; i++) idx[i] = ctn_dofmap_node(&a->map, (size_t)nodes[i / nd]) + (size_t)(i % nd);
    for (int i = 0; i < n; i++) {
        int q = a->map.eq[idx[i]];
        if ((q >= 0) != free) continue;
        double s = 0;
        for (int j = 0; j < n; j++) s += P[i <= j ? ctn_packed_index(n, i, j) : ctn_packed_index(n, j, i)] * x[idx[j]];
        y[free ? (size_t)q : idx[i]] += scale * s;
    }
}

static void packed_fixed(ctn_dyn *dy, size_t e, const double *P, double scale, const double *x, double *y)
{
    packed_rows(dy, e, P, scale, x, y, 0);
}

/* The elements' internal forces at the fixed DOFs into react, their axial forces into
 * force (NULL: none). */
typedef struct int_pass {
    double *react, *force;
} int_pass;

static void int_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    int_pass *ip = data;
    int nd = el->b->ops->ndof_node;
    if (ip->force) ip->force[el->e] = el->st->N;
    for (int i = 0; i < el->b->nedof; i++) {
        size_t k = ctn_dofmap_node(&a->map, (size_t)el->nodes[i / nd]) + (size_t)(i % nd);
        if (a->map.eq[k] < 0) ip->react[k] += el->fe[i];
    }
}

static void motion_rates(ctn_dyn *dy, double t0, double t1, double wa, double wv);

/* Modal damping at the supports: (M w)_s, w = Phi E U^T (v - v_qs) on the free DOFs (a
 * moving support's v_qs, ctn_dyn_modal_support) (dy->vs, dy->as as scratch, before they
 * are set). */
static void modal_reactions(ctn_dyn *dy, double t, double *R)
{
    const ctn_problem *p = dy->p;
    const double *g = NULL;
    if (dy->fsup && dy->sup_K) {
        motion_rates(dy, t, t, 1.0, 1.0);
        ctn_dyn_support_stiffness(dy, dy->vs, dy->mg);
        g = dy->mg;
    }
    ctn_dyn_rot_spatial(dy, dy->d0, dy->v0, dy->R);       /* the spatial velocities */
    ctn_dyn_modal_velocity(dy, dy->R, g, dy->w2);
    for (size_t i = 0; i < p->ns; i++) dy->as[i] = p->a->map.eq[i] >= 0 ? dy->w2[p->a->map.eq[i]] : 0.0;
    for (size_t k = 0; k < dy->nsup; k++) packed_fixed(dy, dy->sup_e[k], dy->sup_M + dy->sup_off[k], 1.0, dy->as, R);
}

int ctn_dyn_reactions(ctn_dyn *dy, double t, double *force)
{
    ctn_problem *p = dy->p;
    const ctn_model *m = p->m;
    const int *eq = p->a->map.eq;
    double *R = dy->react, al = dy->o->damping_alpha;
    int_pass ip = { R, force };
    memset(R, 0, p->ns * sizeof(double));
    if (force) memset(force, 0, p->a->ne * sizeof(double));
    if (ctn_asm_loop(p->a, dy->d0, CTN_EVAL_STRESS, 0, int_visit, &ip, NULL)) memset(R, 0, p->ns * sizeof(double));
    if (dy->mr) modal_reactions(dy, t, R);
    ctn_dyn_rot_spatial(dy, dy->d0, dy->v0, dy->R);       /* a rotation's R W (dy->R: scratch) */
    ctn_dyn_rates(dy, t, dy->R, dy->a0, dy->vs, dy->as);
    ctn_dyn_rot_reactions(dy, R);
    for (size_t k = 0; k < dy->nsup; k++) {
        size_t e = dy->sup_e[k], o = dy->sup_off[k];
        packed_fixed(dy, e, dy->sup_M + o, 1.0, dy->as, R);                  /* M a */
        if (al > 0) packed_fixed(dy, e, dy->sup_M + o, al, dy->vs, R);       /* alpha M v */
        if (dy->sup_K && dy->o->damping_beta > 0)
            packed_fixed(dy, e, dy->sup_K + o, dy->o->damping_beta, dy->vs, R);   /* beta K_0 v */
    }
    for (size_t i = 0; i < p->a->nn; i++)
        for (int c = 0; c < 3; c++) {
            size_t k = ctn_dofmap_node(&p->a->map, i) + (size_t)c;
            if (eq[k] < 0) R[k] += m->nodes.v[i].mass * (dy->as[k] + al * dy->vs[k]);
        }
    const double *fh = p->fl ? ctn_follow_loads(p->fl) : NULL;   /* at the last residual */
    for (size_t k = 0; k < p->ns; k++)
        if (eq[k] < 0) R[k] -= p->fext[k] + (dy->nwind ? dy->wf[k] : 0.0) + (fh ? fh[k] : 0.0);
    return CTN_OK;
}

int ctn_dyn_keep_frame(ctn_dyn *dy, double t)
{
    ctn_dyn_result *res = dy->s->dyn;
    size_t nn = res->nn, w = 1 + 9 * nn + res->ne;
    if (res->nframe == res->fcap) {
        size_t cap = res->fcap ? 2 * res->fcap : 16, c = res->fcap * w;
        int rc = ctn_array_reserve(dy->p->ctx, (void **)&res->frames, &c, cap * w, sizeof(double));
        if (rc) return rc;
        res->fcap = cap;
    }
    double *f = res->frames + res->nframe * w;
    f[0] = t;
    int rc = ctn_dyn_reactions(dy, t, f + 1 + 9 * nn);
    if (rc) return rc;
    ctn_dofmap_to3(&dy->p->a->map, dy->d0, f + 1);
    ctn_dofmap_to3(&dy->p->a->map, dy->vs, f + 1 + 3 * nn);
    ctn_dofmap_to3(&dy->p->a->map, dy->react, f + 1 + 6 * nn);
    res->nframe++;
    return CTN_OK;
}

size_t ctn_solution_frame_count(const ctn_solution *s) { return s && s->dyn ? s->dyn->nframe : 0; }

int ctn_solution_frame(const ctn_solution *s, size_t k, ctn_dyn_frame *out)
{
    if (!s || !out || !s->dyn || k >= s->dyn->nframe) return CTN_ERR_INVALID;
    size_t nn = s->dyn->nn;
    const double *f = s->dyn->frames + k * (1 + 9 * nn + s->dyn->ne);
    out->t = f[0];
    out->d = f + 1;
    out->v = f + 1 + 3 * nn;
    out->react = f + 1 + 6 * nn;
    out->force = f + 1 + 9 * nn;
    out->nodes = nn;
    out->elements = s->dyn->ne;
    return CTN_OK;
}

/* The fixed DOFs' velocity and acceleration from their motions, weighted between t0 and
 * t1 (v = wv v(t1) + (1 - wv) v(t0), a likewise with wa), 0 on the free DOFs. */
static void motion_rates(ctn_dyn *dy, double t0, double t1, double wa, double wv)
{
    const ctn_problem *p = dy->p;
    const ctn_model *m = p->m;
    memset(dy->vs, 0, p->ns * sizeof(double));
    memset(dy->as, 0, p->ns * sizeof(double));
    for (size_t j = 0; j < m->dloads.n; j++) {
        const ctn_dload *dl = &m->dloads.v[j];
        if (!dl->dofs) continue;
        size_t at = ctn_dofmap_node(&p->a->map, (size_t)dl->node);
        double v = wv * fn_rate(m, dl->fn, t1, 1) + (1 - wv) * fn_rate(m, dl->fn, t0, 1);
        double a = wa * fn_rate(m, dl->fn, t1, 2) + (1 - wa) * fn_rate(m, dl->fn, t0, 2);
        for (int k = 0; k < 3; k++)
            if (dl->dofs >> k & 1) {
                dy->vs[at + (size_t)k] += v * dl->F[k];
                dy->as[at + (size_t)k] += a * dl->F[k];
            }
    }
}

/* y (ndof) += the free rows of P x (P element e's packed block, x the state layout). */
static void packed_free(ctn_dyn *dy, size_t e, const double *P, double scale, const double *x, double *y)
{
    packed_rows(dy, e, P, scale, x, y, 1);
}

void ctn_dyn_support_force(ctn_dyn *dy, double t0, double t1, double wa, double wv)
{
    if (!dy->fsup) return;
    double al = dy->o->damping_alpha;
    memset(dy->fsup, 0, dy->p->ndof * sizeof(double));
    motion_rates(dy, t0, t1, wa, wv);
    for (size_t k = 0; k < dy->nsup; k++) {
        size_t e = dy->sup_e[k], o = dy->sup_off[k];
        packed_free(dy, e, dy->sup_M + o, 1.0, dy->as, dy->fsup);            /* M_fs a_s */
        if (al > 0) packed_free(dy, e, dy->sup_M + o, al, dy->vs, dy->fsup); /* alpha M_fs v_s */
        if (dy->sup_K && dy->o->damping_beta > 0)
            packed_free(dy, e, dy->sup_K + o, dy->o->damping_beta, dy->vs, dy->fsup);   /* beta K_fs v_s */
    }
    if (dy->mr && dy->sup_K) {                                             /* C_m K^-1 K_fs v_s */
        ctn_dyn_support_stiffness(dy, dy->vs, dy->mg);
        ctn_dyn_modal_support(dy, dy->mg, dy->fsup);
    }
}

void ctn_dyn_support_stiffness(ctn_dyn *dy, const double *vs, double *g)
{
    memset(g, 0, dy->p->ndof * sizeof(double));
    for (size_t k = 0; k < dy->nsup; k++) packed_free(dy, dy->sup_e[k], dy->sup_K + dy->sup_off[k], 1.0, vs, g);
}
