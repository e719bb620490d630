/* The 4-column supernode sweeps for x86-64's baseline, and the choice between them and
 * the AVX2 copy (psolve_k4.h). */
#include "linalg/backends/cholmod/psolve_k4.h"

#define CTN_PS4(name) ctn_ps4_##name##_base
#include "linalg/backends/cholmod/psolve_k4_impl.h"

void ctn_ps4_choose(ctn_ps4_kernels *k)
{
    k->forward = ctn_ps4_forward_base;
    k->backward = ctn_ps4_backward_base;
#if CTN_PS4_AVX2
    __builtin_cpu_init();                          /* idempotent; safe before any constructor ran */
    if (__builtin_cpu_supports("avx2")) {
        k->forward = ctn_ps4_forward_avx2;
        k->backward = ctn_ps4_backward_avx2;
    }
#endif
}
