/* Internal: the study object. */
#ifndef CTN_COMPARE_STUDY_H
#define CTN_COMPARE_STUDY_H

#include "compare/cmp.h"

struct ctn_study {
    ctn_span span;
    size_t n;               /* rows */
    ctn_study_row *row;     /* [n], by increasing L0 */
    double *claims;         /* [2 nclaims] copied from the options */
    size_t nclaims;
    char claims_title[128]; /* legend of the claims */
    int catenary;           /* the rows are one catenary element each */
    int mesh;               /* and the span's mesh is solved beside it (row.mesh) */
};

/* Index of the last row of the taut branch: the row of least FEA support stress among
 * the rows with FEA and catenary (0 if none) (study_level.c). */
size_t ctn_study_taut_end(const ctn_study *s);

#endif
