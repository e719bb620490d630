/* A model file in, its shape found, the found model out: the source is read once and
 * both parsed and copied from the same bytes. */
#include "design/formfind/ff.h"
#include "catena/io.h"
#include "io/parse.h"

int ctn_formfind_file(ctn_ctx *ctx, const char *in, const char *out, const ctn_formfind_options *opt,
                      ctn_formfind_report *rep, ctn_model **found)
{
    if (found) *found = NULL;
    if (!in) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_formfind_file: bad arguments");
    ctn_formfind_report own;
    if (!rep) rep = &own;
    char *text = NULL;
    size_t len = 0;
    ctn_model *m = NULL;
    int rc = ctn_read_all(ctx, in, &text, &len);
    if (!rc) rc = ctn_read_string(ctx, in, text, len, &m, NULL);
    if (!rc) rc = ctn_formfind(ctx, m, opt, rep);
    if (!rc && out && rep->reason == CTN_FF_CONVERGED) rc = ctn_formfind_write(ctx, m, text, len, out);
    ctn_free(text);
    if (rc || !found) ctn_model_destroy(&m);
    else *found = m;
    return rc;
}
