/* Internal to linalg/: one supernode's sweeps of the parallel solve (cholmod_psolve.c)
 * for exactly 4 right-hand sides, by hand: the BLAS's dtrsm and dgemm pack the factor's
 * block before multiplying it by 4 columns, which made a 4-column solve cost as much as
 * CHOLMOD's own.
 *
 * L11: the supernode's nr x nc column-major block (the lower triangle of its diagonal
 * block over the nr - nc rows of L21); Z: its nc rows of the solution, 4 values each
 * (row-major); E: nr - nc rows of 4. */
#ifndef CTN_LINALG_PSOLVE_K4_H
#define CTN_LINALG_PSOLVE_K4_H

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CTN_PS4_AVX2 1
#else
#define CTN_PS4_AVX2 0
#endif

typedef struct ctn_ps4_kernels {
    /* Z = L11 \ Z, then E = L21 Z. */
    void (*forward)(const double *L11, int nr, int nc, double *Z, double *E);
    /* Z = L11' \ (Z - L21' E). */
    void (*backward)(const double *L11, int nr, int nc, double *Z, const double *E);
} ctn_ps4_kernels;

/* The AVX2 copy where the processor has AVX2, else the baseline's. */
void ctn_ps4_choose(ctn_ps4_kernels *k);

void ctn_ps4_forward_base(const double *L11, int nr, int nc, double *Z, double *E);
void ctn_ps4_backward_base(const double *L11, int nr, int nc, double *Z, const double *E);
#if CTN_PS4_AVX2
void ctn_ps4_forward_avx2(const double *L11, int nr, int nc, double *Z, double *E);
void ctn_ps4_backward_avx2(const double *L11, int nr, int nc, double *Z, const double *E);
#endif

#endif
