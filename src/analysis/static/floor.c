/* The round-off floor of the residual: how small |f_ext - f_int| can be made in double
 * precision at a state, computed from the state, not assumed.
 *
 * An element's force is computed from its chord, whose length is known to about
 * eps (|u_a| + |u_b| + 2 l) (the displacements are stored to eps |u|, the chord is formed
 * at element scale); an error dl in l changes the force by k dl, k the element's
 * stiffness scale (E A / l0, the spring's k; a short beam's transverse 12 E I / l0^3,
 * its round_stiffness op: 100 times E A / l0 for the 1000-element cantilever, whose
 * residual stalled 5 times above the floor of E A / l0 alone), its moments by that
 * force's lever l / 2, and the force itself is rounded to
 * eps |N|. Each DOF of a node collects the bounds of the elements that reach it; the floor
 * is the Euclidean norm of those bounds over the free DOFs. A residual below it cannot be
 * told from zero. The scale it is judged against is the force that meets at the nodes:
 * the norm over the free DOFs of the sum of |N| of the elements there and |f_ext|. */
#include "problem/problem.h"

#include <float.h>
#include <math.h>
#include <string.h>

typedef struct floor_acc {
    const double *d;
    double *b;             /* state: bound per entry */
    double *f;             /* state: force magnitude per entry */
} floor_acc;

static double node_disp(const ctn_asm *a, const double *d, int node)
{
    const double *u = d + ctn_dofmap_node(&a->map, (size_t)node);
    return fmax(fabs(u[0]), fmax(fabs(u[1]), fabs(u[2])));
}

static void floor_visit(void *data, const ctn_asm *a, const ctn_asm_elem *el)
{
    floor_acc *f = data;
    const ctn_asm_block *b = el->b;
    double um = 0;
    for (int k = 0; k < b->nnodes; k++) um += node_disp(a, f->d, el->nodes[k]);
    /* a beam's forces at its nodes are its end forces and moments, not N alone (a
     * cantilever's shears: a 1000-element one under a small tip load has N ~ 0) */
    int beam = b->ops->round_stiffness && el->fe, nd = b->ops->ndof_node;
    double k_e = b->ops->round_stiffness ? b->ops->round_stiffness(el->props) : b->ops->stiffness(el->props);
    double bound = DBL_EPSILON * (4 * fabs(el->st->N) + k_e * (um + 2 * el->st->l));
    for (int k = 0; k < b->nnodes; k++) {
        double *bk = f->b + ctn_dofmap_node(&a->map, (size_t)el->nodes[k]);
        double *fk = f->f + ctn_dofmap_node(&a->map, (size_t)el->nodes[k]);
        for (int j = 0; j < b->ops->ndof_node; j++) {
            bk[j] += j < 3 ? bound : 0.5 * el->st->l * bound;      /* moments: the forces' lever l / 2 */
            fk[j] += beam ? fabs(el->fe[k * nd + j]) : fabs(el->st->N);
        }
    }
}

double ctn_problem_residual_floor(ctn_problem *p, const double *d, double *scale)
{
    floor_acc f = { d, p->react, p->dsave };    /* scratch: free between steps and trials */
    memset(f.b, 0, p->ns * sizeof(double));
    memset(f.f, 0, p->ns * sizeof(double));
    *scale = 0;
    if (ctn_asm_loop(p->a, d, p->mode, 0, floor_visit, &f, NULL)) return INFINITY;
    double s = 0, m = 0;
    for (size_t i = 0; i < p->ns; i++) {
        if (p->a->map.eq[i] < 0) continue;
        double fi = f.f[i] + fabs(p->fext[i]);
        s += f.b[i] * f.b[i];
        m += fi * fi;
    }
    *scale = sqrt(m);
    return sqrt(s);
}
