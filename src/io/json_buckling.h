/* Internal: the buckling analysis's part of the result JSON and of the finite check. */
#ifndef CTN_IO_JSON_BUCKLING_H
#define CTN_IO_JSON_BUCKLING_H

#include "catena/model.h"
#include "catena/solve.h"
#include "io/jsonw.h"

/* "buckling_analysis" (the analysis as a whole) and "buckling" (a factor per mode,
 * lowest first), when the solution has a buckling analysis (else nothing). */
void ctn_json_put_buckling(ctn_jw *j, const ctn_model *m, const ctn_solution *s);
/* 1 if every number of the buckling analysis is finite (or there is none). */
int ctn_buckling_finite(const ctn_model *m, const ctn_solution *s);

#endif
