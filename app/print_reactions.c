/* The reactions of the summary: every supported node up to a limit, then the sum over
 * all of them and, when some were left out, the largest (by |r|). */
#include "app.h"

#include <math.h>

static void reaction_row(FILE *out, const char *label, int id, const double *r)
{
    if (id) fprintf(out, "%16s%8d  %12.6g  %12.6g  %12.6g\n", label, id, r[0], r[1], r[2]);
    else fprintf(out, "%24s  %12.6g  %12.6g  %12.6g\n", label, r[0], r[1], r[2]);
}

void ctn_print_reactions(FILE *out, const ctn_model *m, const ctn_solution *s, long limit)
{
    const double *r = ctn_solution_reactions(s);
    double sum[3] = { 0, 0, 0 }, big = -1;
    size_t count = 0, ibig = 0;
    int idbig = 0;
    const char *fu = ctn_model_force_unit(m);
    fprintf(out, "reactions%s%s%s      node            fx            fy            fz\n", *fu ? " [" : "", fu, *fu ? "]" : "");
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info n;
        ctn_model_node(m, i, &n);
        if (!n.fix) continue;
        if (limit < 0 || count < (size_t)limit) reaction_row(out, "", n.id, r + 3 * i);
        count++;
        double size = hypot(hypot(r[3 * i], r[3 * i + 1]), r[3 * i + 2]);
        if (size > big) big = size, ibig = i, idbig = n.id;
        for (int k = 0; k < 3; k++) sum[k] += r[3 * i + k];
    }
    int cut = limit >= 0 && count > (size_t)limit;
    if (cut) fprintf(out, "%24s  (%ld of %zu supported nodes listed; --reactions all lists every one)\n", "...", limit, count);
    reaction_row(out, "sum", 0, sum);
    if (cut) reaction_row(out, "largest", idbig, r + 3 * ibig);
}
