/* ctn_process_heap (catena/core.h): the catena command's process-wide memory settings,
 * for the programs that ask (the command itself, Python's catena.use_cli_heap).
 *
 * Large arrays (patterns, orderings' workspace, factors, result vectors) from the heap,
 * and kept by the process after free instead of returned to the system: glibc maps every
 * block above 32 MiB afresh and unmaps it on free, so each symbolic analysis of a big
 * net paid its arrays' page faults again (measured on the K = 400 net: the orderings'
 * analyses 3.6 s of CPU with fresh mappings, 1.7 s without). CHOLMOD's blocks advised
 * for transparent huge pages as the library's own are (ctn_mem_huge): on the VM of
 * bench/RESULTS.md a page fault costs 16-32 us, and the K = 1000 net's 5.7 GB were 1.1
 * million of them. Both are process-wide: the process, not the library, sets them. */
#define _GNU_SOURCE 1
#include "catena/core.h"

#include <SuiteSparse_config.h>
#include <malloc.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void *huge_malloc(size_t n)
{
    void *p = malloc(n);
    ctn_mem_huge(p, n);
    return p;
}

static void *huge_calloc(size_t n, size_t size)
{
    void *p = calloc(n, size);
    if (p) ctn_mem_huge(p, n * size);        /* calloc checked n * size */
    return p;
}

static void *huge_realloc(void *p, size_t n)
{
    void *q = realloc(p, n);
    ctn_mem_huge(q, n);
    return q;
}

/* The whole heap advised for huge pages, the small blocks too: with the settings above
 * every block comes from the heap and the heap is never trimmed, so a block as large as
 * the system lends (the machine's memory, or half, ...), advised and freed at once,
 * leaves the heap's address range reserved (nothing is touched) and advised for what
 * follows. Not under a memory checker (AddressSanitizer's and valgrind's allocators are
 * not glibc's heap). */
#define CTN_HUGE_HEAP_MIN ((size_t)256 << 20)
static void huge_heap(void)
{
#if defined(M_MMAP_MAX) && !defined(__SANITIZE_ADDRESS__)
    const char *pre = getenv("LD_PRELOAD");
    if (pre && strstr(pre, "vgpreload")) return;
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page <= 0) return;
    size_t want = (size_t)pages * (size_t)page, cap = (size_t)64 << 30, n = want < cap ? want : cap;
    void *p = malloc(n);
    while (!p && n / 2 >= CTN_HUGE_HEAP_MIN) p = malloc(n /= 2);    /* what the system lends */
    ctn_mem_huge(p, n);
    free(p);
#endif
}

int ctn_process_heap(void)
{
    SuiteSparse_config.malloc_func = huge_malloc;
    SuiteSparse_config.calloc_func = huge_calloc;
    SuiteSparse_config.realloc_func = huge_realloc;
    SuiteSparse_config.free_func = free;
#ifdef M_MMAP_MAX
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);           /* never trim */
    huge_heap();
    return 1;
#else
    return 0;
#endif
}
