/* Meshed cables meeting at a free loaded node (a Y or bridle junction, a guy cluster):
 * the default method converges from what a user writes (straight lines or arcs to a
 * guessed junction, slack, equal to the chords or taut, the guess near or far), and its
 * answer is the exact one:
 * - the junction's position agrees with the same model of one exact elastic catenary
 *   (Irvine) per cable, within the meshes' discretization error, which falls as the
 *   mesh is refined at second order (n = 10, 20, 40);
 * - the reactions balance the loads and the weight;
 * - the answer does not depend on the guess (near or 60 m away, above the supports);
 * - a cluster whose supports all slide along the load has no equilibrium: not
 *   converged, with the reason "no equilibrium (a mechanism)" naming a node and
 *   direction, never a false convergence. */
#include "catena.h"
#include "check.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct result {
    int rc;
    ctn_solve_summary sum;
    double J[3];        /* the junction's position */
    double R[3];        /* sum of the reactions */
    double W[3];        /* sum of the external loads, weight included */
} result;

typedef struct spec {
    int K;              /* cables */
    int n;              /* elements per cable; 0: one catenary element per cable */
    double fac;         /* unstressed length / chord to the guess */
    double guess[3];    /* the junction the lengths are measured to */
    double P[3];        /* its load */
    const char *fix;    /* supports' fix= */
    int tension_only;
    int moved;          /* the junction given at `at`, not at the guess */
    double at[3];
} spec;

static const double sup[4][3] = { { 50, 0, 0 }, { -25, 43.3013, 15 }, { -25, -43.3013, -10 }, { 5, -30, 25 } };

static void model_text(const spec *sp, char *text, size_t size)
{
    size_t o = 0;
    o += (size_t)snprintf(text + o, size - o,
                          "units kN m\ngravity 0 0 -1\nmaterial m E=1e8 strain=engineering%s\n"
                          "section s material=m A=2e-3 w=1.5\n",
                          sp->tension_only ? " tension-only" : "");
    for (int i = 0; i < sp->K; i++)
        o += (size_t)snprintf(text + o, size - o, "node %d %g %g %g fix=%s\n", i + 1, sup[i][0], sup[i][1], sup[i][2],
                              sp->fix);
    const double *J = sp->moved ? sp->at : sp->guess;
    o += (size_t)snprintf(text + o, size - o, "node 9 %g %g %g\n", J[0], J[1], J[2]);
    for (int i = 0; i < sp->K; i++) {
        double c = 0;
        for (int k = 0; k < 3; k++) c += (sup[i][k] - sp->guess[k]) * (sup[i][k] - sp->guess[k]);
        double L = sp->fac * sqrt(c), cJ = 0;
        for (int k = 0; k < 3; k++) cJ += (sup[i][k] - J[k]) * (sup[i][k] - J[k]);
        if (sp->n == 0) o += (size_t)snprintf(text + o, size - o, "catenary %d %d 9 section=s length=%.9f\n", 100 + i, i + 1, L);
        else
            o += (size_t)snprintf(text + o, size - o, "cable %d 9 section=s n=%d length=%.9f%s\n", i + 1, sp->n, L,
                                  L > sqrt(cJ) ? "" : " shape=straight");
    }
    snprintf(text + o, size - o, "load 9 %g %g %g\n", sp->P[0], sp->P[1], sp->P[2]);
}

static result run(const spec *sp)
{
    char text[4096];
    result r;
    memset(&r, 0, sizeof r);
    model_text(sp, text, sizeof text);
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    r.rc = ctn_read_string(ctx, "junction.cable", text, strlen(text), &m, &opt);
    if (!r.rc) r.rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (!r.rc) {
        size_t nn = ctn_model_node_count(m), j;
        double *F = malloc(3 * nn * sizeof(double));
        ctn_solution_summary(s, &r.sum);
        ctn_model_node_index(m, 9, &j);
        ctn_node_info ni;
        ctn_model_node(m, j, &ni);
        const double *u = ctn_solution_displacements(s), *R = ctn_solution_reactions(s);
        ctn_model_external_forces(m, F);
        for (int k = 0; k < 3; k++) r.J[k] = ni.X[k] + u[3 * j + (size_t)k];
        for (size_t i = 0; i < nn; i++)
            for (int k = 0; k < 3; k++) {
                r.R[k] += R[3 * i + (size_t)k];
                r.W[k] += F ? F[3 * i + (size_t)k] : 0;
            }
        free(F);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return r;
}

static double dist(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Converged in few iterations, reactions balance the loads. */
static void check_solved(const char *what, const spec *sp, const result *r)
{
    CHECK_MSG(r->rc == CTN_OK && r->sum.reason == CTN_CONVERGED, "%s K=%d n=%d: %s after %d iterations", what, sp->K,
              sp->n, ctn_reason_name(r->sum.reason), r->sum.iterations);
    CHECK_MSG(r->sum.iterations <= 8, "%s K=%d n=%d: %d iterations", what, sp->K, sp->n, r->sum.iterations);
    double wn = sqrt(r->W[0] * r->W[0] + r->W[1] * r->W[1] + r->W[2] * r->W[2]);
    for (int k = 0; k < 3; k++)
        CHECK_MSG(fabs(r->R[k] + r->W[k]) <= 1e-9 * wn, "%s: reactions %g + loads %g != 0 (dir %d)", what, r->R[k], r->W[k], k);
}

/* The mesh's junction against the catenaries', with second-order convergence. */
static void test_against_catenary(int K, double fac, const double guess[3], const double P[3])
{
    spec sp = { K, 0, fac, { guess[0], guess[1], guess[2] }, { P[0], P[1], P[2] }, "xyz", 1, 0, { 0, 0, 0 } };
    result ref = run(&sp);
    CHECK_MSG(ref.sum.reason == CTN_CONVERGED, "catenary reference K=%d fac=%g: %s", K, fac, ctn_reason_name(ref.sum.reason));
    double err[3];
    int ns[3] = { 10, 20, 40 };
    for (int i = 0; i < 3; i++) {
        sp.n = ns[i];
        result r = run(&sp);
        check_solved("junction", &sp, &r);
        err[i] = dist(r.J, ref.J);
        printf("K=%d fac=%.3f n=%2d: %d iterations, junction (%.6f %.6f %.6f), catenaries' (%.6f %.6f %.6f), "
               "distance %.3e m\n",
               K, fac, ns[i], r.sum.iterations, r.J[0], r.J[1], r.J[2], ref.J[0], ref.J[1], ref.J[2], err[i]);
    }
    CHECK_MSG(err[0] < 0.05, "n=10 junction %.3e m from the catenaries'", err[0]);
    CHECK_MSG(err[1] < err[0] / 3 && err[2] < err[1] / 3, "no second-order convergence: %.3e %.3e %.3e", err[0],
              err[1], err[2]);
}

/* The same model (lengths of the chords to a guess near the answer) with its junction
 * given there and 60 m away, above the supports: one answer. */
static void test_guess(int K, double fac, int n)
{
    double P[3] = { 20, 10, -100 };
    spec near = { K, n, fac, { 8, -5, -12 }, { P[0], P[1], P[2] }, "xyz", 0, 0, { 0, 0, 0 } };
    spec far = near;
    far.moved = 1;
    far.at[0] = 30, far.at[1] = 25, far.at[2] = 30;
    result a = run(&near), b = run(&far);
    check_solved("near guess", &near, &a);
    CHECK_MSG(b.sum.reason == CTN_CONVERGED && b.sum.iterations <= 8, "far guess K=%d n=%d fac=%g: %s after %d iterations",
              K, n, fac, ctn_reason_name(b.sum.reason), b.sum.iterations);
    CHECK_MSG(dist(a.J, b.J) <= 1e-8 * 50, "far and near guesses: junctions %.3e m apart", dist(a.J, b.J));
}

/* Supports free to slide along x under a load with an x component: no equilibrium. */
static void test_mechanism(void)
{
    spec sp = { 3, 20, 1.05, { 0, 0, -10 }, { 20, 0, -100 }, "yz", 1, 0, { 0, 0, 0 } };
    result r = run(&sp);
    CHECK_MSG(r.rc == CTN_OK && r.sum.reason == CTN_DIVERGED_MECHANISM, "sliding supports: %s",
              ctn_reason_name(r.sum.reason));
    CHECK_MSG(r.sum.fail_node >= 1 && r.sum.fail_node <= 9 && r.sum.fail_dir == 0, "mechanism at node %d direction %d",
              r.sum.fail_node, r.sum.fail_dir);
}

int main(void)
{
    const double under[3] = { 0, 0, -20 }, off[3] = { 8, -5, -12 };
    const double down[3] = { 0, 0, -100 }, side[3] = { 40, 10, -60 };
    test_against_catenary(3, 1.05, off, down);
    test_against_catenary(3, 1.02, under, side);
    test_against_catenary(4, 1.05, off, side);
    test_against_catenary(4, 1.0, under, down);
    test_guess(3, 1.05, 20);
    test_guess(4, 0.998, 20);
    test_guess(3, 1.0, 40);
    test_mechanism();
    CHECK_DONE();
}
