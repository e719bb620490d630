/* Preconditioned conjugate gradients (Hestenes-Stiefel, with the preconditioner M):
 *   r = b - A x,  z = M^-1 r,  p = z;  repeat: alpha = r.z / p.Ap,  x += alpha p,
 *   r -= alpha Ap,  beta = r.z' / r.z,  p = z' + beta p. */
#include "linalg/pcg.h"

#include <math.h>
#include <string.h>

void ctn_pcg_init(ctn_pcg *g, size_t n, double *work)
{
    g->n = n;
    g->r = work;
    g->z = work + n;
    g->p = work + 2 * n;
    g->q = work + 3 * n;
}

static double local_dot(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) s += a[i] * b[i];
    return s;
}

static double gdot(const ctn_pcg *g, const double *a, const double *b)
{
    return g->dot ? g->dot(g->data, a, b) : local_dot(a, b, g->n);
}

int ctn_pcg_solve(ctn_pcg *g, const double *b, double *x, double target, int maxit, double *res,
                  int *iters, int *posdef)
{
    size_t n = g->n;
    int rc = g->precond(g->data, b, x);                      /* x0 = M^-1 b */
    if (!rc) rc = g->apply(g->data, x, g->q);
    if (rc) return rc;
    for (size_t i = 0; i < n; i++) g->r[i] = b[i] - g->q[i];
    *res = sqrt(gdot(g, g->r, g->r));
    *iters = 0;
    *posdef = 1;
    double rz = 0;
    while (*res > target && *iters < maxit) {
        if ((rc = g->precond(g->data, g->r, g->z))) return rc;   /* z = M^-1 r */
        double rz1 = gdot(g, g->r, g->z);
        if (*iters == 0) memcpy(g->p, g->z, n * sizeof *g->p);   /* p holds no direction yet */
        else
            for (size_t i = 0; i < n; i++) g->p[i] = g->z[i] + rz1 / rz * g->p[i];
        rz = rz1;
        if ((rc = g->apply(g->data, g->p, g->q))) return rc;    /* q = A p */
        double pq = gdot(g, g->p, g->q);
        if (!(pq > 0)) {
            *posdef = 0;
            return CTN_OK;
        }
        double alpha = rz / pq;
        for (size_t i = 0; i < n; i++) {
            x[i] += alpha * g->p[i];
            g->r[i] -= alpha * g->q[i];
        }
        *res = sqrt(gdot(g, g->r, g->r));
        ++*iters;
    }
    return CTN_OK;
}

void ctn_sym_matvec(const ctn_pattern *p, const double *Ax, const double *x, double *y)
{
    memset(y, 0, p->n * sizeof *y);
    for (size_t j = 0; j < p->n; j++) {
        double xj = x[j], yj = 0;
        for (int k = p->colptr[j]; k < p->colptr[j + 1]; k++) {
            size_t i = (size_t)p->rowind[k];
            y[i] += Ax[k] * xj;                             /* upper entry (i, j) */
            if (i != j) yj += Ax[k] * x[i];                 /* its mirror (j, i) */
        }
        y[j] += yj;
    }
}

void ctn_sym_matvec2(const ctn_pattern *p, const double *Ax, const double *x0, const double *x1, double *y0,
                     double *y1)
{
    memset(y0, 0, p->n * sizeof *y0);
    memset(y1, 0, p->n * sizeof *y1);
    for (size_t j = 0; j < p->n; j++) {
        double a0 = x0[j], a1 = x1[j], s0 = 0, s1 = 0;
        for (int k = p->colptr[j]; k < p->colptr[j + 1]; k++) {
            size_t i = (size_t)p->rowind[k];
            y0[i] += Ax[k] * a0;
            y1[i] += Ax[k] * a1;
            if (i != j) {
                s0 += Ax[k] * x0[i];
                s1 += Ax[k] * x1[i];
            }
        }
        y0[j] += s0;
        y1[j] += s1;
    }
}

void ctn_sym_matvec_abs(const ctn_pattern *p, const double *Ax, const double *x, double *y)
{
    for (size_t j = 0; j < p->n; j++)
        for (int k = p->colptr[j]; k < p->colptr[j + 1]; k++) {
            size_t i = (size_t)p->rowind[k];
            y[i] += fabs(Ax[k] * x[j]);
            if (i != j) y[j] += fabs(Ax[k] * x[i]);
        }
}

void ctn_sym_matvec_abs_pair(const ctn_pattern *p, const double *Ax, const double *Bx, double s, const double *x,
                             double *y)
{
    for (size_t j = 0; j < p->n; j++)
        for (int k = p->colptr[j]; k < p->colptr[j + 1]; k++) {
            size_t i = (size_t)p->rowind[k];
            double a = fabs(Ax[k]) + s * fabs(Bx[k]);
            y[i] += a * fabs(x[j]);
            if (i != j) y[j] += a * fabs(x[i]);
        }
}
