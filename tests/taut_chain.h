/* Shared by tests: the paper's cable between supports 200 m apart, 200.334 m long (taut),
 * as a chain of N members, as model text (a string literal: TAUT_CHAIN(3000)). */
#ifndef CTN_TEST_TAUT_CHAIN_H
#define CTN_TEST_TAUT_CHAIN_H

#define TAUT_CHAIN(N)                                                                \
    "units kN m\n"                                                                   \
    "material steel E=2.0e8\n"                                                       \
    "section strand material=steel A=3.14e-4 w=0.1\n"                                \
    "gravity 0 -1 0\n"                                                               \
    "node 1 0 0 0 fix=xyz\n"                                                         \
    "node 2 200 0 0 fix=xyz\n"                                                       \
    "cable 1 2 section=strand n=" #N " length=200.3340\n"

#endif
