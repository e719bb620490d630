/* Internal: the modal analysis's part of the result JSON and of the finite check. */
#ifndef CTN_IO_JSON_MODES_H
#define CTN_IO_JSON_MODES_H

#include "catena/model.h"
#include "catena/solve.h"
#include "io/jsonw.h"

/* "modal" and "modes", when the solution has modes (else nothing). */
void ctn_json_put_modes(ctn_jw *j, const ctn_model *m, const ctn_solution *s);
/* "shape": a mode's (or a buckling mode's) 3 per node as [{node, ux, uy, uz}, ...]. */
void ctn_json_put_shape(ctn_jw *j, const ctn_model *m, const double *shape);
/* 1 if every number of the modes is finite (or there are none). */
int ctn_modes_finite(const ctn_model *m, const ctn_solution *s);

#endif
