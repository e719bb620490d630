/*
 * catena/core.h - context, status codes and error reporting.
 *
 * Every catena function that can fail returns an int status (CTN_OK == 0) and hands
 * results back through out-parameters. Details of the last error (code, message and,
 * for model input, the file and line) are recorded in a ctn_ctx and read back with
 * ctn_ctx_message() / ctn_ctx_code(). The library never prints and never exits.
 */
#ifndef CATENA_CORE_H
#define CATENA_CORE_H

#include <stddef.h>

#include "catena/export.h"

#ifdef __cplusplus
extern "C" {
#endif
CTN_API_BEGIN

/* Result codes (function return values). */
typedef enum ctn_status {
    CTN_OK = 0,          /* success */
    CTN_ERR_NOMEM = 1,   /* an allocation failed */
    CTN_ERR_INVALID = 2, /* invalid argument passed to the API */
    CTN_ERR_MODEL = 3,   /* the model (file or API calls) is invalid */
    CTN_ERR_IO = 4,      /* a file could not be read or written */
    CTN_ERR_LINALG = 5,  /* the sparse linear algebra backend failed */
    CTN_ERR_NOCONV = 6,  /* a root finder of the analytic module did not converge */
    CTN_ERR_DOMAIN = 7,  /* no solution exists for these inputs (e.g. cable shorter than chord) */
    CTN_ERR_INTERRUPTED = 8 /* the context's interrupt callback asked to stop */
} ctn_status;

/* Name of a status code, e.g. "out of memory". Never NULL. */
const char *ctn_strerror(int status);

/* Opaque error and allocation context. One per thread of use. */
typedef struct ctn_ctx ctn_ctx;

/* Create a context; *out is NULL on failure (CTN_ERR_NOMEM). */
int ctn_ctx_create(ctn_ctx **out);
/* Destroy a context; NULL or *ctx == NULL is a harmless no-op; sets *ctx to NULL. */
void ctn_ctx_destroy(ctn_ctx **ctx);
/* Code of the last recorded error (CTN_OK if none). */
int ctn_ctx_code(const ctn_ctx *ctx);
/* Message of the last recorded error, "" if none. For model input errors it starts
 * with "file:line: ". Owned by the context; valid until the next catena call on it. */
const char *ctn_ctx_message(const ctn_ctx *ctx);
/* Forget the last error. */
void ctn_ctx_clear(ctn_ctx *ctx);

/* Largest model the readers and builders accept: at most `max_items` nodes and at most
 * as many elements (0: no limit, the default). Beyond it, definitions fail with
 * CTN_ERR_MODEL ("model too large"). For services and fuzzing that read untrusted
 * models. */
void ctn_ctx_set_model_limit(ctn_ctx *ctx, long max_items);
long ctn_ctx_model_limit(const ctn_ctx *ctx);

/* Threads. The most threads catena may run at once for work on this context, the
 * caller's included:
 *   1 (the default)  none: catena starts no thread, and the OpenMP regions of the
 *                    libraries it calls (CHOLMOD, an OpenMP BLAS) run on the caller's
 *                    thread alone, whatever a solve's threads= option says. A program
 *                    that embeds catena (a Python process, an MPI rank) gets no thread it
 *                    did not ask for.
 *   n >= 2           up to n: a solve's threads= option may lower it (threads=1: none);
 *                    parts of a large solve, its orderings, triangular solves, modal
 *                    analysis and result writing run on the caller's thread and one
 *                    helper where the machine has two CPUs or more (docs/architecture.md,
 *                    "Threads"); a factorization's OpenMP threads are its threads= (at
 *                    most n).
 *   0                no limit of the context's: the solve's threads= and the machine
 *                    decide (what the catena command sets).
 * The helpers are at most two threads per context, each started at the first work that
 * uses it and kept, asleep, until ctn_ctx_destroy or ctn_ctx_set_threads(ctx, 1) joins
 * them; at most n - 1 of them work at once. catena changes no process-wide setting for
 * its threads: the OpenMP thread count and thread limit it sets around a factorization
 * are the calling thread's own, restored after each call (docs/solver.md, "Threads").
 * One context is used by one thread at a time (its helpers are catena's business).
 * Returns CTN_ERR_INVALID for n < 0 (or ctx NULL); ctn_ctx_threads: the setting. */
int ctn_ctx_set_threads(ctn_ctx *ctx, int n);
int ctn_ctx_threads(const ctn_ctx *ctx);

/* Progress of long operations, for a program that shows it: while the library reads a
 * model file or writes result files it calls fn(data, what, done, total) now and then,
 * what = "reading" (done bytes of total) or "writing" (done bytes, total 0: unknown).
 * fn NULL (the default) stops the calls. The callback must not use this context. */
typedef void (*ctn_progress_fn)(void *data, const char *what, double done, double total);
void ctn_ctx_set_progress(ctn_ctx *ctx, ctn_progress_fn fn, void *data);

/* Interruption, for a program that lets its user stop a long run (Ctrl-C): the library
 * calls fn(data) at safe points (between Newton iterations, between chunks of a model
 * file read and of result files written) and, when it returns non-zero, stops there
 * with CTN_ERR_INTERRUPTED ("interrupted"): a result set being written is abandoned
 * whole (its temporaries removed, older files untouched), never half replaced. fn must
 * be cheap and thread-safe (it may be called from the library's second thread); it is
 * typically a read of a flag that the program's signal handler sets. The library
 * installs no signal handler of its own. fn NULL (the default) stops the calls. */
typedef int (*ctn_interrupt_fn)(void *data);
void ctn_ctx_set_interrupt(ctn_ctx *ctx, ctn_interrupt_fn fn, void *data);

/* Testing hook: make the n-th allocation from now on (1-based) fail, 0 disables.
 * Lets tests check that every allocation failure gives CTN_ERR_NOMEM and no leak. */
void ctn_ctx_fail_alloc_at(ctn_ctx *ctx, long n);
/* Number of allocations made through this context so far. */
long ctn_ctx_alloc_count(const ctn_ctx *ctx);

/* Advise the kernel to back the 2 MB-aligned part of [p, p + bytes) with transparent
 * huge pages (a hint, nothing below 4 MB): what the library does with its own large
 * blocks, for a program that installs its own allocator for SuiteSparse (the catena
 * command does; the library never changes a process-wide allocator). */
void ctn_mem_huge(void *p, size_t bytes);

/* The catena command's memory settings, for a program that asks for them (the library
 * never calls this itself): glibc's heap for every block and never trimmed (mallopt
 * M_MMAP_MAX 0, M_TRIM_THRESHOLD -1), SuiteSparse's allocator advised for transparent
 * huge pages, and the heap's address range reserved once and advised (not under
 * AddressSanitizer or valgrind). PROCESS-WIDE and permanent: every module of the process
 * is affected and nothing undoes it. 1 if the settings were applied, 0 where the
 * platform has none (nothing changed). */
int ctn_process_heap(void);

CTN_API_END
#ifdef __cplusplus
}
#endif
#endif
