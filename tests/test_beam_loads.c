/* Uniform loads on beams (lineload on beams, their weight; element/beam3_model.c's
 * line_load, model/lineload.c; the end forces with the fixed-end actions,
 * post/beam_result.c), against the closed forms of Euler-Bernoulli beams (small loads:
 * the deflections below 1e-4 of the span, the geometric non-linearity below 1e-8):
 * - a clamped-clamped beam, one element: end moments q L^2 / 12 and shears q L / 2 in
 *   its end forces, moment_max q L^2 / 12; two elements: q L^2 / 24 at mid-span;
 * - a simply supported beam: one element gives the end rotation q L^3 / (24 EI) and
 *   moment_max q L^2 / 8 (the parabola's vertex), n = 2, 4, 8 the mid-span deflection
 *   5 q L^4 / (384 EI) (the consistent loads make the cubic elements exact at nodes);
 * - a propped cantilever hinged at the prop (one element, and four): q L^2 / 8 at the
 *   clamp, the reactions 5 q L / 8 and 3 q L / 8, the mid-span deflection q L^4 / (192 EI);
 * - an inclined simply supported beam (a horizontal roller) under a vertical load per
 *   unstressed length: the load stays vertical; its normal part q cos(a) bends it,
 *   q cos(a) L^2 / 8;
 * - the weight w along gravity equals the lineload q = w g (forces and moments);
 * - a lineload of a load case: the case's end forces carry its fixed-end actions. */
#include "check.h"
#include "run_text.h"

#include <stdarg.h>
#include <stdio.h>

#define PI 3.14159265358979323846

static const double E = 2.1e11, Iy = 2e-6, A = 1e-2, q = 10, L = 6;

#define HEAD(extra) "material steel E=2.1e11 nu=0.3\nsection s material=steel A=1e-2 Iy=2e-6 Iz=3e-6 J=4e-6" extra "\n"

static run solve(const char *name, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static run solve(const char *name, const char *fmt, ...)
{
    char text[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    run r = run_text(name, text);
    CHECK_MSG(r.rc == CTN_OK, "%s: %s", name, r.ctx ? ctn_ctx_message(r.ctx) : "");
    return r;
}

/* The end forces of element index i at the last step. */
static ctn_beam_result beam_at(const run *r, size_t i)
{
    ctn_beam_result b = { .size = sizeof b };
    CHECK(ctn_solution_beam(r->m, r->s, ctn_solution_step_count(r->s) - 1, i, &b) == CTN_OK);
    return b;
}

static int node_state(const run *r, int id, double u[3], double th[3])
{
    size_t i;
    if (ctn_model_node_index(r->m, id, &i)) return 1;
    const double *d = ctn_solution_displacements(r->s), *rot = ctn_solution_rotations(r->s);
    for (int j = 0; j < 3; j++) {
        u[j] = d[3 * i + j];
        th[j] = rot[3 * i + j];
    }
    return 0;
}

static void test_clamped(void)
{
    for (int n = 1; n <= 2; n++) {
        run r = solve("clamped", HEAD("") "node 1 0 0 0 fix=xyzrxryrz\nnode 2 %g 0 0 fix=yzrxryrz\n"
                      "beam 1 1 2 section=s orient=0,0,1 n=%d\nlineload all qz=%g\n", L, n, -q);
        if (r.rc) {
            done(&r);
            continue;
        }
        ctn_beam_result b = beam_at(&r, 0);
        CHECK_CLOSE(b.end[0][4], -q * L * L / 12, 1e-8, 0);   /* hogging at the clamp */
        CHECK_CLOSE(b.end[0][2], q * L / 2, 1e-8, 0);
        if (n == 1) {
            CHECK_CLOSE(b.end[1][4], q * L * L / 12, 1e-8, 0);
            CHECK_CLOSE(b.end[1][2], q * L / 2, 1e-8, 0);
            CHECK_CLOSE(b.M_max, q * L * L / 12, 1e-8, 0);
        } else {
            CHECK_CLOSE(b.end[1][4], -q * L * L / 24, 1e-8, 0);   /* sagging at mid-span */
            CHECK(fabs(b.end[1][2]) < 1e-8 * q * L);               /* no shear there */
            ctn_beam_result c = beam_at(&r, 1);
            CHECK_CLOSE(c.end[0][4], q * L * L / 24, 1e-8, 0);
        }
        done(&r);
    }
}

static void test_simply_supported(void)
{
    for (int n = 1; n <= 8; n *= 2) {
        run r = solve("simple", HEAD("") "node 1 0 0 0 fix=xyzrx\nnode 2 %g 0 0 fix=yzrx\n"
                      "beam 1 1 2 section=s orient=0,0,1 n=%d\nlineload all qz=%g\n", L, n, -q);
        if (r.rc) {
            done(&r);
            continue;
        }
        double u[3], th[3] = { 0, 0, 0 };
        CHECK(node_state(&r, 1, u, th) == 0);
        CHECK_CLOSE(th[1], q * L * L * L / (24 * E * Iy), 1e-7, 0);   /* -dw/dx > 0: the end turns about +y */
        if (n == 1) {
            ctn_beam_result b = beam_at(&r, 0);
            CHECK_CLOSE(b.M_max, q * L * L / 8, 1e-8, 0);
            CHECK(fabs(b.end[0][4]) < 1e-9 * q * L * L);
            done(&r);
            continue;
        }
        size_t mid = 0, nn = ctn_model_node_count(r.m);
        for (size_t i = 0; i < nn; i++) {
            ctn_node_info ni;
            ctn_model_node(r.m, i, &ni);
            if (fabs(ni.X[0] - L / 2) < 1e-12) mid = i;
        }
        CHECK_CLOSE(ctn_solution_displacements(r.s)[3 * mid + 2], -5 * q * L * L * L * L / (384 * E * Iy), 1e-7, 0);
        done(&r);
    }
}

/* A propped cantilever of one element hinged at the prop (release=2:ryrz) under q: the
 * hinge's share of the load moment condensed onto the clamp and the shears: the clamp's
 * q L^2 / 8 and 5 q L / 8, the prop's 3 q L / 8 (its support clamped: the hinge is the
 * member's), the mid-span deflection q L^4 / (192 EI) with n = 4,
 * the member's largest moment the clamp's (9 q L^2 / 128 inside is less); with n = 4 the
 * same reactions. */
static void test_propped(void)
{
    for (int n = 1; n <= 4; n *= 4) {
        run r = solve("propped", HEAD("") "node 1 0 0 0 fix=xyzrxryrz\nnode 2 %g 0 0 fix=yzrxryrz\n"
                      "beam 1 1 2 section=s orient=0,0,1 n=%d release=2:ry\nlineload all qz=%g\n", L, n, -q);
        if (r.rc) {
            done(&r);
            continue;
        }
        const double *R = ctn_solution_reactions(r.s), *M = ctn_solution_reaction_moments(r.s);
        CHECK_CLOSE(R[2], 5 * q * L / 8, 1e-8, 0);
        CHECK_CLOSE(R[5], 3 * q * L / 8, 1e-8, 0);
        CHECK_CLOSE(M[1], -q * L * L / 8, 1e-8, 0);   /* the clamp's hogging moment */
        CHECK(fabs(M[4]) < 1e-12 * q * L * L);          /* the hinge's support takes none */
        if (n == 1) {
            ctn_beam_result b = beam_at(&r, 0);
            CHECK(b.end[1][4] == 0);
            CHECK_CLOSE(b.end[0][4], -q * L * L / 8, 1e-8, 0);
            CHECK_CLOSE(b.end[1][2], 3 * q * L / 8, 1e-8, 0);
            CHECK_CLOSE(b.M_max, q * L * L / 8, 1e-8, 0);
        } else {                                       /* mid-span: q L^4 / (192 EI) */
            size_t mid = 0, nn = ctn_model_node_count(r.m);
            for (size_t i = 0; i < nn; i++) {
                ctn_node_info ni;
                ctn_model_node(r.m, i, &ni);
                if (fabs(ni.X[0] - L / 2) < 1e-12) mid = i;
            }
            CHECK_CLOSE(ctn_solution_displacements(r.s)[3 * mid + 2], -q * L * L * L * L / (192 * E * Iy), 1e-7, 0);
        }
        done(&r);
    }
}

static void test_inclined(void)
{
    double a = PI / 6, c = cos(a), s = sin(a);
    run r = solve("inclined", HEAD("") "node 1 0 0 0 fix=xyzrx\nnode 2 %.17g 0 %.17g fix=yzrx\n"
                  "beam 1 1 2 section=s orient=0,1,0\nlineload all qz=%g\n", L * c, L * s, -q);
    if (r.rc) {
        done(&r);
        return;
    }
    ctn_beam_result b = beam_at(&r, 0);
    CHECK_CLOSE(b.M_max, q * c * L * L / 8, 1e-7, 0);
    const double *R = ctn_solution_reactions(r.s);
    CHECK_CLOSE(R[2] + R[5], q * L, 1e-8, 0);       /* the load stays vertical: q L0 (to the solve's tolerance) */
    CHECK(fabs(R[0]) < 1e-8 * q * L);                /* nothing along x */
    done(&r);
}

static void test_weight(void)
{
    const char *geo = "node 1 0 0 0 fix=xyzrxryrz\nnode 2 4 1 2\nnode 3 8 0 3 fix=xyzrxryrz\n"
                      "beam 1 1 2 section=s n=3\nbeam 2 2 3 section=s n=3\nload 2 100 200 -300\n";
    run a = solve("weight", HEAD(" w=25") "gravity 0 0 -1\n%s", geo);
    run b = solve("lineload", HEAD("") "%slineload all qz=-25\n", geo);
    if (!a.rc && !b.rc) {
        size_t ne = ctn_model_element_count(a.m), nn = ctn_model_node_count(a.m);
        const double *da = ctn_solution_displacements(a.s), *db = ctn_solution_displacements(b.s);
        const double *ra = ctn_solution_rotations(a.s), *rb = ctn_solution_rotations(b.s);
        for (size_t i = 0; i < 3 * nn; i++) {
            CHECK_CLOSE(da[i], db[i], 1e-10, 1e-16);
            CHECK_CLOSE(ra[i], rb[i], 1e-10, 1e-16);
        }
        for (size_t e = 0; e < ne; e++) {
            ctn_beam_result x = beam_at(&a, e), y = beam_at(&b, e);
            for (int j = 0; j < 6; j++) CHECK_CLOSE(x.end[0][j], y.end[0][j], 1e-9, 1e-9);
            CHECK_CLOSE(x.M_max, y.M_max, 1e-9, 1e-9);
        }
    }
    done(&a);
    done(&b);
}

static void test_case(void)
{
    run r = solve("case", HEAD("") "node 1 0 0 0 fix=xyzrxryrz\nnode 2 %g 0 0 fix=yzrxryrz\n"
                  "beam 1 1 2 section=s orient=0,0,1\ncase deck\nlineload all qz=%g\n", L, -q);
    if (r.rc) {
        done(&r);
        return;
    }
    CHECK(ctn_solution_case_count(r.s) == 1);
    const ctn_solution *cs = ctn_solution_case(r.s, 0);
    if (cs) {
        ctn_beam_result b = { .size = sizeof b };
        CHECK(ctn_solution_beam(r.m, cs, 0, 0, &b) == CTN_OK);
        CHECK_CLOSE(b.end[0][4], -q * L * L / 12, 1e-8, 0);
        CHECK_CLOSE(b.end[1][2], q * L / 2, 1e-8, 0);
    }
    ctn_beam_result b0 = beam_at(&r, 0);             /* the base state: unloaded */
    CHECK(b0.M_max == 0);
    done(&r);
}

int main(void)
{
    test_clamped();
    test_simply_supported();
    test_propped();
    test_inclined();
    test_weight();
    test_case();
    (void)A;
    CHECK_DONE();
}
