/* Utilisation of beams (material fy=, section Wy= Wz= or by shape; post/beam_result.c)
 * against hand computation:
 * - the section moduli of a box b x h x t and a tube from their second moments summed
 *   from rectangles (Steiner) and the circle's closed form, over the extreme fibre;
 * - a cantilever (box, L = 0.5) with a tip force (P, Fy, Fz): at the root N = P,
 *   My = Fz L, Mz = Fy L, so stress |P|/A + |Fz| L / Wy + |Fy| L / Wz and utilisation
 *   stress / fy, in its end forces' statics (small loads: linear to 1e-6);
 * - a simply supported beam (tube, L = 2) under a lineload q and an axial pull P: the
 *   largest combined stress inside the element, P / A + q L^2 / (8 W), one element
 *   (the parabola's vertex);
 * - the group's max_utilisation and the worst beam are the largest element's;
 * - Wy=, Wz= given replace the shape's, and Iy= given keeps the shape's fibre. */
#include "check.h"
#include "run_text.h"

#include <stdio.h>

#define PI 3.14159265358979323846

static const double fy = 355e6;

static run solve(const char *name, const char *text)
{
    run r = run_text(name, text);
    CHECK_MSG(r.rc == CTN_OK, "%s: %s", name, r.ctx ? ctn_ctx_message(r.ctx) : "");
    return r;
}

/* A box b wide (y), h deep (z), wall t: A, Iy, Iz as four rectangles (Steiner). */
static void box_hand(double b, double h, double t, double *A, double *Iy, double *Iz)
{
    double hw = h - 2 * t, zf = (h - t) / 2, yw = (b - t) / 2;
    *A = 2 * b * t + 2 * t * hw;
    *Iy = 2 * (b * t * t * t / 12 + b * t * zf * zf) + 2 * (t * hw * hw * hw / 12);
    *Iz = 2 * (t * b * b * b / 12) + 2 * (hw * t * t * t / 12 + hw * t * yw * yw);
}

static void test_cantilever(void)
{
    const double b = 0.1, h = 0.2, t = 0.008, L = 0.5, P = -200, Fy = 40, Fz = -100;   /* P L^2 / 3EI: 3e-6 */
    double A, Iy, Iz;
    box_hand(b, h, t, &A, &Iy, &Iz);
    double Wy = Iy / (h / 2), Wz = Iz / (b / 2);
    char text[1024];
    snprintf(text, sizeof text,
             "material steel E=2.1e11 nu=0.3 fy=%.17g\n"
             "section box material=steel b=%g h=%g t=%g\n"
             "node 1 0 0 0 fix=xyzrxryrz\nnode 2 %g 0 0\n"
             "beam 1 1 2 section=box orient=0,0,1 n=3 group=mast\n"
             "load 2 %g %g %g\n", fy, b, h, t, L, P, Fy, Fz);
    run r = solve("cantilever", text);
    if (r.rc) {
        done(&r);
        return;
    }
    ctn_beam_result b0 = { .size = sizeof b0 };
    CHECK(ctn_solution_beam(r.m, r.s, 0, 0, &b0) == CTN_OK);
    double s = fabs(P) / A + fabs(Fz) * L / Wy + fabs(Fy) * L / Wz;
    CHECK_CLOSE(b0.stress, s, 1e-5, 0);
    CHECK_CLOSE(b0.utilisation, s / fy, 1e-5, 0);
    CHECK(b0.fy == fy);
    size_t e = 99;
    ctn_beam_result w = { .size = sizeof w };
    CHECK(ctn_solution_worst_beam(r.m, r.s, 0, &e, &w) == CTN_OK && e == 0 && w.utilisation == b0.utilisation);
    ctn_group_result g;
    CHECK(ctn_solution_group(r.m, r.s, 0, 0, &g) == CTN_OK);
    CHECK(g.has_capacity && g.max_utilisation == b0.utilisation && g.worst_element == 1);
    done(&r);
}

static void test_interior(void)
{
    const double d = 0.3, t = 0.02, L = 2, q = 13, P = 100;   /* P L^2 / EI: 1e-5 */
    double Di = d - 2 * t, A = PI * (d * d - Di * Di) / 4, W = PI * (d * d * d * d - Di * Di * Di * Di) / 64 / (d / 2);
    char text[1024];
    snprintf(text, sizeof text,
             "material steel E=2.1e11 nu=0.3 fy=%.17g\n"
             "section tube material=steel d=%g t=%g\n"
             "node 1 0 0 0 fix=xyzrx\nnode 2 %g 0 0 fix=yzrx\n"
             "beam 1 1 2 section=tube orient=0,0,1\n"
             "load 2 %g 0 0\nlineload all qz=%g\n", fy, d, t, L, P, -q);
    run r = solve("interior", text);
    if (r.rc) {
        done(&r);
        return;
    }
    ctn_beam_result b = { .size = sizeof b };
    CHECK(ctn_solution_beam(r.m, r.s, 0, 0, &b) == CTN_OK);
    CHECK_CLOSE(b.M_max, q * L * L / 8, 1e-5, 0);
    CHECK_CLOSE(b.stress, P / A + q * L * L / 8 / W, 1e-5, 0);
    CHECK_CLOSE(b.utilisation, b.stress / fy, 1e-15, 0);
    done(&r);
}

static void test_given_moduli(void)
{
    const char *text =
        "material steel E=2.1e11 nu=0.3 fy=235e6\n"
        "section a material=steel b=0.1 h=0.2 t=0.008 Wy=1e-4 Wz=5e-5\n"
        "section c material=steel b=0.1 h=0.2 t=0.008 Iy=3e-5\n"
        "node 1 0 0 0 fix=xyzrxryrz\nnode 2 3 0 0\nnode 3 0 1 0 fix=xyzrxryrz\nnode 4 3 1 0\n"
        "beam 1 1 2 section=a\nbeam 2 3 4 section=c\nload 2 0 0 -100\nload 4 0 0 -100\n";
    run r = solve("moduli", text);
    if (r.rc) {
        done(&r);
        return;
    }
    ctn_beam_result a = { .size = sizeof a }, c = { .size = sizeof c };
    CHECK(ctn_solution_beam(r.m, r.s, 0, 0, &a) == CTN_OK && ctn_solution_beam(r.m, r.s, 0, 1, &c) == CTN_OK);
    CHECK_CLOSE(a.stress, fabs(a.end[0][0]) / (0.1 * 0.2 - 0.084 * 0.184) + 300 / 1e-4, 1e-5, 0);
    CHECK_CLOSE(c.stress, fabs(c.end[0][0]) / (0.1 * 0.2 - 0.084 * 0.184) + 300 / (3e-5 / 0.1), 1e-5, 0);
    done(&r);
}

int main(void)
{
    test_cantilever();
    test_interior();
    test_given_moduli();
    CHECK_DONE();
}
