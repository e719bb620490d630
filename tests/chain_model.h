/* Shared by tests: the paper's cable (200 m span, 250.8777 m long, E = 200 GPa,
 * A = 3.14 cm^2, w = 0.1 kN/m) as a chain of n members between two fixed ends, started
 * on the catenary. NULL-safe for the caller's CHECKs: the model is NULL if it failed. */
#ifndef CTN_TEST_CHAIN_MODEL_H
#define CTN_TEST_CHAIN_MODEL_H

#include "catena.h"

static ctn_model *chain_model(ctn_ctx *ctx, int n)
{
    const double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = n, .length = 250.8777, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3,
                            .start = CTN_START_CATENARY, .prestress = CTN_PRESTRESS_NONE };
    ctn_model *m = NULL;
    if (ctn_model_create(ctx, &m)) return NULL;
    ctn_model_set_gravity(m, g);
    ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0);
    ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1);
    ctn_model_add_node(m, 1, A, CTN_FIX_ALL);
    ctn_model_add_node(m, 2, B, CTN_FIX_ALL);
    if (ctn_model_add_cable(m, 1, 2, "strand", &spec, NULL, NULL)) ctn_model_destroy(&m);
    return m;
}

#endif
