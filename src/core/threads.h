/* Internal: the one place that decides whether the library may use a second thread, and
 * the context's helper thread that runs the second half of every parallel region.
 *
 * The policy. A parallel site (the list below) asks ctn_thr_allows(ctx, asked, site,
 * size): the solve's threads= option (`asked`: 0 auto, 1 one thread, n), the context's
 * limit (ctn_ctx_set_threads: 1 by default, none started; 0 in the CLI: no limit), the
 * machine's CPUs (asked once, when the context is created) and the site's size
 * threshold, named once in threads.c. Every site runs on the caller plus at most one
 * helper. The OpenMP thread count of a numeric factorization comes from the same policy
 * (ctn_thr_openmp).
 *
 * The pool. At most CTN_THR_HELPERS helper threads per context, each started at the
 * first job that needs it and kept, idle, until ctn_ctx_destroy or ctn_ctx_set_threads
 * joins it; a helper runs one job at a time. A solve keeps at most threads - 1 of them
 * busy at once (threads=2: one helper; auto: the two, a long job beside the caller and
 * the halves of a parallel region, as the modal analysis has). A site asked when none
 * may take its job (all busy: a long job, or a job that asks from a helper itself) is
 * told no and runs its work serially: nobody waits for a helper it did not start. A
 * helper that cannot be started (no memory, no thread) also means serial: the work is
 * done either way. */
#ifndef CTN_CORE_THREADS_H
#define CTN_CORE_THREADS_H

#define CTN_THR_HELPERS 2

#include "catena/core.h"

typedef enum ctn_thr_site {
    CTN_THR_ASSEMBLY,          /* assemble/gather.c: the nodes in two halves (size: nodes) */
    CTN_THR_OVERLAP,           /* solve/overlap.c: the factorization beside the assembly (DOFs) */
    CTN_THR_ORDER,             /* linalg/backends/cholmod/cholmod_order.c: AMD beside METIS (DOFs) */
    CTN_THR_TOUCH,             /* linalg/backends/cholmod/cholmod_touch.c: a new factor's pages (bytes) */
    CTN_THR_PSOLVE,            /* linalg/backends/cholmod/cholmod_psolve.c: the triangular sweeps (factor order) */
    CTN_THR_LANCZOS,           /* linalg/eigen/blanczos_par.c: the basis's rows in two halves, its
                                  pages written ahead (rows) */
    CTN_THR_MODES,             /* solve/modes_post.c: the modes described in two halves (DOFs) */
    CTN_THR_WRITE,             /* io/results.c: the result files on two threads (nodes + elements) */
    CTN_THR_SITES
} ctn_thr_site;

/* 1 if `site` may use a second thread for work of `size` (the site's unit, above) in a
 * solve that asked for `asked` threads (its threads= option: 0 auto, 1, n). */
int ctn_thr_allows(const ctn_ctx *ctx, int asked, ctn_thr_site site, double size);
/* The OpenMP threads of a numeric factorization: threads= (0: one, the fastest
 * measured), at most the context's limit. */
int ctn_thr_openmp(const ctn_ctx *ctx, int asked);

typedef void (*ctn_thr_fn)(void *arg);
/* Run fn(arg) on one of the context's helpers if the policy allows the site and a
 * helper may take it (started here the first time): a ticket > 0, and the caller must
 * ctn_thr_wait(ctx, ticket) before it reads what fn writes; 0: nothing started, the
 * caller does the work itself. */
int ctn_thr_start(ctn_ctx *ctx, int asked, ctn_thr_site site, double size, ctn_thr_fn fn, void *arg);
/* Wait for the job of that ticket (from the thread that started it). */
void ctn_thr_wait(ctn_ctx *ctx, int ticket);
/* fn(a0) on the caller's thread and fn(a1) on the helper, or, when the helper is not
 * allowed or busy, fn(a0) then fn(a1) on the caller's: 1 if it ran on two threads. */
int ctn_thr_both(ctn_ctx *ctx, int asked, ctn_thr_site site, double size, ctn_thr_fn fn, void *a0, void *a1);
/* Stop and join the helpers, if any (ctn_ctx_destroy, ctn_ctx_set_threads). */
void ctn_thr_release(ctn_ctx *ctx);
/* Threads the library has started for this context so far (tests). */
long ctn_thr_started(const ctn_ctx *ctx);

#endif
