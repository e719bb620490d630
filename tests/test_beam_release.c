/* Beam end releases (beam ... release=END:DOFS, element/beam3_release.c) in solved
 * models, against closed forms:
 * - a propped cantilever (clamped at x = 0, the member hinged at x = L onto a clamped
 *   roller) under a point load P at mid-span, in both bending planes (Iy != Iz):
 *   the deflection under the load 7 P L^3 / (768 EI), the clamp's moment 3 P L / 16,
 *   the prop's reaction 5 P / 16, no moment at the hinge (end forces 0 there);
 * - a portal frame whose beam is hinged to both columns (release=1:ryrz,2:ryrz): the
 *   beam is a link of stiffness EA / L between two cantilever columns of 3 EI / h^3; a
 *   side load H gives the sways H (k + ka) / (k (k + 2 ka)) and ka / (k + ka) of it,
 *   the base moments k sway h, no moment at the column tops;
 * - a two-bar truss of fully released beams (release=1:rxryrz,2:rxryrz) under a large
 *   load (non-linear) gives the answer of the same truss of cable elements of
 *   engineering strain to round-off. */
#include "check.h"
#include "run_text.h"

#include <stdio.h>

static const double E = 2.1e11, Iy = 2e-6, Iz = 3e-6, A = 1e-3;

/* Translations of node `id` at the last step. */
static int node_u(const run *r, int id, double u[3])
{
    size_t i;
    ctn_step_result st;
    if (ctn_model_node_index(r->m, id, &i) || ctn_solution_step(r->s, 0, &st)) return 1;
    for (int j = 0; j < 3; j++) u[j] = st.d[3 * i + j];
    return 0;
}

/* Reaction force and moment at node id. */
static void reaction(const run *r, int id, double F[3], double M[3])
{
    size_t i;
    CHECK(ctn_model_node_index(r->m, id, &i) == CTN_OK);
    const double *R = ctn_solution_reactions(r->s), *Rm = ctn_solution_reaction_moments(r->s);
    for (int j = 0; j < 3; j++) {
        F[j] = R[3 * i + j];
        M[j] = Rm[3 * i + j];
    }
}

/* The end forces of the element of id `id`. */
static void end_forces(const run *r, int id, ctn_beam_result *b)
{
    size_t n = ctn_model_element_count(r->m);
    b->size = sizeof *b;
    for (size_t i = 0; i < n; i++) {
        ctn_element_info ei;
        if (ctn_model_element(r->m, i, &ei) == CTN_OK && ei.id == id) {
            CHECK(ctn_solution_beam(r->m, r->s, 0, i, b) == CTN_OK);
            return;
        }
    }
    CHECK_MSG(0, "no element %d", id);
}

static void test_propped(void)
{
    const double L = 5, P = 200, Q = 300;           /* P along -z (bends about y), Q along y */
    char text[1024];
    snprintf(text, sizeof text,
             "material steel E=%.17g nu=0.3\n"
             "section s material=steel A=%.17g Iy=%.17g Iz=%.17g J=4e-6\n"
             "node 1 0 0 0 fix=xyzrxryrz\nnode 2 %.17g 0 0\nnode 3 %.17g 0 0 fix=yzrxryrz\n"
             "beam 1 1 2 section=s orient=0,0,1 n=4\n"
             "beam 2 2 3 section=s orient=0,0,1 n=4 release=2:ryrz\n"
             "load 2 0 %.17g %.17g\n", E, A, Iy, Iz, L / 2, L, Q, -P);
    run r = run_text("propped", text);
    CHECK_MSG(r.rc == CTN_OK, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
    if (r.rc) {
        done(&r);
        return;
    }
    double u[3], F[3], M[3];
    CHECK(node_u(&r, 2, u) == 0);
    CHECK_CLOSE(u[2], -7 * P * L * L * L / (768 * E * Iy), 1e-7, 0);
    CHECK_CLOSE(u[1], 7 * Q * L * L * L / (768 * E * Iz), 1e-7, 0);
    reaction(&r, 3, F, M);
    CHECK_CLOSE(F[2], 5 * P / 16, 1e-7, 0);
    CHECK_CLOSE(F[1], -5 * Q / 16, 1e-7, 0);
    /* the hinge: no moment but the torque's share about the turned member (its slope 1e-4 squared) */
    CHECK_MSG(fabs(M[1]) < 1e-7 * P * L && fabs(M[2]) < 1e-7 * P * L, "%g %g", M[1], M[2]);
    reaction(&r, 1, F, M);
    CHECK_CLOSE(M[1], -3 * P * L / 16, 1e-7, 0);     /* the clamp's hogging moment */
    CHECK_CLOSE(M[2], -3 * Q * L / 16, 1e-7, 0);
    ctn_beam_result b;
    end_forces(&r, 2, &b);                           /* the member's last element: hinge at NODE2 */
    size_t last = ctn_model_element_count(r.m) - 1;
    CHECK(ctn_solution_beam(r.m, r.s, 0, last, &b) == CTN_OK);
    CHECK(b.end[1][4] == 0 && b.end[1][5] == 0);
    CHECK_CLOSE(b.end[1][2], 5 * P / 16, 1e-6, 0);  /* the shear the prop takes */
    CHECK_CLOSE(b.end[0][4], 5 * P / 16 * (L / 8), 1e-6, 0);   /* the moment one element from the hinge */
    done(&r);
}

static void test_portal(void)
{
    const double h = 4, L = 6, H = 5;     /* sway 1.3e-4: linear to 1e-8 */
    char text[1024];
    snprintf(text, sizeof text,
             "material steel E=%.17g nu=0.3\n"
             "section s material=steel A=%.17g Iy=%.17g Iz=%.17g J=4e-6\n"
             "node 1 0 0 0 fix=xyzrxryrz\nnode 2 %.17g 0 0 fix=xyzrxryrz\n"
             "node 3 0 0 %.17g fix=y\nnode 4 %.17g 0 %.17g fix=y\n"
             "beam 1 1 3 section=s orient=1,0,0 n=4\nbeam 2 2 4 section=s orient=1,0,0 n=4\n"
             "beam 3 3 4 section=s orient=0,0,1 n=3 release=1:ryrz,2:ryrz\n"
             "load 3 %.17g 0 0\n", E, A, Iy, Iz, L, h, L, h, H);
    run r = run_text("portal", text);
    CHECK_MSG(r.rc == CTN_OK, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
    if (r.rc) {
        done(&r);
        return;
    }
    double k = 3 * E * Iy / (h * h * h), ka = E * A / L;   /* columns bend about local y (orient x) */
    double d1 = H * (k + ka) / (k * (k + 2 * ka)), d2 = ka / (k + ka) * d1, u[3], F[3], M[3];
    CHECK(node_u(&r, 3, u) == 0);
    CHECK_CLOSE(u[0], d1, 1e-6, 0);
    CHECK(node_u(&r, 4, u) == 0);
    CHECK_CLOSE(u[0], d2, 1e-6, 0);
    reaction(&r, 1, F, M);
    CHECK_CLOSE(M[1], -k * d1 * h, 1e-6, 0);   /* against the overturning H h */
    reaction(&r, 2, F, M);
    CHECK_CLOSE(M[1], -k * d2 * h, 1e-6, 0);
    CHECK_CLOSE(F[0], -k * d2, 1e-6, 0);
    ctn_beam_result b;
    end_forces(&r, 3, &b);                           /* the link: no moment at its hinge */
    CHECK(b.end[0][4] == 0 && b.end[0][5] == 0);
    CHECK_CLOSE(b.N, -k * d2, 1e-6, 0);        /* it pushes the far column */
    done(&r);
}

static void test_truss(void)
{
    static const char *const fmt =
        "material m E=2e11 nu=0.3 strain=engineering\n"
        "section s material=m A=1e-4 Iy=1e-6 Iz=2e-6 J=1e-6\n"
        "node 1 0 0 0 fix=xyz%s\nnode 2 4 0 0 fix=xyz%s\nnode 3 2 0.2 0.1%s\n"
        "%s\n"
        "load 3 1e4 -2e5 5e4\n";
    char a[1024], b[1024];
    snprintf(a, sizeof a, fmt, "rxryrz", "rxryrz", " fix=rxryrz",
             "beam 1 1 3 section=s release=1:rxryrz,2:rxryrz\nbeam 2 3 2 section=s release=1:rxryrz,2:rxryrz");
    snprintf(b, sizeof b, fmt, "", "", "", "element 1 1 3 section=s\nelement 2 3 2 section=s");
    run rb = run_text("beams", a), rc = run_text("cables", b);
    double ub[3], uc[3];
    if (!rb.rc && !rc.rc && !node_u(&rb, 3, ub) && !node_u(&rc, 3, uc)) {
        CHECK(uc[1] < -0.3);                          /* through the snap: non-linear */
        for (int j = 0; j < 3; j++) CHECK_CLOSE(ub[j], uc[j], 1e-12, 1e-15);
        for (size_t e = 0; e < 2; e++) {
            ctn_element_state sb, sc;
            CHECK(ctn_solution_element(rb.s, e, &sb) == CTN_OK && ctn_solution_element(rc.s, e, &sc) == CTN_OK);
            CHECK_CLOSE(sb.force, sc.force, 1e-11, 0);
        }
    } else {
        CHECK_MSG(0, "%s / %s", ctn_ctx_message(rb.ctx), ctn_ctx_message(rc.ctx));
    }
    done(&rb);
    done(&rc);
}

int main(void)
{
    test_propped();
    test_portal();
    test_truss();
    CHECK_DONE();
}
