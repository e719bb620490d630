/* Directives in any order (issue 27; docs/format.md, "Order of the directives"):
 * - every example and test model (the .cable files of examples/DIR and tests/models/DIR) with its
 *   definitions moved below their uses (the lines of units, gravity, material, section,
 *   function, group and set, and the node lines above the first generator line (cable,
 *   beam, net: lines that number nodes of their own), to
 *   the end of the file, kinds in reverse order: sections above the materials they use)
 *   solves to the same JSON, byte for byte, as the model as written (static steps, cases,
 *   combinations and envelope; the modal, buckling and dynamics requests are dropped on
 *   both sides to keep the test cheap: they run on the same model);
 * - a generated cable's interior node ids follow the file's order: a node line below a
 *   cable that nothing above it names keeps its place (ids as before), one the cable
 *   names is defined first;
 * - groups are numbered by their first mention in the file;
 * - a name or id never defined is an error at the line that uses it; an unknown directive
 *   is reported before the definitions run; two different `units` lines are an error;
 * - an included file's definitions may follow their use. */
/* ctest-cost: 60 (about the seconds it takes under ASan: ctest -j starts it early; 110 s measured on the loaded machine) */
#include "catena.h"
#include "check.h"
#include "model/model.h"

#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const moved_kinds[] = { "set", "group", "section", "function", "material", "node", "gravity", "units" };
#define NKINDS (sizeof moved_kinds / sizeof *moved_kinds)

/* The lines that number nodes of their own after the largest id so far. */
static int is_generator(const char *w)
{
    return !strcmp(w, "cable") || !strcmp(w, "beam") || !strcmp(w, "net");
}

/* The first word of a line (before any comment) into w. */
static void first_word(const char *line, size_t len, char *w, size_t size)
{
    size_t i = 0, k = 0;
    while (i < len && (line[i] == ' ' || line[i] == '\t')) i++;
    while (i < len && line[i] != ' ' && line[i] != '\t' && line[i] != '#' && line[i] != '\r' && k + 1 < size) w[k++] = line[i++];
    w[k] = '\0';
}

/* The text with its definitions moved below their uses (see the header). */
static char *shuffle(const char *text)
{
    size_t n = strlen(text), k = 0;
    char *out = malloc(n + 2);
    for (int pass = -1; pass < (int)NKINDS; pass++) {
        int gen_seen = 0;
        for (const char *p = text; *p;) {
            const char *e = strchr(p, '\n');
            size_t len = e ? (size_t)(e - p) : strlen(p);
            char w[32];
            first_word(p, len, w, sizeof w);
            if (is_generator(w)) gen_seen = 1;
            int kind = -1;
            for (int j = 0; j < (int)NKINDS; j++)
                if (!strcmp(w, moved_kinds[j])) kind = j;
            if (kind >= 0 && !strcmp(w, "node") && gen_seen) kind = -1;
            if (kind == pass) {
                memcpy(out + k, p, len);
                k += len;
                out[k++] = '\n';
            }
            p += len + (e != NULL);
        }
    }
    out[k] = '\0';
    return out;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    size_t got = fread(s, 1, (size_t)n, f);
    s[got] = '\0';
    fclose(f);
    return s;
}

/* Read (a file, or text under the file's name), solve the static part, the JSON; or
 * "error: <message>" with the exit status. */
static char *solve_json(const char *path, const char *text)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    char *json = NULL, *out = NULL;
    ctn_ctx_create(&ctx);
    int rc = text ? ctn_read_string(ctx, path, text, strlen(text), &m, &opt) : ctn_read_file(ctx, path, &m, &opt);
    if (!rc) {
        opt.modal.count = 0;
        opt.buckling.count = 0;
        opt.dynamics.t_end = 0;
        opt.dynamics.dt = 0;
        rc = ctn_model_resolve_targets(ctx, m, &opt, NULL);
    }
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    if (!rc) rc = ctn_result_json(ctx, m, s, 0, &json);
    if (rc) {
        const char *msg = ctn_ctx_message(ctx);
        out = malloc(strlen(msg) + 32);
        sprintf(out, "error %d: %s", rc, msg);
    } else {
        out = malloc(strlen(json) + 1);
        strcpy(out, json);
    }
    ctn_json_free(json);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return out;
}

static void shuffled_models(void)
{
    static const char *const patterns[] = { "examples/*/*.cable", "tests/models/*/*.cable" };
    int models = 0;
    for (size_t p = 0; p < 2; p++) {
        glob_t g;
        if (glob(patterns[p], 0, NULL, &g)) continue;
        for (size_t i = 0; i < g.gl_pathc; i++) {
            const char *path = g.gl_pathv[i];
            char *text = slurp(path), *moved = shuffle(text);
            char *a = solve_json(path, NULL), *b = solve_json(path, moved);
            CHECK_MSG(strcmp(text, moved), "%s: nothing moved", path);
            CHECK_MSG(!strcmp(a, b), "%s: the shuffled model differs: %.200s | %.200s", path, a, b);
            models += strncmp(a, "error", 5) != 0;          /* a fragment for include: the same error */
            free(text);
            free(moved);
            free(a);
            free(b);
        }
        globfree(&g);
    }
    CHECK_MSG(models >= 45, "only %d models solved", models);
}

static ctn_model *read_text(ctn_ctx *ctx, const char *text, int expect_ok)
{
    ctn_model *m = NULL;
    int rc = ctn_read_string(ctx, "t.cable", text, strlen(text), &m, NULL);
    if (expect_ok) CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    return m;
}

static int node_at(const ctn_model *m, size_t i) { return m->nodes.v[i].id; }

/* The ids a cable generates follow the file's order. */
static void generated_ids(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    const char *head = "units kN m\nmaterial s E=2e8\nsection c material=s A=1e-4 w=0.01\ngravity 0 -1 0\n";
    char text[1024];
    /* node 10 below the first cable, named by nothing above it: interior 3, 4, then 11, 12 */
    snprintf(text, sizeof text, "%snode 1 0 0 0 fix=xyz\nnode 2 10 0 0 fix=xyz\ncable 1 2 section=c n=3 length=10.5\n"
             "node 10 20 0 0 fix=xyz\ncable 2 10 section=c n=3 length=10.5\n", head);
    ctn_model *m = read_text(ctx, text, 1);
    if (m) {
        CHECK(m->nodes.n == 7 && node_at(m, 2) == 3 && node_at(m, 3) == 4 && node_at(m, 5) == 11 && node_at(m, 6) == 12);
        ctn_model_destroy(&m);
    }
    /* every definition below its use: the nodes the cables name come first, so the
     * interior ids follow the largest, 10 */
    snprintf(text, sizeof text, "cable 1 2 section=c n=3 length=10.5\ncable 2 10 section=c n=3 length=10.5\n"
             "gravity 0 -1 0\nsection c material=s A=1e-4 w=0.01\nmaterial s E=2e8\n"
             "node 1 0 0 0 fix=xyz\nnode 2 10 0 0 fix=xyz\nnode 10 20 0 0 fix=xyz\nunits kN m\n");
    m = read_text(ctx, text, 1);
    if (m) {
        CHECK(m->nodes.n == 7 && node_at(m, 3) == 11 && node_at(m, 4) == 12 && node_at(m, 6) == 14);
        ctn_model_destroy(&m);
    }
    /* a generated id taken later by an explicit node: still the duplicate, at the node's line */
    snprintf(text, sizeof text, "%snode 1 0 0 0 fix=xyz\nnode 2 10 0 0 fix=xyz\ncable 1 2 section=c n=3 length=10.5\n"
             "node 3 5 -9 0\n", head);
    m = read_text(ctx, text, 0);
    CHECK(!m && strstr(ctn_ctx_message(ctx), "t.cable:8: duplicate node id 3"));
    ctn_ctx_destroy(&ctx);
}

/* Errors: the line of the use; unknown directives first; units once. */
static void errors(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    struct { const char *text, *want; } cases[] = {
        { "section c material=steel A=1\nmaterial s E=1\n", "t.cable:1: " },                 /* never defined */
        { "node 1 0 0 0 fix=xyz\nelement 1 1 2 section=c\nsection c material=s A=1\nmaterial s E=1\n",
          "t.cable:2: undefined node 2" },
        { "section c material=s A=1\nmaterial s E=1\nmateral t E=2\n", "t.cable:3: unknown directive 'materal'" },
        { "units N mm\nmaterial s E=200GPa\nunits kN m\n", "t.cable:3: units: given twice, differently (first on line 1" },
        { "lineload wind qx=1\nmaterial s E=1\n", "t.cable:1: " },
        { "hload q=1 elements=roof\ngroup rof 1\n", "t.cable:2: group 'rof': undefined element 1" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        ctn_model *m = read_text(ctx, cases[i].text, 0);
        CHECK_MSG(!m && strstr(ctn_ctx_message(ctx), cases[i].want), "case %zu: %s", i, ctn_ctx_message(ctx));
        ctn_model_destroy(&m);
    }
    ctn_ctx_destroy(&ctx);
}

/* Groups numbered by their first mention; a set above the nodes it holds. */
static void groups_and_sets(void)
{
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    const char *text = "set mid nodes box=4,-1,-1,6,1,1\ngroup a 2\nmaterial s E=2e8\nsection c material=s A=1e-4\n"
                       "node 1 0 0 0 fix=xyz\nnode 2 5 0 0\nnode 3 10 0 0 fix=xyz\nelement 1 1 2 section=c group=b\n"
                       "element 2 2 3 section=c\nload set=mid fy=-1\n";
    ctn_model *m = read_text(ctx, text, 1);
    if (m) {
        CHECK(m->groups.n == 2 && !strcmp(m->groups.v[0].name, "a") && !strcmp(m->groups.v[1].name, "b"));
        CHECK(m->elements.v[1].group == 0 && m->elements.v[0].group == 1);
        CHECK(m->sets.n == 1 && m->sets.v[0].count == 1);
        CHECK(m->ploads.n == 1 && m->ploads.v[0].node == 1 && m->ploads.v[0].F[1] == -1);
        ctn_model_destroy(&m);
    }
    ctn_ctx_destroy(&ctx);
}

/* An included file's definitions below their use. */
static void included(void)
{
    const char *dir = "/tmp/catena_any_order";
    char path[256], cmd[300];
    snprintf(cmd, sizeof cmd, "mkdir -p %s", dir);
    CHECK(system(cmd) == 0);
    snprintf(path, sizeof path, "%s/defs.cable", dir);
    FILE *f = fopen(path, "w");
    fputs("section c material=s A=1e-4\nmaterial s E=2e8\n", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/top.cable", dir);
    f = fopen(path, "w");
    fputs("node 1 0 0 0 fix=xyz\nnode 2 5 0 0\nnode 3 10 0 0 fix=xyz\nelement 1 1 2 section=c l0=4.9\n"
          "element 2 2 3 section=c l0=4.9\nload 2 0 -1 0\ninclude defs.cable\n", f);
    fclose(f);
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    CHECK_MSG(ctn_read_file(ctx, path, &m, NULL) == CTN_OK, "%s", ctn_ctx_message(ctx));
    CHECK(m && m->elements.n == 2 && m->sections.n == 1);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
}

int main(void)
{
    shuffled_models();
    generated_ids();
    errors();
    groups_and_sets();
    included();
    CHECK_DONE();
}
