/* Loads and cases, the rest of issue 27 (docs/format.md, docs/validation.md):
 * - units on mass=: a section's mass per length and a node's point mass given in kg/m
 *   and kg are converted to the model's consistent mass unit (force s^2/length): t/m in
 *   kN m, t/mm in N mm, slug/ft in lbf ft (exact ratios of the unit definitions);
 * - wind on an iced cable: where ice covers an element in the same solve (a step's
 *   totals, a case and its installed state, a combination), the drag is cd p (d + 2T):
 *   (a) a weightless level span under a horizontal wind with a weightless ice sleeve is
 *       the elastic parabola under q = cd p (d + 2T) per unit span (ctn_parabola_solve,
 *       H to 1e-6 with 800 elements), not under cd p d;
 *   (b) with weight, ice weight and wind, the reactions along the wind sum to
 *       cd p (d + 2T) times the deformed chords' projections and those along gravity to
 *       (w + w_ice) L0 (1e-10: the residual's sum at the free DOFs); the wind case alone uses d, the combination
 *       ice + wind and a step after an ice step use d + 2T;
 * - each step's and case's JSON `cables` (sag, max/min tension, stretched length) of a
 *   level 200 m span of L0 = 204 m, EA = 62800 kN, w = 0.1 kN/m at three temperatures
 *   (two steps, a case) against Irvine's elastic catenary of L0 (1 + alpha dT) and
 *   w L0 / (L0 (1 + alpha dT)) (ctn_ecatenary_solve): the catenary element to 1e-9; the
 *   400-element cable's sag to 1e-5 and its element forces against the closed form's
 *   tension at the first and the middle element's mid-point to 1e-5 (the O(h^2) of the
 *   mesh, h = 0.51 m: measured 3e-6), its stretched length to 1e-6. */
#include "catena.h"
#include "check.h"
#include "model/model.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

static ctn_model *read(ctn_ctx *ctx, const char *text, ctn_solve_options *opt)
{
    ctn_model *m = NULL;
    int rc = ctn_read_string(ctx, "cases2", text, strlen(text), &m, opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    return m;
}

static void mass_case(const char *units, const char *X2, double expect_section, double expect_node)
{
    char text[512];
    snprintf(text, sizeof text,
             "units %s\nmaterial steel E=2e8\nsection s material=steel A=1 mass=10.2kg/m\nnode 1 0 0 0 fix=xyz\n"
             "node 2 %s 0 0 mass=12kg\nelement 1 1 2 section=s\n", units, X2);
    ctn_ctx *ctx = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    ctn_model *m = read(ctx, text, &opt);
    if (m) {
        printf("units %-7s mass=10.2kg/m -> %.17g, mass=12kg -> %.17g\n", units, m->sections.v[0].mass, m->nodes.v[1].mass);
        CHECK_CLOSE(m->sections.v[0].mass, expect_section, 1e-14, 0);
        CHECK_CLOSE(m->nodes.v[1].mass, expect_node, 1e-14, 0);
    }
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_mass_units(void)
{
    double slug = 4.4482216152605 / 0.3048;         /* kg: 1 lbf s^2/ft */
    mass_case("kN m", "10", 10.2e-3, 12e-3);        /* t/m, t */
    mass_case("N mm", "10000", 10.2e-6, 12e-3);     /* t/mm, t */
    mass_case("lbf ft", "30", 10.2 * 0.3048 / slug, 12 / slug);   /* slug/ft, slug */
}

/* A level 100 m span of 130 m, n elements: gravity, the section's keys and the loads. */
static const char *const SPAN =
    "units kN m\n%s\nmaterial steel E=2.0e8 strain=engineering\nsection s material=steel A=1e-3%s\n"
    "node 1 0 0 0 fix=xyz\nnode 2 100 0 0 fix=xyz\ncable 1 2 section=s n=%d length=130\n%s\nsolve tol=1e-12%s\n";

/* H and the reactions along the wind of the weightless span under `loads`. */
static void parabola_case(const char *what, const char *loads, double q)
{
    char text[1024];
    snprintf(text, sizeof text, SPAN, "gravity 0 1 0   # the arc's start and the ice's direction", "", 800, loads, "");
    ctn_ctx *ctx = NULL;
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read(ctx, text, &opt);
    int rc = m ? ctn_solve(ctx, m, &opt, &s) : CTN_ERR_MODEL;
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    ctn_parabola_in in = { 100, 0, q, 130, 2.0e8 * 1e-3 };
    ctn_parabola par;
    CHECK(ctn_parabola_solve(ctx, &in, &par) == CTN_OK);
    if (!rc) {
        const double *R = ctn_solution_reactions(s);
        printf("wind %s: H %.10g, the elastic parabola under %.6g kN/m %.10g (%+.2e)\n", what, -R[0], q, par.H,
               -R[0] / par.H - 1);
        CHECK_CLOSE(-R[0], par.H, 1e-6, 0);
        CHECK_CLOSE(-(R[1] + R[4]), q * 100, 1e-9, 0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_iced_parabola(void)
{
    double cdp = 1.2 * 500, d = 0.03, T = 0.012;                            /* kN/m^2, m */
    parabola_case("iced", "ice all thickness=12mm density=0kg/m3 d=30mm\nwind all dir=0,1,0 pressure=500kPa cd=1.2 d=30mm",
                  cdp * (d + 2 * T));
    parabola_case("bare", "wind all dir=0,1,0 pressure=500kPa cd=1.2 d=30mm", cdp * d);
}

/* Sum of the chords' projections on the plane normal to y, at displacements d. */
static double projected(const ctn_model *m, const double *d)
{
    double proj = 0;
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_info ei;
        ctn_node_info p, r;
        ctn_model_element(m, e, &ei);
        ctn_model_node(m, (size_t)ei.nodes[0], &p);
        ctn_model_node(m, (size_t)ei.nodes[1], &r);
        size_t a = 3 * (size_t)ei.nodes[0], b = 3 * (size_t)ei.nodes[1];
        proj += hypot(r.X[0] - p.X[0] + d[b] - d[a], r.X[2] - p.X[2] + d[b + 2] - d[a + 2]);
    }
    return proj;
}

/* One solution's balance: along the wind, qw times the deformed projection; along
 * gravity, the weight wt. Both to 1e-10: the reactions differ from the loads by the sum of
 * the residual's components at the 120 free DOFs, each within tol = 1e-12 of |f_ext|. */
static void balance(const ctn_model *m, const ctn_solution *s, const char *what, double qw, double wt)
{
    const double *R = ctn_solution_reactions(s), *d = ctn_solution_displacements(s);
    double proj = projected(m, d);
    printf("%-22s reactions along the wind %.12g, q x projection %.12g; along gravity %.12g, weight %.12g\n", what,
           -(R[1] + R[4]), qw * proj, R[2] + R[5], wt);
    CHECK_CLOSE(-(R[1] + R[4]), qw * proj, 1e-10, 1e-12);
    CHECK_CLOSE(R[2] + R[5], wt, 1e-10, 0);
}

static void test_iced_balance(void)
{
    char text[1024];
    double w = 0.01, L0 = 130, cdp = 0.5 * 1.25e-3 * 30 * 30, d = 0.0281, T = 0.01;
    double wi = 0.9 * 9.80665 * PI * T * (d + T);                               /* t/m3 g pi T (d + T) */
    snprintf(text, sizeof text, SPAN, "gravity 0 0 -1", " w=0.01", 40,
             "step install\ncase ice\nice all thickness=10mm density=900kg/m3 d=28.1mm\ncase wind\n"
             "wind all dir=0,1,0 speed=30 rho=1.25kg/m3 d=28.1mm\ncombination both 1*ice + 1*wind\n"
             "step iced\nice all thickness=10mm density=900kg/m3 d=28.1mm\nstep windy\n"
             "wind all dir=0,1,0 speed=30 rho=1.25kg/m3 d=28.1mm", " method=newton steps=10");
    ctn_ctx *ctx = NULL;
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read(ctx, text, &opt);
    int rc = m ? ctn_solve(ctx, m, &opt, &s) : CTN_ERR_MODEL;
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (!rc) {
        CHECK(ctn_solution_case_count(s) == 3);
        balance(m, ctn_solution_case(s, 0), "case ice", 0, (w + wi) * L0);
        balance(m, ctn_solution_case(s, 1), "case wind (bare d)", cdp * d, w * L0);
        balance(m, ctn_solution_case(s, 2), "ice + wind (d + 2T)", cdp * (d + 2 * T), (w + wi) * L0);
        balance(m, s, "steps ice, wind", cdp * (d + 2 * T), (w + wi) * L0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* A level span as a 400-element cable (nodes 1-2) and a catenary element (3-4), two steps
 * and a case at three temperatures. */
static const char *const STATES =
    "units kN m\ngravity 0 -1 0\nmaterial steel E=2.0e8 strain=engineering alpha=1.2e-5\n"
    "section strand material=steel A=3.14e-4 w=0.1\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n"
    "node 3 0 0 50 fix=xyz\nnode 4 200 0 50 fix=xyz\ncable 1 2 section=strand n=400 length=204\n"
    "catenary 9001 3 4 section=strand length=204\nstep install\nstep hot\ntemperature all dT=40\n"
    "case cold from=install\ntemperature all dT=-30\nsolve tol=1e-12\n";

static double num(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    CHECK_MSG(cJSON_IsNumber(v), "no number '%s'", key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

/* The entry's two cables against the elastic catenary at temperature change dT. */
static void check_state(ctn_ctx *ctx, const cJSON *entry, double dT)
{
    const double L0 = 204 * (1 + 1.2e-5 * dT), w = 0.1 * 204 / L0, h = L0 / 400;
    ctn_ecatenary_in in = { 200, 0, w, 2.0e8 * 3.14e-4, L0 };
    ctn_ecatenary cat;
    double T_end = 0, T_mid = 0;
    CHECK(ctn_ecatenary_solve(ctx, &in, &cat) == CTN_OK);
    CHECK(ctn_ecatenary_tension_s(&cat, h / 2, &T_end) == CTN_OK);
    CHECK(ctn_ecatenary_tension_s(&cat, L0 / 2 - h / 2, &T_mid) == CTN_OK);
    const cJSON *cables = cJSON_GetObjectItemCaseSensitive(entry, "cables");
    const cJSON *fe = cJSON_GetArrayItem(cables, 0), *ce = cJSON_GetArrayItem(cables, 1);
    CHECK(cJSON_GetArraySize(cables) == 2 && fe && ce);
    if (!fe || !ce) return;
    printf("dT %+3.0f: sag %.10g (cable %+.1e, catenary %+.1e); T max %.10g (%+.1e, %+.1e); T min %.10g (%+.1e, "
           "%+.1e); length %.10g (%+.1e, %+.1e)\n", dT, cat.sum.sag_mid, num(fe, "sag") / cat.sum.sag_mid - 1,
           num(ce, "sag") / cat.sum.sag_mid - 1, cat.sum.T_max, num(fe, "max_tension") / T_end - 1,
           num(ce, "max_tension") / cat.sum.T_max - 1, cat.sum.T_min, num(fe, "min_tension") / T_mid - 1,
           num(ce, "min_tension") / cat.sum.T_min - 1, cat.sum.length, num(fe, "stretched_length") / cat.sum.length - 1,
           num(ce, "stretched_length") / cat.sum.length - 1);
    CHECK_CLOSE(num(ce, "sag"), cat.sum.sag_mid, 1e-9, 0);
    CHECK_CLOSE(num(ce, "max_tension"), cat.sum.T_max, 1e-9, 0);
    CHECK_CLOSE(num(ce, "min_tension"), cat.sum.T_min, 1e-9, 0);
    CHECK_CLOSE(num(ce, "stretched_length"), cat.sum.length, 1e-9, 0);
    CHECK_CLOSE(num(fe, "sag"), cat.sum.sag_mid, 1e-5, 0);
    CHECK_CLOSE(num(fe, "max_tension"), T_end, 1e-5, 0);
    CHECK_CLOSE(num(fe, "min_tension"), T_mid, 1e-5, 0);
    CHECK_CLOSE(num(fe, "stretched_length"), cat.sum.length, 1e-6, 0);
    CHECK_CLOSE(num(fe, "unstressed_length"), 204, 1e-12, 0);
}

static void test_cable_states(void)
{
    ctn_ctx *ctx = NULL;
    ctn_solve_options opt;
    ctn_solution *s = NULL;
    char *json = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read(ctx, STATES, &opt);
    int rc = m ? ctn_solve(ctx, m, &opt, &s) : CTN_ERR_MODEL;
    if (!rc) rc = ctn_result_json(ctx, m, s, 0, &json);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    cJSON *d = rc ? NULL : cJSON_Parse(json);
    const cJSON *steps = cJSON_GetObjectItemCaseSensitive(d, "steps");
    const cJSON *cases = cJSON_GetObjectItemCaseSensitive(d, "cases");
    CHECK(cJSON_GetArraySize(steps) == 2 && cJSON_GetArraySize(cases) == 1);
    if (cJSON_GetArraySize(steps) == 2 && cJSON_GetArraySize(cases) == 1) {
        check_state(ctx, cJSON_GetArrayItem(steps, 0), 0);
        check_state(ctx, cJSON_GetArrayItem(steps, 1), 40);
        check_state(ctx, cJSON_GetArrayItem(cases, 0), -30);
    }
    cJSON_Delete(d);
    ctn_json_free(json);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_mass_units();
    test_iced_parabola();
    test_iced_balance();
    test_cable_states();
    CHECK_DONE();
}
