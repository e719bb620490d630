/*
 * catena.h - geometrically non-linear static analysis of 3D cable structures.
 *
 * The public API, by module:
 *   catena/core.h      context, status codes, errors
 *   catena/model.h     building a model (nodes, materials, sections, elements, loads)
 *   catena/io.h        reading .cable model files, writing results
 *   catena/solve.h     Newton-Raphson solution and its results
 */
#ifndef CATENA_H
#define CATENA_H

#include "catena/core.h"
#include "catena/model.h"
#include "catena/io.h"
#include "catena/solve.h"
#include "catena/analytic.h"
#include "catena/compare.h"
#include "catena/plot.h"

#endif
