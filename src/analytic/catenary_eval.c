/* Inextensible catenary: shape, sag, tension and arc length at an abscissa x.
 * With t0 = m - u the curve parameter at the left support and a = x / (2c):
 *   y(x) = c (cosh(t0 + x/c) - cosh t0) = 2 c sinh(t0 + a) sinh(a)
 *   s(x) = c (sinh(t0 + x/c) - sinh t0) = 2 c cosh(t0 + a) sinh(a)          */
#include "analytic/an.h"

#include <math.h>

int ctn_catenary_y(const ctn_catenary *cat, double x, double *y)
{
    if (!cat || !y || ctn_an_in_range(x, cat->in.l) != CTN_OK) return CTN_ERR_INVALID;
    double a = x / (2.0 * cat->c);
    *y = 2.0 * cat->c * sinh(cat->m - cat->u + a) * sinh(a);
    return CTN_OK;
}

/* d(x) = x (chord slope - secant slope over [0, x]) with a = x/(2c), b = (l - x)/(2c):
 * chord slope sinh(m) sinhc(u), secant slope sinh(m - b) sinhc(a), expanded so that
 * no two nearly equal terms are subtracted. */
int ctn_catenary_sag(const ctn_catenary *cat, double x, double *d)
{
    if (!cat || !d || ctn_an_in_range(x, cat->in.l) != CTN_OK) return CTN_ERR_INVALID;
    double c = cat->c, a = x / (2.0 * c), b = (cat->in.l - x) / (2.0 * c), m = cat->m;
    double sa = 1.0 + ctn_an_shc1(a), sb2 = sinh(0.5 * b);       /* sinhc(a), sinh(b/2) */
    double curv = ctn_an_shc1(cat->u) - ctn_an_shc1(a) - 2.0 * sb2 * sb2 * sa;
    *d = x * (cosh(m) * sinh(b) * sa + sinh(m) * curv);
    return CTN_OK;
}

int ctn_catenary_tension(const ctn_catenary *cat, double x, double *T)
{
    if (!cat || !T || ctn_an_in_range(x, cat->in.l) != CTN_OK) return CTN_ERR_INVALID;
    *T = cat->sum.H * cosh(cat->m - cat->u + x / cat->c);
    return CTN_OK;
}

int ctn_catenary_arc(const ctn_catenary *cat, double x, double *s)
{
    if (!cat || !s || ctn_an_in_range(x, cat->in.l) != CTN_OK) return CTN_ERR_INVALID;
    double a = x / (2.0 * cat->c);
    *s = 2.0 * cat->c * cosh(cat->m - cat->u + a) * sinh(a);
    return CTN_OK;
}
