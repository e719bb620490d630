/* Stability without a factorization: a tangent that is positive definite by its
 * structure (docs/theory.md, "Stability shown by tension").
 *
 * An axial member's tangent is [[k, -k], [-k, k]] with k = dN/dl e e^T + N/l (I - e e^T):
 * k's eigenvalues are dN/dl along the chord and N/l twice across it. K_T is the sum over
 * the members of (a a^T) (x) k_e, a = e_i - e_j. When every k_e is positive
 * semi-definite (N >= 0 and dN/dl >= 0: members in tension or slack), K_T is; and with
 * mu_e > 0 the least eigenvalue of the definite k_e,
 *     K_T >= sum over the definite members of mu_e (a a^T) (x) I = L_mu (x) I,
 * a weighted graph Laplacian in each direction. With the fixed DOFs removed, L_mu of a
 * direction is definite when every connected component of the definite members holds a
 * node fixed in that direction. So K_T is positive definite, and the state stable, when
 * every free DOF reaches a support through members in tension: what the LL'
 * factorization of the check would prove, at the cost of one element loop. Anything
 * else (another family, a compressed member, a free DOF cut off from the supports) is
 * left to the factorization, which also names the failing node. */
#include "problem/problem.h"

#include <math.h>
#include <string.h>

typedef struct certify {
    int *parent;                /* union-find over the nodes */
    double tol;                 /* a stiffness below tol is not counted as definite */
    int fail;                   /* a member not positive semi-definite (or not axial) */
} certify;

static int root(int *parent, int q)
{
    while (parent[q] != q) {
        parent[q] = parent[parent[q]];              /* path halving */
        q = parent[q];
    }
    return q;
}

static void visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    certify *c = data;
    (void)a;
    if (c->fail) return;
    if (!ctn_asm_block_axial(el->b) || !(el->st->l > 0)) {
        c->fail = 1;
        return;
    }
    const double *K = el->Ke;                       /* k is K's node 1 - node 1 block */
    double trace = K[ctn_packed_index(6, 0, 0)] + K[ctn_packed_index(6, 1, 1)] + K[ctn_packed_index(6, 2, 2)];
    double across = el->st->N / el->st->l;          /* N / l, twice */
    double along = trace - 2.0 * across;            /* dN / dl */
    if (!(across >= 0) || !(along >= -c->tol)) {    /* compressed, or NaN */
        c->fail = 1;
        return;
    }
    if (across > c->tol && along > c->tol) {
        int r1 = root(c->parent, el->nodes[0]), r2 = root(c->parent, el->nodes[1]);
        if (r1 != r2) c->parent[r1] = r2;
    }
}

/* 1 in *ok when the tangent at d is positive definite by the argument above. */
static int certify_at(ctn_problem *p, const double *d, int *ok)
{
    const ctn_asm *a = p->a;
    const ctn_dofmap *map = &a->map;
    *ok = 0;
    if (map->uniform != 3 || a->nn > (size_t)0x7fffffff) return CTN_OK;
    certify c = { NULL, 1e-12 * p->kscale, 0 };
    unsigned char *fixed = NULL;
    c.parent = ctn_malloc(p->ctx, a->nn, sizeof(int));
    fixed = ctn_calloc(p->ctx, a->nn, 1);
    if (!c.parent || !fixed) {
        ctn_free(c.parent);
        ctn_free(fixed);
        return CTN_ERR_NOMEM;
    }
    for (size_t q = 0; q < a->nn; q++) c.parent[q] = (int)q;
    size_t bad;
    if (!ctn_asm_loop(a, d, 0, 1, visit, &c, &bad) && !c.fail) {
        for (size_t q = 0; q < a->nn; q++)          /* a component's fixed directions */
            for (int j = 0; j < 3; j++)
                if (map->eq[3 * q + (size_t)j] < 0) fixed[root(c.parent, (int)q)] |= (unsigned char)(1u << j);
        *ok = 1;
        for (size_t q = 0; q < a->nn && *ok; q++) {
            unsigned char held = fixed[root(c.parent, (int)q)];
            for (int j = 0; j < 3; j++)
                if (map->eq[3 * q + (size_t)j] >= 0 && !(held & (1u << j))) *ok = 0;
        }
    }
    ctn_free(c.parent);
    ctn_free(fixed);
    return CTN_OK;
}

int ctn_problem_stable_by_tension(ctn_problem *p, const ctn_solution *s, int *ok)
{
    *ok = 0;
    if (p->ndof == 0) return CTN_OK;
    double *d = ctn_calloc(p->ctx, p->ns, sizeof(double));
    if (!d) return CTN_ERR_NOMEM;
    const double *d3 = ctn_solution_displacements(s);
    int rc = CTN_OK;
    if (d3 && s->nn == p->m->nodes.n) {
        ctn_dofmap_from3(&p->a->map, d3, d);
        rc = certify_at(p, d, ok);
    }
    ctn_free(d);
    return rc;
}
