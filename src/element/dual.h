/* Internal: first-order forward duals over CTN_DUAL_N variables (a value and its
 * gradient), inline. A function written with these operations gives its exact first
 * derivatives: the beam's closed-form internal forces written on them give the
 * consistent tangent as their Jacobian (beam3_cf.c), at a ninth of the cost of the
 * second-order jets (jet.h) that the energy took. */
#ifndef CTN_ELEMENT_DUAL_H
#define CTN_ELEMENT_DUAL_H

#define CTN_DUAL_N 9

typedef struct ctn_dual {
    double v;               /* value */
    double g[CTN_DUAL_N];   /* gradient */
} ctn_dual;

static inline ctn_dual ctn_dual_const(double v)
{
    ctn_dual c = { v, { 0 } };
    return c;
}

static inline ctn_dual ctn_dual_var(double v, int i)
{
    ctn_dual c = ctn_dual_const(v);
    c.g[i] = 1;
    return c;
}

/* sa a + sb b */
static inline ctn_dual ctn_dual_lin(double sa, ctn_dual a, double sb, ctn_dual b)
{
    ctn_dual c;
    c.v = sa * a.v + sb * b.v;
    for (int i = 0; i < CTN_DUAL_N; i++) c.g[i] = sa * a.g[i] + sb * b.g[i];
    return c;
}

static inline ctn_dual ctn_dual_add(ctn_dual a, ctn_dual b) { return ctn_dual_lin(1, a, 1, b); }
static inline ctn_dual ctn_dual_sub(ctn_dual a, ctn_dual b) { return ctn_dual_lin(1, a, -1, b); }
static inline ctn_dual ctn_dual_scale(double s, ctn_dual a) { return ctn_dual_lin(s, a, 0, a); }

static inline ctn_dual ctn_dual_mul(ctn_dual a, ctn_dual b)
{
    ctn_dual c;
    c.v = a.v * b.v;
    for (int i = 0; i < CTN_DUAL_N; i++) c.g[i] = a.v * b.g[i] + b.v * a.g[i];
    return c;
}

/* f(a) given f(a.v) and f'(a.v) */
static inline ctn_dual ctn_dual_fn(ctn_dual a, double f0, double f1)
{
    ctn_dual c;
    c.v = f0;
    for (int i = 0; i < CTN_DUAL_N; i++) c.g[i] = f1 * a.g[i];
    return c;
}

static inline ctn_dual ctn_dual_dot(const ctn_dual a[3], const ctn_dual b[3])
{
    return ctn_dual_add(ctn_dual_add(ctn_dual_mul(a[0], b[0]), ctn_dual_mul(a[1], b[1])), ctn_dual_mul(a[2], b[2]));
}

static inline void ctn_dual_cross(ctn_dual c[3], const ctn_dual a[3], const ctn_dual b[3])
{
    ctn_dual r[3];
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        r[k] = ctn_dual_sub(ctn_dual_mul(a[i], b[j]), ctn_dual_mul(a[j], b[i]));
    }
    c[0] = r[0];
    c[1] = r[1];
    c[2] = r[2];
}

#endif
