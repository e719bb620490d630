/* Second-order forward jets (jet.h): the chain rule to second order, operation by
 * operation. For c = f(a, b): grad c = f_a grad a + f_b grad b and
 * hess c = f_a hess a + f_b hess b + (second derivatives of f) (grad x grad). */
#include "element/jet.h"

#include <math.h>
#include <string.h>

void ctn_jet_const(ctn_jet *c, double v)
{
    memset(c, 0, sizeof *c);
    c->v = v;
}

void ctn_jet_var(ctn_jet *c, double v, int i)
{
    ctn_jet_const(c, v);
    c->g[i] = 1;
}

void ctn_jet_lin(ctn_jet *c, double sa, const ctn_jet *a, double sb, const ctn_jet *b)
{
    c->v = sa * a->v + sb * b->v;
    for (int i = 0; i < CTN_JET_N; i++) c->g[i] = sa * a->g[i] + sb * b->g[i];
    for (int i = 0; i < CTN_JET_H; i++) c->h[i] = sa * a->h[i] + sb * b->h[i];
}

void ctn_jet_mul(ctn_jet *c, const ctn_jet *a, const ctn_jet *b)
{
    ctn_jet r;
    r.v = a->v * b->v;                                           /* (ab)'' = a b'' + b a'' + a' b' + b' a' */
    for (int i = 0; i < CTN_JET_N; i++) r.g[i] = a->v * b->g[i] + b->v * a->g[i];
    for (int i = 0, k = 0; i < CTN_JET_N; i++)
        for (int j = i; j < CTN_JET_N; j++, k++)
            r.h[k] = a->v * b->h[k] + b->v * a->h[k] + a->g[i] * b->g[j] + a->g[j] * b->g[i];
    *c = r;
}

void ctn_jet_fn(ctn_jet *c, const ctn_jet *a, double f0, double f1, double f2)
{
    ctn_jet r;
    r.v = f0;                                                    /* f(a)'' = f' a'' + f'' a' a' */
    for (int i = 0; i < CTN_JET_N; i++) r.g[i] = f1 * a->g[i];
    for (int i = 0, k = 0; i < CTN_JET_N; i++)
        for (int j = i; j < CTN_JET_N; j++, k++) r.h[k] = f1 * a->h[k] + f2 * a->g[i] * a->g[j];
    *c = r;
}

void ctn_jet_dot(ctn_jet *c, const ctn_jet a[3], const ctn_jet b[3])
{
    ctn_jet t;
    ctn_jet_mul(c, &a[0], &b[0]);
    for (int k = 1; k < 3; k++) {
        ctn_jet_mul(&t, &a[k], &b[k]);
        ctn_jet_lin(c, 1, c, 1, &t);
    }
}

void ctn_jet_cross(ctn_jet c[3], const ctn_jet a[3], const ctn_jet b[3])
{
    ctn_jet r[3], p, q;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;                    /* c_k = a_i b_j - a_j b_i */
        ctn_jet_mul(&p, &a[i], &b[j]);
        ctn_jet_mul(&q, &a[j], &b[i]);
        ctn_jet_lin(&r[k], 1, &p, -1, &q);
    }
    memcpy(c, r, sizeof r);
}

double ctn_jet_unit(ctn_jet c[3], const ctn_jet a[3])
{
    ctn_jet n2, inv;
    ctn_jet_dot(&n2, a, a);
    double n = sqrt(n2.v);                                       /* 1/sqrt(s): -s^-3/2 / 2, 3 s^-5/2 / 4 */
    if (!(n > 0)) return 0;
    ctn_jet_fn(&inv, &n2, 1 / n, -0.5 / (n * n2.v), 0.75 / (n * n2.v * n2.v));
    for (int k = 0; k < 3; k++) ctn_jet_mul(&c[k], &a[k], &inv);
    return n;
}
