/* Shared by the catenary element's tests: a reproducible uniform random number and the
 * properties of a catenary element built by hand (no model). */
#ifndef CTN_TEST_CATENARY_PROPS_H
#define CTN_TEST_CATENARY_PROPS_H

#include "element/catenary.h"

#include <string.h>

static double urand(unsigned *seed, double lo, double hi)
{
    *seed = *seed * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*seed >> 8) & 0xffffff) / (double)0xffffff;
}

/* Properties of a catenary of length L, rigidity EA, weight W along unit gravity g. */
static ctn_catenary_props props(double L, double EA, double W, const double g[3])
{
    ctn_catenary_props p;
    memset(&p, 0, sizeof p);
    p.EA = EA;
    p.l0 = p.l0_ref = L;
    p.A = 1;
    p.W = W;
    for (int i = 0; i < 3; i++) p.up[i] = W > 0 ? -g[i] : 0;
    return p;
}

#endif
