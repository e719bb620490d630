/* use_cli_heap(): the catena command's process-wide memory settings (app/main.c), for a
 * program that asks for them. The package never calls it: a library leaves the process
 * as it found it, and these settings belong to the whole process (every allocation of
 * every module), cannot be undone, and trade memory returned to the system for fewer
 * page faults in large solves:
 *   - glibc's heap for every block (no mmap per large block) and never trimmed, so that
 *     a freed factor's pages are reused instead of faulted in again;
 *   - SuiteSparse's allocator (CHOLMOD's factor and work arrays) advised for transparent
 *     huge pages (ctn_mem_huge), as the library advises its own;
 *   - the heap's address range reserved once at the largest block the system lends and
 *     advised for huge pages. */
#include "pycatena.h"

#include <SuiteSparse_config.h>
#include <malloc.h>
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

#define HUGE_HEAP_MIN ((size_t)256 << 20)

PyObject *pyctn_use_cli_heap(PyObject *module, PyObject *noargs)
{
    (void)module;
    (void)noargs;
#if defined(M_MMAP_MAX) && !defined(__SANITIZE_ADDRESS__)
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);
    SuiteSparse_config.malloc_func = huge_malloc;
    SuiteSparse_config.calloc_func = huge_calloc;
    SuiteSparse_config.realloc_func = huge_realloc;
    SuiteSparse_config.free_func = free;
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) {
        size_t want = (size_t)pages * (size_t)page, cap = (size_t)64 << 30, n = want < cap ? want : cap;
        void *p = malloc(n);
        while (!p && n / 2 >= HUGE_HEAP_MIN) p = malloc(n /= 2);
        ctn_mem_huge(p, n);
        free(p);
    }
    Py_RETURN_TRUE;
#else
    Py_RETURN_FALSE;
#endif
}
