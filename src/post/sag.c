/* The sag of a chain of elements: mid-span sag along "down", largest distance from the
 * chord (sag.h; docs/format.md, "cables"). */
#include "model/model.h"
#include "post/sag.h"

#include <math.h>
#include <string.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double ctn_sag_max_from_chord(const ctn_sag_chain *c)
{
    double A[3], B[3], u[3], best = 0;
    c->point(c->ud, 0, A);
    c->point(c->ud, c->n, B);
    for (int k = 0; k < 3; k++) u[k] = B[k] - A[k];
    double len = sqrt(dot3(u, u));
    for (int k = 0; k < 3; k++) u[k] = len > 0 ? u[k] / len : 0;
    for (size_t j = 1; j < c->n; j++) {
        double P[3], d[3];
        c->point(c->ud, j, P);
        for (int k = 0; k < 3; k++) d[k] = P[k] - A[k];
        double t = dot3(d, u);
        for (int k = 0; k < 3; k++) d[k] -= t * u[k];      /* the part normal to the chord */
        best = fmax(best, sqrt(dot3(d, d)));
    }
    return best;
}

/* Plane coordinates of node j: x along h (horizontal, from M), y along down (from M). */
static void local(const ctn_sag_chain *c, size_t j, const double M[3], const double h[3], double xy[2])
{
    double P[3];
    c->point(c->ud, j, P);
    for (int k = 0; k < 3; k++) P[k] -= M[k];
    xy[0] = dot3(P, h);
    xy[1] = dot3(P, c->down);
}

/* Height at x = 0 of the parabola through nodes i - 1, i, i + 1 (Lagrange form); *y
 * unchanged if two of them share an x. */
static void parabola_at0(const ctn_sag_chain *c, size_t i, const double M[3], const double h[3], double *y)
{
    double p[3][2];
    for (int k = 0; k < 3; k++) local(c, i - 1 + (size_t)k, M, h, p[k]);
    double x0 = p[0][0], x1 = p[1][0], x2 = p[2][0];
    if (x0 == x1 || x1 == x2 || x0 == x2) return;
    *y = p[0][1] * x1 * x2 / ((x0 - x1) * (x0 - x2)) + p[1][1] * x0 * x2 / ((x1 - x0) * (x1 - x2)) +
         p[2][1] * x0 * x1 / ((x2 - x0) * (x2 - x1));
}

/* The mid-span reading along unit horizontal h, from the chord's mid-point M. */
static int read_mid(const ctn_sag_chain *c, const double M[3], const double h[3], double *sag)
{
    double a[2], b[2];
    local(c, 0, M, h, a);
    for (size_t i = 0; i < c->n; i++, a[0] = b[0], a[1] = b[1]) {
        local(c, i + 1, M, h, b);
        if (!((a[0] <= 0 && 0 <= b[0]) || (b[0] <= 0 && 0 <= a[0]))) continue;
        double t = b[0] != a[0] ? -a[0] / (b[0] - a[0]) : 0.5, y = a[1] + t * (b[1] - a[1]);
        size_t mid = t < 0.5 ? i : i + 1;                  /* the node nearest to mid-span */
        mid = mid < 1 ? 1 : mid > c->n - 1 ? c->n - 1 : mid;
        if (c->n >= 2 && !(c->kink && c->kink(c->ud, mid))) parabola_at0(c, mid, M, h, &y);
        *sag = y;
        return isfinite(y) ? CTN_OK : CTN_ERR_DOMAIN;
    }
    return CTN_ERR_DOMAIN;                                  /* folded back: never crosses */
}

int ctn_sag_mid(const ctn_sag_chain *c, double *sag)
{
    double A[3], B[3], M[3], h[3];
    c->point(c->ud, 0, A);
    c->point(c->ud, c->n, B);
    for (int k = 0; k < 3; k++) h[k] = B[k] - A[k], M[k] = 0.5 * (A[k] + B[k]);
    double up = dot3(h, c->down);
    for (int k = 0; k < 3; k++) h[k] -= up * c->down[k];   /* the chord's horizontal part */
    double l = sqrt(dot3(h, h));
    if (dot3(c->down, c->down) == 0 || !(l > 1e-9 * fabs(up)) || !(l > 0)) {
        *sag = ctn_sag_max_from_chord(c);                  /* no down, or a vertical chord */
        return isfinite(*sag) ? CTN_OK : CTN_ERR_DOMAIN;
    }
    for (int k = 0; k < 3; k++) h[k] /= l;
    return read_mid(c, M, h, sag);
}

void ctn_sag_down(const ctn_model *m, double down[3])
{
    double F[3] = { 0, 0, 0 };
    const double *g = m->gravity;
    if (!(dot3(g, g) > 0)) {
        for (size_t i = 0; i < m->ploads.n; i++)
            for (int k = 0; k < 3; k++) F[k] += m->ploads.v[i].F[k];
        g = F;
    }
    double n = sqrt(dot3(g, g));
    for (int k = 0; k < 3; k++) down[k] = n > 0 && isfinite(n) ? g[k] / n : 0;
}

void ctn_sag_node_load(const ctn_model *m, size_t i, double F[3])
{
    memset(F, 0, 3 * sizeof *F);
    for (size_t p = 0; p < m->ploads.n; p++)
        if ((size_t)m->ploads.v[p].node == i)
            for (int k = 0; k < 3; k++) F[k] += m->ploads.v[p].F[k];
}

void ctn_sag_node_loads(const ctn_model *m, double *F)
{
    memset(F, 0, 3 * m->nodes.n * sizeof *F);
    for (size_t p = 0; p < m->ploads.n; p++)
        for (int k = 0; k < 3; k++) F[3 * (size_t)m->ploads.v[p].node + (size_t)k] += m->ploads.v[p].F[k];
}
