/* The buckling analysis in the solve command's summary: one line per factor. */
#include "app.h"

void ctn_print_buckling(FILE *out, const ctn_model *m, const ctn_solution *s)
{
    (void)m;
    ctn_buckling_summary bs;
    if (ctn_solution_buckling_summary(s, &bs)) return;
    fprintf(out, "buckling (linear, about the last step's state, %d free DOFs): %d of %d factor(s) asked, "
                 "time %.3f s\n", bs.ndof, bs.count, bs.asked, bs.t_total);
    if (bs.count < bs.asked)
        fprintf(out, "  the pencil K_T + (lambda - 1) K' has only %d positive factor(s)\n", bs.count);
    fprintf(out, "  mode %16s %8s %12s\n", "load factor", "node", "residual");
    for (size_t k = 0; k < ctn_solution_buckling_count(s); k++) {
        ctn_buckling_mode b;
        ctn_solution_buckling(s, k, &b);
        fprintf(out, "%6zu %16.10g %8d %12.1e\n", k + 1, b.factor, b.node, b.residual);
    }
    if (bs.nl_kind == 1)
        fprintf(out, "  non-linear check (imperfection %.3g in mode 1, %d increments): limit at load factor %.6g\n",
                bs.nl_imperfection, bs.nl_increments, bs.nl_factor);
    else if (bs.nl_kind == 2)
        fprintf(out, "  non-linear check (imperfection %.3g in mode 1, %d increments): stable up to the linear "
                     "factor; Southwell's factor %.6g\n", bs.nl_imperfection, bs.nl_increments, bs.nl_factor);
}
