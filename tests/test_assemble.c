/* Assembly layer: DOF map, pattern and scatter map.
 * - the assembled sparse tangent equals central finite differences of the assembled
 *   internal forces, for a 3D net with shared nodes and partly fixed nodes;
 * - the pattern is the upper triangle, sorted, with no duplicate entries;
 * - internal forces sum to zero (self-equilibrated). */
#include "assemble/asm.h"
#include "catena.h"
#include "check.h"

#include <stdlib.h>

/* A 4 x 3 grid net in the x-z plane with diagonals, corners fixed, one node fixed in y. */
static ctn_model *net(ctn_ctx *ctx)
{
    ctn_model *m = NULL;
    ctn_model_create(ctx, &m);
    ctn_model_add_material(m, "a", 1e4, CTN_STRAIN_GREEN_LAGRANGE, 0);
    ctn_model_add_material(m, "b", 3e3, CTN_STRAIN_ENGINEERING, 0);
    ctn_model_add_section(m, "sa", "a", 1.0, 0);
    ctn_model_add_section(m, "sb", "b", 2.0, 0);
    int id = 1;
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++, id++) {
            double X[3] = { 2.0 * i, 0.3 * i * j, 2.0 * j };
            int corner = (i == 0 || i == 3) && (j == 0 || j == 2);
            ctn_model_add_node(m, id, X, corner ? CTN_FIX_ALL : (id == 6 ? CTN_FIX_Y : 0));
        }
    int e = 1;
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) {
            int n = 1 + i + 4 * j;
            if (i < 3) ctn_model_add_element(m, e++, n, n + 1, "sa", 1.9);
            if (j < 2) ctn_model_add_element(m, e++, n, n + 4, "sb", 1.95);
            if (i < 3 && j < 2) ctn_model_add_element(m, e++, n, n + 5, "sa", CTN_L0_DEFAULT);
        }
    /* two springs across the net (a second element family in the same assembly) */
    int sn[2][2] = { { 2, 11 }, { 6, 8 } };
    for (int k = 0; k < 2; k++) {
        ctn_element_spec sp;
        ctn_element_spec_init(&sp);
        sp.type = "spring";
        sp.id = e++;
        sp.nnodes = 2;
        sp.nodes = sn[k];
        sp.k = 500.0 * (k + 1);
        sp.l0 = k ? 3.5 : CTN_L0_DEFAULT;
        ctn_model_add_element_spec(m, &sp);
    }
    return m;
}

static void test_pattern(const ctn_asm *a)
{
    for (size_t c = 0; c < a->ndof; c++)
        for (int p = a->colptr[c]; p < a->colptr[c + 1]; p++) {
            CHECK(a->rowind[p] <= (int)c);
            if (p > a->colptr[c]) CHECK(a->rowind[p] > a->rowind[p - 1]);
        }
    CHECK(a->colptr[a->ndof] == (int)a->nnz);
}

static void test_fd(const ctn_asm *a)
{
    size_t n3 = a->map.nstate;
    double *d = calloc(n3, sizeof(double)), *f = calloc(n3, sizeof(double));
    double *fp = calloc(n3, sizeof(double)), *fm = calloc(n3, sizeof(double));
    double *Kx = calloc(a->nnz, sizeof(double));
    unsigned seed = 99;
    for (size_t i = 0; i < n3; i++) {
        seed = seed * 1103515245u + 12345u;
        d[i] = a->map.eq[i] >= 0 ? 0.05 * ((double)(seed >> 16 & 0x7fff) / 0x7fff - 0.5) : 0;
    }
    CHECK(ctn_asm_eval(a, d, 0, f, Kx, NULL, NULL) == 0);
    double sum[3] = { 0, 0, 0 }, fmaxabs = 0;
    for (size_t i = 0; i < n3; i++) { sum[i % 3] += f[i]; fmaxabs = fmax(fmaxabs, fabs(f[i])); }
    for (int k = 0; k < 3; k++) CHECK(fabs(sum[k]) <= 1e-12 * fmaxabs);
    double err = 0, kmax = 0;
    for (size_t j = 0; j < n3; j++) {
        int c = a->map.eq[j];
        if (c < 0) continue;
        double h = 1e-6, save = d[j];
        d[j] = save + h;
        ctn_asm_eval(a, d, 0, fp, NULL, NULL, NULL);
        d[j] = save - h;
        ctn_asm_eval(a, d, 0, fm, NULL, NULL, NULL);
        d[j] = save;
        for (size_t i = 0; i < n3; i++) {
            int r = a->map.eq[i];
            if (r < 0) continue;
            double fd = (fp[i] - fm[i]) / (2 * h), k = 0;
            int lo = r < c ? r : c, hi = r < c ? c : r;
            for (int p = a->colptr[hi]; p < a->colptr[hi + 1]; p++)
                if (a->rowind[p] == lo) k = Kx[p];
            err = fmax(err, fabs(k - fd));
            kmax = fmax(kmax, fabs(k));
        }
    }
    CHECK_MSG(err <= 1e-6 * kmax, "global tangent error %.3g of %.3g", err, kmax);
    free(d); free(f); free(fp); free(fm); free(Kx);
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = net(ctx);
    CHECK(m != NULL && ctn_model_element_count(m) == 25);
    ctn_asm *a = NULL;
    CHECK(ctn_asm_create(ctx, m, &a) == CTN_OK);
    CHECK(a->ndof == 3 * 12 - 4 * 3 - 1);
    test_pattern(a);
    test_fd(a);
    ctn_asm_destroy(&a);
    CHECK(a == NULL);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
