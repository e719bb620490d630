/* The force-density start of a net (Schek 1974, "The force density method for form
 * finding and computation of general networks").
 *
 * Each member's start force N, held as a force density q = N / l, makes the equilibrium
 * of the free nodes linear: D_ff x_f = p_f - D_fx x_x, D = C' Q C the graph Laplacian of
 * the net weighted by q, one system of the free nodes for every coordinate (formfind's,
 * design/formfind/system.c: CHOLMOD LL'). Its solution is where a net whose members
 * kept their forces would hang under the loads: the loaded shape of a prestressed net
 * given flat, or in a shape its prestress does not hold, which Newton reaches only by
 * many damped steps. The unstressed lengths stay the model's; only the start moves.
 *
 * Where the members' forces change under the loads (an elastic net carries them by
 * stretching its members as well, which the densities leave out), that shape overshoots
 * the answer: the start moves towards it, d + t (d_q - d), t doubled from 1/4096 to at
 * most 1 while the model's own total potential (its elements' stored energy less the
 * work of the loads) falls, and only if that is below the start's (the measure the
 * globalized Newton method accepts its steps by). A net with a member without tension
 * at the start (no density: the shape would be of another net) keeps its start, as does
 * one whose densities do not hold every free node. The loads are those of the first
 * increment of the first step (its share 1 / steps, or 1 / substeps). */
#include "start/fdensity.h"

#include "design/formfind/ff.h"

#include <math.h>
#include <string.h>

/* *net = 1 if every member is a two-node flexible element, some free node joins three or
 * more and nothing the linear equilibrium leaves out is there. Every process of an MPI
 * job holds the whole model and state: each finds the same start. */
static int is_net(const ctn_problem *p, int *net)
{
    const ctn_asm *a = p->a;
    *net = 0;
    if (a->map.rot || p->fl || p->sp || p->dT || !a->ne) return CTN_OK;
    for (size_t b = 0; b < a->nblocks; b++)
        if (a->blocks[b].nnodes != 2 || !(a->blocks[b].ops->flags & CTN_ELEM_FLEXIBLE)) return CTN_OK;
    int *deg = ctn_calloc(p->ctx, a->nn, sizeof(int));
    if (!deg) return CTN_ERR_NOMEM;
    for (size_t e = 0; e < a->ne; e++)
        for (int k = 0; k < 2; k++) deg[ctn_elem_nodes(p->m, e)[k]]++;
    for (size_t i = 0; i < a->nn && !*net; i++) *net = deg[i] >= 3 && (p->m->nodes.v[i].fix & 7u) != 7u;
    ctn_free(deg);
    return CTN_OK;
}

/* q = N / l of every member at the start; 0 for a member without tension, which then
 * counts in slack. */
typedef struct densities {
    double *q;
    size_t slack;
} densities;

static void density_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    densities *dn = data;
    (void)a;
    int taut = el->st->N > 0 && el->st->l > 0;
    dn->q[el->e] = taut ? el->st->N / el->st->l : 0;
    dn->slack += !taut;
}

/* The total potential at state d under the loads fe (state layout): the elements'
 * stored energy less the work of the loads on the free DOFs; INFINITY if an element
 * collapsed or it is not finite. */
static double potential(ctn_problem *p, const double *d, const double *fe)
{
    size_t bad;
    double U = 0, W = 0;
    if (ctn_asm_eval(p->a, d, p->mode, p->fint, NULL, &U, &bad)) return INFINITY;
    for (size_t i = 0; i < p->ns; i++)
        if (p->a->map.eq[i] >= 0) W += fe[i] * d[i];
    return isfinite(U - W) ? U - W : INFINITY;
}

typedef struct fd_work {
    double *q;          /* ne: the densities */
    double *x;          /* 3 nn: the shape's coordinates */
    double *u;          /* 3 nn: the first step's prescribed displacements */
    double *b;          /* nn: the systems' right-hand side */
    double *fe;         /* state: the first increment's loads */
    double *dq, *dt;    /* state: the shape's displacements, a trial start */
} fd_work;

static int work_alloc(const ctn_problem *p, fd_work *w)
{
    size_t nn = p->a->nn, ne = p->a->ne;
    w->q = ctn_malloc(p->ctx, ne, sizeof(double));
    w->x = ctn_malloc(p->ctx, 3 * nn, sizeof(double));
    w->u = ctn_malloc(p->ctx, 3 * nn, sizeof(double));
    w->b = ctn_malloc(p->ctx, nn, sizeof(double));
    w->fe = ctn_malloc(p->ctx, p->ns, sizeof(double));
    w->dq = ctn_malloc(p->ctx, p->ns, sizeof(double));
    w->dt = ctn_malloc(p->ctx, p->ns, sizeof(double));
    return w->q && w->x && w->u && w->b && w->fe && w->dq && w->dt ? CTN_OK : CTN_ERR_NOMEM;
}

static void work_free(fd_work *w)
{
    ctn_free(w->q);
    ctn_free(w->x);
    ctn_free(w->u);
    ctn_free(w->b);
    ctn_free(w->fe);
    ctn_free(w->dq);
    ctn_free(w->dt);
}

/* The first increment's dead loads into p->v3 (3 per node) and w->fe; 0 when the first
 * step prescribes displacements. */
static int first_loads(ctn_problem *p, fd_work *w)
{
    int sub = ctn_model_step_substeps(p->m, 0);
    double share = 1.0 / (sub > 0 ? sub : p->opt.steps);
    ctn_model_step_loads_ex(p->m, 0, 1, p->v3, w->u);
    for (size_t i = 0; i < 3 * p->a->nn; i++) {
        if (w->u[i] != 0) return 0;
        p->v3[i] *= share;
    }
    ctn_dofmap_from3(&p->a->map, p->v3, w->fe);
    return 1;
}

/* The shape of the densities w->q under the loads p->v3 into w->dq (displacements), its
 * fixed coordinates the start's (d); *ok = 0 when the net's densities do not hold every
 * free node (D_ff not definite). */
static int shape(ctn_problem *p, fd_work *w, const double *d, int *ok)
{
    ctn_dofmap_to3(&p->a->map, d, w->x);
    for (size_t i = 0; i < p->a->nn; i++)
        for (int k = 0; k < 3; k++) w->x[3 * i + (size_t)k] += p->m->nodes.v[i].X[k];
    ctn_ff f;
    memset(&f, 0, sizeof f);
    f.ctx = p->ctx;
    f.m = (ctn_model *)p->m;       /* read only: the shape goes into f.x, not the model */
    f.nn = p->a->nn;
    f.ne = p->a->ne;
    f.q = w->q;
    f.p = p->v3;
    f.b = w->b;
    f.x = w->x;
    f.order = CTN_LA_ORDER_AMD;    /* one ordering analysed, not auto's three */
    int nf = 0, rc = ctn_ff_systems_create(&f);
    if (!rc) rc = ctn_ff_solve_shape(&f, &nf);
    ctn_ff_systems_destroy(&f);
    *ok = !rc;
    if (rc == CTN_ERR_LINALG) {                    /* not definite: no start, no error */
        ctn_ctx_clear(p->ctx);
        rc = CTN_OK;
    }
    if (!*ok) return rc;
    for (size_t i = 0; i < p->a->nn; i++)
        for (int k = 0; k < 3; k++) w->x[3 * i + (size_t)k] -= p->m->nodes.v[i].X[k];
    ctn_dofmap_from3(&p->a->map, w->x, w->dq);
    for (size_t i = 0; i < p->ns; i++)
        if (p->a->map.eq[i] < 0) w->dq[i] = d[i];
    return CTN_OK;
}

/* Towards the shape: t = 1/4096, 1/2048, ... up to 1 along d + t (dq - d) while the
 * potential falls (the lowest of them on a convex potential, a tension-only net's); the
 * last t below the start's potential (d then moved there), else 0. */
static double towards(ctn_problem *p, fd_work *w, double *d)
{
    double best = potential(p, d, w->fe), tb = 0;
    for (int k = 12; k >= 0; k--) {
        double t = ldexp(1.0, -k);
        for (size_t i = 0; i < p->ns; i++) w->dt[i] = d[i] + t * (w->dq[i] - d[i]);
        double pt = potential(p, w->dt, w->fe);
        if (!(pt < best)) break;
        best = pt;
        tb = t;
    }
    for (size_t i = 0; tb > 0 && i < p->ns; i++) d[i] += tb * (w->dq[i] - d[i]);
    return tb;
}

int ctn_fdensity_start(ctn_problem *p, double *d, int *taken)
{
    int net = 0, rc = is_net(p, &net);
    *taken = 0;
    if (rc || !net) return rc;
    fd_work w = { NULL, NULL, NULL, NULL, NULL, NULL, NULL };
    densities dn = { NULL, 0 };
    size_t bad;
    int ok = 0;
    rc = work_alloc(p, &w);
    dn.q = w.q;
    if (!rc && first_loads(p, &w) && !ctn_asm_loop(p->a, d, p->mode, 0, density_visit, &dn, &bad) && !dn.slack)
        rc = shape(p, &w, d, &ok);
    if (!rc && ok) *taken = towards(p, &w, d) > 0;
    work_free(&w);
    return rc;
}
