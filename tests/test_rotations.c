/* Nodes with rotations (6 DOFs), through the rspring family (a linear rotational
 * spring, small rotations):
 * - a spring clamped at node 1 with a moment about z at node 2: rotation M / k exactly,
 *   reaction moment -M at node 1, zero translations and forces; the DOF query;
 * - prescribed rotations: the spring's moment k r at both ends;
 * - a mixed model (a cable chain with a rotational spring at one of its nodes) solves
 *   with the cable's results bit for bit those of the chain alone;
 * - the writers add rotations and moments (JSON, CSV, VTU) only for such a model;
 * - model errors: fix=rz and a moment on a node without rotations (file:line), a modal
 *   analysis whose only free DOF is a massless rotation;
 * - a section's beam constants (Iy, Iz, J, Asy, Asz) and a material's G are read and
 *   kept; a negative one and an unknown key are errors;
 * - every allocation of read + solve failed in turn: a clean error, no leak. */
#include "catena.h"
#include "check.h"
#include "model/model.h"
#include "run_text.h"


static const char *const clamped =
    "node 1 0 0 0 fix=xyzrxryrz\n"
    "node 2 1 0 0 fix=xyz\n"
    "rspring 1 1 2 k=200\n"
    "moment 2 0 0 50\n";

static void test_clamped(void)
{
    run r = run_text("clamped", clamped);
    CHECK(r.rc == CTN_OK);
    if (r.rc) { done(&r); return; }
    const double *th = ctn_solution_rotations(r.s), *mo = ctn_solution_reaction_moments(r.s);
    const double *d = ctn_solution_displacements(r.s), *f = ctn_solution_reactions(r.s);
    CHECK(th && mo && ctn_solution_has_rotations(r.s));
    CHECK(ctn_model_has_rotations(r.m) && ctn_model_node_dofs(r.m, 0) == 6 && ctn_model_node_dofs(r.m, 1) == 6);
    CHECK(ctn_model_node_dofs(r.m, 2) == 0);
    if (th && mo) {
        CHECK(th[5] == 50.0 / 200.0);                   /* rz at node 2: M / k exactly */
        CHECK(th[0] == 0 && th[1] == 0 && th[2] == 0 && th[3] == 0 && th[4] == 0);
        CHECK(mo[2] == -50.0);                          /* the clamp holds -M */
        CHECK(mo[0] == 0 && mo[1] == 0 && mo[3] == 0 && mo[4] == 0 && mo[5] == 0);
    }
    for (int k = 0; k < 6; k++) CHECK(d[k] == 0 && f[k] == 0);
    const double *rot = NULL, *mom = NULL;
    CHECK(ctn_solution_step_rotations(r.s, 0, &rot, &mom) == CTN_OK && rot == th && mom == mo);
    CHECK(ctn_solution_step_rotations(r.s, 1, &rot, &mom) == CTN_ERR_INVALID);
    done(&r);
}

/* A rotation about x prescribed at node 1 of a spring held at node 2 in rotation. */
static void test_prescribed(void)
{
    run r = run_text("prescribed", "node 1 0 0 0 fix=xyzrxryrz\n"
                                   "node 2 0 0 1 fix=xyzrxryrz\n"
                                   "rspring 1 1 2 k=40\n"
                                   "displace 1 rx=0.125\n");
    CHECK(r.rc == CTN_OK);
    if (!r.rc) {
        const double *th = ctn_solution_rotations(r.s), *mo = ctn_solution_reaction_moments(r.s);
        CHECK(th[0] == 0.125 && th[3] == 0);
        CHECK(mo[0] == 40 * 0.125 && mo[3] == -40 * 0.125);
    }
    done(&r);
}

static const char *const chain =
    "node 1 0 0 0 fix=xyz\n"
    "node 2 10 0 -1 fix=z\n"
    "node 3 20 0 0 fix=xyz\n"
    "material steel E=2e8\n"
    "section s material=steel A=1e-4\n"
    "element 1 1 2 section=s l0=9.9\n"
    "element 2 2 3 section=s l0=10.2\n"
    "load 2 0 -3 0\n";

static void test_mixed(void)
{
    char text[1024];
    snprintf(text, sizeof text, "%snode 4 10 0 1 fix=xyzrxryrz\nrspring 3 2 4 k=7\nmoment 2 1 2 3\n", chain);
    run a = run_text("chain", chain), b = run_text("mixed", text);
    CHECK(a.rc == CTN_OK && b.rc == CTN_OK);
    if (!a.rc && !b.rc) {
        const double *da = ctn_solution_displacements(a.s), *db = ctn_solution_displacements(b.s);
        const double *fa = ctn_solution_reactions(a.s), *fb = ctn_solution_reactions(b.s);
        CHECK(!ctn_solution_has_rotations(a.s) && ctn_solution_rotations(a.s) == NULL);
        CHECK(memcmp(da, db, 9 * sizeof(double)) == 0 && memcmp(fa, fb, 9 * sizeof(double)) == 0);
        for (size_t i = 0; i < 2; i++) {
            ctn_element_state ea, eb;
            ctn_solution_element(a.s, i, &ea);
            ctn_solution_element(b.s, i, &eb);
            CHECK(ea.force == eb.force && ea.length == eb.length);
        }
        const double *th = ctn_solution_rotations(b.s), *mo = ctn_solution_reaction_moments(b.s);
        for (int k = 0; k < 3; k++) {
            CHECK_CLOSE(th[3 + k], (k + 1) / 7.0, 1e-15, 0);   /* node 2: M / k */
            CHECK_CLOSE(mo[9 + k], -(k + 1.0), 1e-15, 0);       /* node 4 holds -M */
            CHECK(th[k] == 0 && th[6 + k] == 0);                /* nodes 1, 3: none */
        }
        CHECK(ctn_model_node_dofs(b.m, 0) == 3 && ctn_model_node_dofs(b.m, 1) == 6);
    }
    done(&a);
    done(&b);
}

/* The writers' text for a model: JSON in memory. */
static char *json_of(const char *text)
{
    run r = run_text("w", text);
    char *out = NULL;
    CHECK(r.rc == CTN_OK);
    if (!r.rc) CHECK(ctn_result_json(r.ctx, r.m, r.s, 1, &out) == CTN_OK);
    done(&r);
    return out;
}

static void test_writers(void)
{
    char *a = json_of(chain), *b = json_of(clamped);
    CHECK(a && !strstr(a, "\"rz\"") && !strstr(a, "\"mz\""));
    CHECK(b && strstr(b, "\"rz\":\t0.25") && strstr(b, "\"mz\":\t-50"));
    ctn_json_free(a);
    ctn_json_free(b);
}

/* A model error with this message (a substring). */
static void expect_error(const char *text, const char *msg)
{
    run r = run_text("bad.cable", text);
    CHECK_MSG(r.rc == CTN_ERR_MODEL && strstr(ctn_ctx_message(r.ctx), msg), "rc %d: %s", r.rc, ctn_ctx_message(r.ctx));
    done(&r);
}

static void test_errors(void)
{
    expect_error("node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=xyzrz\nspring 1 1 2 k=1\n",
                 "bad.cable:2: node 2: fix=rz fixes a rotation, but the node has none");
    expect_error("node 1 0 0 0 fix=xyz\nnode 2 1 0 0 fix=y\nspring 1 1 2 k=1\nmoment 2 0 0 1\n",
                 "bad.cable:4: moment on node 2, which has no rotations");
    expect_error("node 1 0 0 0 fix=xyzrxryrz\nnode 2 1 0 0 fix=xyz\nrspring 1 1 2 k=200\ndisplace 2 rz=1\n",
                 "bad.cable:4: node 2: rz is not fixed; only fixed DOFs take a prescribed rotation");
    expect_error("node 1 0 0 0 fix=xyzrxryrz\nnode 2 1 0 0 fix=xyz mass=1\nrspring 1 1 2 k=200\nmodes count=1\n",
                 "bad.cable:4: modes: no free DOF carries mass");   /* the rotation has none */
}

static void test_section_keys(void)
{
    const char *text = "material m E=2e8 G=8e7\n"
                       "section s material=m A=1e-2 Iy=2e-5 Iz=3e-5 J=4e-5 Asy=5e-3 Asz=6e-3\n";
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solve_options opt;
    ctn_ctx_create(&ctx);
    CHECK(ctn_read_string(ctx, "s.cable", text, strlen(text), &m, &opt) == CTN_OK);
    if (m) {
        const ctn_section *sc = &m->sections.v[0];
        CHECK(sc->Iy == 2e-5 && sc->Iz == 3e-5 && sc->J == 4e-5 && sc->Asy == 5e-3 && sc->Asz == 6e-3);
        CHECK(m->materials.v[0].G == 8e7);
    }
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    expect_error("material m E=2e8\nsection s material=m A=1 Iz=-1\n", "bad.cable:2: section 's': Iz must be >= 0 and finite (got -1)");
    expect_error("material m E=2e8\nsection s material=m A=1 Ix=1\n", "bad.cable:2: unknown key 'Ix'");
    expect_error("material m E=2e8 G=-1\n", "bad.cable:1: material 'm': G must be >= 0");
}

static void test_alloc_failures(void)
{
    int nomem = 0, ok = 0;
    for (long k = 1; k < 400 && !ok; k++) {
        ctn_ctx *ctx = NULL;
        ctn_model *m = NULL;
        ctn_solution *s = NULL;
        ctn_solve_options opt;
        ctn_ctx_create(&ctx);
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_read_string(ctx, "clamped", clamped, strlen(clamped), &m, &opt);
        if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
        CHECK_MSG(rc == CTN_OK || rc == CTN_ERR_NOMEM, "k=%ld: rc %d", k, rc);
        nomem += rc == CTN_ERR_NOMEM;
        ok = rc == CTN_OK;
        if (ok) CHECK(ctn_solution_rotations(s)[5] == 0.25);
        ctn_solution_destroy(&s);
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
    CHECK(nomem > 10 && ok);
}

int main(void)
{
    test_clamped();
    test_prescribed();
    test_mixed();
    test_writers();
    test_errors();
    test_section_keys();
    test_alloc_failures();
    CHECK_DONE();
}
