/* The length study (ctn_study_*) and the figure writers (catena/plot.h).
 * - the paper's span over a sweep plus its four lengths: sorted rows, the marked ones
 *   flagged, every FEA converged; on the taut branch the catenary's excess stress grows
 *   as the cable shortens; a marked row equals a direct comparison of that model;
 * - the error at a stress level is interpolated between the bracketing rows, in the
 *   paper's range (150 MPa: a few %; catenary at 300 MPa: 20-40 %), absent outside;
 * - figures: data files of %.17g numbers (NaN refused, nothing written), scripts naming
 *   their data, rendering without gnuplot is not an error, a failing gnuplot is;
 * - one catenary element per length (CTN_STUDY_CATENARY): the elastic catenary to
 *   round-off, the mesh beside it equal to the plain study's FEA;
 * - allocation failures in ctn_study_run give CTN_ERR_NOMEM and no leak (both kinds). */
/* ctest-cost: 20 (about the seconds it takes under ASan: ctest -j starts it early) */
#include "catena.h"
#include "check.h"

#include <dirent.h>
#include <stdlib.h>
#include <unistd.h>

static const double paper_lengths[] = { 200.3340, 201.3545, 250.8777, 279.6157 };

static ctn_model *paper_model(ctn_ctx *ctx, double S, int n)
{
    ctn_model *m = NULL;
    double A[3] = { 0, 0, 0 }, B[3] = { 200, 0, 0 }, g[3] = { 0, -1, 0 };
    ctn_cable_spec spec = { .n = n, .length = S, .shape = CTN_SHAPE_ARC, .guess_strain = 1e-3, .start = CTN_START_ARC, .prestress = CTN_PRESTRESS_NONE };
    if (ctn_model_create(ctx, &m) || ctn_model_set_units(m, "kN", "m") || ctn_model_set_gravity(m, g) ||
        ctn_model_add_material(m, "steel", 2.0e8, CTN_STRAIN_GREEN_LAGRANGE, 0) ||
        ctn_model_add_section(m, "strand", "steel", 3.14e-4, 0.1) ||
        ctn_model_add_node(m, 1, A, CTN_FIX_ALL) || ctn_model_add_node(m, 2, B, CTN_FIX_ALL) ||
        ctn_model_add_cable(m, 1, 2, "strand", &spec, NULL, NULL))
        ctn_model_destroy(&m);
    return m;
}

static void check_rows(const ctn_study *st)
{
    size_t n = ctn_study_count(st), marked = 0;
    double prev = 0, prev_err = INFINITY;
    CHECK_MSG(n == 4 + 24, "%zu rows", n);
    for (size_t i = 0; i < n; i++) {
        const ctn_study_row *r = ctn_study_row_at(st, i);
        CHECK(r->L0 > prev);
        prev = r->L0;
        marked += (size_t)r->marked;
        CHECK_MSG(r->reason == CTN_CONVERGED && (r->present & 1u), "L0=%g: %s", r->L0, ctn_reason_name(r->reason));
        CHECK(r->present & 1u << CTN_FORM_CATENARY && r->present & 1u << CTN_FORM_ECATENARY);
        if (r->L0 > 210 || !(r->present & 1u << CTN_FORM_CATENARY)) continue;
        double err = ctn_compare_rel(r->v[CTN_FORM_CATENARY].stress_max, r->v[CTN_FORM_FEA].stress_max);
        CHECK_MSG(err > 0 && err < prev_err, "L0=%g: excess stress %.4f after %.4f", r->L0, err, prev_err);
        prev_err = err;
    }
    CHECK(marked == 4);
    CHECK(ctn_study_row_at(st, n) == NULL);
}

/* The marked row of 201.3545 against a direct comparison of that model. */
/* The paper's pure Newton, the options of every solve here. */
static ctn_solve_options newton(void)
{
    ctn_solve_options o;
    ctn_solve_options_default(&o);
    o.method = CTN_METHOD_NEWTON;
    return o;
}

static void check_marked(ctn_ctx *ctx, const ctn_study *st)
{
    ctn_solve_options o = newton();
    ctn_model *m = paper_model(ctx, paper_lengths[1], 20);
    ctn_solution *s = NULL;
    ctn_compare *c = NULL;
    ctn_compare_values v;
    CHECK(m && !ctn_solve(ctx, m, &o, &s) && !ctn_compare_create(ctx, m, &c) && !ctn_compare_set_fea(c, s));
    for (size_t i = 0; i < ctn_study_count(st); i++) {
        const ctn_study_row *r = ctn_study_row_at(st, i);
        if (fabs(r->L0 - paper_lengths[1]) > 1e-9) continue;
        CHECK(r->marked && !ctn_compare_get(c, CTN_FORM_FEA, &v));
        CHECK_CLOSE(r->v[CTN_FORM_FEA].sag, v.sag, 1e-12, 0);
        CHECK_CLOSE(r->v[CTN_FORM_FEA].T_max, v.T_max, 1e-12, 0);
        CHECK(!ctn_compare_get(c, CTN_FORM_CATENARY, &v));
        CHECK_CLOSE(r->v[CTN_FORM_CATENARY].stress_max, v.stress_max, 1e-14, 0);
    }
    ctn_compare_destroy(&c);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
}

static void check_levels(const ctn_study *st)
{
    ctn_study_level L;
    CHECK(ctn_study_level_at(st, CTN_LEVEL_FEA, 150e3, &L) == CTN_OK);    /* kN/m^2 */
    CHECK(L.found && L.L0 > 201 && L.L0 < 202);
    CHECK_CLOSE(L.stress_fea, 150e3, 1e-12, 0);
    CHECK_MSG(L.err_max > 0.03 && L.err_max < 0.08 && L.err_sag < -0.03, "150 MPa: %.4f %.4f", L.err_max, L.err_sag);
    CHECK(ctn_study_level_at(st, CTN_LEVEL_CATENARY, 300e3, &L) == CTN_OK);
    CHECK(L.found && L.stress_cat > 0);
    CHECK_CLOSE(L.stress_cat, 300e3, 1e-12, 0);
    CHECK_MSG(L.err_max > 0.2 && L.err_max < 0.4, "catenary 300 MPa: %.4f", L.err_max);
    CHECK(ctn_study_level_at(st, CTN_LEVEL_FEA, 10e3, &L) == CTN_OK && !L.found);
    CHECK(ctn_study_level_at(st, CTN_LEVEL_FEA, -1, &L) == CTN_ERR_INVALID && !L.found);
}

/* ---- files ----------------------------------------------------------------------------- */
static int has_file(const char *dir, const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return access(path, R_OK) == 0;
}

/* 1 if the file holds text (and not "nan"/"inf" when numbers is set). */
static int file_contains(const char *dir, const char *name, const char *text)
{
    char path[512], buf[65536];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return strstr(buf, text) != NULL;
}

static void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char path[512];
    while (d && (e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        unlink(path);
    }
    if (d) closedir(d);
    rmdir(dir);
}

static void check_figures(ctn_ctx *ctx, const ctn_study *st, const char *dir)
{
    const char *names[4] = { NULL, NULL, NULL, NULL };
    CHECK(ctn_study_write_figures(ctx, st, dir, names) == CTN_OK);
    static const char *files[] = { "study_fea.dat", "study_catenary.dat", "study_elastic_catenary.dat",
                                   "study_marked_fea.dat", "study_error.dat", "study_claims.dat",
                                   "study_stress_max.gp", "study_stress_min.gp", "study_sag.gp", "study_error.gp" };
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) CHECK_MSG(has_file(dir, files[i]), "%s", files[i]);
    CHECK(names[3] && !strcmp(names[3], "study_error"));
    CHECK(file_contains(dir, "study_stress_max.gp", "\"study_fea.dat\" using 2:4"));
    CHECK(file_contains(dir, "study_error.gp", "the paper"));
    CHECK(file_contains(dir, "study_marked_fea.dat", "200.334"));
    CHECK(!file_contains(dir, "study_fea.dat", "nan") && !file_contains(dir, "study_error.dat", "inf"));
}

static void test_study(const char *dir)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *base = paper_model(ctx, 250.8777, 20);
    ctn_study *st = NULL;
    ctn_study_options opt;
    double claims[6] = { 50, 1, 150, 6, 300, 30 };
    ctn_study_options_default(&opt);
    opt.lengths = paper_lengths;
    opt.nlengths = 4;
    opt.sweep = 24;
    opt.claims = claims;
    opt.nclaims = 3;
    opt.claims_title = "the paper";
    ctn_solve_options o = newton();
    opt.solve = &o;
    CHECK(base && ctn_study_run(ctx, base, &opt, &st) == CTN_OK);
    if (st) {
        const ctn_span *sp = ctn_study_span(st);
        CHECK(sp && sp->n == 20 && fabs(sp->mpa - 1e-3) < 1e-15);
        CHECK(ctn_study_row_at(st, 0)->L0 > 200 && ctn_study_row_at(st, ctn_study_count(st) - 1)->L0 <= 300 + 1e-9);
        check_rows(st);
        check_marked(ctx, st);
        check_levels(st);
        check_figures(ctx, st, dir);
    }
    opt.sweep_from = 199;                       /* below the chord: refused */
    ctn_study *bad = (ctn_study *)&bad;
    CHECK(ctn_study_run(ctx, base, &opt, &bad) == CTN_ERR_INVALID && bad == NULL);
    ctn_study_destroy(&st);
    ctn_model_destroy(&base);
    ctn_ctx_destroy(&ctx);
}

/* The study on one catenary element per length: the element is the elastic catenary to
 * round-off on every row, the mesh beside it is the plain study's FEA, the figures carry
 * it; a catenary base is studied on catenary elements; an hload span is refused. */
static void test_study_catenary(const char *dir)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *base = paper_model(ctx, 250.8777, 20);
    ctn_study *st = NULL, *mesh = NULL;
    ctn_study_options opt;
    ctn_study_options_default(&opt);
    opt.lengths = paper_lengths;
    opt.nlengths = 4;
    opt.sweep = 12;
    ctn_solve_options o = newton();
    opt.solve = &o;
    CHECK(base && ctn_study_run(ctx, base, &opt, &mesh) == CTN_OK);
    opt.element = CTN_STUDY_CATENARY;
    CHECK(base && ctn_study_run(ctx, base, &opt, &st) == CTN_OK);
    if (st && mesh) {
        CHECK(ctn_study_element_kind(st) == CTN_STUDY_CATENARY && ctn_study_element_kind(mesh) == CTN_STUDY_MESH);
        CHECK(ctn_study_count(st) == ctn_study_count(mesh));
        double worst = 0, mesh_worst = 0;
        for (size_t i = 0; i < ctn_study_count(st) && i < ctn_study_count(mesh); i++) {
            const ctn_study_row *r = ctn_study_row_at(st, i), *q = ctn_study_row_at(mesh, i);
            const unsigned both = 1u << CTN_FORM_FEA | 1u << CTN_FORM_ECATENARY;
            CHECK((r->present & both) == both && r->has_mesh && r->mesh_reason == CTN_CONVERGED);
            const ctn_compare_values *f = &r->v[CTN_FORM_FEA], *e = &r->v[CTN_FORM_ECATENARY];
            double d[3] = { ctn_compare_rel(f->sag, e->sag), ctn_compare_rel(f->stress_max, e->stress_max),
                            ctn_compare_rel(f->H, e->H) };
            for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(d[k]));
            /* the mesh beside it is the plain study's FEA, and differs from the element by
             * the mesh's error (Green-Lagrange strain, 20 elements: a few 1e-4) */
            CHECK(q->present & 1u << CTN_FORM_FEA);
            CHECK(r->mesh.sag == q->v[CTN_FORM_FEA].sag && r->mesh.stress_max == q->v[CTN_FORM_FEA].stress_max);
            mesh_worst = fmax(mesh_worst, fabs(ctn_compare_rel(r->mesh.stress_max, f->stress_max)));
        }
        printf("catenary element against the elastic catenary: largest relative difference %.2e; FE mesh %.2e\n", worst,
               mesh_worst);
        CHECK(worst < 1e-10);
        CHECK(mesh_worst > 1e-5 && mesh_worst < 3e-3);
        const char *names[4] = { NULL, NULL, NULL, NULL };
        CHECK(ctn_study_write_figures(ctx, st, dir, names) == CTN_OK);
        CHECK(has_file(dir, "study_mesh.dat") && file_contains(dir, "study_fea.dat", "catenary element"));
        CHECK(file_contains(dir, "study_stress_max.gp", "FE mesh, 20 cable elements"));
        const char *el = NULL;
        CHECK(ctn_study_write_element_figure(ctx, st, dir, &el) == CTN_OK && el && !strcmp(el, "study_element"));
        CHECK(has_file(dir, "study_element.dat") && file_contains(dir, "study_element.gp", "\"study_element.dat\" using 2:3"));
        CHECK(ctn_study_write_element_figure(ctx, mesh, dir, &el) == CTN_OK && el == NULL);
    }
    ctn_study_destroy(&st);
    ctn_study_destroy(&mesh);
    ctn_model_destroy(&base);
    /* a base of one catenary element: catenary rows, no mesh beside them */
#define PAPER_SUPPORTS "units kN m\ngravity 0 -1 0\nmaterial steel E=2e8\nsection s material=steel A=3.14e-4 w=0.1\n" \
                       "node 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n"
    const char *one = PAPER_SUPPORTS "catenary 1 1 2 section=s length=201.3545\n";
    CHECK(ctn_read_string(ctx, "one.cable", one, strlen(one), &base, NULL) == CTN_OK);
    opt.element = CTN_STUDY_MESH;
    opt.nlengths = 0;
    opt.sweep = 3;
    CHECK(base && ctn_study_run(ctx, base, &opt, &st) == CTN_OK);
    if (st) {
        CHECK(ctn_study_element_kind(st) == CTN_STUDY_CATENARY && ctn_study_count(st) == 4);
        for (size_t i = 0; i < ctn_study_count(st); i++) {
            const ctn_study_row *r = ctn_study_row_at(st, i);
            CHECK(!r->has_mesh && (r->present & 1u << CTN_FORM_FEA));
            CHECK_CLOSE(r->v[CTN_FORM_FEA].stress_max, r->v[CTN_FORM_ECATENARY].stress_max, 1e-10, 0);
        }
    }
    ctn_study_destroy(&st);
    ctn_model_destroy(&base);
    /* an hload cannot ride on a catenary element; an unknown kind is refused */
    const char *hl = PAPER_SUPPORTS "cable 1 2 section=s n=10 length=201\nhload q=0.5 elements=all\n";
    CHECK(ctn_read_string(ctx, "hl.cable", hl, strlen(hl), &base, NULL) == CTN_OK);
    opt.element = CTN_STUDY_CATENARY;
    CHECK(ctn_study_run(ctx, base, &opt, &st) == CTN_ERR_MODEL && strstr(ctn_ctx_message(ctx), "hl.cable: a catenary element"));
    opt.element = (ctn_study_element)7;
    CHECK(ctn_study_run(ctx, base, &opt, &st) == CTN_ERR_INVALID && st == NULL);
    ctn_model_destroy(&base);
    ctn_ctx_destroy(&ctx);
}

static void test_plot(const char *dir)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    double good[4] = { 1, 0.1, 2, 1e-300 }, bad[4] = { 1, 2, NAN, 4 };
    CHECK(ctn_plot_write_data(ctx, dir, "p.dat", "x y\nsecond line", 2, 2, good) == CTN_OK);
    CHECK(file_contains(dir, "p.dat", "# x y\n# second line\n1 0.10000000000000001\n2 1e-300\n"));
    CHECK(ctn_plot_write_data(ctx, dir, "q.dat", NULL, 2, 2, bad) == CTN_ERR_INVALID && !has_file(dir, "q.dat"));
    CHECK(ctn_plot_write_data(ctx, dir, "../q.dat", NULL, 2, 1, good) == CTN_ERR_INVALID);
    CHECK(ctn_plot_write_data(ctx, dir, "a b.dat", NULL, 2, 1, good) == CTN_ERR_INVALID);
    ctn_plot_series ser = { "p.dat", 1, 2, "a \"quoted\" title", CTN_PLOT_LINES, 1 };
    ctn_plot_figure fig = { "p", "t", "x [m]", "y [m]", 1, 0, NULL, NULL, 1, &ser };
    CHECK(ctn_plot_write_script(ctx, dir, &fig) == CTN_OK);
    CHECK(file_contains(dir, "p.gp", "\"p.dat\" using 1:2 with lines") && file_contains(dir, "p.gp", "\\\"quoted\\\""));
    CHECK(file_contains(dir, "p.gp", "set logscale x") && file_contains(dir, "p.gp", "set output \"p.\".fmt"));
    ser.xcol = 0;
    CHECK(ctn_plot_write_script(ctx, dir, &fig) == CTN_ERR_INVALID);
    int done = 1;
    setenv("CATENA_GNUPLOT", "/nonexistent/gnuplot", 1);
    CHECK(ctn_plot_render(ctx, dir, "p", &done) == CTN_OK && done == 0);
    setenv("CATENA_GNUPLOT", "false", 1);
    CHECK(ctn_plot_render(ctx, dir, "p", &done) == CTN_ERR_IO && done == 0);
    unsetenv("CATENA_GNUPLOT");
    ctn_ctx_clear(ctx);
    ser.xcol = 1;
    CHECK(ctn_plot_write_script(ctx, dir, &fig) == CTN_OK);
    if (ctn_plot_render(ctx, dir, "p", &done) == CTN_OK && done) CHECK(has_file(dir, "p.svg"));
    else printf("gnuplot not installed: rendering not checked\n");
    ctn_ctx_destroy(&ctx);
}

static void test_alloc(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    ctn_model *base = paper_model(ctx, 210, 4);
    ctn_study_options opt;
    ctn_study_options_default(&opt);
    opt.sweep = 2;
    ctn_solve_options o = newton();
    opt.solve = &o;
    for (int kind = 0; kind < 2; kind++) {          /* the mesh, then catenary elements */
        int done = 0, failures = 0;
        opt.element = kind ? CTN_STUDY_CATENARY : CTN_STUDY_MESH;
        for (long k = 1; k < 20000 && base && !done; k++) {
            ctn_study *st = NULL;
            ctn_ctx_fail_alloc_at(ctx, k);
            int rc = ctn_study_run(ctx, base, &opt, &st);
            ctn_ctx_fail_alloc_at(ctx, 0);
            if (rc) {
                failures++;
                CHECK_MSG(rc == CTN_ERR_NOMEM && st == NULL, "allocation %ld: status %d", k, rc);
            } else done = 1;
            ctn_study_destroy(&st);
            ctn_ctx_clear(ctx);
        }
        CHECK(done && failures >= 10);
    }
    ctn_model_destroy(&base);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    char dir[] = "/tmp/catena-study-XXXXXX";
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    test_study(dir);
    test_study_catenary(dir);
    test_plot(dir);
    test_alloc();
    remove_dir(dir);
    CHECK_DONE();
}
