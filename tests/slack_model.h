/* A model whose equilibrium is not stable: a taut cable, and node 4 hanging from it by a
 * slack tension-only strut, unloaded, in equilibrium, but with no stiffness at all (a
 * semi-definite tangent at node 4). */
#ifndef CTN_TEST_SLACK_MODEL_H
#define CTN_TEST_SLACK_MODEL_H

static const char *slack_text =
    "material rope E=1e8 tension-only\n"
    "section s material=rope A=1e-4\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 10 0 0\n"
    "node 3 20 0 0 fix=xyz\n"
    "node 4 10 0 -3\n"
    "element 1 1 2 section=s l0=9.99\n"
    "element 2 2 3 section=s l0=9.99\n"
    "element 3 2 4 section=s l0=3.5\n"
    "load 2 0 0 -1\n";

#endif
