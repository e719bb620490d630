/* The corotational beam (element/beam3.c) in solved models, against closed forms and
 * published values:
 * - a cantilever under small tip loads and a torque: P L^3 / (3 E I), P L^2 / (2 E I)
 *   about each local axis as orient= sets them, Timoshenko's P L / (G As) with shear
 *   areas, T L / (G J);
 * - a cantilever under an end moment: the tip rotation M L / EI exactly, the nodes on
 *   the polygon of chords L/n turning by M (L/n) / EI (the element's closed form) and
 *   O(h^2) close to Euler's circle of radius EI / M; M = 2 pi EI / L rolls it into a
 *   full circle, the tip back at the root;
 * - Bathe and Bolourchi's 45-degree bend, 8 elements: the published tip displacements at
 *   P = 300, 450, 600;
 * - a mesh of beams (a space frame) moved rigidly by 90 degrees about x, y, z and a
 *   skew axis: no internal force;
 * - a stiff straight beam pulled along its axis gives the answer of the same member of
 *   cable elements (engineering strain) to round-off;
 * - a guyed mast (beam mast clamped at its base, three cables to anchors, a side load):
 *   the reactions and the base moment balance the loads;
 * - sections by their dimensions against independent sums (grid integration, plates). */
#include "check.h"
#include "run_text.h"
#include "element/beam3.h"
#include "model/model.h"

#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

/* Translations u and rotations r (0 in a model without) of node `id` at step k. */
static int node_state(const run *r, size_t k, int id, double u[3], double rot[3])
{
    size_t i;
    ctn_step_result st;
    const double *th = NULL, *mo = NULL;
    if (ctn_model_node_index(r->m, id, &i) || ctn_solution_step(r->s, k, &st)) return 1;
    if (ctn_solution_has_rotations(r->s) && ctn_solution_step_rotations(r->s, k, &th, &mo)) return 1;
    for (int j = 0; j < 3; j++) {
        u[j] = st.d[3 * i + j];
        rot[j] = th ? th[3 * i + j] : 0;            /* a model without rotations: 0 */
    }
    return 0;
}

static const char *const cantilever_head =
    "material steel E=2e11 G=8e10\n"
    "section s material=steel A=1e-2 Iy=2e-6 Iz=8e-6 J=3e-6%s\n"
    "node 1 0 0 0 fix=xyzrxryrz\n"
    "node 2 4 0 0\n"
    "beam 1 1 2 section=s orient=%s n=4\n"
    "load 2 %g %g %g %g 0 0\n";

/* The root element's end forces (ctn_solution_beam) against the statics of the
 * cantilever: the clamp holds the member against the load F (3) at the tip, displaced
 * to x (3): the root node applies -F and the moment -(x x F), in the root element's
 * local axes (x, y, z here: the chord turns by 1e-5 at most, so a component of F of
 * 1e-5 |F| moves between the axes). */
static void check_root(const run *r, const double F[3], const double x[3])
{
    ctn_beam_result b = { .size = sizeof b };
    CHECK(ctn_solution_beam(r->m, r->s, 0, 0, &b) == CTN_OK);
    CHECK(ctn_solution_beam(r->m, r->s, 1, 0, &b) == CTN_ERR_INVALID);
    const double M[3] = { x[1] * F[2] - x[2] * F[1], x[2] * F[0] - x[0] * F[2], x[0] * F[1] - x[1] * F[0] };
    for (int j = 0; j < 3; j++) {
        CHECK_CLOSE(b.end[0][j], -F[j], 1e-6, 1e-5);
        CHECK_CLOSE(b.end[0][3 + j], -M[j], 1e-6, 1e-5);
    }
    CHECK_CLOSE(b.M_max, hypot(M[1], M[2]), 1e-6, 1e-9);
}

/* One cantilever run: tip translations and rotations. */
static int cantilever(const char *shear, const char *orient, double Fy, double Fz, double T, double u[3], double rot[3])
{
    char text[1024];
    snprintf(text, sizeof text, cantilever_head, shear, orient, 0.0, Fy, Fz, T);
    run r = run_text("cantilever", text);
    int rc = r.rc || node_state(&r, 0, 2, u, rot);
    CHECK_MSG(rc == 0, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
    if (!rc && !strcmp(orient, "0,0,1") && T == 0) {
        const double F[3] = { 0, Fy, Fz }, x[3] = { 4 + u[0], u[1], u[2] };
        check_root(&r, F, x);
    }
    done(&r);
    return rc;
}

static void test_cantilever(void)
{
    const double E = 2e11, G = 8e10, L = 4, P = 1, Iy = 2e-6, Iz = 8e-6, J = 3e-6, As = 1e-2 * 5 / 6;
    double u[3], r[3];
    if (!cantilever("", "0,0,1", 0, -P, 0, u, r)) {         /* local z = global z: bending about y */
        CHECK_CLOSE(u[2], -P * L * L * L / (3 * E * Iy), 1e-7, 0);
        CHECK_CLOSE(r[1], P * L * L / (2 * E * Iy), 1e-7, 0);
        CHECK(fabs(u[1]) < 1e-15 && fabs(r[0]) < 1e-15 && fabs(r[2]) < 1e-15);
    }
    if (!cantilever("", "0,0,1", P, 0, 0, u, r)) {          /* along global y: about local z */
        CHECK_CLOSE(u[1], P * L * L * L / (3 * E * Iz), 1e-7, 0);
        CHECK_CLOSE(r[2], P * L * L / (2 * E * Iz), 1e-7, 0);
    }
    if (!cantilever("", "0,1,0", P, 0, 0, u, r)) {          /* local z = global y: about local y */
        CHECK_CLOSE(u[1], P * L * L * L / (3 * E * Iy), 1e-7, 0);
    }
    if (!cantilever(" Asy=0.008333333333333333 Asz=0.008333333333333333", "0,0,1", 0, -P, 0, u, r))
        CHECK_CLOSE(u[2], -(P * L * L * L / (3 * E * Iy) + P * L / (G * As)), 1e-7, 0);
    if (!cantilever("", "0,0,1", 0, 0, P, u, r)) {           /* a torque */
        CHECK_CLOSE(r[0], P * L / (G * J), 1e-7, 0);
        CHECK(fabs(u[0]) < 1e-12 && fabs(u[1]) < 1e-15 && fabs(u[2]) < 1e-15);
    }
}

/* A cantilever of n elements (L = 10, EI = 1e5) under the end moment lambda 2 pi EI / L
 * about z, in `steps` load steps. */
static void rolled(int n, double lambda, int steps, double u[3], double rot[3], double *mroot)
{
    const double L = 10, EI = 1e5, M = lambda * 2 * PI * EI / L;
    char text[1024];
    snprintf(text, sizeof text,
             "material m E=1e7 G=5e6\n"
             "section s material=m A=1 Iy=1e-2 Iz=1e-2 J=1e-2\n"
             "node 1 0 0 0 fix=xyzrxryrz\n"
             "node 2 10 0 0 fix=zrxry\n"
             "beam 1 1 2 section=s orient=0,0,1 n=%d\n"
             "load 2 0 0 0 0 0 %.17g\n"
             "solve steps=%d\n", n, M, steps);
    run r = run_text("rolled", text);
    memset(u, 0, 3 * sizeof *u);
    if (r.rc || node_state(&r, 0, 2, u, rot)) {
        CHECK_MSG(0, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
    } else {
        const double *mo = ctn_solution_reaction_moments(r.s);
        *mroot = mo[2];
    }
    done(&r);
}

static void test_roll_up(void)
{
    const double L = 10;
    double u[3], r[3], m0 = 0;
    rolled(20, 1.0, 20, u, r, &m0);                     /* the full circle */
    CHECK_CLOSE(r[2], 2 * PI, 1e-12, 0);
    CHECK(fabs(u[0] + L) < 1e-9 * L && fabs(u[1]) < 1e-9 * L);
    CHECK_CLOSE(m0, -2 * PI * 1e5 / L, 1e-9, 0);
    double err[2];
    for (int q = 0; q < 2; q++) {                       /* half the moment: a half circle */
        int n = 10 << q;
        rolled(n, 0.5, 8, u, r, &m0);
        double phi = PI, pe = phi / n, x = 0, y = 0;
        CHECK_CLOSE(r[2], phi, 1e-12, 0);
        double c = L / n * (1 - pe * pe / 24);         /* no axial force: the chord is the
                                                           arc shortened by the bowing,
                                                           int w'^2 / 2 = 5 (pe/2)^2 L0 / 30 */
        for (int k = 0; k < n; k++) {                   /* chords c at (k + 1/2) pe */
            x += c * cos((k + 0.5) * pe);
            y += c * sin((k + 0.5) * pe);
        }
        CHECK(fabs(L + u[0] - x) < 1e-9 * L && fabs(u[1] - y) < 1e-9 * L);
        double R = L / phi;                             /* Euler: radius EI / M */
        err[q] = hypot(L + u[0] - R * sin(phi), u[1] - R * (1 - cos(phi)));
        CHECK(err[q] < pe * pe / 10 * L);
    }
    CHECK_CLOSE(err[0] / err[1], 16.0, 0.05, 0);        /* O(h^4): the chords are 2 R sin(pe/2)
                                                           to O(pe^4) */
}

/* The 45-degree bend: published tip displacements (Bathe and Bolourchi 1979, as
 * tabulated by Simo and Vu-Quoc 1986: tip positions (58.84, 22.33, 40.08),
 * (52.32, 18.62, 48.39), (47.23, 15.79, 53.37) from (70.71, 29.29, 0)), to the 0.25 by
 * which published 8-element solutions differ among themselves. */
static void test_bend45(void)
{
    static const double pub[3][3] = { { 58.84, 22.33, 40.08 }, { 52.32, 18.62, 48.39 }, { 47.23, 15.79, 53.37 } };
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    fprintf(f, "material m E=1e7 nu=0\nsection s material=m A=1 Iy=%.17g Iz=%.17g J=%.17g\n", 1.0 / 12, 1.0 / 12, 1.0 / 6);
    for (int k = 0; k <= 8; k++) {
        double p = PI / 4 * k / 8;
        fprintf(f, "node %d %.17g %.17g 0%s\n", k + 1, 100 * sin(p), 100 * (1 - cos(p)), k ? "" : " fix=xyzrxryrz");
    }
    for (int k = 1; k <= 8; k++) fprintf(f, "beam %d %d %d section=s orient=0,0,1\n", k, k, k + 1);
    fprintf(f, "solve method=newton linear_solver=cholmod-ldl\n"
               "step P300 substeps=6\nload 9 0 0 300\nstep P450 substeps=3\nload 9 0 0 150\n"
               "step P600 substeps=3\nload 9 0 0 150\n");
    fclose(f);
    run r = run_text("bend45", text);
    CHECK(r.rc == CTN_OK && ctn_solution_step_count(r.s) == 3);
    for (size_t k = 0; !r.rc && k < 3; k++) {
        double u[3], rot[3], X[3] = { 100 * sin(PI / 4), 100 * (1 - cos(PI / 4)), 0 };
        CHECK(node_state(&r, k, 9, u, rot) == 0);
        for (int j = 0; j < 3; j++)
            CHECK_MSG(fabs(X[j] + u[j] - pub[k][j]) < 0.25, "step %zu, %c: %.4f published %.2f", k, "xyz"[j], X[j] + u[j], pub[k][j]);
    }
    done(&r);
    free(text);
}

/* A space frame of beams (three members of two elements each, several orientations) is
 * moved rigidly by 90 degrees about axis n: every element's forces vanish (to the
 * round-off of its axial stiffness). */
static void rigid_frame(const double n[3])
{
    static const char *const frame =
        "material m E=2e11 nu=0.3\n"
        "section s material=m A=1e-2 Iy=1e-4 Iz=2e-4 J=1e-4\n"
        "node 1 0 0 0\nnode 2 4 0 0\nnode 3 4 3 1\nnode 4 4 3 6\n"
        "beam 1 1 2 section=s orient=0,0,1 n=2\n"
        "beam 2 2 3 section=s orient=1,1,1 n=2\n"
        "beam 3 3 4 section=s n=2\n";
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solve_options opt;
    CHECK(ctn_ctx_create(&ctx) == CTN_OK && ctn_read_string(ctx, "frame", frame, strlen(frame), &m, &opt) == CTN_OK);
    if (!m) { ctn_ctx_destroy(&ctx); return; }
    double t = PI / 2, c = cos(t), s = sin(t), C = 1 - c, Q[9] = {
        c + n[0] * n[0] * C, n[0] * n[1] * C - n[2] * s, n[0] * n[2] * C + n[1] * s,
        n[1] * n[0] * C + n[2] * s, c + n[1] * n[1] * C, n[1] * n[2] * C - n[0] * s,
        n[2] * n[0] * C - n[1] * s, n[2] * n[1] * C + n[0] * s, c + n[2] * n[2] * C };
    const ctn_element_ops *ops = ctn_element_family(ctn_element_family_find("beam"));
    for (size_t e = 0; e < m->elements.n; e++) {
        ctn_beam_props p;
        double X[6], u[12], f[12], fmax = 0;
        const int *nd = ctn_elem_nodes(m, e);
        ops->setup(m, e, &p);
        for (int a = 0; a < 2; a++) {
            memcpy(X + 3 * a, m->nodes.v[nd[a]].X, sizeof(double) * 3);
            for (int i = 0; i < 3; i++) {
                double x = 0;
                for (int j = 0; j < 3; j++) x += Q[3 * i + j] * X[3 * a + j];
                u[6 * a + i] = x - X[3 * a + i] + 7.0 * (i + 1);      /* and a translation */
                u[6 * a + 3 + i] = t * n[i];
            }
        }
        CHECK(ops->eval(&p, 0, X, u, f, NULL, NULL) == 0);
        for (int k = 0; k < 12; k++) fmax = fmax > fabs(f[k]) ? fmax : fabs(f[k]);
        CHECK_MSG(fmax < 1e-14 * p.EA, "element %zu: largest force %g", e, fmax);
    }
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_rigid(void)
{
    const double axes[4][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.26726124191242440, 0.53452248382484879, 0.80178372573727319 } };
    for (int k = 0; k < 4; k++) rigid_frame(axes[k]);
}

/* A straight member along (3, 4, 12)/13 pulled at its tip along its axis: four beam
 * elements and four cable elements (engineering strain) of the same E A. */
static void test_truss(void)
{
    static const char *const fmt =
        "material m E=2e11 nu=0.3 strain=engineering\n"
        "section s material=m A=1e-3 Iy=1e-6 Iz=1e-6 J=1e-6\n"
        "node 1 0 0 0 fix=xyz%s\nnode 2 3 4 12\n"
        "%s\n"
        "load 2 %.17g %.17g %.17g 0 0 0\n";          /* zero moments: on any node */
    const double P = 5e5;
    char a[1024], b[1024];
    snprintf(a, sizeof a, fmt, "rxryrz", "beam 1 1 2 section=s n=4", P * 3 / 13, P * 4 / 13, P * 12 / 13);
    snprintf(b, sizeof b, fmt, "", "node 3 0.75 1 3\nnode 4 1.5 2 6\nnode 5 2.25 3 9\n"
             "element 1 1 3 section=s\nelement 2 3 4 section=s\nelement 3 4 5 section=s\nelement 4 5 2 section=s",
             P * 3 / 13, P * 4 / 13, P * 12 / 13);
    run rb = run_text("beam", a), rc = run_text("cables", b);
    double ub[3], uc[3], r[3];
    if (!rb.rc && !rc.rc && !node_state(&rb, 0, 2, ub, r) && !node_state(&rc, 0, 2, uc, r)) {
        double d = P * 13 / (2e11 * 1e-3);              /* N l0 / EA along the axis */
        for (int j = 0; j < 3; j++) {
            CHECK_CLOSE(ub[j], uc[j], 1e-12, 0);
            CHECK_CLOSE(ub[j], d * (j == 0 ? 3 : j == 1 ? 4 : 12) / 13, 1e-12, 0);
        }
    } else {
        CHECK_MSG(0, "%s / %s", ctn_ctx_message(rb.ctx), ctn_ctx_message(rc.ctx));
    }
    done(&rb);
    done(&rc);
}

/* A guyed mast: a beam mast of 20 clamped at its base, three guys (cable elements,
 * 0.5 % short) from its top to anchors at 12 around it, a side load at the top.
 * The support reactions balance the loads: forces, and moments about the base. */
static void test_guyed_mast(void)
{
    char text[2048];
    int len = snprintf(text, sizeof text,
                       "material steel E=2.1e11 nu=0.3\nmaterial wire E=1.6e11\n"
                       "section tube material=steel A=6e-3 Iy=4e-5 Iz=4e-5 J=8e-5\n"
                       "section guy material=wire A=2e-4\n"
                       "node 1 0 0 0 fix=xyzrxryrz\nnode 2 0 0 20\n");
    for (int k = 0; k < 3; k++) {
        double a = 2 * PI * k / 3, x = 12 * cos(a), y = 12 * sin(a);
        len += snprintf(text + len, sizeof text - (size_t)len, "node %d %.17g %.17g 0 fix=xyz\nelement %d 2 %d section=guy l0=%.17g\n",
                        3 + k, x, y, 10 + k, 3 + k, 0.995 * hypot(12, 20));
    }
    snprintf(text + len, sizeof text - (size_t)len, "beam 1 1 2 section=tube n=10\nload 2 5e3 2e3 0 0 0 0\n");
    run r = run_text("mast", text);
    CHECK_MSG(r.rc == CTN_OK, "%s", r.ctx ? ctn_ctx_message(r.ctx) : "");
    if (!r.rc) {
        const double *R = ctn_solution_reactions(r.s), *M = ctn_solution_reaction_moments(r.s), *d = ctn_solution_displacements(r.s);
        const double F[3] = { 5e3, 2e3, 0 };
        double sf[3] = { 0 }, sm[3] = { 0 };
        size_t nn = ctn_model_node_count(r.m);
        for (size_t i = 0; i < nn; i++) {
            ctn_node_info ni;
            ctn_model_node(r.m, i, &ni);
            double x[3] = { ni.X[0] + d[3 * i], ni.X[1] + d[3 * i + 1], ni.X[2] + d[3 * i + 2] };
            double f[3] = { R[3 * i], R[3 * i + 1], R[3 * i + 2] };
            if (ni.id == 2)
                for (int j = 0; j < 3; j++) f[j] += F[j];      /* the load where it acts */
            for (int j = 0; j < 3; j++) {
                int p = (j + 1) % 3, q = (j + 2) % 3;
                sf[j] += f[j];
                sm[j] += x[p] * f[q] - x[q] * f[p] + M[3 * i + j];
            }
        }
        for (int j = 0; j < 3; j++) {
            CHECK_MSG(fabs(sf[j]) < 1e-6, "force balance %c: %g", "xyz"[j], sf[j]);
            CHECK_MSG(fabs(sm[j]) < 1e-5, "moment balance %c: %g", "xyz"[j], sm[j]);
        }
        size_t top;
        CHECK(ctn_model_node_index(r.m, 2, &top) == CTN_OK && d[3 * top] > 0);
    }
    done(&r);
}

/* Rectangle b x h (h along z) centred at (y, z): A, and its second moments about the
 * section's axes by Steiner's rule: Iy = b h^3 / 12 + A z^2, Iz = h b^3 / 12 + A y^2. */
static void rect(double b, double h, double y, double z, double *A, double *Iy, double *Iz)
{
    *A += b * h;
    *Iy += b * h * h * h / 12 + b * h * z * z;
    *Iz += h * b * b * b / 12 + b * h * y * y;
}

/* Sections by their dimensions (d=, t=, b=, h=, tf=, tw=) against independent sums: the
 * circle and the tube by midpoint integration on a 2000 x 2000 grid (1e-5), the box and
 * the I-section as their plates by Steiner's rule (1e-12); J = Iy + Iz for the circles. */
static void test_shapes(void)
{
    static const char *const text =
        "material steel E=2.1e11 nu=0.3\n"
        "section rod material=steel d=0.05\n"
        "section tube material=steel d=0.2 t=0.01\n"
        "section rhs material=steel b=0.1 h=0.2 t=0.008\n"
        "section ipe material=steel b=0.1 h=0.2 tf=0.0085 tw=0.0056 J=1e-7\n";
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solve_options opt;
    CHECK(ctn_ctx_create(&ctx) == CTN_OK && ctn_read_string(ctx, "shapes", text, strlen(text), &m, &opt) == CTN_OK);
    if (!m) { ctn_ctx_destroy(&ctx); return; }
    const ctn_section *sec = m->sections.v;
    for (int c = 0; c < 2; c++) {                       /* rod, tube */
        double D = c ? 0.2 : 0.05, Di = c ? 0.18 : 0, A = 0, I = 0, h = D / 2000;
        for (int i = 0; i < 2000; i++)
            for (int j = 0; j < 2000; j++) {
                double y = -D / 2 + (i + 0.5) * h, z = -D / 2 + (j + 0.5) * h, r2 = y * y + z * z;
                if (r2 <= D * D / 4 && r2 >= Di * Di / 4) {
                    A += h * h;
                    I += z * z * h * h;
                }
            }
        CHECK_CLOSE(sec[c].A, A, 1e-3, 0);
        CHECK_CLOSE(sec[c].Iy, I, 1e-3, 0);
        CHECK(sec[c].Iy == sec[c].Iz && sec[c].J == 2 * sec[c].Iy);
    }
    double A = 0, Iy = 0, Iz = 0, t = 0.008;            /* the box: two flanges, two webs */
    rect(0.1, t, 0, 0.1 - t / 2, &A, &Iy, &Iz);
    rect(0.1, t, 0, -0.1 + t / 2, &A, &Iy, &Iz);
    rect(t, 0.2 - 2 * t, 0.05 - t / 2, 0, &A, &Iy, &Iz);
    rect(t, 0.2 - 2 * t, -0.05 + t / 2, 0, &A, &Iy, &Iz);
    CHECK_CLOSE(sec[2].A, A, 1e-12, 0);
    CHECK_CLOSE(sec[2].Iy, Iy, 1e-12, 0);
    CHECK_CLOSE(sec[2].Iz, Iz, 1e-12, 0);
    A = Iy = Iz = 0;                                    /* the I: two flanges and the web */
    rect(0.1, 0.0085, 0, 0.1 - 0.0085 / 2, &A, &Iy, &Iz);
    rect(0.1, 0.0085, 0, -0.1 + 0.0085 / 2, &A, &Iy, &Iz);
    rect(0.0056, 0.2 - 2 * 0.0085, 0, 0, &A, &Iy, &Iz);
    CHECK_CLOSE(sec[3].A, A, 1e-12, 0);
    CHECK_CLOSE(sec[3].Iy, Iy, 1e-12, 0);
    CHECK_CLOSE(sec[3].Iz, Iz, 1e-12, 0);
    CHECK(sec[3].J == 1e-7);                            /* a key given replaces the shape's */
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Modes of a cantilever beam (L = 100, r^2 / L^2 = 1e-6: the rotary inertia is below
 * the checks): the first bending frequency about each axis against Euler-Bernoulli's
 * 1.8751^2 / (2 pi) sqrt(EI / (m L^4)), O(h^2) from below with both mass matrices. */
static double beam_mode_error(int n, const char *mass, int mode)
{
    char text[768];
    snprintf(text, sizeof text,
             "units kN m\nmaterial steel E=2.1e8 nu=0.3\n"
             "section s material=steel A=1e-2 Iy=1e-4 Iz=2e-4 J=3e-4 mass=0.0785\n"
             "node 1 0 0 0 fix=xyzrxryrz\nnode 2 100 0 0\n"
             "beam 1 1 2 section=s orient=0,0,1 n=%d\nmodes count=2 mass=%s\n", n, mass);
    run r = run_text("modes.cable", text);
    double err = NAN;
    ctn_mode md;
    if (r.rc == CTN_OK && ctn_solution_mode_count(r.s) == 2 && !ctn_solution_mode(r.s, (size_t)mode, &md)) {
        double I = mode ? 2e-4 : 1e-4, f = 1.8751040687119611 * 1.8751040687119611 / (2 * PI) *
                                           sqrt(2.1e8 * I / (0.0785 * 1e8));
        err = md.frequency / f - 1;
    }
    CHECK_MSG(r.rc == CTN_OK, "%s", ctn_ctx_message(r.ctx));
    done(&r);
    return err;
}

static void test_modes(void)
{
    for (int mode = 0; mode < 2; mode++) {
        double c20 = beam_mode_error(20, "consistent", mode), c40 = beam_mode_error(40, "consistent", mode);
        double l20 = beam_mode_error(20, "lumped", mode), l40 = beam_mode_error(40, "lumped", mode);
        CHECK_MSG(c40 < 0 && fabs(c40) < 1e-4 && fabs(l40) < 5e-4, "mode %d: %g %g", mode, c40, l40);
        CHECK_MSG(fabs(c20 / c40 - 4) < 0.3 && fabs(l20 / l40 - 4) < 0.3, "mode %d: not O(h^2): %g %g, %g %g", mode,
                  c20, c40, l20, l40);
        CHECK(l40 < c40);                               /* the lumped mass is the lower */
    }
}

int main(void)
{
    test_shapes();
    test_cantilever();
    test_roll_up();
    test_bend45();
    test_rigid();
    test_truss();
    test_guyed_mast();
    test_modes();
    CHECK_DONE();
}
