/* modal_study [ROOT [OUTDIR]]: the modal analysis's validation study (docs/validation.md,
 * "Modal analysis"): (a) the taut string, (b) Irvine's suspended cable across the
 * crossover and where the shallow theory departs, (c) the founding paper's four cables,
 * (d) a hypar net. Tables on stdout (markdown), figures in OUTDIR (default out/modal).
 * ROOT is the source tree (for examples/paper/), default ".". Exit 0, or 1 on a failure. */
#include "modal_study.h"

#include <stdio.h>

int main(int argc, char **argv)
{
    const char *root = argc > 1 ? argv[1] : ".", *dir = argc > 2 ? argv[2] : "out/modal";
    ctn_ctx *ctx = NULL;
    if (ctn_ctx_create(&ctx)) return 1;
    int rc = ctn_plot_mkdir(ctx, dir);
    if (!rc) rc = study_string(ctx, dir);
    if (!rc) rc = study_irvine(ctx, dir);
    if (!rc) rc = study_depth(ctx, dir);
    if (!rc) rc = study_paper(root);
    if (!rc) rc = study_net(ctx, dir);
    if (rc && *ctn_ctx_message(ctx)) fprintf(stderr, "modal_study: %s\n", ctn_ctx_message(ctx));
    ctn_ctx_destroy(&ctx);
    return rc ? 1 : 0;
}
