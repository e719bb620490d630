/* The buckling analysis in the result JSON: "buckling_analysis" (the analysis as a
 * whole) and "buckling" (one object per factor, lowest first: factor, node, residual,
 * shape). docs/format.md, "buckling". */
#include "io/json_buckling.h"
#include "io/json_modes.h"

#include "catena/analysis.h"

#include <math.h>

void ctn_json_put_buckling(ctn_jw *j, const ctn_model *m, const ctn_solution *s)
{
    ctn_buckling_summary bs;
    if (ctn_solution_buckling_summary(s, &bs)) return;
    ctn_jw_object(j, "buckling_analysis");
    ctn_jw_number(j, "count", bs.count);
    ctn_jw_number(j, "asked", bs.asked);
    ctn_jw_number(j, "ndof", bs.ndof);
    ctn_jw_number(j, "h", bs.h);
    ctn_jw_number(j, "load_norm", bs.load_norm);
    if (bs.nl_kind) {                            /* check=1 (buckling_check.c) */
        ctn_jw_object(j, "nonlinear");
        ctn_jw_string(j, "kind", bs.nl_kind == 1 ? "limit" : "southwell");
        ctn_jw_number(j, "factor", bs.nl_factor);
        ctn_jw_number(j, "imperfection", bs.nl_imperfection);
        ctn_jw_number(j, "increments", bs.nl_increments);
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
    ctn_jw_array(j, "buckling");
    for (size_t k = 0; k < ctn_solution_buckling_count(s); k++) {
        ctn_buckling_mode b;
        ctn_solution_buckling(s, k, &b);
        ctn_jw_object(j, NULL);
        ctn_jw_number(j, "mode", (double)(k + 1));
        ctn_jw_number(j, "factor", b.factor);
        ctn_jw_number(j, "node", b.node);
        ctn_jw_number(j, "residual", b.residual);
        ctn_json_put_shape(j, m, b.shape);
        ctn_jw_end(j);
    }
    ctn_jw_end(j);
}

int ctn_buckling_finite(const ctn_model *m, const ctn_solution *s)
{
    size_t nn = ctn_model_node_count(m);
    for (size_t k = 0; k < ctn_solution_buckling_count(s); k++) {
        ctn_buckling_mode b;
        ctn_solution_buckling(s, k, &b);
        if (!isfinite(b.factor) || !isfinite(b.residual)) return 0;
        for (size_t i = 0; i < 3 * nn; i++)
            if (!isfinite(b.shape[i])) return 0;
    }
    ctn_buckling_summary bs;
    return ctn_solution_buckling_summary(s, &bs) || (isfinite(bs.h) && isfinite(bs.load_norm));
}
