/* Context: error recording and checked, fault-injectable allocation. */
#define _DEFAULT_SOURCE                  /* madvise, MADV_HUGEPAGE */
#include "core/ctx.h"
#include "core/threads.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

int ctn_ctx_create(ctn_ctx **out)
{
    if (!out) return CTN_ERR_INVALID;
    *out = calloc(1, sizeof(ctn_ctx));
    if (!*out) return CTN_ERR_NOMEM;
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    (*out)->threads = 1;
    (*out)->cpus = cpus > 0 && cpus < 4096 ? (int)cpus : 1;
    return CTN_OK;
}

void ctn_ctx_destroy(ctn_ctx **ctx)
{
    if (!ctx) return;
    ctn_thr_release(*ctx);
    free(*ctx);
    *ctx = NULL;
}

int ctn_ctx_code(const ctn_ctx *ctx) { return ctx ? ctx->code : CTN_ERR_INVALID; }

const char *ctn_ctx_message(const ctn_ctx *ctx) { return ctx ? ctx->msg : ""; }

void ctn_ctx_clear(ctn_ctx *ctx)
{
    if (!ctx) return;
    ctx->code = CTN_OK;
    ctx->msg[0] = '\0';
}

void ctn_ctx_fail_alloc_at(ctn_ctx *ctx, long n)
{
    if (ctx) ctx->alloc_fail_at = n > 0 ? ctx->alloc_count + n : 0;
}

long ctn_ctx_alloc_count(const ctn_ctx *ctx) { return ctx ? ctx->alloc_count : 0; }

void ctn_ctx_set_model_limit(ctn_ctx *ctx, long max_items)
{
    if (ctx) ctx->model_limit = max_items > 0 ? max_items : 0;
}

long ctn_ctx_model_limit(const ctn_ctx *ctx) { return ctx ? ctx->model_limit : 0; }

int ctn_ctx_set_threads(ctn_ctx *ctx, int n)
{
    if (!ctx || n < 0) return CTN_ERR_INVALID;
    if (n == 1) ctn_thr_release(ctx);
    ctx->threads = n;
    return CTN_OK;
}

int ctn_ctx_threads(const ctn_ctx *ctx) { return ctx ? ctx->threads : 1; }

void ctn_ctx_set_progress(ctn_ctx *ctx, ctn_progress_fn fn, void *data)
{
    if (!ctx) return;
    ctx->progress = fn;
    ctx->progress_data = data;
}

void ctn_ctx_note_input(ctn_ctx *ctx, int fd)
{
    struct stat st;
    if (!ctx || ctx->ninputs >= CTN_INPUTS_MAX || fstat(fd, &st)) return;
    if (ctn_ctx_is_input(ctx, (unsigned long long)st.st_dev, (unsigned long long)st.st_ino)) return;
    ctx->input_dev[ctx->ninputs] = (unsigned long long)st.st_dev;
    ctx->input_ino[ctx->ninputs++] = (unsigned long long)st.st_ino;
}

int ctn_ctx_is_input(const ctn_ctx *ctx, unsigned long long dev, unsigned long long ino)
{
    for (int i = 0; ctx && i < ctx->ninputs; i++)
        if (ctx->input_dev[i] == dev && ctx->input_ino[i] == ino) return 1;
    return 0;
}

void ctn_ctx_set_interrupt(ctn_ctx *ctx, ctn_interrupt_fn fn, void *data)
{
    if (!ctx) return;
    ctx->interrupt = fn;
    ctx->interrupt_data = data;
}

int ctn_interrupted(ctn_ctx *ctx)
{
    if (!ctx || !ctx->interrupt || !ctx->interrupt(ctx->interrupt_data)) return CTN_OK;
    return ctn_error(ctx, CTN_ERR_INTERRUPTED, "interrupted");
}

void ctn_progress(ctn_ctx *ctx, const char *what, double done, double total)
{
    if (ctx && ctx->progress) ctx->progress(ctx->progress_data, what, done, total);
}

int ctn_error(ctn_ctx *ctx, int code, const char *fmt, ...)
{
    if (!ctx) return code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx->msg, sizeof ctx->msg, fmt, ap);
    va_end(ap);
    ctx->code = code;
    return code;
}

int ctn_error_at(ctn_ctx *ctx, int code, const char *file, int line, const char *fmt, ...)
{
    if (!ctx) return code;
    int k;                   /* a model built through the API has no file, no line */
    if (file && *file) k = line > 0 ? snprintf(ctx->msg, sizeof ctx->msg, "%s:%d: ", file, line)
                                    : snprintf(ctx->msg, sizeof ctx->msg, "%s: ", file);
    else k = line > 0 ? snprintf(ctx->msg, sizeof ctx->msg, "line %d: ", line) : 0;
    if (k < 0 || (size_t)k >= sizeof ctx->msg) k = 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx->msg + k, sizeof ctx->msg - (size_t)k, fmt, ap);
    va_end(ap);
    ctx->code = code;
    return code;
}

/* Count the allocation; 1 if it must fail (injected or overflow). */
static int alloc_refused(ctn_ctx *ctx, size_t n, size_t size)
{
    if (size && n > SIZE_MAX / size) {
        ctn_error(ctx, CTN_ERR_NOMEM, "allocation of %zu x %zu bytes overflows", n, size);
        return 1;
    }
    if (!ctx) return 0;
    ctx->alloc_count++;
    if (ctx->alloc_fail_at && ctx->alloc_count == ctx->alloc_fail_at) {
        ctn_error(ctx, CTN_ERR_NOMEM, "out of memory (injected failure)");
        return 1;
    }
    return 0;
}

void ctn_mem_huge(void *p, size_t bytes)
{
    if (!p || bytes < CTN_HUGE_MIN) return;
    uintptr_t a = ((uintptr_t)p + CTN_HUGE_PAGE - 1) & ~(uintptr_t)(CTN_HUGE_PAGE - 1);
    uintptr_t b = ((uintptr_t)p + bytes) & ~(uintptr_t)(CTN_HUGE_PAGE - 1);
    if (b > a) (void)madvise((void *)a, b - a, MADV_HUGEPAGE);   /* a hint: may be refused */
}

void *ctn_malloc(ctn_ctx *ctx, size_t n, size_t size)
{
    if (alloc_refused(ctx, n, size)) return NULL;
    void *p = malloc(n * size > 0 ? n * size : 1);
    if (!p) ctn_error(ctx, CTN_ERR_NOMEM, "out of memory (%zu bytes)", n * size);
    ctn_mem_huge(p, n * size);
    return p;
}

void *ctn_calloc(ctn_ctx *ctx, size_t n, size_t size)
{
    if (alloc_refused(ctx, n, size)) return NULL;
    void *p = calloc(n ? n : 1, size ? size : 1);
    if (!p) ctn_error(ctx, CTN_ERR_NOMEM, "out of memory (%zu bytes)", n * size);
    ctn_mem_huge(p, n * size);
    return p;
}

void *ctn_realloc(ctn_ctx *ctx, void *p, size_t n, size_t size)
{
    if (alloc_refused(ctx, n, size)) return NULL;
    void *q = realloc(p, n * size > 0 ? n * size : 1);
    if (!q) ctn_error(ctx, CTN_ERR_NOMEM, "out of memory (%zu bytes)", n * size);
    ctn_mem_huge(q, n * size);
    return q;
}

void ctn_free(void *p) { free(p); }
