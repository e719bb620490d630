/* The sag-tension chart's rows (`sagtension`, io/directives_chart.c): accessors. */
#include "model/model.h"

size_t ctn_model_chart_count(const ctn_model *m) { return m ? m->chart.n : 0; }

int ctn_model_chart_row(const ctn_model *m, size_t r, size_t *entry, double *dT, const char **base)
{
    if (!m || r >= m->chart.n) return CTN_ERR_INVALID;
    const ctn_chart_row *row = &m->chart.v[r];
    if (entry) *entry = (size_t)row->index + (row->combination ? m->cases.n : 0);
    if (dT) *dT = row->dT;
    if (base) *base = row->base >= 0 ? m->cases.v[row->base].name : NULL;
    return CTN_OK;
}
