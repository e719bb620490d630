/* The node-by-node assembly (assemble/gather.c) against the generic element loop
 * (CTN_ASM_GENERIC, every element's 6 x 6 added through the scatter map):
 * - tangent values, internal forces (every state entry, fixed DOFs included) and the
 *   stored energy agree to 1e-15 relative (to 1e-13 for the energy, summed in another
 *   order), at random states, with and without the tangent, with compression cut; bit
 *   for bit on models of axial members only;
 * - on chains (one and two threads: 60 000 nodes; their nodes plain but the ends' and
 *   their neighbours'), a net with partly fixed nodes (no node plain), two
 *   members joining the same nodes (free ones too: that node not plain) and members
 *   numbered against the nodes, springs,
 *   tension-only and slack members, and a model mixing cables with catenary and pulley
 *   elements (the generic loop adds those after the node-by-node path);
 * - a collapsed element is reported as the same (first) element;
 * - each family's eval_axial gives eval's forces and tangent bit for bit;
 * - a process's share (ctn_asm_gather_eval_nodes over a node range) gives the same bits
 *   after ctn_asm_gather_keep has dropped the other nodes' lists, and ctn_asm_eval then
 *   (the generic loop) the forces of every node bit for bit;
 * - every allocation of the assembler may fail: CTN_ERR_NOMEM, no leak. */
#include "assemble/asm.h"
#include "element/axial.h"
#include "catena.h"
#include "chain_model.h"
#include "check.h"

#include <stdlib.h>
#include <string.h>

static const char *NET =
    "material a E=1e4\n"
    "material b E=3e3 strain=engineering tension-only\n"
    "section sa material=a A=1\n"
    "section sb material=b A=2\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 2 0 0.1 fix=y\n"
    "node 3 4 0.3 0 fix=xz\n"
    "node 4 6 0 0 fix=xyz\n"
    "node 5 0 0 2\n"
    "node 6 2 0.5 2\n"
    "node 7 4 0.2 2.1\n"
    "node 8 6 0 2 fix=xyz\n"
    "node 9 3 1 1\n"
    "element 1 1 2 section=sa l0=1.9\n"
    "element 2 3 2 section=sa l0=2.1\n"
    "element 3 3 4 section=sb l0=1.95\n"
    "element 4 5 1 section=sb l0=2.2\n"
    "element 5 5 6 section=sa\n"
    "element 6 7 6 section=sa l0=1.8\n"
    "element 7 7 8 section=sb\n"
    "element 8 2 6 section=sa l0=2.05\n"
    "element 9 6 2 section=sb l0=1.9\n"          /* a second member on 2-6 */
    "element 10 9 2 section=sa\n"
    "element 11 9 7 section=sb l0=1.5\n"
    "element 12 3 7 section=sa\n"
    "spring 13 9 6 k=500\n"
    "spring 14 1 9 k=800 l0=3.5\n";

/* Free nodes 2 .. 5, two members on 3-4: node 4 is not plain (two blocks summed), node 5
 * is (its lower neighbour 4 free, one member to it). */
static const char *DOUBLED =
    "material a E=1e4\n"
    "section sa material=a A=1\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 1 0 0.1\n"
    "node 3 2 0.1 0\n"
    "node 4 3 0 -0.1\n"
    "node 5 4 0.1 0\n"
    "node 6 5 0 0 fix=xyz\n"
    "element 1 1 2 section=sa l0=0.9\n"
    "element 2 2 3 section=sa l0=0.95\n"
    "element 3 3 4 section=sa l0=0.97\n"
    "element 4 4 3 section=sa l0=1.01\n"
    "element 5 4 5 section=sa l0=0.99\n"
    "element 6 5 6 section=sa l0=0.9\n";

static const char *MIXED =
    "material rope E=1e5 strain=engineering\n"
    "material steel E=2e8\n"
    "section r material=rope A=0.01 w=0.02\n"
    "section s material=steel A=1e-4 w=0.1\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 4 0 0 fix=xyz\n"
    "node 3 8 0 3 fix=xyz\n"
    "node 4 8 0 -2\n"
    "node 5 12 0 -2\n"
    "node 6 16 1 -1 fix=z\n"
    "node 7 20 0 0 fix=xyz\n"
    "pulley 9 1 2 3 4 section=r length=15\n"
    "element 10 4 5 section=s\n"
    "catenary 11 5 6 section=s length=4.5\n"
    "element 12 6 7 section=s l0=4.1\n"
    "spring 13 5 2 k=300\n"
    "element 14 7 5 section=s l0=8.3\n";

static double rel_max(const double *x, const double *y, size_t n)
{
    double e = 0, s = 0;
    for (size_t i = 0; i < n; i++) {
        e = fmax(e, fabs(x[i] - y[i]));
        s = fmax(s, fmax(fabs(x[i]), fabs(y[i])));
    }
    return s > 0 ? e / s : e;
}

/* Evaluate both assemblers at one state d and compare. */
static void compare_at(const ctn_asm *g, const ctn_asm *r, const double *d, unsigned mode, const char *what)
{
    size_t ns = g->map.nstate, nz = g->nnz;
    double *f1 = malloc(ns * sizeof(double)), *f2 = malloc(ns * sizeof(double));
    double *K1 = malloc(nz * sizeof(double)), *K2 = malloc(nz * sizeof(double)), U1 = 0, U2 = 0;
    size_t b1 = 0, b2 = 0;
    memset(f1, 0x7f, ns * sizeof(double));          /* garbage: every entry must be written */
    memset(K1, 0x7f, nz * sizeof(double));
    CHECK_MSG(ctn_asm_eval(g, d, mode, f1, K1, &U1, &b1) == ctn_asm_eval(r, d, mode, f2, K2, &U2, &b2), "%s", what);
    CHECK_MSG(rel_max(K1, K2, nz) <= 1e-15, "%s: K differs by %g", what, rel_max(K1, K2, nz));
    CHECK_MSG(rel_max(f1, f2, ns) <= 1e-15, "%s: f differs by %g", what, rel_max(f1, f2, ns));
    CHECK_CLOSE(U1, U2, 1e-13, 0);
    if (!g->gather->mixed) {                        /* axial members only: the same sums */
        size_t nK = 0, nf = 0;
        for (size_t i = 0; i < nz; i++) nK += K1[i] != K2[i];
        for (size_t i = 0; i < ns; i++) nf += f1[i] != f2[i];
        CHECK_MSG(nK == 0 && nf == 0, "%s: %zu values of K and %zu of f not bit for bit", what, nK, nf);
    }
    memset(f1, 0x7f, ns * sizeof(double));
    CHECK(ctn_asm_eval(g, d, mode, f1, NULL, &U1, &b1) == 0);       /* forces only */
    CHECK_MSG(rel_max(f1, f2, ns) <= 1e-15, "%s: f alone differs by %g", what, rel_max(f1, f2, ns));
    free(f1); free(f2); free(K1); free(K2);
}

/* Both assemblers of m (the first with `flags`), compared at `states` random states of
 * amplitude amp, both modes; 1 if the node-by-node path was taken. */
static int compare_model(ctn_ctx *ctx, const ctn_model *m, unsigned flags, double amp, int states, const char *what)
{
    ctn_asm *g = NULL, *r = NULL;
    CHECK(ctn_asm_create_ex(ctx, m, flags, &g) == CTN_OK);
    CHECK(ctn_asm_create_ex(ctx, m, CTN_ASM_GENERIC, &r) == CTN_OK);
    if (!g || !r) return 0;
    CHECK(r->gather == NULL && g->nnz == r->nnz);
    size_t ns = g->map.nstate;
    double *d = calloc(ns, sizeof(double));
    unsigned seed = 7;
    for (int s = 0; s < states; s++) {
        for (size_t i = 0; i < ns; i++) {
            seed = seed * 1103515245u + 12345u;
            d[i] = amp * ((double)(seed >> 16 & 0x7fff) / 0x7fff - 0.5);
        }
        compare_at(g, r, d, 0, what);
        compare_at(g, r, d, CTN_EVAL_CUT_COMPRESSION, what);
    }
    int taken = g->gather != NULL;
    free(d);
    ctn_asm_destroy(&g);
    ctn_asm_destroy(&r);
    return taken;
}

static ctn_model *read_model(ctn_ctx *ctx, const char *text)
{
    ctn_model *m = NULL;
    CHECK(ctn_read_string(ctx, "gather.cable", text, strlen(text), &m, NULL) == CTN_OK);
    return m;
}

/* A chain of n cables between two fixed ends: the paper's cable when small, a long one
 * for the two threads (their split falls inside it). */
static ctn_model *chain(ctn_ctx *ctx, int n)
{
    ctn_model *m = chain_model(ctx, n);
    CHECK(m != NULL);
    return m;
}

/* Nodes of m that the node-by-node path takes as plain (free bit 3). */
static size_t plain_nodes(ctn_ctx *ctx, const ctn_model *m)
{
    ctn_asm *a = NULL;
    size_t n = 0;
    CHECK(ctn_asm_create(ctx, m, &a) == CTN_OK && a->gather);
    for (size_t q = 0; a && a->gather && q < a->nn; q++) n += a->gather->free[q] >> 3 & 1;
    ctn_asm_destroy(&a);
    return n;
}

static void test_models(ctn_ctx *ctx)
{
    ctn_model *m = chain(ctx, 40);
    CHECK(compare_model(ctx, m, 0, 0.5, 3, "chain 40"));
    CHECK(plain_nodes(ctx, m) == 41 - 4);    /* all but the fixed ends and their neighbours */
    ctn_model_destroy(&m);
    m = chain(ctx, 60000);
    ctn_asm *a = NULL;
    CHECK(ctn_asm_create(ctx, m, &a) == CTN_OK && a->gather && a->gather->threads >= 1);
    ctn_asm_destroy(&a);
    CHECK(compare_model(ctx, m, 0, 0.05, 1, "chain 60000"));
    CHECK(compare_model(ctx, m, CTN_ASM_ONE_THREAD, 0.05, 1, "chain 60000, one thread"));
    ctn_model_destroy(&m);
    m = read_model(ctx, NET);
    CHECK(plain_nodes(ctx, m) == 0);           /* every node next to a fixed direction */
    CHECK(compare_model(ctx, m, 0, 0.8, 4, "net"));         /* large: many compressed */
    CHECK(compare_model(ctx, m, 0, 0.02, 2, "net, small"));
    ctn_model_destroy(&m);
    m = read_model(ctx, DOUBLED);
    CHECK(plain_nodes(ctx, m) == 2);           /* nodes 3 and 5 */
    CHECK(compare_model(ctx, m, 0, 0.3, 3, "two members on a pair"));
    ctn_model_destroy(&m);
    m = read_model(ctx, MIXED);
    CHECK(compare_model(ctx, m, 0, 0.3, 3, "mixed families"));
    ctn_model_destroy(&m);
}

/* Two nodes at the same place: the first collapsed element in model order, both ways. */
static void test_collapse(ctn_ctx *ctx)
{
    ctn_model *m = read_model(ctx, NET);
    ctn_asm *g = NULL, *r = NULL;
    CHECK(ctn_asm_create(ctx, m, &g) == CTN_OK && g->gather);
    CHECK(ctn_asm_create_ex(ctx, m, CTN_ASM_GENERIC, &r) == CTN_OK);
    size_t ns = g->map.nstate, b1 = 0, b2 = 0;
    double *d = calloc(ns, sizeof(double)), *f = calloc(ns, sizeof(double)), *K = calloc(g->nnz, sizeof(double));
    d[3 * 8 + 0] = 1; d[3 * 8 + 1] = -0.8; d[3 * 8 + 2] = 1.1;     /* node 9 onto node 7: element 11 */
    d[3 * 5 + 0] = -2; d[3 * 5 + 1] = -0.5;                         /* node 6 onto node 5: element 5 */
    CHECK(ctn_asm_eval(g, d, 0, f, K, NULL, &b1) == 1);
    CHECK(ctn_asm_eval(r, d, 0, f, K, NULL, &b2) == 1);
    CHECK(b1 == 4 && b2 == 4);                                       /* element 5, the first */
    CHECK(ctn_asm_eval(g, d, 0, f, NULL, NULL, &b1) == 1 && b1 == 4);
    d[3 * 5 + 0] = 0;
    CHECK(ctn_asm_eval(g, d, 0, f, K, NULL, &b1) == 1 && b1 == 10);  /* element 11 alone */
    free(d); free(f); free(K);
    ctn_asm_destroy(&g);
    ctn_asm_destroy(&r);
    ctn_model_destroy(&m);
}

/* eval_axial gives bit for bit eval's forces and tangent, for every family that has it
 * (properties from the net's elements of that family, random chords, both modes). */
static void test_axial_ops(ctn_ctx *ctx)
{
    ctn_model *m = read_model(ctx, NET);
    ctn_asm *a = NULL;
    CHECK(ctn_asm_create_ex(ctx, m, CTN_ASM_GENERIC, &a) == CTN_OK);
    int families = 0;
    unsigned seed = 3;
    for (size_t k = 0; a && k < a->nblocks; k++) {
        const ctn_element_ops *ops = a->blocks[k].ops;
        if (!ops->eval_axial) continue;
        families++;
        for (int t = 0; t < 50; t++) {
            double X[6], u[6], f1[6], f2[6], K1[21], K2[21], kk[6];
            for (int i = 0; i < 6; i++) {
                seed = seed * 1103515245u + 12345u;
                X[i] = (i >= 3 ? 2.0 : 0.0) + (double)(seed >> 16 & 0x7fff) / 0x7fff;
                u[i] = 0.3 * ((double)(seed >> 8 & 0xff) / 0xff - 0.5);
            }
            const void *props = ctn_asm_props(a, a->blocks[k].e0);
            ctn_elem_state s1, s2;
            unsigned mode = t % 2 ? CTN_EVAL_CUT_COMPRESSION : 0;
            CHECK(ops->eval(props, mode, X, u, f1, K1, &s1) == 0);
            CHECK(ops->eval_axial(props, mode, X, u, f2, kk, &s2) == 0);
            ctn_axial_expand(kk, K2);
            CHECK(!memcmp(f1, f2, sizeof f1) && !memcmp(K1, K2, sizeof K1));
            CHECK(s1.N == s2.N && s1.energy == s2.energy && s1.l == s2.l && s1.slack == s2.slack);
        }
    }
    CHECK(families == 2);                             /* cable and spring */
    ctn_asm_destroy(&a);
    ctn_model_destroy(&m);
}

/* The first column of node q or a later one (problem/dist.c's). */
static size_t first_column(const ctn_asm *a, size_t q)
{
    for (; q < a->nn; q++)
        for (int j = 0; j < 3; j++)
            if (a->map.eq[3 * q + (size_t)j] >= 0) return (size_t)a->map.eq[3 * q + (size_t)j];
    return a->ndof;
}

/* Node ranges [q0, q1) of parts of m evaluated before and after ctn_asm_gather_keep. */
static void keep_parts(ctn_ctx *ctx, const ctn_model *m, int parts, const char *what)
{
    ctn_asm *r = NULL;
    CHECK(ctn_asm_create_ex(ctx, m, CTN_ASM_ONE_THREAD, &r) == CTN_OK && r->gather);
    size_t ns = r->map.nstate, nz = r->nnz;
    double *d = calloc(ns, sizeof(double)), *f0 = calloc(ns, sizeof(double)), *f1 = calloc(ns, sizeof(double));
    double *K0 = calloc(nz + 1, sizeof(double)), *K1 = calloc(nz + 1, sizeof(double)), *fr = calloc(ns, sizeof(double));
    unsigned seed = 11;
    for (size_t i = 0; i < ns; i++) {
        seed = seed * 1103515245u + 12345u;
        d[i] = 0.3 * ((double)(seed >> 16 & 0x7fff) / 0x7fff - 0.5);
    }
    ctn_asm_eval(r, d, 0, fr, NULL, NULL, NULL);
    for (int k = 0; k < parts; k++) {
        ctn_asm *a = NULL;
        size_t q0 = r->nn * (size_t)k / (size_t)parts, q1 = r->nn * (size_t)(k + 1) / (size_t)parts, b0, b1;
        CHECK(ctn_asm_create_ex(ctx, m, CTN_ASM_ONE_THREAD, &a) == CTN_OK && a->gather);
        if (!a) continue;
        size_t k0 = (size_t)a->colptr[first_column(a, q0)], k1 = (size_t)a->colptr[first_column(a, q1)];
        double U0 = 0, U1 = 0;
        int c0 = ctn_asm_gather_eval_nodes(a, d, 0, q0, q1, f0, K0, &U0, &b0);
        CHECK(ctn_asm_gather_keep(a, q0, q1) == CTN_OK);
        int c1 = ctn_asm_gather_eval_nodes(a, d, 0, q0, q1, f1, K1, &U1, &b1);
        CHECK_MSG(c0 == c1 && U0 == U1 && !memcmp(f0 + 3 * q0, f1 + 3 * q0, 3 * (q1 - q0) * sizeof(double)) &&
                      !memcmp(K0, K1, (k1 - k0) * sizeof(double)), "%s: part %d of %d", what, k, parts);
        memset(f1, 0x7f, ns * sizeof(double));
        CHECK(ctn_asm_eval(a, d, 0, f1, NULL, NULL, NULL) == 0);       /* the generic loop */
        CHECK_MSG(!memcmp(f1, fr, ns * sizeof(double)), "%s: part %d: every node's forces", what, k);
        ctn_asm_destroy(&a);
    }
    free(d); free(f0); free(f1); free(K0); free(K1); free(fr);
    ctn_asm_destroy(&r);
}

static void test_keep(ctn_ctx *ctx)
{
    ctn_model *m = read_model(ctx, NET);
    keep_parts(ctx, m, 3, "net");
    ctn_model_destroy(&m);
    m = chain(ctx, 40);
    keep_parts(ctx, m, 2, "chain 40");
    ctn_model_destroy(&m);
}

/* Every allocation of the assembler with its node-by-node path may fail. */
static void test_alloc_failures(ctn_ctx *ctx)
{
    ctn_model *m = read_model(ctx, MIXED);
    int done = 0;
    for (long n = 1; n < 200 && !done; n++) {
        ctn_asm *a = NULL;
        ctn_ctx_fail_alloc_at(ctx, n);
        int rc = ctn_asm_create(ctx, m, &a);
        ctn_ctx_fail_alloc_at(ctx, 0);
        CHECK(rc == CTN_OK || rc == CTN_ERR_NOMEM);
        CHECK((rc == CTN_OK) == (a != NULL));
        if (rc == CTN_OK) {
            CHECK(a->gather != NULL);
            done = 1;
        }
        ctn_asm_destroy(&a);
    }
    CHECK(done);
    ctn_model_destroy(&m);
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_ctx_set_threads(ctx, 2);                         /* the two halves allowed */
    test_models(ctx);
    test_collapse(ctx);
    test_axial_ops(ctx);
    test_keep(ctx);
    test_alloc_failures(ctx);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
