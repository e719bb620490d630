/* Results of one element rebuilt from a step's displacements: a catenary's forces,
 * tensions and sag, and the deformed shape of any element (public accessors for the
 * writers). */
#include "element/catenary.h"
#include "problem/solution.h"

#include <math.h>
#include <string.h>

/* X and u of element i's nodes at step k into X, u (3 per node); its node count. */
static int gather(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, double *X, double *u)
{
    const ctn_element *e = &m->elements.v[i];
    const int *nd = ctn_elem_nodes(m, i);
    for (int a = 0; a < e->nnodes; a++)
        for (int j = 0; j < 3; j++) {
            X[3 * a + j] = m->nodes.v[nd[a]].X[j];
            u[3 * a + j] = s->steps[k].d[3 * (size_t)nd[a] + (size_t)j];
        }
    return e->nnodes;
}

static int valid(const ctn_model *m, const ctn_solution *s, size_t k, size_t i)
{
    return m && s && k < s->nsteps && i < m->elements.n && i < s->ne && m->nodes.n == s->nn;
}

/* The catenary of element i at step k (its props, state, unit horizontal chord). */
static int catenary_at(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, ctn_catenary_props *p,
                       ctn_ecat *c, double ex[3], double X[6], double u[6], int *bar)
{
    if (!valid(m, s, k, i) || ctn_element_family(m->elements.v[i].type) != &ctn_catenary2_ops) return CTN_ERR_INVALID;
    ctn_catenary2_ops.setup(m, i, p);
    double dT = ctn_model_element_temperature(m, k, i);                          /* the step's length */
    if (s->of_case) {                                                           /* or the case's */
        int tags[CTN_MAX_CASE_TERMS];
        double f[CTN_MAX_CASE_TERMS];
        ctn_loadsel sel;
        if (ctn_model_case_terms(m, s->of_case - 1) > CTN_MAX_CASE_TERMS) return CTN_ERR_INVALID;
        ctn_model_case_sel(m, s->of_case - 1, &sel, tags, f);
        dT = ctn_model_sel_element_temperature(m, &sel, i);
    }
    ctn_catenary2_ops.temperature(p, dT);
    gather(m, s, k, i, X, u);
    return ctn_catenary_state(p, X, u, c, ex, bar) ? CTN_ERR_NOCONV : CTN_OK;
}

int ctn_solution_catenary(const ctn_model *m, const ctn_solution *s, size_t k, size_t i,
                          ctn_catenary_result *out)
{
    ctn_catenary_props p;
    ctn_ecat c;
    double ex[3], X[6], u[6];
    int bar, rc;
    if (!out || out->size < sizeof *out) return CTN_ERR_INVALID;
    if ((rc = catenary_at(m, s, k, i, &p, &c, ex, X, u, &bar))) return rc;
    memset(out, 0, sizeof *out);
    out->size = sizeof *out;
    if (bar) {                                         /* the bar: N along the chord */
        double C = hypot(c.l, c.h), N = C > p.l0 ? p.EA * (C / p.l0 - 1) : 0;
        out->H = N * c.l / C;
        out->tension[0] = out->tension[1] = N;
        for (int j = 0; j < 3; j++) {
            double a = (X[3 + j] - X[j]) + (u[3 + j] - u[j]);
            out->force[0][j] = N * a / C;
            out->force[1][j] = -N * a / C;
        }
        out->length = fmax(C, p.l0);
        return CTN_OK;
    }
    out->H = c.H;
    out->V[0] = c.Va;
    out->V[1] = c.Vb;
    out->tension[0] = hypot(c.H, c.Va);
    out->tension[1] = hypot(c.H, c.Vb);
    for (int j = 0; j < 3; j++) {
        out->force[0][j] = c.H * ex[j] - c.Va * p.up[j];
        out->force[1][j] = -c.H * ex[j] - c.Vb * p.up[j];
    }
    out->sag = ctn_ecat_sag(&c);
    out->length = ctn_ecat_length(&c);
    return isfinite(out->sag) ? CTN_OK : CTN_ERR_NOCONV;
}

/* n points along a catenary, at s = j L / (n - 1). */
static int catenary_shape(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, int n, double *xyz)
{
    ctn_catenary_props p;
    ctn_ecat c;
    double ex[3], X[6], u[6];
    int bar, rc = catenary_at(m, s, k, i, &p, &c, ex, X, u, &bar);
    for (int j = 0; !rc && j < n; j++) {
        double t = (double)j / (n - 1), x = 0, z = 0;
        if (!bar) ctn_ecat_point(&c, t * p.l0, &x, &z);
        for (int d = 0; d < 3; d++) {
            double x1 = X[d] + u[d], a = (X[3 + d] - X[d]) + (u[3 + d] - u[d]);
            xyz[3 * j + d] = bar ? x1 + t * a : x1 + x * ex[d] + z * p.up[d];
        }
    }
    if (!rc && !bar)                                   /* the last point is node 2 */
        for (int d = 0; d < 3; d++) xyz[3 * (n - 1) + d] = X[3 + d] + u[3 + d];
    return rc;
}

int ctn_solution_element_shape(const ctn_model *m, const ctn_solution *s, size_t k, size_t i,
                               int n, double *xyz)
{
    if (!valid(m, s, k, i) || n < 2 || !xyz) return CTN_ERR_INVALID;
    if (ctn_element_family(m->elements.v[i].type) == &ctn_catenary2_ops) return catenary_shape(m, s, k, i, n, xyz);
    double X[3 * CTN_ELEM_MAX_NODES], u[3 * CTN_ELEM_MAX_NODES], cum[CTN_ELEM_MAX_NODES], x[3 * CTN_ELEM_MAX_NODES];
    int nn = gather(m, s, k, i, X, u);
    cum[0] = 0;                                        /* arc length at each node */
    for (int a = 0; a < nn; a++)
        for (int d = 0; d < 3; d++) x[3 * a + d] = X[3 * a + d] + u[3 * a + d];
    for (int a = 1; a < nn; a++)
        cum[a] = cum[a - 1] + hypot(hypot(x[3 * a] - x[3 * a - 3], x[3 * a + 1] - x[3 * a - 2]), x[3 * a + 2] - x[3 * a - 1]);
    for (int j = 0, a = 0; j < n; j++) {
        double t = cum[nn - 1] * j / (n - 1);
        while (a + 2 < nn && cum[a + 1] < t) a++;
        double seg = cum[a + 1] - cum[a], r = seg > 0 ? fmin(fmax((t - cum[a]) / seg, 0), 1) : 0;
        for (int d = 0; d < 3; d++) xyz[3 * j + d] = x[3 * a + d] + r * (x[3 * a + 3 + d] - x[3 * a + d]);
    }
    return CTN_OK;
}
