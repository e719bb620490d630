/* Internal: second-order forward jets over CTN_JET_N variables: a value with its
 * gradient and its Hessian (packed upper triangle, ctn_packed_index). A function of a
 * few variables written with these operations gives its exact gradient and Hessian
 * (the beam's energy, beam3.c: the internal forces and the consistent tangent). */
#ifndef CTN_ELEMENT_JET_H
#define CTN_ELEMENT_JET_H

#define CTN_JET_N 9                                  /* variables */
#define CTN_JET_H (CTN_JET_N * (CTN_JET_N + 1) / 2)  /* Hessian entries */

typedef struct ctn_jet {
    double v;                 /* value */
    double g[CTN_JET_N];      /* gradient */
    double h[CTN_JET_H];      /* Hessian, packed upper triangle */
} ctn_jet;

void ctn_jet_const(ctn_jet *c, double v);                          /* c = v */
void ctn_jet_var(ctn_jet *c, double v, int i);                     /* c = variable i at v */
void ctn_jet_lin(ctn_jet *c, double sa, const ctn_jet *a, double sb, const ctn_jet *b); /* c = sa a + sb b */
void ctn_jet_mul(ctn_jet *c, const ctn_jet *a, const ctn_jet *b);  /* c = a b (c may alias) */
/* c = f(a), given f(a.v), f'(a.v), f''(a.v) (c may alias a). */
void ctn_jet_fn(ctn_jet *c, const ctn_jet *a, double f0, double f1, double f2);
void ctn_jet_dot(ctn_jet *c, const ctn_jet a[3], const ctn_jet b[3]);        /* c = a . b */
void ctn_jet_cross(ctn_jet c[3], const ctn_jet a[3], const ctn_jet b[3]);    /* c = a x b */
/* c = a / |a| (3 jets); returns |a|.v. */
double ctn_jet_unit(ctn_jet c[3], const ctn_jet a[3]);

#endif
