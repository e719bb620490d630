/* An hload on the deformed projection: the span's nodal loads are those of the FEA's
 * deformed geometry (q times half the horizontal projection of each adjacent segment, down
 * along the plane's y), so the funicular polygons, which take the nodal loads as given,
 * are solved again with the loads the FEA balanced. The distributed forms (catenary,
 * parabola) take the total, which does not change. */
#include "compare/cmp.h"

#include <math.h>
#include <string.h>

/* Horizontal projection of segment j (nodes j, j + 1) at displacements d (or the
 * reference positions when d is NULL). */
static double projection(const ctn_compare *c, const double *d, size_t j)
{
    double p[3];
    for (int k = 0; k < 3; k++) {
        double a = c->Xref[3 * j + (size_t)k] + (d ? d[3 * c->node[j] + (size_t)k] : 0);
        double b = c->Xref[3 * (j + 1) + (size_t)k] + (d ? d[3 * c->node[j + 1] + (size_t)k] : 0);
        p[k] = b - a;
    }
    double v = ctn_cmp_dot3(p, c->span.ey), h2 = ctn_cmp_dot3(p, p) - v * v;
    return sqrt(h2 > 0 ? h2 : 0);
}

int ctn_cmp_follow_loads(ctn_compare *c, const double *d)
{
    size_t n = c->span.n;
    if (!c->Pref) {                                  /* first FEA: keep the reference loads */
        if (!(c->Pref = ctn_malloc(c->ctx, 2 * (n + 1), sizeof(double)))) return CTN_ERR_NOMEM;
        memcpy(c->Pref, c->P, 2 * (n + 1) * sizeof(double));
    }
    memcpy(c->P, c->Pref, 2 * (n + 1) * sizeof(double));
    for (size_t j = 0; j < n; j++) {
        double dp = 0.5 * c->span.q * (projection(c, d, j) - projection(c, NULL, j));
        c->P[2 * j + 1] -= dp;                   /* the load acts along -y */
        c->P[2 * (j + 1) + 1] -= dp;
    }
    c->W = 0;
    for (size_t j = 0; j <= n; j++) c->W -= c->P[2 * j + 1];
    return ctn_cmp_solve_forms(c);
}
