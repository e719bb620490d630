/* What form finding needs of a model, checked before the first solve: members of two
 * nodes with a force density or a target force, supports where they are in the first
 * step, every free DOF joined to an anchor of its direction, and targets that some shape
 * can balance at each node. */
#include "design/formfind/ff.h"
#include "element/element.h"

#include <math.h>

static int member_error(const ctn_ff *f, size_t e, const char *what)
{
    const ctn_element *el = &f->m->elements.v[e];
    return ctn_error_at(f->ctx, CTN_ERR_MODEL, f->m->file, el->line, "element %d: %s", el->id, what);
}

static int check_members(const ctn_ff *f)
{
    for (size_t e = 0; e < f->ne; e++) {
        const ctn_element *el = &f->m->elements.v[e];
        const ctn_element_ops *ops = ctn_element_family(el->type);
        if (el->nnodes != 2 || !ops->prestress_l0)
            return member_error(f, e, "form finding takes members of two nodes whose unstressed length "
                                "follows from their force (cable, spring)");
        if (!ctn_model_density_of(f->m, e))
            return member_error(f, e, "form finding needs a force density q= or a target force force= on every member");
    }
    return CTN_OK;
}

static int check_displacements(const ctn_ff *f)
{
    for (size_t i = 0; i < f->m->pdisps.n; i++) {
        const ctn_pdisp *d = &f->m->pdisps.v[i];
        if (d->step > 1) continue;
        const ctn_node *p = &f->m->nodes.v[d->node];
        return ctn_error_at(f->ctx, CTN_ERR_MODEL, f->m->file, p->line, "node %d: a displacement is prescribed in the "
                            "first step; form finding holds the supports where they are (move it in a later step)", p->id);
    }
    for (size_t i = 0; i < f->m->tloads.n; i++)      /* the lengths are found at the reference temperature */
        if (f->m->tloads.v[i].step <= 1)
            return ctn_error_at(f->ctx, CTN_ERR_MODEL, f->m->file, f->m->tloads.v[i].line,
                                "a temperature change in the first step; form finding finds the shape at the reference "
                                "temperature (change it in a later step)");
    return CTN_OK;
}

static int root(int *up, int i)
{
    while (up[i] != i) i = up[i] = up[up[i]];
    return i;
}

/* Coordinate k: every node free in k reaches, through members between nodes free in k,
 * a member to a node fixed in k; otherwise D_ff is singular. up, held: nn each. */
static int check_anchored(const ctn_ff *f, int k, int *up, unsigned char *held)
{
    const ctn_model *m = f->m;
    unsigned bit = 1u << k;
    for (size_t i = 0; i < f->nn; i++) {
        up[i] = (int)i;
        held[i] = 0;
    }
    for (size_t e = 0; e < f->ne; e++) {
        const int *nd = ctn_elem_nodes(m, e);
        int fa = !(m->nodes.v[nd[0]].fix & bit), fb = !(m->nodes.v[nd[1]].fix & bit);
        if (fa && fb) up[root(up, nd[0])] = root(up, nd[1]);
        else if (fa) held[nd[0]] = 1;
        else if (fb) held[nd[1]] = 1;
    }
    for (size_t i = 0; i < f->nn; i++)
        if (held[i]) held[root(up, (int)i)] = 1;
    for (size_t i = 0; i < f->nn; i++) {
        const ctn_node *p = &m->nodes.v[i];
        if (p->fix & bit || held[root(up, (int)i)]) continue;
        return ctn_error_at(f->ctx, CTN_ERR_MODEL, m->file, p->line, "node %d is free in %c but no chain of members "
                            "joins it to a node fixed in %c: form finding cannot place it (an anchor is a node with fix=)",
                            p->id, "xyz"[k], "xyz"[k]);
    }
    return CTN_OK;
}

int ctn_ff_check_model(ctn_ff *f)
{
    int rc = check_members(f);
    if (!rc) rc = check_displacements(f);
    int *up = rc ? NULL : ctn_malloc(f->ctx, f->nn ? f->nn : 1, sizeof(int));
    unsigned char *held = up ? ctn_malloc(f->ctx, f->nn ? f->nn : 1, 1) : NULL;
    if (!rc && !held) rc = CTN_ERR_NOMEM;
    for (int k = 0; k < 3 && !rc; k++) rc = check_anchored(f, k, up, held);
    ctn_free(up);
    ctn_free(held);
    return rc;
}

/* At a free node whose members all have targets, the forces and the load must close a
 * polygon: none larger than all the others together. sum, big: 2 per node (the sum of
 * the magnitudes and the largest), arg: the member of the largest (-1: the load). */
int ctn_ff_check_targets(ctn_ff *f)
{
    const ctn_model *m = f->m;
    double *sum = ctn_calloc(f->ctx, 2 * (f->nn ? f->nn : 1), sizeof(double));
    long *arg = ctn_malloc(f->ctx, f->nn ? f->nn : 1, sizeof(long));
    if (!sum || !arg) {
        ctn_free(sum);
        ctn_free(arg);
        return CTN_ERR_NOMEM;
    }
    double *big = sum + f->nn;
    for (size_t i = 0; i < f->nn; i++) {
        const double *p = f->p + 3 * i;
        sum[i] = big[i] = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        arg[i] = -1;
    }
    for (size_t e = 0; e < f->ne; e++) {
        const int *nd = ctn_elem_nodes(m, e);
        const ctn_density *dn = ctn_model_density_of(m, e);
        double F = dn ? dn->force : 0;
        for (int s = 0; s < 2; s++) {
            size_t i = (size_t)nd[s];
            sum[i] = F > 0 && isfinite(sum[i]) ? sum[i] + F : INFINITY;   /* a q member: any force */
            if (F > big[i]) big[i] = F, arg[i] = (long)e;
        }
    }
    int rc = CTN_OK;
    for (size_t i = 0; i < f->nn && !rc; i++) {
        const ctn_node *p = &m->nodes.v[i];
        double rest = sum[i] - big[i];
        if (p->fix || !isfinite(sum[i]) || big[i] <= rest * (1 + 1e-12)) continue;
        if (arg[i] < 0)
            rc = ctn_error_at(f->ctx, CTN_ERR_MODEL, m->file, p->line, "node %d: its load (%g) is larger than the target "
                              "forces of its members together (%g): no shape balances them", p->id, big[i], rest);
        else
            rc = ctn_error_at(f->ctx, CTN_ERR_MODEL, m->file, m->elements.v[arg[i]].line, "element %d: its target force %g "
                              "is larger than the other forces at node %d together (%g, with the load there): no shape "
                              "balances them", m->elements.v[arg[i]].id, big[i], p->id, rest);
    }
    ctn_free(sum);
    ctn_free(arg);
    return rc;
}
