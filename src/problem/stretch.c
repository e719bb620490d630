/* The second-order correction of a step for the stretch it puts in the beams (a model
 * of finite rotations). A beam chain that swings as a mechanism (hinged at a support,
 * from an unstressed start) turns its nodes by spins, exactly, but Newton's step moves
 * the nodes along straight lines, the tangents of their circles: each member of chord
 * l whose ends move apart by a part t across it is stretched by |t|^2 / (2 l) that the
 * linear step did not predict, and its axial stiffness E A / L0 (against a weight of
 * the same force scale) makes the step's potential rise as the fourth power of the turn:
 * the corrector then only creeps (a pinned bar swung down by a tip load: 122
 * iterations; a hinged chain: more than the 50 of an increment, and a cut-back cannot
 * help a mechanism, which swings all the way under any part of the load).
 * The correction: the forces of those unpredicted stretches along the members' chords
 * at the start of the step, g = sum B^T (E A / L0) s, s = l(d + dd) - l(d) - e1 .
 * (dd2 - dd1), solved on the step's own factorization, (K + mu I) dc = -g: along the
 * chords K is stiff, so dc takes the stretch back and little else, and d + dd + dc lies
 * on the members' circles to second order. */
#include "problem/problem.h"

#include <math.h>
#include <string.h>

/* The chord of element e (nodes a, b) at state d, and its length. */
static double chord(const ctn_problem *p, int a, int b, const double *d, double c[3])
{
    const ctn_dofmap *map = &p->a->map;
    const double *Xa = p->m->nodes.v[a].X, *Xb = p->m->nodes.v[b].X;
    size_t sa = ctn_dofmap_node(map, (size_t)a), sb = ctn_dofmap_node(map, (size_t)b);
    for (int k = 0; k < 3; k++) c[k] = (Xb[k] - Xa[k]) + (d[sb + (size_t)k] - d[sa + (size_t)k]);
    return sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

/* The step's translation of node a along k (0 if fixed). */
static double step_of(const ctn_problem *p, int a, int k, const double *dd)
{
    int q = p->a->map.eq[ctn_dofmap_node(&p->a->map, (size_t)a) + (size_t)k];
    return q >= 0 ? dd[q] : 0.0;
}

int ctn_problem_stretch_rhs(ctn_problem *p, const double *d, const double *dtrial, const double *dd, double *g)
{
    const ctn_asm *as = p->a;
    int any = 0;
    memset(g, 0, p->ndof * sizeof(double));
    for (size_t k = 0; k < as->nblocks; k++) {
        const ctn_asm_block *b = &as->blocks[k];
        if (!(b->ops->flags & CTN_ELEM_FINITE_ROTATION) || b->nnodes != 2) continue;
        for (size_t i = 0; i < b->count; i++) {
            const int *nd = ctn_elem_nodes(p->m, b->e0 + i);
            double c0[3], c1[3], l0 = chord(p, nd[0], nd[1], d, c0), l1 = chord(p, nd[0], nd[1], dtrial, c1), lin = 0;
            if (!(l0 > 0)) continue;
            for (int j = 0; j < 3; j++) lin += c0[j] / l0 * (step_of(p, nd[1], j, dd) - step_of(p, nd[0], j, dd));
            double s = l1 - l0 - lin, N = b->ops->stiffness(as->props + b->props0 + i * b->ops->props_size) * s;
            if (!isfinite(N)) return 0;
            for (int a = 0; a < 2; a++)
                for (int j = 0; j < 3; j++) {
                    int q = as->map.eq[ctn_dofmap_node(&as->map, (size_t)nd[a]) + (size_t)j];
                    if (q >= 0) g[q] -= (a ? 1 : -1) * N * c0[j] / l0;     /* -B^T N */
                }
            any = 1;
        }
    }
    return any;
}
