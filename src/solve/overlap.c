/* The assembly of the tangent and its factorization, overlapped. A Newton iteration
 * assembles K at the new state, then factorizes it: on a chain the assembly is a
 * quarter of the iteration. With the factor computed row by row in the natural ordering
 * (linsolve's factor_feed), row k needs only the columns up to k, so a second thread
 * assembles the nodes in order and publishes the columns done while the calling thread
 * factorizes behind it: the iteration costs the factorization, not the sum. */
#include "solve/overlap.h"

#include <pthread.h>
#include <time.h>
#include <unistd.h>

typedef struct job {
    const ctn_asm *a;
    const double *d;
    unsigned mode;
    double *f, *Kx;
    ctn_feed *feed;
    ctn_overlap *out;
} job;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void *assemble(void *arg)
{
    job *j = arg;
    double t0 = now();
    j->out->collapsed = ctn_asm_eval_feed(j->a, j->d, j->mode, j->f, j->Kx, &j->out->U, &j->out->bad, j->feed);
    j->out->t_asm = now() - t0;
    return NULL;
}

int ctn_overlap_possible(const ctn_asm *a, const ctn_linsolve *ls)
{
    return a->ndof >= CTN_OVERLAP_MIN_DOF && ctn_asm_can_feed(a) && ctn_linsolve_feedable(ls) &&
           sysconf(_SC_NPROCESSORS_ONLN) >= 2;
}

int ctn_overlap_eval_factor(const ctn_asm *a, ctn_linsolve *ls, const double *d, unsigned mode, double *f,
                            double *Kx, double shift, ctn_overlap *out)
{
    ctn_feed feed;
    job j = { a, d, mode, f, Kx, &feed, out };
    pthread_t t;
    out->bad = 0;
    out->U = 0;
    int fed = !ctn_feed_init(&feed, a->ndof), threaded = fed && !pthread_create(&t, NULL, assemble, &j);
    if (!threaded) {                               /* one after the other */
        if (fed) ctn_feed_destroy(&feed);
        double t0 = now();
        out->collapsed = ctn_asm_eval(a, d, mode, f, Kx, &out->U, &out->bad);
        out->t_asm = now() - t0;
        t0 = now();
        int rc = ctn_linsolve_factor(ls, Kx, shift, &out->info);
        out->t_fac = now() - t0;
        return rc;
    }
    double t0 = now();
    int rc = ctn_linsolve_factor_feed(ls, Kx, shift, &feed, &out->info);
    out->t_fac = now() - t0;
    pthread_join(t, NULL);
    ctn_feed_destroy(&feed);
    return rc;
}
