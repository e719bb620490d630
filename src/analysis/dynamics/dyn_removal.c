/* Elements removed in time (`remove`): severed at their time, the state balanced
 * again there, restored after the analysis. */
#include "analysis/dynamics/dynamics.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The removals due at t (their time at most t): each element severed, then the state at
 * t balanced again (r0, a0; the strain energy the elements held counts as dissipated). */
int ctn_dyn_apply_removals(ctn_dyn *dy, double t)
{
    ctn_problem *p = dy->p;
    const ctn_model *m = p->m;
    int changed = 0, valid = 0, rc = CTN_OK;
    for (size_t i = 0; i < m->removals.n && !rc; i++) {
        if (dy->severed[i] || m->removals.v[i].t > t + 1e-9 * dy->o->dt) continue;
        rc = ctn_asm_sever_element(p->a, (size_t)m->removals.v[i].element);
        dy->severed[i] = changed = 1;
    }
    if (rc || !changed) return rc;
    ctn_dyn_set_time(dy, t, dy->d0);
    if ((rc = ctn_dyn_residual(dy, dy->d0, 0, dy->r0, &valid))) return rc;
    ctn_dyn_wind(dy, dy->d0, dy->v0, t, dy->r0);
    dy->D += dy->U - dy->U1;
    dy->U = dy->U1;
    ctn_dyn_support_force(dy, t, t, 1.0, 1.0);
    return ctn_dyn_acceleration(dy);
}

/* The earliest removal after t, or INFINITY. */
double ctn_dyn_next_removal(const ctn_dyn *dy, double t)
{
    double next = INFINITY;
    for (size_t i = 0; i < dy->p->m->removals.n; i++)
        if (!dy->severed[i] && dy->p->m->removals.v[i].t > t) next = fmin(next, dy->p->m->removals.v[i].t);
    return next;
}

/* The severed elements restored (the problem outlives the analysis). */
void ctn_dyn_restore_removals(ctn_dyn *dy)
{
    ctn_problem *p = dy->p;
    for (size_t i = 0; dy->severed && i < p->m->removals.n; i++) {
        size_t e = (size_t)p->m->removals.v[i].element;
        if (dy->severed[i]) ctn_asm_setup_element(p->a, e, p->dT ? p->dT[e] : 0.0);
    }
}
