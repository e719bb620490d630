/* A transmission line span under EN 50341-style load cases (issue 27, acceptance): one
 * installed state (the conductor strung to a 10.5 m sag under its weight, its length
 * found by the sag target), then independent cases from it: minimum temperature, ice,
 * wind, maximum temperature, and the combinations ice + wind and 1.35 ice + 1.5 wind.
 * Each case and combination, meshed finely, is checked against the elastic catenary
 * (Irvine, engineering strain: ctn_ecatenary_solve, an independent closed form) of its
 * own load per unstressed length in the plane it swings to:
 *   temperature dT: unstressed length L0 (1 + alpha dT), the same weight w L0 over it;
 *   ice q_i (a lineload along gravity): w + q_i;
 *   wind q_w (a lineload across the span): sqrt(w^2 + q_w^2), the plane swung;
 *   a combination: the resultant of w and the factored loads.
 * H, the support tension and the sag in the swung plane agree to 1e-6. */
#include "catena.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define SPAN 350.0
#define W 0.01594
#define QI 0.0163
#define QW 0.0095
#define EA (6.9e7 * 4.68e-4)
#define ALPHA 1.9e-5
#define N 800

static const char *const text =
    "units kN m\ngravity 0 0 -1\nmaterial acsr E=6.9e7 strain=engineering alpha=1.9e-5\n"
    "section drake material=acsr A=4.68e-4 w=0.01594 mbl=140 safety=2.5\n"
    "node 1 0 0 0 fix=xyz\nnode 2 350 0 0 fix=xyz\ncable 1 2 section=drake n=800 sag=10.5 group=conductor\n"
    "step install\ncase cold\ntemperature all dT=-25\ncase ice\nlineload conductor qz=-0.0163\n"
    "case wind\nlineload conductor qy=0.0095\ncase hot\ntemperature all dT=65\n"
    "combination ice_wind 1*ice + 0.5*wind\ncombination ULS 1.35*ice + 1.5*wind\nsolve tol=1e-12\n";

/* Load per unstressed length (y, z) and temperature change of each case. */
static const struct { const char *name; double qy, qz, dT; } cases[] = {
    { "cold", 0, -W, -25 }, { "ice", 0, -W - QI, 0 }, { "wind", QW, -W, 0 }, { "hot", 0, -W, 65 },
    { "ice_wind", 0.5 * QW, -W - QI, 0 }, { "ULS", 1.5 * QW, -W - 1.35 * QI, 0 },
};

static void check_case(const ctn_model *m, const ctn_solution *cs, size_t i, double L0)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double r = hypot(cases[i].qy, cases[i].qz), eu[3] = { 0, -cases[i].qy / r, -cases[i].qz / r };
    double L = L0 * (1 + ALPHA * cases[i].dT);
    ctn_ecatenary_in in = { SPAN, 0, r * L0 / L, EA, L };      /* the same weight over L */
    ctn_ecatenary cat;
    CHECK(ctn_ecatenary_solve(ctx, &in, &cat) == CTN_OK);
    ctn_step_result st;
    CHECK(ctn_solution_step(cs, 0, &st) == CTN_OK && st.reason == CTN_CONVERGED);
    const double *R = st.react, *d = st.d;
    double H = -R[0], T = sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2]), sag = 0;
    for (size_t p = 0; p < ctn_model_node_count(m); p++) {
        ctn_node_info nd;
        ctn_model_node(m, p, &nd);
        double x[3] = { nd.X[0] + d[3 * p], nd.X[1] + d[3 * p + 1], nd.X[2] + d[3 * p + 2] };
        sag = fmax(sag, -(x[1] * eu[1] + x[2] * eu[2]));
    }
    printf("%-9s H %.10g (%+.2e)  T %.10g (%+.2e)  sag %.10g (%+.2e)\n", cases[i].name, H, H / cat.H - 1, T,
           T / cat.sum.T_max - 1, sag, sag / cat.sum.sag - 1);
    CHECK_CLOSE(H, cat.H, 1e-6, 0);
    CHECK_CLOSE(T, cat.sum.T_max, 1e-6, 0);
    CHECK_CLOSE(sag, cat.sum.sag, 1e-6, 0);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "line", text, strlen(text), &m, &opt);
    if (!rc) rc = ctn_model_resolve_targets(ctx, m, &opt, NULL);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    ctn_cable_info c;
    if (!rc && ctn_model_cable(m, 0, &c) == CTN_OK && ctn_solution_case_count(s) == 6) {
        for (size_t i = 0; i < 6; i++) {
            const char *name = NULL;
            ctn_model_case_info(m, i, &name, NULL, NULL);
            CHECK(!strcmp(name, cases[i].name));
            check_case(m, ctn_solution_case(s, i), i, c.length);
        }
    } else {
        CHECK(0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
