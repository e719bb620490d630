/* bench_order - what each fill-reducing ordering gives (issue 10, item 3).
 *
 * For a model file (or the paper's cable with n elements), the symbolic analysis of the
 * tangent's pattern with the natural, AMD and METIS orderings and `auto`: analysis time
 * (wall and CPU), factor non-zeros, flops of one factorization, and the ordering `auto`
 * keeps. No factorization.
 *
 *   bench_order MODEL.cable        bench_order --cable N
 */
#include "assemble/asm.h"
#include "linalg/linsolve.h"
#include "problem/la_options.h"

#include "bench_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int main(int argc, char **argv)
{
    ctn_ctx *ctx = NULL;
    bench_keep_heap();
    ctn_model *m = NULL;
    ctn_asm *a = NULL;
    int n = 0, rc = ctn_ctx_create(&ctx);
    if (!rc) ctn_ctx_set_threads(ctx, 0);           /* as the catena command: no limit */
    if (argc == 3 && !strcmp(argv[1], "--cable") && !parse_count(argv[2], 2, 100000000, &n))
        rc = rc ? rc : build_paper_cable(ctx, n, CTN_START_CATENARY, &m);
    else if (argc == 2) rc = rc ? rc : ctn_read_file(ctx, argv[1], &m, NULL);
    else {
        fprintf(stderr, "usage: bench_order MODEL.cable | bench_order --cable N\n");
        return 1;
    }
    if (!rc) rc = ctn_asm_create(ctx, m, &a);
    if (rc) {
        fprintf(stderr, "bench_order: %s\n", ctn_ctx_message(ctx));
        return 2;
    }
    ctn_pattern pat = { a->ndof, a->colptr, a->rowind };
    static const ctn_ordering ords[] = { CTN_ORDER_NATURAL, CTN_ORDER_AMD, CTN_ORDER_METIS, CTN_ORDER_AUTO };
    printf("# %s: %zu DOFs, %d non-zeros in triu(K)\n", argc == 2 ? argv[1] : "paper cable", a->ndof, a->colptr[a->ndof]);
    printf("%-8s %-8s %12s %12s %14s %12s\n", "asked", "kept", "analyse[s]", "CPU[s]", "factor nnz", "flops");
    for (size_t i = 0; i < sizeof ords / sizeof *ords; i++) {
        ctn_linsolve *ls = NULL;
        double t0 = now(), c0 = cpu_now();
        int r = ctn_linsolve_create(ctx, "cholmod", &pat, ctn_la_ordering_of(ords[i]), &ls);
        double t1 = now(), c1 = cpu_now();
        if (r) printf("%-8s failed: %s\n", ctn_ordering_name(ords[i]), ctn_ctx_message(ctx));
        else printf("%-8s %-8s %12.3f %12.3f %14zu %12.4g\n", ctn_ordering_name(ords[i]),
                    ctn_la_ordering_name(ctn_linsolve_ordering(ls)), t1 - t0, c1 - c0, ctn_linsolve_factor_nnz(ls),
                    ctn_linsolve_flops(ls));
        ctn_ctx_clear(ctx);
        ctn_linsolve_destroy(&ls);
    }
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return 0;
}
