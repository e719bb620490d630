/* Analytic layer: bad inputs give the documented status codes, a message in the
 * context, and a zeroed (NaN-free) output; evaluation outside the cable is refused. */
#include "catena/analytic.h"
#include "check.h"

/* Every byte of the object is zero (so every double is +0.0, never NaN). */
static int all_zero(const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++)
        if (b[i]) return 0;
    return 1;
}

/* Fill with 0xFF (a NaN pattern) so a failed call must overwrite it. */
#define POISON(x) memset(&(x), 0xFF, sizeof(x))

static void expect(ctn_ctx *ctx, int st, int code, const void *out, size_t n)
{
    CHECK_MSG(st == code, "got %s, expected %s", ctn_strerror(st), ctn_strerror(code));
    CHECK(ctn_ctx_code(ctx) == code);
    CHECK(ctn_ctx_message(ctx)[0] != '\0');
    CHECK(all_zero(out, n));
    ctn_ctx_clear(ctx);
}

static void test_catenary(ctn_ctx *ctx)
{
    const ctn_catenary_in bad[] = {
        {0.0, 0.0, 1.0, 2.0}, {-1.0, 0.0, 1.0, 2.0}, {NAN, 0.0, 1.0, 2.0},
        {INFINITY, 0.0, 1.0, 2.0}, {1.0, NAN, 1.0, 2.0}, {1.0, INFINITY, 1.0, 2.0},
        {1.0, 0.0, 0.0, 2.0}, {1.0, 0.0, -1.0, 2.0}, {1.0, 0.0, NAN, 2.0},
        {1.0, 0.0, 1.0, NAN}, {1.0, 0.0, 1.0, -2.0}, {1.0, 0.0, 1.0, INFINITY}};
    ctn_catenary out;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        POISON(out);
        expect(ctx, ctn_catenary_solve(ctx, &bad[i], &out), CTN_ERR_INVALID, &out, sizeof out);
    }
    const ctn_catenary_in dom[] = {
        {3.0, 4.0, 1.0, 5.0}, {3.0, -4.0, 1.0, 4.9}, {2.0, 0.0, 1.0, 1.0}};
    for (size_t i = 0; i < 3; i++) {
        POISON(out);
        expect(ctx, ctn_catenary_solve(ctx, &dom[i], &out), CTN_ERR_DOMAIN, &out, sizeof out);
    }
    POISON(out);
    expect(ctx, ctn_catenary_solve(ctx, NULL, &out), CTN_ERR_INVALID, &out, sizeof out);
    CHECK(ctn_catenary_solve(NULL, &dom[0], NULL) == CTN_ERR_INVALID);
    ctn_catenary_in ok = {3.0, 4.0, 1.0, 6.0};
    double y;
    CHECK(ctn_catenary_solve(NULL, &ok, &out) == CTN_OK);
    CHECK(ctn_catenary_y(&out, -1e-9, &y) == CTN_ERR_INVALID);
    CHECK(ctn_catenary_y(&out, 3.0 + 1e-9, &y) == CTN_ERR_INVALID);
    CHECK(ctn_catenary_tension(&out, NAN, &y) == CTN_ERR_INVALID);
    CHECK(ctn_catenary_arc(&out, INFINITY, &y) == CTN_ERR_INVALID);
    CHECK(ctn_catenary_sag(&out, 1.0, NULL) == CTN_ERR_INVALID);
    CHECK(ctn_catenary_y(NULL, 1.0, &y) == CTN_ERR_INVALID);
}

static void test_ecatenary(ctn_ctx *ctx)
{
    const ctn_ecatenary_in bad[] = {
        {0.0, 0.0, 1.0, 1e3, 2.0}, {1.0, NAN, 1.0, 1e3, 2.0}, {1.0, 0.0, -1.0, 1e3, 2.0},
        {1.0, 0.0, 1.0, 0.0, 2.0}, {1.0, 0.0, 1.0, -INFINITY, 2.0}, {1.0, 0.0, 1.0, NAN, 2.0},
        {1.0, 0.0, 1.0, 1e3, 0.0}, {1.0, 0.0, 1.0, 1e3, INFINITY}, {1.0, 0.0, 1.0, 1e3, NAN}};
    ctn_ecatenary out;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        POISON(out);
        expect(ctx, ctn_ecatenary_solve(ctx, &bad[i], &out), CTN_ERR_INVALID, &out, sizeof out);
    }
    ctn_ecatenary_in dom = {3.0, 4.0, 1.0, INFINITY, 5.0};     /* inextensible, = chord */
    POISON(out);
    expect(ctx, ctn_ecatenary_solve(ctx, &dom, &out), CTN_ERR_DOMAIN, &out, sizeof out);
    dom.EA = 1e3;                                               /* elastic: fine */
    CHECK(ctn_ecatenary_solve(ctx, &dom, &out) == CTN_OK);
    double x, y;
    CHECK(ctn_ecatenary_point(&out, 5.0 + 1e-9, &x, &y) == CTN_ERR_INVALID);
    CHECK(ctn_ecatenary_point(&out, -0.1, &x, &y) == CTN_ERR_INVALID);
    CHECK(ctn_ecatenary_tension_s(&out, NAN, &y) == CTN_ERR_INVALID);
    CHECK(ctn_ecatenary_s_at(&out, 3.5, &y) == CTN_ERR_INVALID);
    CHECK(ctn_ecatenary_y(&out, -1.0, &y) == CTN_ERR_INVALID);
    CHECK(ctn_ecatenary_tension(&out, 1.0, NULL) == CTN_ERR_INVALID);
}

static void test_parabola(ctn_ctx *ctx)
{
    const ctn_parabola_in bad[] = {
        {-1.0, 0.0, 1.0, 2.0, INFINITY}, {1.0, INFINITY, 1.0, 2.0, INFINITY},
        {1.0, 0.0, 0.0, 2.0, INFINITY}, {1.0, 0.0, 1.0, -2.0, INFINITY},
        {1.0, 0.0, 1.0, 2.0, 0.0}, {1.0, 0.0, 1.0, 2.0, NAN}};
    ctn_parabola out;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        POISON(out);
        expect(ctx, ctn_parabola_solve(ctx, &bad[i], &out), CTN_ERR_INVALID, &out, sizeof out);
    }
    ctn_parabola_in dom = {3.0, -4.0, 1.0, 4.5, INFINITY};
    POISON(out);
    expect(ctx, ctn_parabola_solve(ctx, &dom, &out), CTN_ERR_DOMAIN, &out, sizeof out);
    dom.EA = 1e4;
    CHECK(ctn_parabola_solve(ctx, &dom, &out) == CTN_OK);
    double y;
    CHECK(ctn_parabola_y(&out, 3.1, &y) == CTN_ERR_INVALID);
    CHECK(ctn_parabola_tension(&out, -0.1, &y) == CTN_ERR_INVALID);
}

static void test_funicular(ctn_ctx *ctx)
{
    double L[3] = {2.0, 2.0, 2.0}, Lbad[3] = {2.0, -1.0, 2.0}, EAbad[3] = {1.0, NAN, 1.0};
    double P[4] = {0.0, -1.0, 0.0, -1.0}, Pbad[4] = {0.0, -1.0, INFINITY, -1.0};
    double xy[8], N[3];
    const ctn_funicular_in bad[] = {
        {0.0, 0.0, 3, L, NULL, P}, {4.0, NAN, 3, L, NULL, P}, {4.0, 0.0, 0, L, NULL, P},
        {4.0, 0.0, 3, NULL, NULL, P}, {4.0, 0.0, 3, Lbad, NULL, P},
        {4.0, 0.0, 3, L, EAbad, P}, {4.0, 0.0, 3, L, NULL, Pbad}};
    ctn_funicular out;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        POISON(out);
        expect(ctx, ctn_funicular_solve(ctx, &bad[i], xy, N, &out), CTN_ERR_INVALID, &out,
               sizeof out);
    }
    const ctn_funicular_in dom[] = {
        {6.0, 0.0, 3, L, NULL, P},                      /* inextensible, = chord */
        {4.0, 0.0, 3, L, NULL, NULL}};                  /* unloaded, slack */
    for (size_t i = 0; i < 2; i++) {
        POISON(out);
        expect(ctx, ctn_funicular_solve(ctx, &dom[i], xy, N, &out), CTN_ERR_DOMAIN, &out,
               sizeof out);
    }
    POISON(out);
    expect(ctx, ctn_funicular_solve(ctx, &bad[0], NULL, N, &out), CTN_ERR_INVALID, &out,
           sizeof out);
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    CHECK(ctn_ctx_create(&ctx) == CTN_OK);
    test_catenary(ctx);
    test_ecatenary(ctx);
    test_parabola(ctx);
    test_funicular(ctx);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
