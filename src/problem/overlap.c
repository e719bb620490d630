/* The factorization of the tangent beside its assembly. A Newton iteration assembles K at
 * the new state, then factorizes it: on a chain the assembly is a fifth of the
 * iteration. With the factor computed row by row in the natural ordering (linsolve's
 * factor_feed), row k needs only the columns up to k, so a thread of its own factorizes
 * K a block of rows behind the caller's assembly, which publishes the columns it has
 * finished: the iteration costs the factorization, not the sum. The caller keeps its
 * thread, and can still drop the factorization (a converged state needs none) once its
 * residual is known. */
#include "core/threads.h"
#include "problem/problem.h"

static void factorize(void *arg)
{
    ctn_overlap *o = arg;
    double t0 = ctn_clock();
    o->rc = ctn_linsolve_factor_feed(o->ls, o->Kx, o->shift, &o->feed, &o->info);
    o->t_fac = ctn_clock() - t0;
}

int ctn_overlap_possible(const ctn_asm *a, const ctn_linsolve *ls)
{
    return ctn_asm_can_feed(a) && ctn_linsolve_feedable(ls) &&
           ctn_thr_allows(a->gather->ctx, ctn_asm_threads(a), CTN_THR_OVERLAP, (double)a->ndof);
}

int ctn_overlap_start(ctn_overlap *o, const ctn_asm *a, ctn_linsolve *ls, const double *Kx, double shift)
{
    o->running = 0;
    if (!ctn_asm_can_feed(a)) return 0;
    o->ctx = a->gather->ctx;
    o->ls = ls;
    o->Kx = Kx;
    o->shift = shift;
    o->rc = CTN_OK;
    o->info = (ctn_factor_info){ 0, -1 };
    o->t_fac = 0;
    if (ctn_feed_init(&o->feed, ctn_linsolve_order(ls))) return 0;
    o->ticket = ctn_thr_start(o->ctx, ctn_asm_threads(a), CTN_THR_OVERLAP, (double)a->ndof, factorize, o);
    if (!o->ticket) {
        ctn_feed_destroy(&o->feed);
        return 0;
    }
    o->running = 1;
    return 1;
}

int ctn_overlap_assemble(ctn_overlap *o, const ctn_asm *a, const double *d, unsigned mode, double *f, double *Kx,
                         double *U, size_t *bad)
{
    return ctn_asm_eval_feed(a, d, mode, f, Kx, U, bad, &o->feed);
}

int ctn_overlap_finish(ctn_overlap *o, ctn_factor_info *info)
{
    ctn_thr_wait(o->ctx, o->ticket);
    ctn_feed_destroy(&o->feed);
    o->running = 0;
    *info = o->info;
    return o->rc;
}

void ctn_overlap_abandon(ctn_overlap *o)
{
    if (!o->running) return;
    ctn_feed_stop(&o->feed);
    ctn_factor_info info;
    (void)ctn_overlap_finish(o, &info);
}

int ctn_overlap_eval_factor(const ctn_asm *a, ctn_linsolve *ls, const double *d, unsigned mode, double *f,
                            double *Kx, double shift, double *U, size_t *bad, int *collapsed,
                            ctn_factor_info *info)
{
    ctn_overlap o;
    if (!ctn_overlap_start(&o, a, ls, Kx, shift)) {
        *collapsed = ctn_asm_eval(a, d, mode, f, Kx, U, bad);
        return ctn_linsolve_factor(ls, Kx, shift, info);
    }
    *collapsed = ctn_overlap_assemble(&o, a, d, mode, f, Kx, U, bad);
    return ctn_overlap_finish(&o, info);
}
