/* Internal: cables set by a target (H=, sag=, tension=): the checks on the target and
 * the first length of the outer root find (cable_target.c). */
#ifndef CTN_MODEL_CABLE_TARGET_H
#define CTN_MODEL_CABLE_TARGET_H

#include "model/model.h"

/* For a cable (or a catenary element) with a target: check that the target can be asked
 * of it (a model error starting "what: " otherwise) and put a first unstressed length in
 * *length, from the taut parabola under the section's weight. Without a target: CTN_OK,
 * *length unchanged. */
int ctn_cable_target_check(const ctn_model *m, const char *what, const ctn_cable_spec *s, const char *section,
                           const double A[3], const double B[3], double chord, double *length);

/* A catenary element with a target (spec s, record e staged with its section and
 * nodes, chord the distance of its nodes): the checks of the target and the first
 * unstressed length into e->l0; CTN_OK and nothing done without a target
 * (element_target.c). */
int ctn_element_target_first(const ctn_model *m, const ctn_element_spec *s, ctn_element *e, double chord);
/* Append the record of element index e, just added from spec s with a target (room
 * reserved in m->etargets). */
void ctn_element_target_record(ctn_model *m, const ctn_element_spec *s, size_t e);

#endif
