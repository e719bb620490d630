/* wind (issue 27 item 2): drag cd p d per unit length of each chord projected on the
 * plane normal to the wind, following the deformed geometry.
 * - along gravity it is the hload on the deformed projection: the same displacements and
 *   reactions to 1e-12 (not bit for bit: the start's pre-shaping passes over chains under
 *   an hload, not under a wind);
 * - across a weightless level span it is a load per unit length of the span's
 *   projection on its own plane, so the span is the elastic parabola (engineering
 *   strain, ctn_parabola_solve) in the plane of the chord and the wind: H to 1e-6 with
 *   800 elements;
 * - with weight and a horizontal wind the load follows the deformed chords: the
 *   reactions along the wind sum to cd p d times the chords' projections normal to the
 *   wind at the solved state (1e-12), not at the start;
 * - oblique to a weightless span (30 degrees), from the default start: the inclined
 *   elastic parabola in the wind's frame, O(h^2) (test_oblique); and 5 degrees to it, the
 *   load nearly along the chord (test_near_axial: it stalled at the default maxit before
 *   the start on the funicular of the drag through the anchors). */
#include "catena.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define HEAD "units kN m\nmaterial steel E=2.0e8 strain=engineering\nsection s material=steel A=1e-3%s\n%s\n" \
             "node 1 0 0 0 fix=xyz\nnode 2 100 0 0 fix=xyz\ncable 1 2 section=s n=%d length=130\n%s\nsolve tol=1e-12\n"

static ctn_solution *solve(ctn_ctx *ctx, const char *text, ctn_model **m)
{
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    int rc = ctn_read_string(ctx, "wind", text, strlen(text), m, &opt);
    if (!rc) rc = ctn_solve(ctx, *m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    return s;
}

static void test_as_hload(void)
{
    char a[1024], b[1024];
    snprintf(a, sizeof a, HEAD, " w=0.5", "gravity 0 0 -1", 20, "wind all dir=0,0,-2 pressure=20kPa d=1m cd=1");
    snprintf(b, sizeof b, HEAD, " w=0.5", "gravity 0 0 -1", 20, "hload q=20");
    ctn_ctx *ctx = NULL;
    ctn_model *ma = NULL, *mb = NULL;
    ctn_ctx_create(&ctx);
    ctn_solution *sa = solve(ctx, a, &ma), *sb = solve(ctx, b, &mb);
    if (sa && sb) {
        const double *da = ctn_solution_displacements(sa), *db = ctn_solution_displacements(sb);
        const double *ra = ctn_solution_reactions(sa), *rb = ctn_solution_reactions(sb);
        double big = 0, dif = 0;
        for (size_t i = 0; i < 3 * ctn_model_node_count(ma); i++) {
            big = fmax(big, fabs(db[i]));
            dif = fmax(dif, fabs(da[i] - db[i]));
            CHECK_CLOSE(ra[i], rb[i], 1e-12, 1e-12 * fabs(rb[2]));
        }
        printf("wind along gravity against hload: displacements within %.3g of the largest\n", dif / big);
        CHECK(dif <= 1e-12 * big);
    }
    ctn_solution_destroy(&sa);
    ctn_solution_destroy(&sb);
    ctn_model_destroy(&ma);
    ctn_model_destroy(&mb);
    ctn_ctx_destroy(&ctx);
}

static void test_parabola(void)
{
    char a[1024];
    snprintf(a, sizeof a, HEAD, "", "gravity 0 1 0   # the arc's start only: no weight", 800,
             "wind all dir=0,1,0 speed=200 rho=1.25kg/m3 cd=1.2 d=1m");
    double q = 1.2 * 0.5 * 1.25e-3 * 200 * 200 * 1.0;                   /* kN/m (1.25 kg/m3 = 1.25e-3 t/m3) */
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    ctn_parabola_in in = { 100, 0, q, 130, 2.0e8 * 1e-3 };
    ctn_parabola par;
    CHECK(ctn_parabola_solve(ctx, &in, &par) == CTN_OK);
    ctn_solution *s = solve(ctx, a, &m);
    if (s) {
        const double *R = ctn_solution_reactions(s);
        printf("wind across a weightless span: H %.10g, the elastic parabola %.10g (%+.2e)\n", -R[0], par.H,
               -R[0] / par.H - 1);
        CHECK_CLOSE(-R[0], par.H, 1e-6, 0);
        CHECK_CLOSE(-(R[1] + R[4]), q * 100, 1e-9, 0);             /* the projection is the span */
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_follows(void)
{
    char a[1024];
    snprintf(a, sizeof a, HEAD, " w=0.5", "gravity 0 0 -1", 40,
             "wind all dir=0,1,0 pressure=2kPa cd=1 d=1m\nsolve method=newton steps=20   # a swing of 76 degrees");
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    ctn_solution *s = solve(ctx, a, &m);
    if (s) {
        const double *R = ctn_solution_reactions(s), *d = ctn_solution_displacements(s);
        double proj = 0, proj0 = 0;
        for (size_t e = 0; e < ctn_model_element_count(m); e++) {
            ctn_element_info ei;
            ctn_node_info p, r;
            ctn_model_element(m, e, &ei);
            ctn_model_node(m, (size_t)ei.nodes[0], &p);
            ctn_model_node(m, (size_t)ei.nodes[1], &r);
            double hx = r.X[0] - p.X[0], hz = r.X[2] - p.X[2];
            proj0 += hypot(hx, hz);
            hx += d[3 * (size_t)ei.nodes[1]] - d[3 * (size_t)ei.nodes[0]];
            hz += d[3 * (size_t)ei.nodes[1] + 2] - d[3 * (size_t)ei.nodes[0] + 2];
            proj += hypot(hx, hz);
        }
        printf("wind with weight: reactions along the wind %.12g, 2 x the deformed projection %.12g, at the start %.12g\n",
               -(R[1] + R[4]), 2 * proj, 2 * proj0);
        CHECK_CLOSE(-(R[1] + R[4]), 2 * proj, 1e-12, 0);
        CHECK(fabs(proj - proj0) > 1e-3 * proj);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* A wind oblique to a weightless slack span (th to the chord, issue 27's "oblique wind
 * start"): the load per unit length projected normal to the wind is a load per
 * "horizontal" length in the frame whose "down" is the wind, so the span is the elastic
 * parabola of an inclined span in that frame: horizontal span l sin(th), the far support
 * l cos(th) below the near one along the wind. The default method starts on the chain's
 * funicular under the drag through its anchors (2 iterations at 30 degrees; 36 from the
 * catenary of the reference chords' mean drag, the start before it; before that, an arc
 * along gravity, it stalled at maxit). The reactions along the wind q l sin(th) to 1e-9;
 * H (the reactions normal to the wind, both ends) equal to 1e-9; *iterations -1 if not
 * converged. */
static double oblique(int n, const ctn_parabola *par, double th, int *iterations)
{
    char a[1024], wind[256];
    double u[2] = { cos(th), sin(th) }, nn[2] = { -sin(th), cos(th) }, q = 30, err = NAN;
    snprintf(wind, sizeof wind, "wind all dir=%.17g,%.17g,0 pressure=30 d=1m cd=1", u[0], u[1]);
    snprintf(a, sizeof a, HEAD, "", "gravity 0 1 0   # the arc's start only: no weight", n, wind);
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    ctn_solution *s = solve(ctx, a, &m);
    if (s) {
        const double *R = ctn_solution_reactions(s);
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        double H1 = R[0] * nn[0] + R[1] * nn[1], H2 = -(R[3] * nn[0] + R[4] * nn[1]);
        double along = R[0] * u[0] + R[1] * u[1] + R[3] * u[0] + R[4] * u[1];
        printf("wind %g degrees to a weightless span, n = %d: H %.10g and %.10g, the inclined elastic parabola %.10g "
               "(%+.2e), %d iterations%s\n", th * 180 / acos(-1.0), n, H1, H2, par->H, H1 / par->H - 1, sum.iterations,
               sum.reason == CTN_CONVERGED ? "" : " (not converged)");
        *iterations = sum.reason == CTN_CONVERGED ? sum.iterations : -1;
        CHECK_CLOSE(H2, H1, 1e-9, 0);
        CHECK_CLOSE(-along, q * 100 * sin(th), 1e-9, 0);
        err = H1 / par->H - 1;
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return err;
}

/* The inclined elastic parabola of a wind at th (radians) to the weightless span, solved
 * at n and 2 n elements by the default method: H within tol at n, falling as h^2 (ratio
 * 3.8 .. 4.2), its Richardson extrapolation within rich; each solve converged within
 * maxit iterations. */
static void oblique_pair(double th, int n, double tol, double rich, int maxit)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_parabola_in in = { 100 * sin(th), -100 * cos(th), 30, 130, 2.0e8 * 1e-3 };
    ctn_parabola par;
    CHECK(ctn_parabola_solve(ctx, &in, &par) == CTN_OK);
    ctn_ctx_destroy(&ctx);
    int i1 = -1, i2 = -1;
    double e1 = oblique(n, &par, th, &i1), e2 = oblique(2 * n, &par, th, &i2);
    printf("oblique wind (%g degrees): H error ratio %.3f, Richardson %.2e\n", th * 180 / acos(-1.0), e1 / e2,
           (4 * e2 - e1) / 3);
    CHECK(i1 >= 0 && i1 <= maxit && i2 >= 0 && i2 <= maxit);
    CHECK(fabs(e1) <= tol && e1 / e2 >= 3.8 && e1 / e2 <= 4.2 && fabs(4 * e2 - e1) / 3 <= rich);
}

/* 30 degrees at n = 800 and 1600: H within 5e-6, its Richardson extrapolation to 1e-7. */
static void test_oblique(void) { oblique_pair(30 * acos(-1.0) / 180, 800, 5e-6, 1e-7, 100); }

/* A wind within a few degrees of the span's direction (issue 27: it stalled at the
 * default maxit from the catenary of the mean drag, the load then nearly along the
 * chord): 5 degrees, from the funicular of the drag through the anchors (preshape.c), at
 * n = 800 and 1600 (measured -1.04e-4 and -2.51e-5, ratio 4.14, Richardson 1.2e-6; the
 * span runs steeply along the wind, so the mesh error is larger than at 30 degrees). */
static void test_near_axial(void) { oblique_pair(5 * acos(-1.0) / 180, 800, 2e-4, 5e-6, 30); }

int main(void)
{
    test_as_hload();
    test_parabola();
    test_follows();
    test_oblique();
    test_near_axial();
    CHECK_DONE();
}
