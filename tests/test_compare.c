/* Comparison layer (catena/compare.h): a model's single span against the closed forms.
 * - point loads, engineering strain: the FEA equals the elastic funicular polygon solved
 *   here independently (ctn_funicular_solve) to 1e-9, and so does the compare module's
 *   elastic funicular;
 * - the FEA's support tension is the resultant reaction (statics: T^2 = H^2 + (w L0/2)^2
 *   on a level span), above the force of the first element;
 * - a user-built chain (scrambled ids, reversed elements) is the same span as the
 *   generated cable; models that are not a single span are refused;
 * - a load per horizontal length is recognised (q, parabola);
 * - the paper's four lengths: the catenary (checked against a bisection written here)
 *   over-predicts the stress and under-predicts the sag at high stress, by roughly the
 *   paper's 30 % / 6 %, and agrees within 1 % on the slack cables;
 * - one sag: solve's ctn_solution_cable_sag and compare's FEA sag are the same number for
 *   odd and even n, with no dip at odd n, and point loads beside mid-span are read on
 *   the straight element;
 * - every allocation failure gives CTN_ERR_NOMEM and no leak (ASan build). */
#include "catena.h"
#include "check.h"

#include <stdlib.h>

#define KN_M2_TO_MPA 1e-3

static const double paper_lengths[] = { 200.3340, 201.3545, 250.8777, 279.6157 };

static ctn_model *paper_model(ctn_ctx *ctx, double S, int n, ctn_strain strain)
{
    ctn_model *m = NULL;
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = n, .length = S, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    if (ctn_model_create(ctx, &m) || ctn_model_set_units(m, "kN", "m") || ctn_model_set_gravity(m, g) ||
        ctn_model_add_material(m, "steel", 2.0e8, strain, 0) ||
        ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1) ||
        ctn_model_add_node(m, 1, A, CTN_FIX_ALL) || ctn_model_add_node(m, 2, B, CTN_FIX_ALL) ||
        ctn_model_add_cable(m, 1, 2, "strand", &spec, NULL, NULL))
        ctn_model_destroy(&m);
    return m;
}

static ctn_solution *solve(ctn_ctx *ctx, const ctn_model *m, ctn_method method, double tol)
{
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    ctn_solve_summary sum;
    ctn_solve_options_default(&opt);
    opt.method = method;
    opt.tol = tol;
    if (ctn_solve(ctx, m, &opt, &s)) return NULL;
    ctn_solution_summary(s, &sum);
    CHECK_MSG(sum.reason == CTN_CONVERGED, "%s", ctn_reason_name(sum.reason));
    return s;
}

/* ---- point loads: FEA == elastic funicular ---------------------------------------- */
#define NSEG 6
static const double seg_l0[NSEG] = { 6.0, 5.5, 7.0, 6.5, 5.0, 6.0 };
static const double joint_P[2 * (NSEG - 1)] = { 0.5, -10, 0, -20, -1.0, -5, 0, -15, 0.3, -8 };

static ctn_model *chain_model(ctn_ctx *ctx)
{
    ctn_model *m = NULL;
    double g[3] = { 0, -1, 0 }, X[3] = { 0, 0, 0 };
    int rc = ctn_model_create(ctx, &m) || ctn_model_set_gravity(m, g) ||
             ctn_model_add_material(m, "rope", 2.0e8, CTN_STRAIN_ENGINEERING, 0) ||
             ctn_model_add_section(m, "s", "rope", 1e-4, 0);
    for (int j = 0; j <= NSEG && !rc; j++) {          /* joints on a sagging guess */
        X[0] = 30.0 * j / NSEG;
        X[1] = 5.0 * j / NSEG - (j > 0 && j < NSEG ? 6.0 : 0.0);
        rc = ctn_model_add_node(m, 10 + j, X, j == 0 || j == NSEG ? CTN_FIX_ALL : CTN_FIX_Z);
    }
    for (int i = 0; i < NSEG && !rc; i++) rc = ctn_model_add_element(m, 100 + i, 10 + i, 11 + i, "s", seg_l0[i]);
    for (int j = 1; j < NSEG && !rc; j++) {
        double F[3] = { joint_P[2 * (j - 1)], joint_P[2 * (j - 1) + 1], 0 };
        rc = ctn_model_add_load(m, 10 + j, F);
    }
    if (rc) ctn_model_destroy(&m);
    return m;
}

static void test_funicular_exact(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = chain_model(ctx);
    ctn_solution *s = m ? solve(ctx, m, CTN_METHOD_AUTO, 1e-13) : NULL;
    CHECK(s != NULL);
    if (!s) { ctn_model_destroy(&m); ctn_ctx_destroy(&ctx); return; }
    double EA[NSEG], xy[2 * (NSEG + 1)], N[NSEG];
    for (int i = 0; i < NSEG; i++) EA[i] = 2.0e8 * 1e-4;
    ctn_funicular_in in = { 30, 5, NSEG, seg_l0, EA, joint_P };
    ctn_funicular fu;
    CHECK(ctn_funicular_solve(NULL, &in, xy, N, &fu) == CTN_OK);
    const double *d = ctn_solution_displacements(s), *r = ctn_solution_reactions(s);
    for (int j = 0; j <= NSEG; j++) {          /* nodes are in model order = joint order */
        ctn_node_info nd;
        ctn_model_node(m, (size_t)j, &nd);
        CHECK_CLOSE(nd.X[0] + d[3 * j], xy[2 * j], 0, 1e-9 * 30);
        CHECK_CLOSE(nd.X[1] + d[3 * j + 1], xy[2 * j + 1], 0, 1e-9 * 30);
    }
    for (int i = 0; i < NSEG; i++) {
        ctn_element_state st;
        ctn_solution_element(s, (size_t)i, &st);
        CHECK_CLOSE(st.force, N[i], 1e-9, 0);
    }
    CHECK_CLOSE(r[0], fu.sum.reaction_left[0], 1e-9, 0);
    CHECK_CLOSE(r[1], fu.sum.reaction_left[1], 1e-9, 0);
    CHECK_CLOSE(r[3 * NSEG + 1], fu.sum.reaction_right[1], 1e-9, 0);
    /* the compare module: its elastic funicular equals the FEA, both read the same span */
    ctn_compare *c = NULL;
    ctn_compare_values vf, ve;
    CHECK(ctn_compare_create(ctx, m, &c) == CTN_OK);
    CHECK(c && ctn_compare_set_fea(c, s) == CTN_OK);
    const ctn_span *sp = ctn_compare_span(c);
    CHECK(sp && sp->loads == CTN_SPAN_POINT && sp->n == NSEG && !sp->generated);
    CHECK(sp && fabs(sp->l - 30) < 1e-12 && fabs(sp->h - 5) < 1e-12);
    CHECK(ctn_compare_has(c, CTN_FORM_FUNICULAR) && ctn_compare_has(c, CTN_FORM_EFUNICULAR));
    CHECK(!ctn_compare_has(c, CTN_FORM_CATENARY) && !ctn_compare_has(c, CTN_FORM_PARABOLA));
    CHECK(ctn_compare_get(c, CTN_FORM_FEA, &vf) == CTN_OK);
    CHECK(ctn_compare_get(c, CTN_FORM_EFUNICULAR, &ve) == CTN_OK);
    CHECK_CLOSE(vf.sag, ve.sag, 1e-9, 0);
    CHECK_CLOSE(vf.T_max, ve.T_max, 1e-9, 0);
    CHECK_CLOSE(vf.T_min, ve.T_min, 1e-9, 0);
    CHECK_CLOSE(vf.H, ve.H, 1e-9, 0);
    CHECK_CLOSE(vf.T_max, fmax(hypot(r[0], r[1]), hypot(r[3 * NSEG], r[3 * NSEG + 1])), 1e-12, 0);
    /* the sag: the polygon below the chord's mid-point, interpolated here */
    double ym = 0;
    for (int j = 0; j < NSEG; j++)
        if (xy[2 * j] <= 15 && 15 <= xy[2 * j + 2])
            ym = xy[2 * j + 1] + (15 - xy[2 * j]) / (xy[2 * j + 2] - xy[2 * j]) * (xy[2 * j + 3] - xy[2 * j + 1]);
    CHECK_CLOSE(vf.sag, 2.5 - ym, 1e-9, 0);
    ctn_compare_destroy(&c);
    CHECK(c == NULL);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* ---- support tension = resultant reaction ------------------------------------------ */
static void test_support_tension(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = paper_model(ctx, 250.8777, 20, CTN_STRAIN_GREEN_LAGRANGE);
    ctn_solution *s = m ? solve(ctx, m, CTN_METHOD_NEWTON, 1e-12) : NULL;
    ctn_compare *c = NULL;
    ctn_compare_values v;
    CHECK(s && ctn_compare_create(ctx, m, &c) == CTN_OK && ctn_compare_set_fea(c, s) == CTN_OK);
    CHECK(ctn_compare_get(c, CTN_FORM_FEA, &v) == CTN_OK);
    double V = 0.1 * 250.8777 / 2;                 /* statics: half the weight per support */
    CHECK_CLOSE(v.T_max, sqrt(v.H * v.H + V * V), 1e-9, 0);
    ctn_element_state first;
    ctn_solution_element(s, 0, &first);
    CHECK_MSG(v.T_max > 1.03 * first.force, "T_max %g, first element %g", v.T_max, first.force);
    CHECK_CLOSE(v.stress_max, v.T_max / 3.14e-4, 1e-15, 0);
    ctn_compare_destroy(&c);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* ---- a user-built chain is the generated cable's span ------------------------------ */
static ctn_model *reversed_chain(ctn_ctx *ctx, const ctn_model *gen, int n, double S)
{
    ctn_model *m = NULL;
    double g[3] = { 0, -1, 0 };
    ctn_node_info a, b, nd;
    int rc = ctn_model_create(ctx, &m) || ctn_model_set_gravity(m, g) ||
             ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0) ||
             ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1) ||
             ctn_model_node(gen, 0, &a) || ctn_model_node(gen, 1, &b) ||
             ctn_model_add_node(m, 50, b.X, CTN_FIX_ALL);          /* the far support first */
    for (int k = n - 2; k >= 0 && !rc; k--) {                     /* interior, reversed ids */
        rc = ctn_model_node(gen, (size_t)(2 + k), &nd) || ctn_model_add_node(m, 500 - 7 * k, nd.X, 0);
    }
    if (!rc) rc = ctn_model_add_node(m, 5, a.X, CTN_FIX_ALL);
    for (int k = 0; k < n && !rc; k++) {                          /* elements: scrambled ids */
        int from = k == 0 ? 5 : 500 - 7 * (k - 1), to = k == n - 1 ? 50 : 500 - 7 * k;
        rc = ctn_model_add_element(m, 3000 - 11 * k, to, from, "strand", S / n);
    }
    if (rc) ctn_model_destroy(&m);
    return m;
}

static void test_user_chain(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    const double S = 250.8777;
    ctn_model *gen = paper_model(ctx, S, 20, CTN_STRAIN_GREEN_LAGRANGE);
    ctn_model *usr = gen ? reversed_chain(ctx, gen, 20, S) : NULL;
    CHECK(gen && usr);
    ctn_solution *sg = gen ? solve(ctx, gen, CTN_METHOD_AUTO, 1e-12) : NULL, *su = usr ? solve(ctx, usr, CTN_METHOD_AUTO, 1e-12) : NULL;
    ctn_compare *cg = NULL, *cu = NULL;
    ctn_compare_values vg, vu;
    CHECK(sg && su);
    CHECK(ctn_compare_create(ctx, gen, &cg) == CTN_OK && ctn_compare_create(ctx, usr, &cu) == CTN_OK);
    CHECK(cg && cu && ctn_compare_set_fea(cg, sg) == CTN_OK && ctn_compare_set_fea(cu, su) == CTN_OK);
    if (cg && cu) {
        const ctn_span *a = ctn_compare_span(cg), *b = ctn_compare_span(cu);
        CHECK(a->generated && !b->generated && b->n == 20 && b->support[0] == 50 && b->support[1] == 5);
        CHECK_CLOSE(a->l, b->l, 1e-14, 0);
        CHECK_CLOSE(a->L0, b->L0, 1e-14, 0);
        CHECK(a->loads == CTN_SPAN_WEIGHT && b->loads == CTN_SPAN_WEIGHT);
        CHECK_CLOSE(b->w, 0.1, 1e-15, 0);
        for (int f = 0; f < CTN_FORM_COUNT; f++) {
            CHECK(ctn_compare_has(cg, (ctn_form)f) == ctn_compare_has(cu, (ctn_form)f));
            if (ctn_compare_get(cg, (ctn_form)f, &vg) || ctn_compare_get(cu, (ctn_form)f, &vu)) continue;
            CHECK_CLOSE(vg.sag, vu.sag, 1e-8, 0);
            CHECK_CLOSE(vg.T_max, vu.T_max, 1e-8, 0);
            CHECK_CLOSE(vg.T_min, vu.T_min, 1e-8, 0);
            CHECK_CLOSE(vg.H, vu.H, 1e-8, 0);
        }
    }
    ctn_compare_destroy(&cg);
    ctn_compare_destroy(&cu);
    ctn_solution_destroy(&sg);
    ctn_solution_destroy(&su);
    ctn_model_destroy(&gen);
    ctn_model_destroy(&usr);
    ctn_ctx_destroy(&ctx);
}

/* ---- models that are not a single span ---------------------------------------------- */
static void expect_refused(ctn_ctx *ctx, ctn_model *m, const char *what)
{
    ctn_compare *c = (ctn_compare *)&c;           /* must be reset to NULL */
    CHECK_MSG(m != NULL, "%s: model not built", what);
    if (!m) return;
    int rc = ctn_compare_create(ctx, m, &c);
    CHECK_MSG(rc == CTN_ERR_MODEL, "%s: got %d", what, rc);
    CHECK_MSG(c == NULL && ctn_ctx_message(ctx)[0], "%s: no message", what);
    ctn_ctx_clear(ctx);
    ctn_compare_destroy(&c);
}

static void test_refused(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double P[3] = { 100, 0, 0 }, Q[3] = { 100, -5, 0 }, F[3] = { 0, 0, 1 };
    ctn_model *m = paper_model(ctx, 201, 4, CTN_STRAIN_GREEN_LAGRANGE);
    if (m) ctn_model_add_node(m, 99, P, CTN_FIX_ALL);
    expect_refused(ctx, m, "three supports");
    /* the message names the model's file, as the model checks' do */
    ctn_compare *c = NULL;
    if (m) ctn_model_set_origin(m, "span.cable", 0);
    CHECK(m && ctn_compare_create(ctx, m, &c) == CTN_ERR_MODEL);
    CHECK_MSG(!strncmp(ctn_ctx_message(ctx), "span.cable: not a single span", 29), "%s", ctn_ctx_message(ctx));
    ctn_model_destroy(&m);
    m = paper_model(ctx, 201, 4, CTN_STRAIN_GREEN_LAGRANGE);
    if (m && (ctn_model_add_node(m, 99, Q, 0) || ctn_model_add_element(m, 99, 3, 99, "strand", CTN_L0_DEFAULT)))
        ctn_model_destroy(&m);
    expect_refused(ctx, m, "branch");
    ctn_model_destroy(&m);
    m = paper_model(ctx, 201, 4, CTN_STRAIN_GREEN_LAGRANGE);
    if (m && (ctn_model_add_section(m, "thin", "steel", 1e-4, 0.1) ||
              ctn_model_add_element(m, 99, 1, 2, "thin", 203)))
        ctn_model_destroy(&m);
    expect_refused(ctx, m, "a second path between the supports");
    ctn_model_destroy(&m);
    m = paper_model(ctx, 201, 4, CTN_STRAIN_GREEN_LAGRANGE);
    if (m && ctn_model_add_load(m, 4, F)) ctn_model_destroy(&m);
    expect_refused(ctx, m, "load out of the plane");
    ctn_model_destroy(&m);
    ctn_model_create(ctx, &m);
    expect_refused(ctx, m, "no elements");
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* ---- load per unit horizontal length ------------------------------------------------ */
static void test_hload(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = NULL;
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 10, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = 40, .length = 206, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    int first = 0, last = 0;
    int rc = ctn_model_create(ctx, &m) || ctn_model_set_gravity(m, g) ||
             ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_ENGINEERING, 0) ||
             ctn_model_add_section(m, "s", "steel", 1e-3, 0) || ctn_model_add_node(m, 1, A, CTN_FIX_ALL) ||
             ctn_model_add_node(m, 2, B, CTN_FIX_ALL) || ctn_model_add_cable(m, 1, 2, "s", &spec, &first, &last) ||
             ctn_model_add_hload(m, 2.0, first, last);
    CHECK(rc == 0);
    ctn_solution *s = rc ? NULL : solve(ctx, m, CTN_METHOD_AUTO, 1e-12);
    ctn_compare *c = NULL;
    ctn_compare_values vf, ve, vp;
    CHECK(s && ctn_compare_create(ctx, m, &c) == CTN_OK && ctn_compare_set_fea(c, s) == CTN_OK);
    if (c) {
        const ctn_span *sp = ctn_compare_span(c);
        CHECK(sp->loads == CTN_SPAN_HLOAD && sp->w == 0);
        CHECK_CLOSE(sp->q, 2.0, 1e-12, 0);
        CHECK_CLOSE(sp->h, 10, 1e-14, 0);
        CHECK(ctn_compare_has(c, CTN_FORM_PARABOLA) && ctn_compare_has(c, CTN_FORM_EPARABOLA));
        CHECK(ctn_compare_has(c, CTN_FORM_CATENARY) && !ctn_compare_has(c, CTN_FORM_FUNICULAR));
        CHECK(!ctn_compare_get(c, CTN_FORM_FEA, &vf) && !ctn_compare_get(c, CTN_FORM_EFUNICULAR, &ve) &&
              !ctn_compare_get(c, CTN_FORM_EPARABOLA, &vp));
        CHECK_CLOSE(vf.sag, ve.sag, 1e-9, 0);
        CHECK_CLOSE(vf.T_max, ve.T_max, 1e-9, 0);
        CHECK_CLOSE(vf.H, vp.H, 5e-3, 0);          /* discretization and reference projection */
        CHECK_CLOSE(vf.sag, vp.sag, 5e-3, 0);
    }
    ctn_compare_destroy(&c);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* ---- the paper's four lengths --------------------------------------------------------- */
/* Inextensible catenary of a level span by bisection on S = 2 c sinh(l / 2c). */
static double catenary_c(double l, double S)
{
    double lo = 1e-3 * l, hi = 1e6 * l;
    for (int i = 0; i < 200; i++) {
        double c = sqrt(lo * hi);
        if (2 * c * sinh(l / (2 * c)) > S) lo = c;
        else hi = c;
    }
    return sqrt(lo * hi);
}

static void test_paper(void)
{
    /* the paper: the catenary's error grows with stress: ~30 % near 300 MPa, ~6 % near
     * 150 MPa, < 1 % below ~50 MPa; it over-predicts stress and under-predicts sag */
    static const double lo[4] = { 0.20, 0.03, -0.01, -0.01 }, hi[4] = { 0.45, 0.09, 0.01, 0.01 };
    for (int k = 0; k < 4; k++) {
        ctn_ctx *ctx = NULL;
        ctn_ctx_create(&ctx);
        double S = paper_lengths[k], c0 = catenary_c(200, S);
        ctn_model *m = paper_model(ctx, S, 20, CTN_STRAIN_GREEN_LAGRANGE);
        ctn_solution *s = m ? solve(ctx, m, CTN_METHOD_NEWTON, 1e-10) : NULL;
        ctn_compare *c = NULL;
        ctn_compare_values f, cat;
        CHECK(s && ctn_compare_create(ctx, m, &c) == CTN_OK && ctn_compare_set_fea(c, s) == CTN_OK);
        CHECK(!ctn_compare_get(c, CTN_FORM_FEA, &f) && !ctn_compare_get(c, CTN_FORM_CATENARY, &cat));
        CHECK_CLOSE(cat.T_max, 0.1 * c0 * cosh(100 / c0), 1e-10, 0);
        CHECK_CLOSE(cat.T_min, 0.1 * c0, 1e-10, 0);
        CHECK_CLOSE(cat.sag, c0 * (cosh(100 / c0) - 1), 1e-9, 0);
        double dmax = ctn_compare_rel(cat.stress_max, f.stress_max), dsag = ctn_compare_rel(cat.sag, f.sag);
        double dmin = ctn_compare_rel(cat.stress_min, f.stress_min);
        CHECK_MSG(dmax >= lo[k] && dmax <= hi[k], "S=%g: support stress difference %.4f", S, dmax);
        CHECK_MSG(dmin >= lo[k] - 0.005 && dmin <= hi[k], "S=%g: vertex stress difference %.4f", S, dmin);
        if (k < 2) CHECK_MSG(dsag < -0.03, "S=%g: the catenary must under-predict the sag (%.4f)", S, dsag);
        else CHECK_MSG(fabs(dsag) < 0.01, "S=%g: sag difference %.4f", S, dsag);
        if (k < 2) CHECK_MSG(f.stress_max * KN_M2_TO_MPA > 140, "S=%g: a high-stress case", S);
        else CHECK_MSG(f.stress_max * KN_M2_TO_MPA < 55, "S=%g: a low-stress case", S);
        ctn_compare_destroy(&c);
        ctn_solution_destroy(&s);
        ctn_model_destroy(&m);
        ctn_ctx_destroy(&ctx);
    }
}

/* ---- allocation failures -------------------------------------------------------------- */
static void test_alloc(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *m = chain_model(ctx);
    ctn_solution *s = m ? solve(ctx, m, CTN_METHOD_AUTO, 1e-10) : NULL;
    int done = 0, failures = 0;
    for (long k = 1; k < 1000 && s && !done; k++) {
        ctn_compare *c = NULL;
        ctn_ctx_fail_alloc_at(ctx, k);
        int rc = ctn_compare_create(ctx, m, &c);
        if (!rc) rc = ctn_compare_set_fea(c, s);
        ctn_ctx_fail_alloc_at(ctx, 0);
        if (rc) {
            failures++;
            CHECK_MSG(rc == CTN_ERR_NOMEM, "allocation %ld: status %d", k, rc);
        } else done = 1;
        ctn_compare_destroy(&c);
        ctn_ctx_clear(ctx);
    }
    CHECK(done && failures >= 5);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

/* ---- one sag: solve and compare agree ------------------------------------------------ */
/* FEA sag of the model through compare; NAN if it fails. */
static double compare_sag(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s)
{
    ctn_compare *c = NULL;
    ctn_compare_values v;
    double sag = NAN;
    if (!ctn_compare_create(ctx, m, &c) && !ctn_compare_set_fea(c, s) && !ctn_compare_get(c, CTN_FORM_FEA, &v))
        sag = v.sag;
    ctn_compare_destroy(&c);
    return sag;
}

/* The paper's slack cable with odd and even n: ctn_solution_cable_sag (solve, the JSON)
 * and compare give the same number, and odd n does not dip: with engineering strain the
 * FEA's sag approaches the elastic catenary's from above as C / n^2 for every n. */
static void test_one_sag(void)
{
    static const int ns[] = { 9, 10, 11, 19, 20, 21, 40, 41 };
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double ref = NAN;
    for (size_t i = 0; i < sizeof ns / sizeof *ns; i++) {
        ctn_model *m = paper_model(ctx, 250.8777, ns[i], CTN_STRAIN_ENGINEERING);
        ctn_solution *s = m ? solve(ctx, m, CTN_METHOD_AUTO, 1e-12) : NULL;
        double sag = NAN, cs = NAN;
        CHECK(s && ctn_solution_cable_sag(m, s, 0, &sag) == CTN_OK);
        if (s) cs = compare_sag(ctx, m, s);
        CHECK_MSG(sag == cs, "n=%d: solve %.17g, compare %.17g", ns[i], sag, cs);
        if (isnan(ref)) {
            ctn_compare *c = NULL;
            ctn_compare_values e;
            if (m && !ctn_compare_create(ctx, m, &c) && !ctn_compare_get(c, CTN_FORM_ECATENARY, &e)) ref = e.sag;
            ctn_compare_destroy(&c);
        }
        double err = (sag - ref) / ref * ns[i] * ns[i];        /* C: about 0.54 for this cable */
        CHECK_MSG(err > 0.3 && err < 0.8, "n=%d: sag %.10g, elastic catenary %.10g: n^2 error %.3g", ns[i], sag, ref, err);
        ctn_solution_destroy(&s);
        ctn_model_destroy(&m);
    }
    ctn_ctx_destroy(&ctx);
}

/* A cable with point loads on the two interior nodes beside mid-span (odd n): both read
 * the straight element between them (the chain has kinks at the loaded nodes, which a
 * parabola would round off), and agree. */
static void test_sag_point_load(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    double A[3] = { 0, 0, 0 }, B[3] = { 30, 0, 0 }, g[3] = { 0, -1, 0 }, F[3] = { 0, -10, 0 };
    ctn_cable_spec spec = { .n = 5, .length = 32, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    int rc = ctn_model_create(ctx, &m) || ctn_model_set_gravity(m, g) ||
             ctn_model_add_material(m, "rope", 2.0e8, CTN_STRAIN_ENGINEERING, 0) ||
             ctn_model_add_section(m, "s", "rope", 1e-4, 0.01) || ctn_model_add_node(m, 1, A, CTN_FIX_ALL) ||
             ctn_model_add_node(m, 2, B, CTN_FIX_ALL) || ctn_model_add_cable(m, 1, 2, "s", &spec, NULL, NULL) ||
             ctn_model_add_load(m, 4, F) || ctn_model_add_load(m, 5, F);   /* interior nodes 2 and 3 */
    CHECK(rc == 0);
    ctn_solution *s = rc ? NULL : solve(ctx, m, CTN_METHOD_AUTO, 1e-12);
    double sag = NAN, cs = NAN;
    CHECK(s && ctn_solution_cable_sag(m, s, 0, &sag) == CTN_OK);
    if (s) cs = compare_sag(ctx, m, s);
    CHECK_MSG(sag == cs, "solve %.17g, compare %.17g", sag, cs);
    if (s) {                                              /* linear between nodes 4 and 5 */
        const double *d = ctn_solution_displacements(s);
        ctn_node_info a, b;
        size_t ia = 0, ib = 0;
        ctn_model_node_index(m, 4, &ia);
        ctn_model_node_index(m, 5, &ib);
        ctn_model_node(m, ia, &a);
        ctn_model_node(m, ib, &b);
        double xa = a.X[0] + d[3 * ia], ya = a.X[1] + d[3 * ia + 1];
        double xb = b.X[0] + d[3 * ib], yb = b.X[1] + d[3 * ib + 1];
        CHECK(xa < 15 && 15 < xb);
        CHECK_CLOSE(sag, -(ya + (15 - xa) / (xb - xa) * (yb - ya)), 1e-12, 0);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_one_sag();
    test_sag_point_load();
    test_funicular_exact();
    test_support_tension();
    test_user_chain();
    test_refused();
    test_hload();
    test_paper();
    test_alloc();
    CHECK_DONE();
}
