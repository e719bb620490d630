/* Mass of the catenary and pulley families in modal analysis, against closed forms:
 * - element matrices: a catenary element's are a cable element's of the same unstressed
 *   length; a pulley's rope mass is shared by its segments in proportion to their input
 *   lengths; total mass and rigid-body translation exact (both matrices);
 * - a mass on a taut line of two weightless catenary elements (a bar under tension N):
 *   the transverse pair at omega^2 = 2 (N / l) / m_mid and the axial mode at
 *   2 (EA / L) / m_mid, m_mid = m' L (lumped) or 2 m' L / 3 (consistent);
 * - the same line as one pulley over the middle node: the transverse pair at
 *   2 (N / l) / m_mid, m_mid = m' L / 2 or m' L / 3 (L the whole rope), and a zero mode
 *   along the rope (the node slides);
 * - with every mode asked for, the effective masses sum to the moving mass r^T M r, which
 *   is m_mid for either matrix (the consistent one couples part of the mass to the
 *   supports, where it does not move). */
#include "element/catenary.h"
#include "element/pulley.h"
#include "catena.h"
#include "check.h"
#include "run_text.h"

#include <math.h>

#define PI 3.14159265358979323846

/* M r for the rigid translation r along d of an nn-node element's packed matrix P. */
static void translate(const double *P, int nn, int d, double *f)
{
    const int n = 3 * nn;
    for (int i = 0; i < n; i++) {
        f[i] = 0;
        for (int j = 0; j < n; j++)
            if (j % 3 == d) f[i] += P[i <= j ? ctn_packed_index(n, i, j) : ctn_packed_index(n, j, i)];
    }
}

static void test_element_matrices(void)
{
    ctn_catenary_props cp = { .EA = 1e4, .l0 = 2.5, .l0_ref = 2.5, .A = 1e-4, .mass = 7.5 };
    ctn_cable_props cb = { .EA = 1e4, .l0 = 2.5, .l0_ref = 2.5, .A = 1e-4, .mass = 7.5 };
    ctn_pulley_props pp = { .cable = { .EA = 1e4, .l0 = 6, .A = 1e-4, .mass = 12 }, .nnodes = 3, .l0_ref = 6 };
    const double X[9] = { 0, 0, 0, 3, 4, 0, 3, 4, 1 };         /* segments of 5 and 1 */
    for (int lumped = 0; lumped < 2; lumped++) {
        double Pc[21], Pb[21], Pp[45], f[9];
        ctn_catenary2_ops.mass(&cp, X, lumped, Pc);
        ctn_cable2_ops.mass(&cb, X, lumped, Pb);
        for (int t = 0; t < 21; t++) CHECK(Pc[t] == Pb[t]);
        ctn_pulley_ops.mass(&pp, X, lumped, Pp);
        for (int d = 0; d < 3; d++) {
            translate(Pp, 3, d, f);
            const double node[3] = { 5, 6, 1 };                /* shares 10 and 2, halved */
            for (int i = 0; i < 9; i++) CHECK_CLOSE(f[i], i % 3 == d ? node[i / 3] : 0.0, 1e-15, 1e-15);
        }
        CHECK(Pp[ctn_packed_index(9, 0, 3)] == (lumped ? 0.0 : 10.0 / 6));   /* consistent: segment 1 */
        CHECK(Pp[ctn_packed_index(9, 0, 6)] == 0.0);                         /* no coupling across */
    }
}

static double omega2(const run *r, size_t k)
{
    ctn_mode md;
    return ctn_solution_mode(r->s, k, &md) ? NAN : md.eigenvalue;
}

/* Nodes 1 and 3 pinned 20 m apart, node 2 free between them; weightless rope of mass
 * 0.5 t/m, EA = 1e4 kN, unstressed 19.8 m in all: N = EA (20 - 19.8) / 19.8. */
static void test_line(int pulley, int lumped)
{
    const double EA = 1e4, L = 19.8, mp = 0.5, N = EA * (20 - L) / L;
    char text[768];
    snprintf(text, sizeof text,
             "units kN m\nmaterial steel E=1e8 strain=engineering\nsection s material=steel A=1e-4 mass=%g\n"
             "node 1 0 0 0 fix=xyz\nnode 2 10 0 0\nnode 3 20 0 0 fix=xyz\n%s\nmodes count=3 mass=%s\n", mp,
             pulley ? "pulley 1 1 2 3 section=s length=19.8"
                    : "catenary 1 1 2 section=s length=9.9\ncatenary 2 2 3 section=s length=9.9",
             lumped ? "lumped" : "consistent");
    run r = run_text("test.cable", text);
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
    if (r.rc == CTN_OK) {
        CHECK(ctn_solution_mode_count(r.s) == 3);
        double mmid = lumped ? mp * L / 2 : mp * L / 3;
        double wt = 2 * (N / 10) / mmid;
        ctn_modal_summary ms;                   /* all modes: effective masses sum to it */
        CHECK(ctn_solution_modal_summary(r.s, &ms) == CTN_OK);
        for (int d = 0; d < 3; d++) {
            double sum = 0;
            for (size_t k = 0; k < 3; k++) {
                ctn_mode md;
                if (ctn_solution_mode(r.s, k, &md) == CTN_OK) sum += md.effective_mass[d];
            }
            CHECK_CLOSE(ms.total_mass[d], mmid, 1e-14, 0);
            CHECK_CLOSE(sum, mmid, 1e-12, 0);
        }
        if (pulley) {
            CHECK(fabs(omega2(&r, 0)) <= 1e-9 * wt);           /* sliding along the rope */
            ctn_mode md;
            CHECK(ctn_solution_mode(r.s, 0, &md) == CTN_OK && md.kind == CTN_MODE_ZERO);
            CHECK_CLOSE(omega2(&r, 1), wt, 1e-9, 0);
            CHECK_CLOSE(omega2(&r, 2), wt, 1e-9, 0);
        } else {
            CHECK_CLOSE(omega2(&r, 0), wt, 1e-9, 0);
            CHECK_CLOSE(omega2(&r, 1), wt, 1e-9, 0);
            CHECK_CLOSE(omega2(&r, 2), 2 * (EA / (L / 2)) / mmid, 1e-9, 0);
        }
    }
    done(&r);
}

int main(void)
{
    test_element_matrices();
    for (int lumped = 0; lumped < 2; lumped++) {
        test_line(0, lumped);
        test_line(1, lumped);
    }
    CHECK_DONE();
}
