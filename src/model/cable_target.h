/* Internal: cables set by a target (H=, sag=, tension=): the checks on the target and
 * the first length of the outer root find (cable_target.c). */
#ifndef CTN_MODEL_CABLE_TARGET_H
#define CTN_MODEL_CABLE_TARGET_H

#include "model/model.h"

/* For a cable with a target: check that the target can be asked of this cable (a model
 * error otherwise) and put a first unstressed length in *length, from the taut parabola
 * under the section's weight. Without a target: CTN_OK, *length unchanged. */
int ctn_cable_target_check(const ctn_model *m, const ctn_cable_spec *s, const char *section, const double A[3],
                           const double B[3], double chord, double *length);

#endif
