/* Internal: the dynamics analysis's part of the result JSON and of the finite check. */
#ifndef CTN_IO_JSON_DYNAMICS_H
#define CTN_IO_JSON_DYNAMICS_H

#include "catena/model.h"
#include "catena/solve.h"
#include "io/jsonw.h"

/* "dynamics": the analysis as a whole, the times, the recorded histories and the energy
 * balance, when the solution has a dynamics analysis (else nothing). */
void ctn_json_put_dynamics(ctn_jw *j, const ctn_solution *s);
/* 1 if every number of the dynamics analysis is finite (or there is none). */
int ctn_dynamics_finite(const ctn_solution *s);

#endif
