/* Internal: the context structure, error recording and checked allocation. */
#ifndef CTN_CORE_CTX_H
#define CTN_CORE_CTX_H

#include "catena/core.h"

#include <stdarg.h>

#define CTN_MSG_MAX 1024
#define CTN_INPUTS_MAX 8

struct ctn_ctx {
    int code;                /* last error code, CTN_OK if none */
    char msg[CTN_MSG_MAX];   /* last error message */
    long alloc_count;        /* allocations made through ctn_malloc/ctn_calloc */
    long alloc_fail_at;      /* fail the allocation with this count, 0 = never */
    long model_limit;        /* most nodes / elements in a model, 0 = no limit */
    ctn_progress_fn progress;/* ctn_ctx_set_progress: NULL = none */
    void *progress_data;
    ctn_interrupt_fn interrupt; /* ctn_ctx_set_interrupt: NULL = none */
    void *interrupt_data;
    int ninputs;             /* the files read through this context, that no output */
    unsigned long long input_dev[CTN_INPUTS_MAX], input_ino[CTN_INPUTS_MAX]; /* replaces */
    int threads;             /* ctn_ctx_set_threads: 1 (default) none started, 0 no limit */
    int cpus;                /* the machine's CPUs online, asked once at creation */
    struct ctn_thr_pool *pool;  /* the helper thread (core/threads.c), NULL until needed */
    long thr_started;        /* threads started for this context (tests) */
    int thr_any_size;        /* tests: 1 takes every site's size threshold as met */
    const struct ctn_comm *comm; /* the processes of an analysis (dist/comm.h), NULL: one */
};

/* Remember the file open as fd as an input of this context (the first CTN_INPUTS_MAX):
 * the atomic writers refuse to replace it. */
void ctn_ctx_note_input(ctn_ctx *ctx, int fd);
/* 1 if (dev, ino) is a file noted as an input. */
int ctn_ctx_is_input(const ctn_ctx *ctx, unsigned long long dev, unsigned long long ino);

/* Report progress through the context's callback, if any. */
void ctn_progress(ctn_ctx *ctx, const char *what, double done, double total);

/* CTN_ERR_INTERRUPTED, recorded, when the context's interrupt callback asks to stop;
 * else CTN_OK. Called at the library's safe points. */
int ctn_interrupted(ctn_ctx *ctx);

/* Record an error and return its code. printf-style message. */
int ctn_error(ctn_ctx *ctx, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Record an error located in an input file: message "file:line: ..." ("file: ..."
 * without a line, "..." alone for a model built through the API: no file, line 0). */
int ctn_error_at(ctn_ctx *ctx, int code, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

/* Checked allocation (counted, fault-injectable). NULL on failure, error recorded.
 * n * size overflow is detected. ctn_free(NULL) is a no-op. Blocks of CTN_HUGE_MIN bytes
 * or more are advised to the kernel for transparent huge pages (ctn_mem_huge). */
void *ctn_malloc(ctn_ctx *ctx, size_t n, size_t size);
void *ctn_calloc(ctn_ctx *ctx, size_t n, size_t size);
/* Grow or shrink p to n * size bytes; on failure p is untouched and NULL returned. */
void *ctn_realloc(ctn_ctx *ctx, void *p, size_t n, size_t size);
void ctn_free(void *p);

/* Ask the kernel to back the 2 MB-aligned part of [p, p + bytes) with transparent huge
 * pages (madvise MADV_HUGEPAGE; nothing below CTN_HUGE_MIN bytes, and a hint the kernel
 * may ignore): one page fault per 2 MB instead of 512. Where a page fault is costly (a
 * virtual machine that traps each one: bench/RESULTS.md measured 4-8 s per GB of first
 * writes) this is most of the cost of fresh memory. */
#define CTN_HUGE_PAGE ((size_t)2 << 20)
#define CTN_HUGE_MIN ((size_t)4 << 20)
/* ctn_mem_huge is public (catena/core.h). */

#endif
