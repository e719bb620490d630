/* Form finding by force density (catena/formfind.h, `catena formfind`): every free node
 * in equilibrium to 1e-10 with the forces its members' unstressed lengths give by their
 * own laws; the funicular polygon of one cable under point loads against the closed form;
 * a symmetric net found symmetric; the found model re-solved stays put with forces q l;
 * targeted forces reached; partial supports, self-weight of a generated cable, springs;
 * the written model read back; errors with file:line; allocation failures. */
#include "catena.h"
#include "check.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static ctn_model *read_text(ctn_ctx *ctx, const char *text)
{
    ctn_model *m = NULL;
    int rc = ctn_read_string(ctx, "ff.cable", text, strlen(text), &m, NULL);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    return m;
}

static double dist(const double *a, const double *b)
{
    return sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
}

/* The force of element e of m at its reference length, by its own law from its l0 (not
 * from the form finding's q): the force a solve starting there sees. */
static double law_force(const ctn_model *m, size_t e)
{
    ctn_element_info in;
    ctn_node_info a, b;
    ctn_model_element(m, e, &in);
    ctn_model_node(m, (size_t)in.node[0], &a);
    ctn_model_node(m, (size_t)in.node[1], &b);
    double l = dist(a.X, b.X), lam = l / in.l0;
    if (!in.has_section) return in.k * (l - in.l0);
    if (in.strain == CTN_STRAIN_ENGINEERING) return in.E * in.A * (lam - 1);
    return in.E * in.A * (lam * lam - 1) / 2 * lam;
}

/* The resolution of a member's force in double precision: N follows from l / l0, whose
 * rounding moves it by about eps E A (eps k l for a spring); 16 of those. */
static double force_floor(const ctn_model *m, size_t e)
{
    ctn_element_info in;
    ctn_model_element(m, e, &in);
    return 16 * DBL_EPSILON * (in.has_section ? in.E * in.A : in.k * in.l0);
}

/* Largest |sum of member forces + load| at a free DOF over the largest force; the forces
 * by the members' laws, the loads of the first step. */
static double equilibrium(const ctn_model *m)
{
    size_t nn = ctn_model_node_count(m), ne = ctn_model_element_count(m);
    double *r = calloc(3 * nn, sizeof(double)), scale = 0, worst = 0;
    ctn_model_step_loads(m, 0, r, NULL);
    for (size_t e = 0; e < ne; e++) {
        ctn_element_info in;
        ctn_node_info a, b;
        ctn_model_element(m, e, &in);
        ctn_model_node(m, (size_t)in.node[0], &a);
        ctn_model_node(m, (size_t)in.node[1], &b);
        double N = law_force(m, e), l = dist(a.X, b.X);
        scale = fmax(scale, fabs(N));
        for (int k = 0; k < 3; k++) {
            r[3 * (size_t)in.node[0] + (size_t)k] += N * (b.X[k] - a.X[k]) / l;
            r[3 * (size_t)in.node[1] + (size_t)k] -= N * (b.X[k] - a.X[k]) / l;
        }
    }
    for (size_t i = 0; i < nn; i++) {
        ctn_node_info p;
        ctn_model_node(m, i, &p);
        for (int k = 0; k < 3; k++)
            if (!(p.fix & (1u << k))) worst = fmax(worst, fabs(r[3 * i + (size_t)k]));
    }
    free(r);
    return worst / scale;
}

/* Forces q l (q members) and targets (force members) against the members' laws. */
static void check_forces(const ctn_model *m, double qtol, double ftol)
{
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_info in;
        ctn_node_info a, b;
        double q = 0, F = 0;
        ctn_model_element(m, e, &in);
        ctn_model_node(m, (size_t)in.node[0], &a);
        ctn_model_node(m, (size_t)in.node[1], &b);
        ctn_model_force_density(m, e, &q, &F);
        if (q > 0) CHECK_CLOSE(law_force(m, e), q * dist(a.X, b.X), qtol, force_floor(m, e));
        else CHECK_CLOSE(law_force(m, e), F, ftol, force_floor(m, e));
    }
}

/* Solve m as it is: at the end of the first step (the state form finding found),
 * displacements at most utol, forces equal to those of the laws at the reference (q l)
 * to ntol, each beside the round-off of its force (force_floor). */
static void check_stays(ctn_ctx *ctx, const ctn_model *m, double utol, double ntol)
{
    ctn_solution *s = NULL;
    int rc = ctn_solve(ctx, m, NULL, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (rc) return;
    ctn_step_result r;
    ctn_solution_step(s, 0, &r);
    CHECK(r.reason == CTN_CONVERGED);
    double umax = 0;
    for (size_t i = 0; i < 3 * ctn_model_node_count(m); i++) umax = fmax(umax, fabs(r.d[i]));
    CHECK_MSG(umax <= utol, "largest displacement %g", umax);
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_state st;
        ctn_solution_step_element(s, 0, e, &st);
        CHECK_CLOSE(st.force, law_force(m, e), ntol, force_floor(m, e));
    }
    ctn_solution_destroy(&s);
}

/* A chain of 6 members between inclined anchors with unequal point loads and q = 8:
 * x equally spaced, H = q dx, y = chord - M(x) / H (M: the simply supported moment). */
static void test_funicular(void)
{
    const double L = 12, yA = 1, yB = 4, q = 8, P[5] = { 3, 1, 4, 1.5, 9 };
    char text[2048];
    int n = snprintf(text, sizeof text, "material s E=2e8 strain=engineering\nsection c material=s A=1e-4\n"
                     "node 1 0 %g 0 fix=xyz\nnode 7 %g %g 0 fix=xyz\n", yA, L, yB);
    for (int i = 1; i <= 5; i++) n += snprintf(text + n, sizeof text - (size_t)n, "node %d %g 0 0\n", i + 1, 0.3 * i);
    for (int i = 1; i <= 6; i++) n += snprintf(text + n, sizeof text - (size_t)n, "element %d %d %d section=c q=%g\n", i, i, i + 1, q);
    for (int i = 1; i <= 5; i++) n += snprintf(text + n, sizeof text - (size_t)n, "load %d 0 %g 0\n", i + 1, -P[i - 1]);
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = read_text(ctx, text);
    ctn_formfind_report rep;
    int rc = ctn_formfind(ctx, m, NULL, &rep);
    CHECK_MSG(rc == CTN_OK && rep.reason == CTN_FF_CONVERGED, "%s", ctn_ctx_message(ctx));
    CHECK(rep.iterations == 1 && rep.factorizations == 1 && rep.free_nodes == 5);
    double dx = L / 6, H = q * dx, RA = 0;
    for (int j = 1; j <= 5; j++) RA += P[j - 1] * (L - j * dx) / L;
    for (int i = 1; i <= 5; i++) {
        double x = i * dx, M = RA * x;
        for (int j = 1; j < i; j++) M -= P[j - 1] * (x - j * dx);
        ctn_node_info p;
        size_t idx;
        ctn_model_node_index(m, i + 1, &idx);
        ctn_model_node(m, idx, &p);
        CHECK_CLOSE(p.X[0], x, 0, 1e-13 * L);
        CHECK_CLOSE(p.X[1], yA + (yB - yA) * x / L - M / H, 0, 1e-13 * L);
        CHECK(p.X[2] == 0);
    }
    CHECK(equilibrium(m) <= 1e-10 && rep.residual <= 1e-13);
    check_forces(m, 1e-12, 0);
    check_stays(ctx, m, 1e-12 * L, 1e-12);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Index of the node whose reference position (in m0) is (x, y), -1 if none. */
static long node_at(const ctn_model *m0, double x, double y)
{
    for (size_t i = 0; i < ctn_model_node_count(m0); i++) {
        ctn_node_info p;
        ctn_model_node(m0, i, &p);
        if (fabs(p.X[0] - x) < 1e-9 && fabs(p.X[1] - y) < 1e-9) return (long)i;
    }
    return -1;
}

/* The example net (examples/formfind/hypar_net.cable): symmetric about x = 0 and about
 * y = 0, every free node in equilibrium, forces q l, and the written model (read back)
 * stays put when solved. */
static void test_hypar(void)
{
    const char *src = "examples/formfind/hypar_net.cable";
    char out[] = "/tmp/catena-ff-XXXXXX";
    int fd = mkstemp(out);
    if (fd >= 0) close(fd);
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL, *m0 = NULL, *back = NULL;
    ctn_formfind_report rep;
    ctn_ctx_create(&ctx);
    int rc = ctn_formfind_file(ctx, src, out, NULL, &rep, &m);
    CHECK_MSG(rc == CTN_OK && rep.reason == CTN_FF_CONVERGED, "%s", ctn_ctx_message(ctx));
    if (!rc) rc = ctn_model_read_file(ctx, src, &m0);
    if (!rc) rc = ctn_model_read_file(ctx, out, &back);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (rc) goto done;
    CHECK(rep.factorizations == 1 && rep.free_nodes == 309 && rep.targets == 0);
    CHECK(rep.residual <= 1e-13);
    CHECK(equilibrium(m) <= 1e-10 && equilibrium(back) <= 1e-10);
    check_forces(m, 1e-12, 0);
    double worst = 0;
    for (size_t i = 0; i < ctn_model_node_count(m0); i++) {
        ctn_node_info p0, p, r;
        ctn_model_node(m0, i, &p0);
        long j = node_at(m0, -p0.X[0], p0.X[1]), k = node_at(m0, p0.X[0], -p0.X[1]);
        CHECK(j >= 0 && k >= 0);
        if (j < 0 || k < 0) continue;
        ctn_model_node(m, i, &p);
        ctn_model_node(m, (size_t)j, &r);                    /* mirror in x = 0 */
        worst = fmax(worst, fmax(fabs(r.X[0] + p.X[0]), fmax(fabs(r.X[1] - p.X[1]), fabs(r.X[2] - p.X[2]))));
        ctn_model_node(m, (size_t)k, &r);                    /* mirror in y = 0 */
        worst = fmax(worst, fmax(fabs(r.X[0] - p.X[0]), fmax(fabs(r.X[1] + p.X[1]), fabs(r.X[2] - p.X[2]))));
        ctn_node_info b;
        ctn_model_node(back, i, &b);                         /* the file holds the same doubles */
        CHECK(b.X[0] == p.X[0] && b.X[1] == p.X[1] && b.X[2] == p.X[2] && b.fix == p0.fix && b.id == p0.id);
    }
    CHECK_MSG(worst <= 1e-12 * 24, "asymmetry %g m", worst);
    for (size_t e = 0; e < ctn_model_element_count(m); e++) {
        ctn_element_info a, b;
        ctn_model_element(m, e, &a);
        ctn_model_element(back, e, &b);
        CHECK(a.l0 == b.l0 && a.id == b.id);
    }
    check_stays(ctx, back, 1e-12 * 24, 1e-12);
done:
    unlink(out);
    ctn_model_destroy(&m);
    ctn_model_destroy(&m0);
    ctn_model_destroy(&back);
    ctn_ctx_destroy(&ctx);
}

/* A square grid net, (n+1)^2 nodes 1 m apart, its border pinned on the saddle
 * z = (x^2 - y^2) / n, the free nodes starting flat at z = 0 under a load of 0.3 down;
 * member e gets key=values[e] (key "q" or "force"). */
static char *grid_net(int n, const char *key, const double *values)
{
    size_t cap = 200 + (size_t)(n + 1) * (size_t)(n + 1) * 160, len = 0;
    char *t = malloc(cap);
    len += (size_t)snprintf(t, cap, "material s E=1e7\nsection c material=s A=1e-3\n");
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            int edge = i == 0 || j == 0 || i == n || j == n;
            double x = i - n / 2.0, y = j - n / 2.0;
            len += (size_t)snprintf(t + len, cap - len, "node %d %g %g %.17g%s\n", i * (n + 1) + j + 1, x, y,
                                    edge ? (x * x - y * y) / n : 0.0, edge ? " fix=xyz" : "");
            if (!edge) len += (size_t)snprintf(t + len, cap - len, "load %d 0 0 -0.3\n", i * (n + 1) + j + 1);
        }
    int e = 0;
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            for (int d = 0; d < 2; d++) {
                int i2 = i + (d == 0), j2 = j + (d == 1);
                if (i2 > n || j2 > n) continue;
                if ((d == 0 && (j == 0 || j == n)) || (d == 1 && (i == 0 || i == n))) continue;   /* along the border */
                len += (size_t)snprintf(t + len, cap - len, "element %d %d %d section=c %s=%.17g\n", e + 1,
                                        i * (n + 1) + j + 1, i2 * (n + 1) + j2 + 1, key, values[e]);
                e++;
            }
    return t;
}

/* Targets reached: forces found with uneven densities become the targets of a second run
 * that starts from the flat net with q = force / l there; every force meets its target to
 * 1e-10 and the shape is the first run's. Then a mixed model (targets on half). */
static void test_targets(void)
{
    enum { N = 8, NE = 2 * (N + 1) * N - 4 * N };
    double q[NE], F[NE];
    for (int e = 0; e < NE; e++) q[e] = 1 + 0.25 * (e % 5);
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    char *t1 = grid_net(N, "q", q);
    ctn_model *m1 = read_text(ctx, t1), *m2 = NULL;
    ctn_formfind_report rep;
    int rc = ctn_formfind(ctx, m1, NULL, &rep);
    CHECK_MSG(rc == CTN_OK && rep.reason == CTN_FF_CONVERGED, "%s", ctn_ctx_message(ctx));
    for (int e = 0; e < NE && !rc; e++) {
        ctn_element_info in;
        ctn_node_info a, b;
        ctn_model_element(m1, (size_t)e, &in);
        ctn_model_node(m1, (size_t)in.node[0], &a);
        ctn_model_node(m1, (size_t)in.node[1], &b);
        F[e] = q[e] * dist(a.X, b.X);
    }
    char *t2 = grid_net(N, "force", F);
    m2 = read_text(ctx, t2);
    ctn_formfind_options o;
    ctn_formfind_options_init(&o);
    rc = ctn_formfind(ctx, m2, &o, &rep);
    CHECK_MSG(rc == CTN_OK && rep.reason == CTN_FF_CONVERGED, "%s (%d iterations, mismatch %g)", ctn_ctx_message(ctx),
              rep.iterations, rep.force_mismatch);
    CHECK(rep.targets == NE && rep.force_mismatch <= 1e-10 && rep.iterations > 1);
    printf("targets: %d iterations, %d factorizations, mismatch %.3g\n", rep.iterations, rep.factorizations,
           rep.force_mismatch);
    check_forces(m2, 0, 1e-10);
    CHECK(equilibrium(m2) <= 1e-10);
    double far = 0;
    for (size_t i = 0; i < ctn_model_node_count(m1); i++) {
        ctn_node_info a, b;
        ctn_model_node(m1, i, &a);
        ctn_model_node(m2, i, &b);
        far = fmax(far, dist(a.X, b.X));
    }
    CHECK_MSG(far <= 1e-8, "the targeted net lies %g from the first", far);
    check_stays(ctx, m2, 1e-9, 1e-10);
    ctn_model_destroy(&m2);
    free(t2);
    for (int e = 0; e < NE; e += 2) F[e] = -q[e];                /* even members: q, odd: force */
    t2 = grid_net(N, "force", F);
    for (char *p = strstr(t2, "force=-"); p; p = strstr(p, "force=-")) memcpy(p, "     q=", 7);
    m2 = read_text(ctx, t2);
    rc = ctn_formfind(ctx, m2, NULL, &rep);
    CHECK_MSG(rc == CTN_OK && rep.reason == CTN_FF_CONVERGED, "%s", ctn_ctx_message(ctx));
    CHECK(rep.targets == NE / 2);
    check_forces(m2, 1e-12, 1e-10);
    CHECK(equilibrium(m2) <= 1e-10);
    ctn_model_destroy(&m1);
    ctn_model_destroy(&m2);
    free(t1);
    free(t2);
    ctn_ctx_destroy(&ctx);
}

/* Find the shape of text; the model (NULL on failure, with the message checked). */
static ctn_model *find(ctn_ctx *ctx, const char *text, ctn_formfind_report *rep)
{
    ctn_model *m = read_text(ctx, text);
    int rc = m ? ctn_formfind(ctx, m, NULL, rep) : CTN_ERR_MODEL;
    CHECK_MSG(rc == CTN_OK && rep->reason == CTN_FF_CONVERGED, "%s", ctn_ctx_message(ctx));
    if (rc) ctn_model_destroy(&m);
    return m;
}

/* Supports in some directions only: one system serves the coordinates whose free nodes
 * are the same (x and y here: 1 factorization, z held); a node held in x only adds one. */
static void test_partial_supports(void)
{
    const char *plane = "material s E=1e7\nsection c material=s A=1e-3\n"
                        "node 1 0 0 0 fix=xyz\nnode 2 4 0 0 fix=xyz\nnode 3 2 3 0 fix=xyz\n"
                        "node 4 1 1 0 fix=z\nnode 5 3 1 0 fix=z\n"
                        "element 1 1 4 section=c q=2\nelement 2 4 5 section=c q=3\nelement 3 5 2 section=c q=2\n"
                        "element 4 4 3 section=c q=1\nelement 5 5 3 section=c q=1\nload 4 0.5 -1 0\n";
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_formfind_report rep;
    ctn_model *m = find(ctx, plane, &rep);
    if (m) {
        CHECK(rep.factorizations == 1 && rep.free_nodes == 2);
        CHECK(equilibrium(m) <= 1e-10 && rep.residual <= 1e-13);
        check_stays(ctx, m, 1e-12, 1e-12);
        ctn_node_info p;
        ctn_model_node(m, 3, &p);
        CHECK(p.X[2] == 0 && p.fix == CTN_FIX_Z);
    }
    ctn_model_destroy(&m);
    char text[1024];
    snprintf(text, sizeof text, "%s%s", plane, "node 6 2 -2 1 fix=x\nelement 6 6 1 section=c q=1\n"
             "element 7 6 2 section=c q=1\nelement 8 6 4 section=c q=1\n");
    m = find(ctx, text, &rep);
    if (m) {
        CHECK(rep.factorizations == 3);                  /* x; y; z (node 6 free in y and z) */
        CHECK(equilibrium(m) <= 1e-10 && rep.residual <= 1e-13);
        ctn_node_info p;
        ctn_model_node(m, 5, &p);
        CHECK(p.X[0] == 2);
    }
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* A generated cable with a force density under its own weight, a point load on a
 * generated node and a deck load (hload) on half of it: the funicular of the lumped loads w l0 / 2 (l0 found), q dx / 2 and the load;
 * written (the cable expanded into nodes and elements, the load kept on its node) and
 * read back: the same doubles, and the solve stays put. With a spring in line. */
static void test_cable_weight(void)
{
    const char *text = "units kN m\ngravity 0 -1 0\nmaterial steel E=2e8 strain=engineering\n"
                       "section strand material=steel A=3e-4 w=0.5   # heavy\n"
                       "node 1 0 0 0 fix=xyz\nnode 2 60 0 0\nnode 3 61 0 0 fix=xyz\n"
                       "cable 1 2 section=strand n=12 length=61 q=40\n"
                       "spring 100 2 3 k=5e4 q=3000\nstep dead\nload 7 0 -3 0\nhload q=2 elements=1-6\nstep more\nload 5 0 -1 0\n";
    char out[] = "/tmp/catena-ff-XXXXXX";
    int fd = mkstemp(out);
    if (fd >= 0) close(fd);
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_formfind_report rep;
    ctn_model *m = find(ctx, text, &rep), *back = NULL;
    if (!m) goto done;
    CHECK(rep.iterations >= 3 && rep.factorizations == 1);
    CHECK(equilibrium(m) <= 1e-10 && rep.residual <= 1e-13);
    check_forces(m, 1e-12, 0);
    int rc = ctn_formfind_write(ctx, m, text, strlen(text), out);
    if (!rc) rc = ctn_model_read_file(ctx, out, &back);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (rc) goto done;
    CHECK(ctn_model_cable_count(back) == 0 && ctn_model_element_count(back) == 13);
    CHECK(ctn_model_step_count(back) == 2);
    double *f = calloc(3 * ctn_model_node_count(m), sizeof(double)), *g = calloc(3 * ctn_model_node_count(m), sizeof(double));
    ctn_model_step_loads(m, 1, f, NULL);
    ctn_model_step_loads(back, 1, g, NULL);
    for (size_t i = 0; i < 3 * ctn_model_node_count(m); i++) CHECK(f[i] == g[i]);   /* same loads, same nodes */
    free(f);
    free(g);
    for (size_t i = 0; i < ctn_model_node_count(m); i++) {
        ctn_node_info a, b;
        ctn_model_node(m, i, &a);
        ctn_model_node(back, i, &b);
        CHECK(a.id == b.id && a.X[0] == b.X[0] && a.X[1] == b.X[1] && a.X[2] == b.X[2] && a.fix == b.fix);
    }
    for (size_t e = 0; e < 13; e++) {
        ctn_element_info a, b;
        ctn_model_element(m, e, &a);
        ctn_model_element(back, e, &b);
        CHECK(a.id == b.id && a.l0 == b.l0 && a.node[0] == b.node[0] && a.node[1] == b.node[1] && a.k == b.k);
    }
    /* The chain 1 .. 2 (node 2 held by the spring) hangs as the funicular of its lumped
     * loads: x even from 0 to node 2's, H = q dx. */
    ctn_element_info in;
    ctn_node_info p;
    ctn_model_node(m, 1, &p);
    double L = p.X[0], dx = L / 12, H = 40 * dx, R = 0, P[11];
    CHECK(L > 60 && L < 61);
    for (int i = 1; i <= 11; i++) {
        ctn_model_element(m, (size_t)i - 1, &in);
        double w0 = in.l0;
        ctn_model_element(m, (size_t)i, &in);
        P[i - 1] = 0.5 * 0.5 * (w0 + in.l0) + (i == 4 ? 3 : 0)    /* node 7: the fourth (ids 4 ..) */
                   + 0.5 * 2 * dx * ((i <= 6) + (i + 1 <= 6));     /* hload on elements 1-6 */
        R += P[i - 1] * (L - i * dx) / L;
    }
    double yB = p.X[1];
    for (int i = 1; i <= 11; i++) {
        double x = i * dx, M = R * x;
        for (int j = 1; j < i; j++) M -= P[j - 1] * (x - j * dx);
        ctn_model_node(m, (size_t)i + 2, &p);
        CHECK_CLOSE(p.X[0], x, 0, 1e-12 * L);
        CHECK_CLOSE(p.X[1], yB * x / L - M / H, 0, 1e-12 * L);
    }
    check_stays(ctx, back, 1e-12 * L, 1e-12);
done:
    unlink(out);
    ctn_model_destroy(&m);
    ctn_model_destroy(&back);
    ctn_ctx_destroy(&ctx);
}

/* The error of finding the shape of text: code and a piece of the message; the model
 * (when read) is left as it was. */
static void expect_error(const char *text, int code, const char *piece)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = NULL;
    int rc = ctn_read_string(ctx, "bad.cable", text, strlen(text), &m, NULL);
    double X[3] = { 0, 0, 0 };
    ctn_node_info p;
    if (!rc) {
        ctn_model_node(m, ctn_model_node_count(m) - 1, &p);
        memcpy(X, p.X, sizeof X);
        rc = ctn_formfind(ctx, m, NULL, NULL);
        ctn_model_node(m, ctn_model_node_count(m) - 1, &p);
        CHECK(!memcmp(X, p.X, sizeof X));
    }
    CHECK_MSG(rc == code && strstr(ctn_ctx_message(ctx), piece), "got %d '%s', want %d '%s'", rc,
              ctn_ctx_message(ctx), code, piece);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static void test_errors(void)
{
    const char *head = "material s E=1e7\nsection c material=s A=1e-3\nnode 1 0 0 0 fix=xyz\nnode 2 4 0 0 fix=xyz\n"
                       "node 3 2 -1 0\n";
    static const char *const cases[][2] = {             /* the lines after head; the message */
        { "element 1 1 3 section=c q=0\n", "bad.cable:6: element 1: q must be positive (found 0)" },
        { "element 1 1 3 section=c force=-2\n", "bad.cable:6: element 1: force must be positive (found -2)" },
        { "element 1 1 3 section=c q=1 force=2\n", "bad.cable:6: element 1: give q= or force=, not both" },
        { "element 1 1 3 section=c q=1 l0=2\n", "bad.cable:6: element 1: q= is for form finding" },
        { "element 1 1 3 section=c q=1\nelement 2 3 2 section=c\n",
          "bad.cable:7: element 2: form finding needs a force density q= or a target force" },
        { "element 1 1 3 section=c q=1\nelement 2 3 2 section=c q=1\nnode 4 9 9 0\nnode 5 9 8 0\nelement 3 4 5 section=c q=1\n",
          "part that no support reaches" },                             /* ctn_model_validate first */
        { "element 1 1 3 section=c q=1\nelement 2 3 2 section=c q=1\nnode 4 2 3 0 fix=yz\nnode 5 3 3 0 fix=yz\n"
          "element 3 5 4 section=c q=1\n",
          "bad.cable:8: node 4 is free in x but no chain of members joins it to a node fixed in x" },
        { "element 1 1 3 section=c force=10\nelement 2 3 2 section=c force=4\nload 3 0 -1 0\n",
          "bad.cable:6: element 1: its target force 10 is larger than the other forces at node 3 together (5" },
        { "element 1 1 3 section=c force=1\nelement 2 3 2 section=c force=1\nload 3 0 -5 0\n",
          "bad.cable:5: node 3: its load (5) is larger than the target forces of its members together (2)" },
        { "element 1 1 3 section=c q=1\nelement 2 3 2 section=c q=1\nstep a\ndisplace 2 x=1\n",
          "bad.cable:4: node 2: a displacement is prescribed in the first step" },
        { "spring 1 1 3 k=1 q=5\nelement 2 3 2 section=c q=1\n",
          "bad.cable:6: spring 1: no positive free length gives that prestress" },
    };
    char t[1024];
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        snprintf(t, sizeof t, "%s%s", head, cases[k][0]);
        expect_error(t, CTN_ERR_MODEL, cases[k][1]);
    }
    /* Equal forces in three members to a node in an obtuse triangle of anchors (an angle
     * above 120 degrees): no shape has them (the node runs into the obtuse corner). */
    snprintf(t, sizeof t, "%snode 4 2 0.2 0 fix=xyz\nelement 1 1 3 section=c force=1\nelement 2 3 2 section=c force=1\n"
             "element 3 3 4 section=c force=1\n", head);
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_formfind_report rep;
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "bad.cable", t, strlen(t), &m, NULL);
    if (!rc) rc = ctn_formfind(ctx, m, NULL, &rep);
    CHECK_MSG(rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "bad.cable:9: element 3 shrank to zero length "
              "(nodes 3 and 4 met) while the densities followed the target forces"), "%s", ctn_ctx_message(ctx));
    ctn_node_info p;
    ctn_model_node(m, 2, &p);
    CHECK(p.X[0] == 2 && p.X[1] == -1);                        /* unchanged */
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* Every allocation of reading, finding and writing fails in turn: a clean error, no
 * leak (the sanitizer build), no file left, until it succeeds. */
static void test_alloc_failures(void)
{
    char out[] = "/tmp/catena-ff-XXXXXX";
    int fd = mkstemp(out);
    if (fd >= 0) close(fd);
    unlink(out);
    int done = 0;
    for (long n = 1; n < 2000 && !done; n++) {
        ctn_ctx *ctx = NULL;
        ctn_ctx_create(&ctx);
        ctn_ctx_fail_alloc_at(ctx, n);
        ctn_model *m = NULL;
        ctn_formfind_report rep;
        int rc = ctn_formfind_file(ctx, "examples/formfind/hypar_net.cable", out, NULL, &rep, &m);
        if (rc) {
            CHECK_MSG(rc == CTN_ERR_NOMEM && !m && access(out, F_OK) != 0, "allocation %ld: %d %s", n, rc, ctn_ctx_message(ctx));
        } else {
            done = 1;
            CHECK(m && rep.reason == CTN_FF_CONVERGED && access(out, F_OK) == 0);
        }
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
    CHECK(done);
    unlink(out);
}

int main(void)
{
    test_funicular();
    test_hypar();
    test_targets();
    test_partial_supports();
    test_cable_weight();
    test_errors();
    test_alloc_failures();
    CHECK_DONE();
}
