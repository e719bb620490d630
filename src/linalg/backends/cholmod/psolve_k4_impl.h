/* A supernode's forward and backward sweeps for blocks of 4 right-hand sides
 * (psolve_k4.h): the body of psolve_k4.c and psolve_k4_avx2.c, compiled once for
 * x86-64's baseline and once for AVX2, CTN_PS4(name) naming each copy's functions (no
 * include guard: a file includes it once). The 4 values of a row are one vector; every entry of the factor is read
 * once per sweep and multiplies a whole row. Columns go 4 at a time, so a row of E or Z
 * is loaded and stored once for 4 columns of the factor; the backward sweep's 4
 * accumulators are independent, so its sums do not wait on each other. GCC's vector
 * extension: 4 doubles, one AVX2 register (two SSE2 ones on the baseline). */

#include <stddef.h>
#include <string.h>

typedef double v4 __attribute__((vector_size(32)));
typedef double v4u __attribute__((vector_size(32), aligned(8), may_alias));   /* unaligned */

#define LD(p) (*(const v4u *)(p))
#define ST(p, v) (*(v4u *)(p) = (v))
#define BC(x) ((v4){ (x), (x), (x), (x) })

/* The block's first 64 KB asked for at once: most supernodes are a few KB, too short for
 * the hardware's stream prefetchers, and 4 columns read side by side waited for each line
 * in turn (the 4-column solve of the K = 400 net: 15-20 % faster). */
#define CTN_PS4_PREFETCH 65536
static inline void prefetch_block(const double *L11, int nr, int nc)
{
    const char *b = (const char *)L11;
    size_t bytes = (size_t)nr * (size_t)nc * sizeof(double);
    if (bytes > CTN_PS4_PREFETCH) bytes = CTN_PS4_PREFETCH;
    for (size_t at = 0; at < bytes; at += 64) __builtin_prefetch(b + at);
}

void CTN_PS4(forward)(const double *L11, int nr, int nc, double *Z, double *E)
{
    const size_t ld_ = (size_t)nr;
    prefetch_block(L11, nr, nc);
    const int m = nr - nc;
    memset(E, 0, (size_t)(m > 0 ? m : 0) * 4 * sizeof(double));
    int u = 0;
    for (; u + 4 <= nc; u += 4) {
        const double *c0 = L11 + ld_ * (size_t)u, *c1 = c0 + ld_, *c2 = c1 + ld_, *c3 = c2 + ld_;
        double *z = Z + 4 * (size_t)u;
        v4 z0 = LD(z) / BC(c0[u]);
        v4 z1 = (LD(z + 4) - BC(c0[u + 1]) * z0) / BC(c1[u + 1]);
        v4 z2 = (LD(z + 8) - BC(c0[u + 2]) * z0 - BC(c1[u + 2]) * z1) / BC(c2[u + 2]);
        v4 z3 = (LD(z + 12) - BC(c0[u + 3]) * z0 - BC(c1[u + 3]) * z1 - BC(c2[u + 3]) * z2) / BC(c3[u + 3]);
        ST(z, z0);
        ST(z + 4, z1);
        ST(z + 8, z2);
        ST(z + 12, z3);
        for (int t = u + 4; t < nc; t++) {
            double *y = Z + 4 * (size_t)t;
            ST(y, LD(y) - (BC(c0[t]) * z0 + BC(c1[t]) * z1 + BC(c2[t]) * z2 + BC(c3[t]) * z3));
        }
        const double *l0 = c0 + nc, *l1 = c1 + nc, *l2 = c2 + nc, *l3 = c3 + nc;
        for (int i = 0; i < m; i++) {
            double *e = E + 4 * (size_t)i;
            ST(e, LD(e) + (BC(l0[i]) * z0 + BC(l1[i]) * z1 + BC(l2[i]) * z2 + BC(l3[i]) * z3));
        }
    }
    for (; u < nc; u++) {
        const double *c0 = L11 + ld_ * (size_t)u;
        v4 z0 = LD(Z + 4 * (size_t)u) / BC(c0[u]);
        ST(Z + 4 * (size_t)u, z0);
        for (int t = u + 1; t < nc; t++) ST(Z + 4 * (size_t)t, LD(Z + 4 * (size_t)t) - BC(c0[t]) * z0);
        for (int i = 0; i < m; i++) ST(E + 4 * (size_t)i, LD(E + 4 * (size_t)i) + BC(c0[nc + i]) * z0);
    }
}

/* a += sum over the rows t in [0, rows) of column c's entry p_c[t] times row t of Y. */
static inline void dots(const double *p0, const double *p1, const double *p2, const double *p3, int rows,
                        const double *Y, v4 a[4])
{
    v4 a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3];
    for (int t = 0; t < rows; t++) {
        v4 y = LD(Y + 4 * (size_t)t);
        a0 += BC(p0[t]) * y;
        a1 += BC(p1[t]) * y;
        a2 += BC(p2[t]) * y;
        a3 += BC(p3[t]) * y;
    }
    a[0] = a0;
    a[1] = a1;
    a[2] = a2;
    a[3] = a3;
}

void CTN_PS4(backward)(const double *L11, int nr, int nc, double *Z, const double *E)
{
    const size_t ld_ = (size_t)nr;
    prefetch_block(L11, nr, nc);
    int u = nc;
    while (u > 0) {
        const int k = u >= 4 ? 4 : u, u0 = u - k;          /* columns u0 .. u - 1 */
        const double *cols[4];
        v4 a[4];
        for (int c = 0; c < k; c++) cols[c] = L11 + ld_ * (size_t)(u0 + c);
        for (int c = k; c < 4; c++) cols[c] = cols[0];       /* (their sums unused) */
        for (int c = 0; c < 4; c++) a[c] = BC(0);
        dots(cols[0] + u, cols[1] + u, cols[2] + u, cols[3] + u, nc - u, Z + 4 * (size_t)u, a);  /* below the group */
        dots(cols[0] + nc, cols[1] + nc, cols[2] + nc, cols[3] + nc, nr - nc, E, a);           /* L21's rows */
        for (int c = k - 1; c >= 0; c--) {                  /* the group's own triangle */
            const int r = u0 + c;
            v4 s = LD(Z + 4 * (size_t)r) - a[c];
            for (int t = r + 1; t < u; t++) s -= BC(cols[c][t]) * LD(Z + 4 * (size_t)t);
            ST(Z + 4 * (size_t)r, s / BC(cols[c][r]));
        }
        u = u0;
    }
}
