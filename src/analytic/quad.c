/* Composite 10-point Gauss-Legendre quadrature. */
#include "analytic/an.h"

#include <math.h>

/* Nodes (positive half) and weights on [-1, 1]. */
static const double gl_x[5] = {0.973906528517171720066, 0.865063366688984510704,
                               0.679409568299024406262, 0.433395394129247190794,
                               0.148874338981631210881};
static const double gl_w[5] = {0.0666713443086881376191, 0.149451349150580593082,
                               0.219086362515982043919, 0.26926671930999635505,
                               0.295524224714752870079};

/* Add the weighted values at node t to acc[0..k-1]. */
static void add_node(ctn_an_integrand fn, void *data, int k, double t, double wt, double *acc)
{
    double f[4];
    fn(data, t, f);
    for (int j = 0; j < k; j++) acc[j] += wt * f[j];
}

void ctn_an_gauss(ctn_an_integrand fn, void *data, int k, double a, double b, double hmax,
                  double *out)
{
    double npan = ceil(fabs(b - a) / hmax);
    long n = npan < 1.0 ? 1 : npan > 1e6 ? 1000000 : (long)npan;
    double h = (b - a) / (double)n;
    for (int j = 0; j < k; j++) out[j] = 0.0;
    for (long p = 0; p < n; p++) {
        double mid = a + ((double)p + 0.5) * h, half = 0.5 * h, acc[4] = {0, 0, 0, 0};
        for (int i = 0; i < 5; i++) {
            add_node(fn, data, k, mid - half * gl_x[i], gl_w[i], acc);
            add_node(fn, data, k, mid + half * gl_x[i], gl_w[i], acc);
        }
        for (int j = 0; j < k; j++) out[j] += half * acc[j];
    }
}
