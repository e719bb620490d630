/* The force-density start of a net (Schek's method): the free nodes placed where the
 * members' start forces, held as force densities, balance the first step's loads. */
#ifndef CTN_START_FDENSITY_H
#define CTN_START_FDENSITY_H

#include "problem/problem.h"

/* Place the free nodes of a net of cables (every member a two-node flexible element, a
 * free node joining three or more; no rotations, follower loads, temperatures or
 * prescribed displacements) on the linear equilibrium of the densities
 * q = N / l of the start state d under the first step's dead loads, when that state
 * predicts a lower residual than the start; *taken = 1 if it did (d changed). Only
 * CTN_ERR_NOMEM fails: a net the densities do not hold keeps its start. */
int ctn_fdensity_start(ctn_problem *p, double *d, int *taken);

#endif
