/* The 4-column supernode sweeps compiled for AVX2: one register holds a row's 4 values
 * (2.6x CHOLMOD's 4-column solve on one thread, against 1.4x for the SSE2 copy; bench/
 * RESULTS.md). Chosen at run time by ctn_ps4_choose, on processors that have it. */
#include "linalg/backends/cholmod/psolve_k4.h"

#if CTN_PS4_AVX2
#pragma GCC target("avx2")
#define CTN_PS4(name) ctn_ps4_##name##_avx2
#include "linalg/backends/cholmod/psolve_k4_impl.h"
#else
typedef int ctn_ps4_no_avx2;     /* (ISO C: a translation unit declares something) */
#endif
