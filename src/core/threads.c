/* The thread policy and the context's helper thread (threads.h). */
#define _GNU_SOURCE                      /* RTLD_DEFAULT */
#include "core/threads.h"
#include "core/ctx.h"

#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdint.h>

/* From what size each site's second thread pays for itself on the machine of
 * bench/RESULTS.md (where each figure was measured). */
static const double threshold[CTN_THR_SITES] = {
    [CTN_THR_ASSEMBLY] = 50000,          /* nodes (bench_floor) */
    [CTN_THR_OVERLAP] = 30000,           /* DOFs: below, a thread's start costs what it saves */
    [CTN_THR_ORDER] = 20000,             /* DOFs */
    [CTN_THR_TOUCH] = 256.0 * 1048576,   /* bytes of factor values */
    [CTN_THR_PSOLVE] = 50000,            /* order of the factor (bench_psolve) */
    [CTN_THR_LANCZOS] = 50000,           /* rows of the basis (as the assembly's) */
    [CTN_THR_MODES] = 50000,             /* DOFs: each mode reads K and M once */
    [CTN_THR_WRITE] = 200000,            /* nodes + elements (the K = 1000 net's 1.4 GB) */
};

/* The most threads the context lets a solve run at once. */
static int limit(const ctn_ctx *ctx) { return ctx->threads > 0 ? ctx->threads : INT_MAX; }

int ctn_thr_allows(const ctn_ctx *ctx, int asked, ctn_thr_site site, double size)
{
    if (!ctx || asked == 1 || limit(ctx) < 2 || ctx->cpus < 2) return 0;
    return size >= threshold[site] || ctx->thr_any_size;
}

int ctn_thr_openmp(const ctn_ctx *ctx, int asked)
{
    int n = asked > 0 ? asked : 1;
    return ctx && n > limit(ctx) ? limit(ctx) : n;
}

/* The helpers a solve may keep busy at once: the threads it may run, less the caller's,
 * and at most CTN_THR_HELPERS (a long job beside the caller, a modal analysis's pages
 * written ahead, and the halves of a parallel region). */
static int helpers(const ctn_ctx *ctx, int asked)
{
    int n = asked > 0 && asked < limit(ctx) ? asked : limit(ctx);
    return n - 1 < CTN_THR_HELPERS ? n - 1 : CTN_THR_HELPERS;
}

typedef struct slot {
    struct ctn_thr_pool *pool;
    pthread_cond_t wake;       /* to the helper: a job is posted, or quit */
    pthread_cond_t done;       /* to the caller: the job is done */
    pthread_t thread;
    int started;               /* the thread runs */
    ctn_thr_fn fn;
    void *arg;
    int busy;                  /* a job handed out and not yet waited for */
    int posted;                /* a job not yet finished */
} slot;

struct ctn_thr_pool {
    pthread_mutex_t lock;
    int quit;
    slot s[CTN_THR_HELPERS];
};

static void *helper(void *arg)
{
    slot *h = arg;
    struct ctn_thr_pool *p = h->pool;
    typedef void (*set_fn)(int);
    set_fn set = (set_fn)(uintptr_t)dlsym(RTLD_DEFAULT, "omp_set_num_threads");
    if (set) set(1);                         /* this thread's own OpenMP count: no team */
    pthread_mutex_lock(&p->lock);
    for (;;) {
        while (!h->posted && !p->quit) pthread_cond_wait(&h->wake, &p->lock);
        if (!h->posted) break;               /* quit, nothing left to run */
        pthread_mutex_unlock(&p->lock);
        h->fn(h->arg);
        pthread_mutex_lock(&p->lock);
        h->posted = 0;
        pthread_cond_signal(&h->done);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

/* The pool (no thread yet): 0, or 1 if it could not be made (nothing to undo, no error
 * left in the context: the caller works serially). */
static int pool_open(ctn_ctx *ctx)
{
    int had_error = ctx->code != CTN_OK;
    struct ctn_thr_pool *p = ctn_calloc(ctx, 1, sizeof *p);
    if (!p) {
        if (!had_error) ctn_ctx_clear(ctx);  /* an outcome here, not an error */
        return 1;
    }
    if (pthread_mutex_init(&p->lock, NULL)) {
        ctn_free(p);
        return 1;
    }
    ctx->pool = p;
    return 0;
}

/* Slot i's thread started (under the pool's lock): 0, or 1 if it could not be. */
static int slot_open(ctn_ctx *ctx, int i)
{
    slot *h = &ctx->pool->s[i];
    if (h->started) return 0;
    h->pool = ctx->pool;
    if (pthread_cond_init(&h->wake, NULL)) return 1;
    if (pthread_cond_init(&h->done, NULL)) goto no_done;
    if (pthread_create(&h->thread, NULL, helper, h)) goto no_thread;
    h->started = 1;
    ctx->thr_started++;
    return 0;
no_thread:
    pthread_cond_destroy(&h->done);
no_done:
    pthread_cond_destroy(&h->wake);
    return 1;
}

int ctn_thr_start(ctn_ctx *ctx, int asked, ctn_thr_site site, double size, ctn_thr_fn fn, void *arg)
{
    if (!ctn_thr_allows(ctx, asked, site, size)) return 0;
    if (!ctx->pool && pool_open(ctx)) return 0;
    struct ctn_thr_pool *p = ctx->pool;
    int ticket = 0, busy = 0, n = helpers(ctx, asked);
    pthread_mutex_lock(&p->lock);
    for (int i = 0; i < CTN_THR_HELPERS; i++) busy += p->s[i].busy;
    for (int i = 0; !ticket && busy < n && i < CTN_THR_HELPERS; i++) {
        slot *h = &p->s[i];
        if (h->busy || slot_open(ctx, i)) continue;
        h->busy = h->posted = 1;
        h->fn = fn;
        h->arg = arg;
        pthread_cond_signal(&h->wake);
        ticket = i + 1;
    }
    pthread_mutex_unlock(&p->lock);
    return ticket;
}

void ctn_thr_wait(ctn_ctx *ctx, int ticket)
{
    struct ctn_thr_pool *p = ctx->pool;
    slot *h = &p->s[ticket - 1];
    pthread_mutex_lock(&p->lock);
    while (h->posted) pthread_cond_wait(&h->done, &p->lock);
    h->busy = 0;
    pthread_mutex_unlock(&p->lock);
}

int ctn_thr_both(ctn_ctx *ctx, int asked, ctn_thr_site site, double size, ctn_thr_fn fn, void *a0, void *a1)
{
    int ticket = ctn_thr_start(ctx, asked, site, size, fn, a1);
    fn(a0);
    if (ticket) ctn_thr_wait(ctx, ticket);
    else fn(a1);
    return ticket != 0;
}

void ctn_thr_release(ctn_ctx *ctx)
{
    struct ctn_thr_pool *p = ctx ? ctx->pool : NULL;
    if (!p) return;
    pthread_mutex_lock(&p->lock);
    p->quit = 1;
    for (int i = 0; i < CTN_THR_HELPERS; i++)
        if (p->s[i].started) pthread_cond_signal(&p->s[i].wake);
    pthread_mutex_unlock(&p->lock);
    for (int i = 0; i < CTN_THR_HELPERS; i++) {
        slot *h = &p->s[i];
        if (!h->started) continue;
        pthread_join(h->thread, NULL);
        pthread_cond_destroy(&h->done);
        pthread_cond_destroy(&h->wake);
    }
    pthread_mutex_destroy(&p->lock);
    ctn_free(p);
    ctx->pool = NULL;
}

long ctn_thr_started(const ctn_ctx *ctx) { return ctx ? ctx->thr_started : 0; }
