/* Nodes and elements from arrays (ctn_model_add_nodes, ctn_model_add_elements) between
 * pieces of text (ctn_read_string_into), against the one file they make read by
 * ctn_read_string (the independent truth: the reader, line by line):
 *   - a prestressed chain built so has the file's nodes, elements (l0 from N0, bit for
 *     bit) and solves to the file's displacements and forces bit for bit;
 *   - bad rows (a duplicate node id in the rows or after a node of the text, an undefined
 *     node, an undefined section, a duplicate element id) give the reader's message for
 *     the same file, "file:line: ..." on the row's line;
 *   - without an origin line the messages carry no location; bad arguments are refused;
 *   - every family (beam, catenary, pulley, rspring) in bulk: see families().
 * ctest-cost: 1 */
#include "check.h"

#include <catena.h>

#include <stdio.h>
#include <stdlib.h>

#define HEAD "units kN m\nmaterial steel E=2.0e8\nsection rope material=steel A=1e-4\n"
#define HEAD_LINES 3
#define MAXROWS 8

typedef struct rows {
    size_t nn, ne;
    int nid[MAXROWS];
    double X[3 * MAXROWS];
    unsigned fix[MAXROWS];
    int eid[MAXROWS], conn[2 * MAXROWS];
    double N0[MAXROWS];
    const char *section;
    const char *tail;      /* text after the rows */
} rows;

/* The file the rows make: HEAD, a node line per row, an element line per row, tail. */
static void file_text(const rows *r, char *buf, size_t size)
{
    size_t k = (size_t)snprintf(buf, size, "%s", HEAD);
    for (size_t i = 0; i < r->nn; i++)
        k += (size_t)snprintf(buf + k, size - k, "node %d %.17g %.17g %.17g%s\n", r->nid[i], r->X[3 * i],
                              r->X[3 * i + 1], r->X[3 * i + 2], r->fix[i] ? " fix=xyz" : "");
    for (size_t i = 0; i < r->ne; i++)
        k += (size_t)snprintf(buf + k, size - k, "element %d %d %d section=%s N0=%.17g group=g\n", r->eid[i],
                              r->conn[2 * i], r->conn[2 * i + 1], r->section, r->N0[i]);
    snprintf(buf + k, size - k, "%s", r->tail);
}

/* The same model: HEAD as text, the rows from arrays, the tail as text. */
static int build(ctn_ctx *ctx, const rows *r, ctn_model **m, ctn_solve_options *opt)
{
    ctn_element_spec spec;
    ctn_element_rows er;
    ctn_element_spec_init(&spec);
    ctn_element_rows_init(&er);
    spec.nnodes = 2;
    spec.section = r->section;
    spec.prestress = CTN_PRESTRESS_FORCE;
    spec.group = "g";
    er.n = r->ne;
    er.ids = r->eid;
    er.nodes = r->conn;
    er.prestress_value = r->N0;
    ctn_solve_options_default(opt);
    int rc = ctn_model_create(ctx, m), line = HEAD_LINES + 1;
    if (!rc) rc = ctn_read_string_into(*m, "m.cable", 1, HEAD, strlen(HEAD), opt);
    if (!rc) rc = ctn_model_set_origin(*m, "m.cable", line);
    if (!rc) rc = ctn_model_add_nodes(*m, r->nn, r->nid, r->X, r->fix);
    if (!rc) rc = ctn_model_set_origin(*m, "m.cable", line += (int)r->nn);
    if (!rc) rc = ctn_model_add_elements(*m, &spec, &er);
    if (!rc) rc = ctn_read_string_into(*m, "m.cable", line + (int)r->ne, r->tail, strlen(r->tail), opt);
    return rc;
}

/* A chain of n nodes along x, ends fixed, a cable element between neighbours. */
static void chain(rows *r, size_t n, const char *tail)
{
    memset(r, 0, sizeof *r);
    r->nn = n;
    r->ne = n - 1;
    for (size_t i = 0; i < n; i++) {
        r->nid[i] = (int)i + 1;
        r->X[3 * i] = 1.25 * (double)i;
        r->fix[i] = i == 0 || i == n - 1 ? CTN_FIX_ALL : 0u;
    }
    for (size_t i = 0; i + 1 < n; i++) {
        r->eid[i] = (int)i + 1;
        r->conn[2 * i] = (int)i + 1;
        r->conn[2 * i + 1] = (int)i + 2;
        r->N0[i] = 10.0 + 0.1 * (double)i;
    }
    r->section = "rope";
    r->tail = tail;
}

static int same_tables(const ctn_model *a, const ctn_model *b)
{
    if (ctn_model_node_count(a) != ctn_model_node_count(b) || ctn_model_element_count(a) != ctn_model_element_count(b))
        return 0;
    for (size_t i = 0; i < ctn_model_node_count(a); i++) {
        ctn_node_info p, q;
        ctn_model_node(a, i, &p);
        ctn_model_node(b, i, &q);
        if (p.id != q.id || p.fix != q.fix || memcmp(p.X, q.X, sizeof p.X)) return 0;
    }
    for (size_t i = 0; i < ctn_model_element_count(a); i++) {
        ctn_element_info p, q;
        ctn_model_element(a, i, &p);
        ctn_model_element(b, i, &q);
        if (p.id != q.id || p.node[0] != q.node[0] || p.node[1] != q.node[1] || memcmp(&p.l0, &q.l0, sizeof p.l0) ||
            strcmp(p.group ? p.group : "", q.group ? q.group : ""))
            return 0;
    }
    return 1;
}

static void solve_same(ctn_ctx *ctx)
{
    rows r;
    char text[4096];
    ctn_model *mf = NULL, *ma = NULL;
    ctn_solution *sf = NULL, *sa = NULL;
    ctn_solve_options of, oa;
    chain(&r, 6, "load 3 0 -2 0.5\nload 4 0 -1 0\nsolve tol=1e-12\n");
    file_text(&r, text, sizeof text);
    CHECK_MSG(ctn_read_string(ctx, "m.cable", text, strlen(text), &mf, &of) == CTN_OK, "%s", ctn_ctx_message(ctx));
    CHECK_MSG(build(ctx, &r, &ma, &oa) == CTN_OK, "%s", ctn_ctx_message(ctx));
    CHECK(of.tol == 1e-12 && oa.tol == 1e-12);            /* the tail's solve line */
    CHECK(mf && ma && same_tables(mf, ma));
    CHECK(ma && ctn_solve(ctx, ma, &oa, &sa) == CTN_OK);
    CHECK(mf && ctn_solve(ctx, mf, &of, &sf) == CTN_OK);
    if (sf && sa) {
        ctn_solve_summary a, b;
        ctn_solution_summary(sf, &a);
        ctn_solution_summary(sa, &b);
        size_t n = 3 * r.nn;
        CHECK(a.reason == CTN_CONVERGED && b.reason == CTN_CONVERGED && a.iterations == b.iterations);
        CHECK(!memcmp(ctn_solution_displacements(sf), ctn_solution_displacements(sa), n * sizeof(double)));
        for (size_t e = 0; e < r.ne; e++) {
            ctn_element_state p, q;
            ctn_solution_element(sf, e, &p);
            ctn_solution_element(sa, e, &q);
            CHECK(!memcmp(&p.force, &q.force, sizeof p.force) && p.force > 0);
        }
    }
    ctn_solution_destroy(&sf);
    ctn_solution_destroy(&sa);
    ctn_model_destroy(&mf);
    ctn_model_destroy(&ma);
}

/* The rows r are bad: both routes fail with the same message, which names want. */
static void same_error(ctn_ctx *ctx, const rows *r, const char *want)
{
    char text[4096], msg[1024];
    ctn_model *mf = NULL, *ma = NULL;
    ctn_solve_options opt;
    file_text(r, text, sizeof text);
    CHECK(ctn_read_string(ctx, "m.cable", text, strlen(text), &mf, &opt) == CTN_ERR_MODEL);
    snprintf(msg, sizeof msg, "%s", ctn_ctx_message(ctx));
    CHECK(build(ctx, r, &ma, &opt) == CTN_ERR_MODEL);
    CHECK_MSG(!strcmp(msg, ctn_ctx_message(ctx)), "file: %s | arrays: %s", msg, ctn_ctx_message(ctx));
    CHECK_MSG(strstr(msg, want) != NULL, "%s lacks %s", msg, want);
    ctn_model_destroy(&ma);
}

static void errors(ctn_ctx *ctx)
{
    rows r;
    chain(&r, 5, "");
    r.nid[3] = 2;                                          /* rows 2 and 4: lines 5 and 7 */
    same_error(ctx, &r, "m.cable:7: duplicate node id 2 (defined on line 5)");
    chain(&r, 5, "");
    r.conn[5] = 9;                                         /* element 3: line 11 */
    same_error(ctx, &r, "m.cable:11: undefined node 9");
    chain(&r, 5, "");
    r.section = "wire";
    same_error(ctx, &r, "m.cable:9: element 1: undefined section 'wire'");
    chain(&r, 5, "");
    r.eid[3] = 1;
    same_error(ctx, &r, "m.cable:12: duplicate element id 1 (defined on line 9)");
}

/* A node of the text before the rows, and the API's own use (no origin). */
static void api(ctn_ctx *ctx)
{
    const char *head = HEAD "node 2 5 5 5\n";
    ctn_model *m = NULL;
    int ids[2] = { 1, 2 };
    double X[6] = { 0, 0, 0, 1, 0, 0 };
    CHECK(ctn_model_create(ctx, &m) == CTN_OK);
    CHECK(ctn_read_string_into(m, "m.cable", 1, head, strlen(head), NULL) == CTN_OK);
    CHECK(ctn_model_set_origin(m, "m.cable", 5) == CTN_OK);
    CHECK(ctn_model_add_nodes(m, 2, ids, X, NULL) == CTN_ERR_MODEL);
    CHECK_MSG(!strcmp(ctn_ctx_message(ctx), "m.cable:6: duplicate node id 2 (defined on line 4)"), "%s",
              ctn_ctx_message(ctx));
    CHECK(ctn_model_node_count(m) == 2);                   /* the text's and row 1 stay */
    ctn_model_destroy(&m);

    CHECK(ctn_model_create(ctx, &m) == CTN_OK);
    ids[1] = 1;
    CHECK(ctn_model_add_nodes(m, 2, ids, X, NULL) == CTN_ERR_MODEL);
    CHECK_MSG(!strcmp(ctn_ctx_message(ctx), "duplicate node id 1"), "%s", ctn_ctx_message(ctx));
    CHECK(ctn_model_add_nodes(m, 0, NULL, NULL, NULL) == CTN_OK);
    CHECK(ctn_model_add_nodes(m, 1, NULL, X, NULL) == CTN_ERR_INVALID);
    CHECK(ctn_model_add_nodes(NULL, 1, ids, X, NULL) == CTN_ERR_INVALID);
    ctn_element_spec spec;
    ctn_element_rows er;
    ctn_element_spec_init(&spec);
    ctn_element_rows_init(&er);
    er.n = 1;
    CHECK(ctn_model_add_elements(m, &spec, &er) == CTN_ERR_INVALID);   /* no ids, nodes */
    CHECK(ctn_model_add_elements(m, &spec, NULL) == CTN_ERR_INVALID);
    CHECK(ctn_read_string_into(m, "x", 0, "", 0, NULL) == CTN_ERR_INVALID);
    ctn_model_destroy(&m);
}

/* Every family in bulk (issue 24): beams meshed into 3 with an orient and a release per
 * row, catenaries with a target H per row, a pulley of 4 nodes, rotational springs,
 * between text pieces, against the file of the same lines: the same tables and, solved,
 * the same displacements and forces bit for bit; a bad row of each (a beam's undefined
 * node, a catenary's undefined section, a pulley's undefined node) the reader's message
 * on the row's line (a zero orient is the default in the spec, an error in the text: the
 * Python side sends such rows as text). */
#define FHEAD "units kN m\ngravity 0 0 -1\nmaterial m E=2e8 G=7.7e7\nmaterial rope E=1e5 strain=engineering\n" \
              "section b material=m A=1e-2 Iy=1e-4 Iz=2e-4 J=3e-4 w=0.5\nsection r material=rope A=0.01 w=0.01\n" \
              "node 1 0 0 0 fix=xyzrxryrz\nnode 2 6 0 0\nnode 3 12 0 0 fix=xyzrxryrz\n" \
              "node 4 0 5 0 fix=xyz\nnode 5 30 5 2 fix=xyz\nnode 6 0 9 0 fix=xyz\nnode 7 40 9 0 fix=xyz\n" \
              "node 11 0 20 0 fix=xyz\nnode 12 4 20 0 fix=xyz\nnode 13 8 20 3 fix=xyz\nnode 14 8 20 -2\n" \
              "node 21 12 0 -3 fix=xyzrxryrz\n"
#define FHEAD_LINES 18

typedef struct fam {
    const char *type, *section;
    int nnodes;
    size_t n;
    int ids[2], nodes[8];
    double value[2], orient[6];
    unsigned release[2];
    int segments[2];
    ctn_cable_target target;
} fam;

static void fam_lines(const fam *f, char *buf, size_t size, size_t *k)
{
    static const char *const tkey[] = { "", "H", "sag", "tension" };
    for (size_t i = 0; i < f->n; i++) {
        *k += (size_t)snprintf(buf + *k, size - *k, "%s %d", f->type, f->ids[i]);
        for (int j = 0; j < f->nnodes; j++) *k += (size_t)snprintf(buf + *k, size - *k, " %d", f->nodes[f->nnodes * (int)i + j]);
        if (f->section) *k += (size_t)snprintf(buf + *k, size - *k, " section=%s", f->section);
        if (!strcmp(f->type, "beam"))
            *k += (size_t)snprintf(buf + *k, size - *k, " orient=%.17g,%.17g,%.17g n=%d%s", f->orient[3 * i],
                                   f->orient[3 * i + 1], f->orient[3 * i + 2], f->segments[i],
                                   f->release[i] ? " release=2:ryrz" : "");
        else if (!strcmp(f->type, "catenary"))
            *k += (size_t)snprintf(buf + *k, size - *k, " %s=%.17g", tkey[f->target], f->value[i]);
        else if (!strcmp(f->type, "pulley"))
            *k += (size_t)snprintf(buf + *k, size - *k, " length=%.17g", f->value[i]);
        else
            *k += (size_t)snprintf(buf + *k, size - *k, " k=%.17g", f->value[i]);
        *k += (size_t)snprintf(buf + *k, size - *k, " group=%s\n", f->type);
    }
}

static int fam_add(ctn_model *m, const fam *f)
{
    ctn_element_spec spec;
    ctn_element_rows er;
    ctn_element_spec_init(&spec);
    ctn_element_rows_init(&er);
    spec.type = f->type;
    spec.nnodes = f->nnodes;
    spec.section = f->section;
    spec.group = f->type;
    spec.target = f->target;
    er.n = f->n;
    er.ids = f->ids;
    er.nodes = f->nodes;
    if (!strcmp(f->type, "beam")) {
        er.orient = f->orient;
        er.release = f->release;
        er.segments = f->segments;
    } else if (!strcmp(f->type, "catenary"))
        er.target_value = f->value;
    else if (!strcmp(f->type, "pulley"))
        er.l0 = f->value;
    else
        er.k = f->value;
    return ctn_model_add_elements(m, &spec, &er);
}

static const char *const FTAIL = "load 14 0 0 -20\nsolve tol=1e-10\n";

static void fam_file(const fam *f, size_t nf, char *buf, size_t size)
{
    size_t k = (size_t)snprintf(buf, size, "%s", FHEAD);
    for (size_t i = 0; i < nf; i++) fam_lines(&f[i], buf, size, &k);
    snprintf(buf + k, size - k, "%s", FTAIL);
}

static int fam_build(ctn_ctx *ctx, const fam *f, size_t nf, ctn_model **m, ctn_solve_options *opt)
{
    ctn_solve_options_default(opt);
    int rc = ctn_model_create(ctx, m), line = FHEAD_LINES + 1;
    if (!rc) rc = ctn_read_string_into(*m, "f.cable", 1, FHEAD, strlen(FHEAD), opt);
    for (size_t i = 0; i < nf && !rc; i++) {
        rc = ctn_model_set_origin(*m, "f.cable", line);
        if (!rc) rc = fam_add(*m, &f[i]);
        line += (int)f[i].n;
    }
    if (!rc) rc = ctn_read_string_into(*m, "f.cable", line, FTAIL, strlen(FTAIL), opt);
    return rc;
}

static void families_set(fam *f)
{
    memset(f, 0, 4 * sizeof *f);
    f[0] = (fam){ "beam", "b", 2, 2, { 1, 2 }, { 1, 2, 2, 3 }, { 0, 0 }, { 0, 0, 1, 0, 1, 1 }, { 0, CTN_RELEASE_RY2 | CTN_RELEASE_RZ2 }, { 3, 3 },
                  CTN_TARGET_NONE };
    f[1] = (fam){ "catenary", "r", 2, 2, { 3, 4 }, { 4, 5, 6, 7 }, { 5, 8 }, { 0 }, { 0 }, { 0 }, CTN_TARGET_H };
    f[2] = (fam){ "pulley", "r", 4, 1, { 5 }, { 11, 12, 13, 14 }, { 15 }, { 0 }, { 0 }, { 0 }, CTN_TARGET_NONE };
    f[3] = (fam){ "rspring", NULL, 2, 1, { 6 }, { 3, 21 }, { 40 }, { 0 }, { 0 }, { 0 }, CTN_TARGET_NONE };
}

static void families(ctn_ctx *ctx)
{
    fam f[4];
    char text[8192], msg[1024];
    families_set(f);
    ctn_model *mf = NULL, *ma = NULL;
    ctn_solution *sf = NULL, *sa = NULL;
    ctn_solve_options of, oa;
    fam_file(f, 4, text, sizeof text);
    CHECK_MSG(ctn_read_string(ctx, "f.cable", text, strlen(text), &mf, &of) == CTN_OK, "%s", ctn_ctx_message(ctx));
    CHECK_MSG(fam_build(ctx, f, 4, &ma, &oa) == CTN_OK, "%s", ctn_ctx_message(ctx));
    CHECK(mf && ma && same_tables(mf, ma) && ctn_model_element_count(ma) == 10);   /* 2 x 3 beams, 2, 1, 1 */
    CHECK(ma && ctn_model_resolve_targets(ctx, ma, &oa, NULL) == CTN_OK && ctn_solve(ctx, ma, &oa, &sa) == CTN_OK);
    CHECK_MSG(mf && ctn_model_resolve_targets(ctx, mf, &of, NULL) == CTN_OK && ctn_solve(ctx, mf, &of, &sf) == CTN_OK,
              "%s", ctn_ctx_message(ctx));
    if (sf && sa) {
        ctn_solve_summary a, b;
        ctn_solution_summary(sf, &a);
        ctn_solution_summary(sa, &b);
        CHECK(a.reason == CTN_CONVERGED && a.iterations == b.iterations);
        CHECK(same_tables(mf, ma));                        /* the catenaries' lengths found */
        CHECK(!memcmp(ctn_solution_displacements(sf), ctn_solution_displacements(sa),
                      3 * ctn_model_node_count(mf) * sizeof(double)));
        for (size_t e = 0; e < ctn_model_element_count(mf); e++) {
            ctn_element_state p, q;
            ctn_solution_element(sf, e, &p);
            ctn_solution_element(sa, e, &q);
            CHECK(!memcmp(&p.force, &q.force, sizeof p.force));
        }
        printf("every family in bulk: %d iterations, the file's displacements and forces bit for bit\n", b.iterations);
    }
    ctn_solution_destroy(&sf);
    ctn_solution_destroy(&sa);
    ctn_model_destroy(&mf);
    ctn_model_destroy(&ma);
    for (int bad = 0; bad < 3; bad++) {                  /* a bad row of three families */
        families_set(f);
        if (bad == 0) f[0].nodes[2] = 98;
        if (bad == 1) f[1].section = "wire";
        if (bad == 2) f[2].nodes[1] = 99;
        fam_file(f, 4, text, sizeof text);
        int rf = ctn_read_string(ctx, "f.cable", text, strlen(text), &mf, &of);
        snprintf(msg, sizeof msg, "%s", ctn_ctx_message(ctx));
        int ra = fam_build(ctx, f, 4, &ma, &oa);
        printf("bad row %d: %s | %s\n", bad, msg, ctn_ctx_message(ctx));
        CHECK_MSG(rf == CTN_ERR_MODEL && ra == rf, "codes %d %d", rf, ra);
        CHECK_MSG(!strcmp(msg, ctn_ctx_message(ctx)), "file: %s | arrays: %s", msg, ctn_ctx_message(ctx));
        ctn_model_destroy(&mf);
        ctn_model_destroy(&ma);
    }
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    if (ctn_ctx_create(&ctx)) return 1;
    solve_same(ctx);
    errors(ctx);
    api(ctx);
    families(ctx);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
