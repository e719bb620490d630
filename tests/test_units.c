/* Units (issue 27 item 5): `units F L` names the model's units and a value may carry its
 * own unit, converted to them. The same span (self-weight, a wind lineload, a point load,
 * a displaced support, in two steps) is written three ways:
 *   (a) kN m, every number in kN and m;
 *   (b) N mm, every number converted by hand (E in N/mm2 = MPa, A in mm2, w in N/mm);
 *   (c) kip ft, every number carrying its own unit (E=200GPa, A=314mm2, w=100N/m,
 *       length=250877.7mm, coordinates in m, the load in kN);
 * and gives the same displacements and reactions after conversion, to 1e-12, and the
 * same element forces to their resolution (see compare()) (the conversion factors are the definitions: 1 lbf = 4.4482216152605 N, 1 ft =
 * 0.3048 m). Bad units are file:line errors (tests/errors/units_*.cable). */
#include "catena.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define LBF 4.4482216152605

static const char *const model_a =
    "units kN m\ngravity 0 -1 0\nmaterial steel E=2.0e8\nsection strand material=steel A=3.14e-4 w=0.1\n"
    "node 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\ncable 1 2 section=strand n=20 length=250.8777\n"
    "step wind\nlineload all qz=0.05\nstep point\nload 11 0 -5 2\ndisplace 2 x=0.25\nsolve tol=1e-13\n";
static const char *const model_b =
    "units N mm\ngravity 0 -1 0\nmaterial steel E=2.0e5\nsection strand material=steel A=314 w=0.1\n"
    "node 1 0 0 0 fix=xyz\nnode 2 200000 0 0 fix=xyz\ncable 1 2 section=strand n=20 length=250877.7\n"
    "step wind\nlineload all qz=0.05\nstep point\nload 11 0 -5000 2000\ndisplace 2 x=250\nsolve tol=1e-13\n";
static const char *const model_c =
    "units kip ft\ngravity 0 -1 0\nmaterial steel E=200GPa\nsection strand material=steel A=314mm2 w=100N/m\n"
    "node 1 0 0 0 fix=xyz\nnode 2 200m 0 0 fix=xyz\ncable 1 2 section=strand n=20 length=250877.7mm\n"
    "step wind\nlineload all qz=0.05kN/m\nstep point\nload 11 0 -5kN 2000N\ndisplace 2 x=25cm\nsolve tol=1e-13\n";

typedef struct result {
    double d[3 * 21], N[20], R[3 * 21];
    int ok;
} result;

/* Solve text; lengths times lf and forces times ff give m and kN. */
static void run(const char *text, double lf, double ff, result *r)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    r->ok = 0;
    int rc = ctn_read_string(ctx, "units", text, strlen(text), &m, &opt);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (!rc) {
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        CHECK(sum.reason == CTN_CONVERGED);
        const double *d = ctn_solution_displacements(s), *R = ctn_solution_reactions(s);
        for (size_t i = 0; i < 3 * 21; i++) r->d[i] = d[i] * lf, r->R[i] = R[i] * ff;
        for (size_t e = 0; e < 20; e++) {
            ctn_element_state es;
            ctn_solution_element(s, e, &es);
            r->N[e] = es.force * ff;
        }
        r->ok = 1;
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static double compare(const result *a, const result *b)
{
    double dmax = 0, worst = 0;
    for (size_t i = 0; i < 3 * 21; i++) dmax = fmax(dmax, fabs(a->d[i]));
    for (size_t i = 0; i < 3 * 21; i++) {
        CHECK_CLOSE(b->d[i], a->d[i], 0, 1e-12 * dmax);
        CHECK_CLOSE(b->R[i], a->R[i], 1e-12, 1e-12 * a->N[0]);
        worst = fmax(worst, fabs(b->d[i] - a->d[i]) / (1e-12 * dmax));
    }
    /* An element force N = EA (l - l0) / l0 is resolved only to EA / l0 times the
     * resolution of its end positions: one ulp of the 200 m span moves it by
     * 62 800 / 12.544 x 2.8e-14 = 1.4e-10 kN (7e-12 relative), so it is asserted to
     * that resolution (two ulps of each end), the positions and reactions to 1e-12. */
    double res = 2.0e8 * 3.14e-4 / (250.8777 / 20) * 4 * (nextafter(200.0, 1e3) - 200.0);
    for (size_t e = 0; e < 20; e++) {
        CHECK_CLOSE(b->N[e], a->N[e], 0, res);
        worst = fmax(worst, fabs(b->N[e] - a->N[e]) / res);
    }
    return worst;
}

static void test_round_trip(void)
{
    result a, b, c;
    run(model_a, 1, 1, &a);
    run(model_b, 1e-3, 1e-3, &b);
    run(model_c, 0.3048, LBF, &c);
    if (!(a.ok && b.ok && c.ok)) return;
    double wb = compare(&a, &b), wc = compare(&a, &c);
    printf("largest difference (of 1e-12 of the displacements, or of the forces' resolution): N mm %.3g, kip ft "
           "%.3g\n", wb, wc);
}

/* The conversions themselves, read back from the model. */
static void test_values(void)
{
    const char *text = "units N mm\nmaterial steel E=200GPa\nsection s material=steel A=3.14cm2 w=100N/m mbl=140kN\n"
                       "node 1 0 0 0 fix=xyz\nnode 2 1ft 0 0\nelement 1 1 2 section=s l0=12in\n";
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "values", text, strlen(text), &m, &opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (!rc) {
        ctn_node_info p;
        ctn_element_info e;
        ctn_model_node(m, 1, &p);
        ctn_model_element(m, 0, &e);
        CHECK_CLOSE(p.X[0], 304.8, 1e-15, 0);
        CHECK_CLOSE(e.l0, 304.8, 1e-15, 0);
        CHECK_CLOSE(e.E, 2e5, 1e-15, 0);
        CHECK_CLOSE(e.A, 314, 1e-15, 0);
        CHECK_CLOSE(e.w, 0.1, 1e-15, 0);
        CHECK_CLOSE(e.capacity, 140e3, 1e-15, 0);
        CHECK_CLOSE(ctn_model_mpa_factor(m), 1.0, 1e-15, 0);
    }
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_round_trip();
    test_values();
    CHECK_DONE();
}
