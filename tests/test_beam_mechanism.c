/* Beam mechanisms from an unstressed start (issue 23): the corrector's stretch
 * correction (problem/stretch.c, analysis/static/correct.c). Against closed forms and
 * equilibrium:
 * - a chain of three hinged links (2 m, 4 elements each, release=1:ryrz), pinned at a
 *   support, horizontal at the start, loaded by P at each joint: it must swing down by
 *   90 degrees as a mechanism. Hanging, every node is on the vertical below the pin, the
 *   links stretched by their tensions 3P, 2P, P (l = L0 (1 + N / E A)), turned by
 *   pi / 2 about y. Converged within one increment's 50 iterations (the default
 *   strategy took 550 and failed before);
 * - a conductor between two strain insulator strings (beams hinged at the arms, weight
 *   0.35 kN/m), then follower wind (`wind`) on the conductor: converged (it failed
 *   before), and the reactions balance the weight of every member and the wind's drag
 *   recomputed here from the solved chords (q = cd p d per projected length); within 50
 *   iterations (130 when the merit rejected the Newton steps of the strings' swing:
 *   analysis/static/correct.c, the watchdog; 32 with it).
 * ctest-cost: 2 */
#include "check.h"
#include "run_text.h"
#include "model/model.h"

#include <stdio.h>

#define PI 3.14159265358979323846

/* The current position x (3) of node id at the last step and, if rot, its rotation. */
static int position(const run *r, int id, double x[3], double rot[3])
{
    size_t i, k = ctn_solution_step_count(r->s) - 1;
    ctn_step_result st;
    const double *th = NULL, *mo = NULL;
    if (ctn_model_node_index(r->m, id, &i) || ctn_solution_step(r->s, k, &st)) return 1;
    if (rot && ctn_solution_step_rotations(r->s, k, &th, &mo)) return 1;
    for (int j = 0; j < 3; j++) {
        x[j] = r->m->nodes.v[i].X[j] + st.d[3 * i + j];
        if (rot) rot[j] = th[3 * i + j];
    }
    return 0;
}

static void test_chain(void)
{
    const double P = 1000, EA = 2e11 * 1e-3;
    run r = run_text("chain", "material steel E=2e11 nu=0.3\n"
                              "section s material=steel A=1e-3 Iy=1e-6 Iz=1e-6 J=2e-6\n"
                              "node 1 0 0 0 fix=xyz\nnode 2 2 0 0\nnode 3 4 0 0\nnode 4 6 0 0\n"
                              "beam 1 1 2 section=s n=4\n"
                              "beam 2 2 3 section=s n=4 release=1:ryrz\n"
                              "beam 3 3 4 section=s n=4 release=1:ryrz\n"
                              "load 2 0 0 -1000\nload 3 0 0 -1000\nload 4 0 0 -1000\n");
    ctn_solve_summary sum;
    if (r.rc) {
        CHECK_MSG(0, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
        done(&r);
        return;
    }
    ctn_solution_summary(r.s, &sum);
    printf("hinged chain: %d iterations\n", sum.iterations);
    CHECK(sum.iterations <= 50);
    double z = 0, x[3], rot[3];
    const int joint[3] = { 2, 3, 4 };
    for (int k = 0; k < 3; k++) {
        z -= 2 * (1 + (3 - k) * P / EA);
        CHECK(position(&r, joint[k], x, rot) == 0);
        CHECK(fabs(x[0]) < 1e-9 && fabs(x[1]) < 1e-9);
        CHECK_CLOSE(x[2], z, 1e-12, 0);
    }
    CHECK(position(&r, 2, x, rot) == 0);
    CHECK_CLOSE(rot[1], PI / 2, 1e-9, 0);
    done(&r);
}

static void test_insulators(void)
{
    const double q = 0.6 * 0.0281, w[2] = { 0.35, 0.0159 };
    run r = run_text("insulators", "units kN m\ngravity 0 0 -1\n"
                                   "material glass E=50GPa nu=0.2\n"
                                   "material acsr E=69GPa strain=engineering tension-only\n"
                                   "section insulator material=glass d=0.12 w=0.35\n"
                                   "section conductor material=acsr A=434.3mm2 w=0.0159\n"
                                   "node 1 0 0 0 fix=xyzrxryrz\nnode 2 3 0 0\n"
                                   "node 3 300 0 0 fix=xyzrxryrz\nnode 4 297 0 0\n"
                                   "beam 1 1 2 section=insulator orient=0,0,1 release=1:ryrz\n"
                                   "beam 2 3 4 section=insulator orient=0,0,1 release=1:ryrz\n"
                                   "cable 2 4 section=conductor n=40 length=294.04 group=conductors\n"
                                   "step still\nstep wind\n"
                                   "wind conductors dir=0,1,0 pressure=0.6 d=0.0281\n");
    if (r.rc) {
        CHECK_MSG(0, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
        done(&r);
        return;
    }
    double W = 0, D = 0, R[3] = { 0, 0, 0 };
    const double *re = ctn_solution_reactions(r.s);
    ctn_solve_summary sum;
    ctn_solution_summary(r.s, &sum);
    printf("insulators: %d iterations\n", sum.iterations);
    CHECK(sum.iterations <= 50);          /* 130 before the corrector's watchdog */
    for (size_t e = 0; e < r.m->elements.n; e++) {    /* the weights, and the wind's drag */
        const ctn_element *el = &r.m->elements.v[e];
        const int *nd = ctn_elem_nodes(r.m, e);
        int beam = e < 2;
        W += w[!beam] * el->l0;
        if (beam) continue;
        double a[3], b[3];
        CHECK(position(&r, r.m->nodes.v[nd[0]].id, a, NULL) == 0 && position(&r, r.m->nodes.v[nd[1]].id, b, NULL) == 0);
        D += q * hypot(b[0] - a[0], b[2] - a[2]);     /* the chord projected normal to y */
    }
    for (size_t i = 0; i < r.m->nodes.n; i++)
        for (int j = 0; j < 3; j++) R[j] += re[3 * i + j];
    printf("insulators: weight %.6f, drag %.6f, reactions %.6f %.6f %.6f\n", W, D, R[0], R[1], R[2]);
    CHECK_CLOSE(R[2], W, 1e-9, 0);
    CHECK_CLOSE(R[1], -D, 1e-9, 0);
    CHECK(fabs(R[0]) < 1e-9 * W);
    done(&r);
}

int main(void)
{
    test_chain();
    test_insulators();
    CHECK_DONE();
}
