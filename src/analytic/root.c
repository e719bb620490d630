/* Safeguarded scalar root finding: Newton steps inside a shrinking bracket, bisection
 * whenever Newton leaves the bracket or does not halve the step (Numerical Recipes'
 * rtsafe), and a bracketing search for increasing functions of a positive variable. */
#include "analytic/an.h"

#include <float.h>
#include <math.h>

#define CTN_AN_XTOL (4.0 * DBL_EPSILON)

/* Tolerance on x near x: relative, with a floor far below any physical quantity. */
static double xtol(double x) { return CTN_AN_XTOL * fabs(x) + 1e-300; }

int ctn_an_root(ctn_an_fn fn, void *data, double lo, double hi, double x0, double *root)
{
    double x = (x0 > lo && x0 < hi) ? x0 : 0.5 * (lo + hi);
    double dx_old = hi - lo;                           /* step before last */
    double dx = dx_old;                                /* last step */
    for (int it = 0; it < CTN_AN_MAXIT; it++) {
        double f, df;
        int st = fn(data, x, &f, &df);
        if (st != CTN_OK) return st;
        if (isnan(f)) return CTN_ERR_NOCONV;
        if (f == 0.0) { *root = x; return CTN_OK; }
        if (f < 0.0) lo = x; else hi = x;              /* keep f(lo) < 0 < f(hi) */
        double step = f / df, xn = x - step;           /* Newton: x - f / f' */
        dx_old = dx;
        if (!isfinite(xn) || !(xn > lo && xn < hi) || fabs(2.0 * step) > fabs(dx_old)) {
            dx = 0.5 * (hi - lo);                      /* bisection */
            xn = lo + dx;
        } else {
            dx = step;
        }
        if (fabs(dx) <= xtol(xn) || hi - lo <= xtol(xn)) { *root = xn; return CTN_OK; }
        x = xn;
    }
    return CTN_ERR_NOCONV;
}

/* Sign of the increasing function at x: -1, 0 or +1 into *sgn. */
static int sign_at(ctn_an_fn fn, void *data, double x, int *sgn)
{
    double f, df;
    int st = fn(data, x, &f, &df);
    if (st != CTN_OK) return st;
    if (isnan(f)) return CTN_ERR_NOCONV;
    *sgn = (f > 0.0) - (f < 0.0);
    return CTN_OK;
}

int ctn_an_bracket(ctn_an_fn fn, void *data, double x0, double *lo, double *hi)
{
    int sgn, st = sign_at(fn, data, x0, &sgn);
    if (st != CTN_OK) return st;
    *lo = *hi = x0;
    double factor = sgn < 0 ? 2.0 : 0.5;               /* walk towards the sign change */
    for (int it = 0; sgn != 0 && it < CTN_AN_MAXGROW; it++) {
        double x = (sgn < 0 ? *lo : *hi) * factor;
        if (!(x > 0.0) || !isfinite(x)) return CTN_ERR_NOCONV;
        int s;
        st = sign_at(fn, data, x, &s);
        if (st != CTN_OK) return st;
        if (s == 0) { *lo = *hi = x; return CTN_OK; }
        if (s < 0) *lo = x; else *hi = x;
        if (s != sgn) return CTN_OK;
    }
    return sgn == 0 ? CTN_OK : CTN_ERR_NOCONV;
}

int ctn_an_solve_pos(ctn_an_fn fn, void *data, double x0, double *root)
{
    double lo, hi;
    int st = ctn_an_bracket(fn, data, x0, &lo, &hi);
    if (st != CTN_OK) return st;
    if (lo == hi) { *root = lo; return CTN_OK; }
    return ctn_an_root(fn, data, lo, hi, x0, root);
}
