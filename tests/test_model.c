/* Model layer: whole-model checks of ctn_model_validate.
 * - parts without supports: a chain beside a supported cable, a floating triangle, a
 *   single element, a loaded floating chain (refused by ctn_solve at once), a part with
 *   many non-consecutive ids (the message abbreviates); the message names the part's
 *   elements and is located at the line of its first element (file:line from the
 *   reader, no location from the API);
 * - accepted: every part with a fixed DOF (one DOF is enough for this check), several
 *   separately supported parts, a fully fixed node that no element touches;
 * - a million-element chain is checked in linear time;
 * - every allocation failure of the check gives CTN_ERR_NOMEM and no leak. */
#include "catena.h"
#include "check.h"

#include <stdlib.h>
#include <time.h>

static ctn_model *base(ctn_ctx *ctx)
{
    ctn_model *m = NULL;
    ctn_model_create(ctx, &m);
    ctn_model_add_material(m, "m", 1000, CTN_STRAIN_ENGINEERING, 0);
    ctn_model_add_section(m, "s", "m", 1, 0);
    return m;
}

static void node(ctn_model *m, int id, double x, double y, unsigned fix)
{
    double X[3] = { x, y, 0 };
    CHECK_MSG(ctn_model_add_node(m, id, X, fix) == CTN_OK, "node %d", id);
}

static void element(ctn_model *m, int id, int a, int b)
{
    CHECK_MSG(ctn_model_add_element(m, id, a, b, "s", CTN_L0_DEFAULT) == CTN_OK, "element %d", id);
}

/* A supported two-element cable (nodes 1-3, elements 1-2) with a load. */
static ctn_model *supported(ctn_ctx *ctx)
{
    ctn_model *m = base(ctx);
    double F[3] = { 0, -1, 0 };
    node(m, 1, 0, 0, CTN_FIX_ALL);
    node(m, 2, 10, 0, CTN_FIX_ALL);
    node(m, 3, 5, -1, CTN_FIX_Z);
    element(m, 1, 1, 3);
    element(m, 2, 3, 2);
    ctn_model_add_load(m, 3, F);
    return m;
}

/* validate(m) fails with CTN_ERR_MODEL and a message starting with `msg`. */
static void check_refused(ctn_ctx *ctx, ctn_model *m, const char *msg)
{
    int rc = ctn_model_validate(m);
    CHECK_MSG(rc == CTN_ERR_MODEL, "rc %d for '%s'", rc, msg);
    CHECK_MSG(!strncmp(ctn_ctx_message(ctx), msg, strlen(msg)), "message '%s', expected '%s...'",
              ctn_ctx_message(ctx), msg);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "no support reaches") != NULL, "%s", ctn_ctx_message(ctx));
}

static void test_chain_and_triangle(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = supported(ctx);
    CHECK(ctn_model_validate(m) == CTN_OK);
    node(m, 101, 0, 10, 0);                      /* a chain that touches nothing */
    node(m, 102, 5, 10, 0);
    node(m, 103, 10, 10, 0);
    element(m, 7, 101, 102);
    element(m, 8, 102, 103);
    check_refused(ctx, m, "elements 7-8 (2 elements) form a part that no support reaches");
    ctn_model_destroy(&m);

    m = supported(ctx);                          /* a floating triangle */
    node(m, 4, 20, 0, 0);
    node(m, 5, 24, 0, 0);
    node(m, 6, 22, 3, 0);
    element(m, 5, 4, 5);
    element(m, 6, 5, 6);
    element(m, 7, 6, 4);
    check_refused(ctx, m, "elements 5-7 (3 elements) form a part");
    ctn_model_destroy(&m);

    m = supported(ctx);                          /* one element */
    node(m, 4, 20, 0, 0);
    node(m, 5, 24, 0, 0);
    element(m, 9, 4, 5);
    check_refused(ctx, m, "element 9 (1 element) forms a part");
    ctn_model_destroy(&m);

    m = supported(ctx);                          /* joined to the cable: one part, accepted */
    node(m, 4, 20, 0, 0);
    element(m, 9, 2, 4);
    CHECK(ctn_model_validate(m) == CTN_OK);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* The unsupported part is found whatever the element order: here it comes first, and
 * its elements are mixed with the supported ones. */
static void test_order_and_many_ids(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = base(ctx);
    node(m, 1, 0, 0, CTN_FIX_ALL);
    for (int i = 0; i <= 10; i++) node(m, 100 + i, i, 5, 0);      /* free chain 100..110 */
    for (int i = 0; i < 10; i++) {
        node(m, 2 + i, i + 1, 0, i == 9 ? CTN_FIX_Y : 0);          /* supported chain */
        element(m, 2 * i + 1, i ? 1 + i : 1, 2 + i);               /* odd ids: supported */
        element(m, 2 * i + 2, 100 + i, 101 + i);                   /* even ids: floating */
    }
    check_refused(ctx, m, "elements 2, 4, 6, 8, 10, 12, ... (10 elements) form a part");
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_located(void)
{
    static const char text[] =
        "material m E=1000\n"
        "section s material=m A=1\n"
        "node 1 0 0 0 fix=xyz\n"
        "node 2 10 0 0 fix=xyz\n"
        "element 1 1 2 section=s l0=9.9\n"
        "node 3 0 5 0\n"
        "node 4 5 5 0\n"
        "\n"
        "element 12 3 4 section=s\n"
        "load 3 0 -1 0\n";
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    CHECK(ctn_model_read_string(ctx, "net.cable", text, sizeof text - 1, &m) == CTN_OK);
    check_refused(ctx, m, "net.cable:9: element 12 (1 element) forms a part that no support reaches");
    /* the solver refuses it before iterating */
    CHECK(ctn_solve(ctx, m, NULL, &s) == CTN_ERR_MODEL);
    CHECK(s == NULL);
    CHECK(strstr(ctn_ctx_message(ctx), "net.cable:9: element 12") != NULL);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_accepted(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = supported(ctx);
    node(m, 11, 0, 5, CTN_FIX_X);                /* a second part held in x only */
    node(m, 12, 5, 4, 0);
    element(m, 20, 11, 12);
    node(m, 30, 50, 50, CTN_FIX_ALL);            /* a fixed node no element touches */
    CHECK_MSG(ctn_model_validate(m) == CTN_OK, "%s", ctn_ctx_message(ctx));
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* A chain of n elements fixed at its far end only: the worst case for a naive walk. */
static void test_large(void)
{
    enum { N = 1000000 };
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = base(ctx);
    int ok = 1;
    for (int i = 0; i <= N && ok; i++) {
        double X[3] = { i, 0, 0 };
        ok = ctn_model_add_node(m, i + 1, X, i == N ? CTN_FIX_ALL : 0) == CTN_OK;
        if (ok && i) ok = ctn_model_add_element(m, i, i, i + 1, "s", CTN_L0_DEFAULT) == CTN_OK;
    }
    CHECK(ok);
    clock_t t0 = clock();
    CHECK_MSG(ctn_model_validate(m) == CTN_OK, "%s", ctn_ctx_message(ctx));
    double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    CHECK_MSG(secs < 10, "validate took %.2f s on %d elements", secs, N);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_alloc_failures(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = supported(ctx);
    node(m, 4, 20, 0, 0);
    node(m, 5, 24, 0, 0);
    element(m, 9, 4, 5);
    int nomem = 0, refused = 0;
    for (long k = 1; k < 20; k++) {
        ctn_ctx_clear(ctx);
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_model_validate(m);
        CHECK_MSG(rc == CTN_ERR_NOMEM || rc == CTN_ERR_MODEL, "k=%ld: rc %d", k, rc);
        nomem += rc == CTN_ERR_NOMEM;
        refused += rc == CTN_ERR_MODEL;
    }
    ctn_ctx_fail_alloc_at(ctx, 0);
    CHECK(nomem >= 1 && refused >= 1);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_chain_and_triangle();
    test_order_and_many_ids();
    test_located();
    test_accepted();
    test_large();
    test_alloc_failures();
    CHECK_DONE();
}
