/* The first touch of a new factor, on two threads, before its first factorization.
 *
 * On the virtual machine of bench/RESULTS.md the host backs a page only when the guest
 * first writes it, at 4-8 s per GB: the K = 1000 net's 2.4 GB factor paid about 10 s of
 * its first factorization in page faults. CHOLMOD writes the factor from one thread.
 * Writing one byte of every page of its values first, the two halves on two threads,
 * takes those faults on both CPUs. The bytes written are zeros in memory the
 * factorization clears before it uses (each supernode is zeroed first), and nothing
 * else runs on the factor meanwhile. (Faulting the pages in with madvise
 * MADV_POPULATE_WRITE, on a helper beside the factorization, did not help: the host
 * still backs each page at its first write.) */
#include "core/threads.h"
#include "linalg/backends/cholmod/chol.h"

#include <stdint.h>
#include <unistd.h>

typedef struct span {
    uintptr_t a, b, page;
} span;

static void touch(void *arg)
{
    const span *s = arg;
    for (uintptr_t p = s->a; p < s->b; p += s->page) *(volatile char *)p = 0;
}

void ctn_chol_touch(chol *c)
{
    long page = sysconf(_SC_PAGESIZE);
    size_t bytes = c->L->xsize * sizeof(double);
    if (page <= 0 || !ctn_thr_allows(c->ctx, c->threads, CTN_THR_TOUCH, (double)bytes)) return;
    uintptr_t pg = (uintptr_t)page, x = (uintptr_t)c->L->x;
    uintptr_t a = (x + pg - 1) / pg * pg, b = (x + bytes) / pg * pg;
    uintptr_t mid = a + (b - a) / 2 / pg * pg;
    span s[2] = { { a, mid, pg }, { mid, b, pg } };
    ctn_thr_both(c->ctx, c->threads, CTN_THR_TOUCH, (double)bytes, touch, &s[0], &s[1]);
}
