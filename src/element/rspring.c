/* Two-node linear rotational spring: the moment k (theta2 - theta1) between the
 * rotations of its two nodes, about x, y and z alike; no force on the translations.
 * A family of 6 DOFs per node (x, y, z, rx, ry, rz), the test family of the rotation DOFs
 * (small rotations: the rotation vectors are added, as the DOF map's default update).
 *   U = k |theta2 - theta1|^2 / 2,  M2 = -M1 = k (theta2 - theta1),
 *   K = k [[I, -I], [-I, I]] on the rotations, zero on the translations. */
#include "element/element.h"

#include <math.h>
#include <string.h>

typedef struct rspring_props {
    double k;           /* rotational stiffness [force length/rad] */
} rspring_props;

/* Packed 12 x 12 index of rotation j of node a with rotation j of node b (a <= b). */
static int rot_index(int a, int b, int j) { return ctn_packed_index(12, 6 * a + 3 + j, 6 * b + 3 + j); }

static int rspring_eval(const void *props, unsigned mode, const double *X, const double *u, double *f,
                        double *K, ctn_elem_state *out)
{
    const rspring_props *p = props;
    double c[3], U = 0;
    (void)mode;
    for (int j = 0; j < 3; j++) c[j] = (X[3 + j] - X[j]) + (u[6 + j] - u[j]);
    memset(f, 0, 12 * sizeof(double));
    for (int j = 0; j < 3; j++) {
        double m = p->k * (u[9 + j] - u[3 + j]);     /* the moment on node 2 */
        f[3 + j] = -m;
        f[9 + j] = m;
        U += 0.5 * m * (u[9 + j] - u[3 + j]);
    }
    if (K) {
        memset(K, 0, (size_t)ctn_packed_size(12) * sizeof(double));
        for (int j = 0; j < 3; j++) {
            K[rot_index(0, 0, j)] = p->k;
            K[rot_index(1, 1, j)] = p->k;
            K[rot_index(0, 1, j)] = -p->k;
        }
    }
    if (out) *out = (ctn_elem_state){ sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), 0, 0, 0, U, 0 };
    return 0;
}

static int rspring_check(const ctn_model *m, const ctn_element *e)
{
    if (!isfinite(e->par[0]) || e->par[0] <= 0)
        return ctn_model_error(m, CTN_ERR_MODEL, "rspring %d: k must be positive and finite (got %g)", e->id, e->par[0]);
    return CTN_OK;
}

static void rspring_params(const ctn_element_spec *s, double *par) { par[0] = s->k; }

static void rspring_setup(const ctn_model *m, size_t e, void *props)
{
    ((rspring_props *)props)->k = m->elements.v[e].par[0];
}

static double rspring_stiffness(const void *props) { return ((const rspring_props *)props)->k; }

const ctn_element_ops ctn_rspring_ops = {
    .name = "rspring", .nnodes = 2, .ndof_node = 6, .props_size = sizeof(rspring_props), .flags = 0,
    .check = rspring_check, .params = rspring_params, .setup = rspring_setup, .eval = rspring_eval,
    .stiffness = rspring_stiffness,
};
