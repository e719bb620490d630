/* Reader (io layer): line ends and integers.
 * - line ends: LF, CRLF and a lone CR each end a line, mixed too; an error on line 5 of
 *   a CR-only text says line 5; a CR-only copy of the paper's model reads to the same
 *   model and solves to the same displacements, bit for bit;
 * - integers: every id and integer-valued key (node, element, cable, load, displace
 *   ids, the hload range, n=, substeps=, maxit=, steps=, cutbacks=, arcsteps=) takes an
 *   exactly integral decimal ("7.0", "7e0", "70e-1", "0.7e1") as that integer, the same
 *   model as "7"; "7.5", "7.000000000000001", "0x7" are refused with a message naming
 *   the line and saying integer;
 * - the file reader (a chunk at a time): a 1.2 MB model with CRLF, lone-CR and LF line
 *   ends, a comment longer than the chunk, gives the model ctn_read_string gives from
 *   the same bytes, node for node and element for element, and an error on its last
 *   line names that line; the progress callback sees "reading" rise to the file's size;
 * - ids far apart (1, 2, 3000, 2e9, ...) and dense ones map to their nodes. */
#include "catena.h"
#include "check.h"

#include <stdlib.h>

static const char paper[] =
    "units kN m\n"
    "material steel E=2.0e8\n"
    "section strand material=steel A=3.14e-4 w=0.1\n"
    "gravity 0 -1 0\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 200 0 0 fix=xyz\n"
    "cable 1 2 section=strand n=20 length=200.3340\n";

/* text with every "\n" replaced by `eol` (malloc'ed). */
static char *with_eol(const char *text, const char *eol)
{
    size_t n = 0, k = strlen(eol);
    for (const char *p = text; *p; p++) n += *p == '\n' ? k : 1;
    char *out = malloc(n + 1), *q = out;
    for (const char *p = text; *p; p++) {
        if (*p == '\n') memcpy(q, eol, k), q += k;
        else *q++ = *p;
    }
    *q = '\0';
    return out;
}

/* Read and solve; displacements into d (3 nn, at most cap). 0 on failure. */
static size_t solve_text(ctn_ctx *ctx, const char *text, double *d, size_t cap)
{
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    size_t n = 0;
    ctn_solve_options opt;
    if (!ctn_read_string(ctx, "paper.cable", text, strlen(text), &m, &opt) && !ctn_solve(ctx, m, &opt, &s)) {
        n = 3 * ctn_model_node_count(m);
        if (n <= cap) memcpy(d, ctn_solution_displacements(s), n * sizeof *d);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    return n;
}

static void test_line_ends(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    static const char *const eols[] = { "\n", "\r\n", "\r" };
    double ref[63], d[63];
    CHECK(solve_text(ctx, paper, ref, 63) == 63);
    for (int k = 1; k < 3; k++) {
        char *t = with_eol(paper, eols[k]);
        CHECK_MSG(solve_text(ctx, t, d, 63) == 63, "eol %d: %s", k, ctn_ctx_message(ctx));
        CHECK_MSG(!memcmp(d, ref, sizeof d), "eol %d: another answer", k);
        free(t);
    }
    /* an error on line 5 of a CR-only text, after a blank line and a comment */
    static const char bad[] = "units kN m\r\r# comment\rmaterial steel E=2.0e8\rbogus 5\r";
    CHECK(ctn_model_read_string(ctx, "cr.cable", bad, sizeof bad - 1, &m) == CTN_ERR_MODEL);
    CHECK_MSG(!strncmp(ctn_ctx_message(ctx), "cr.cable:5: unknown directive 'bogus'", 37), "%s", ctn_ctx_message(ctx));
    /* mixed: CR, CRLF, LF, CR CR -> the error is on line 6; CR CR LF is two line ends */
    static const char mixed[] = "units kN m\rmaterial steel E=2.0e8\r\nsection s material=steel A=1\n\r\rbogus 6\n";
    CHECK(ctn_model_read_string(ctx, "mixed.cable", mixed, sizeof mixed - 1, &m) == CTN_ERR_MODEL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "mixed.cable:6:") != NULL, "%s", ctn_ctx_message(ctx));
    static const char crcrlf[] = "units kN m\r\r\nbogus 3\r\n";
    CHECK(ctn_model_read_string(ctx, "x.cable", crcrlf, sizeof crcrlf - 1, &m) == CTN_ERR_MODEL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "x.cable:3:") != NULL, "%s", ctn_ctx_message(ctx));
    /* a comment ends at a lone CR */
    static const char comment[] = "units kN m # comment\rbogus 2";
    CHECK(ctn_model_read_string(ctx, "c.cable", comment, sizeof comment - 1, &m) == CTN_ERR_MODEL);
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "c.cable:2: unknown directive") != NULL, "%s", ctn_ctx_message(ctx));
    ctn_ctx_destroy(&ctx);
}

/* A model with every integer slot; "@" is replaced by the spelling of 7 under test.
 * Each slot is one line of `slots`: the model with that line's "@" substituted and the
 * others written as "7". */
static const char *const slots[] = {
    "node @ 0 0 0 fix=xyz\n",
    "element @ 7 8 section=s\n",
    "element 1 @ 8 section=s\n",
    "cable 8 @ section=s n=4 length=60\n",
    "cable 8 9 section=s n=@ length=60\n",
    "load @ 0 -1 0\n",
    "hload q=0.1 elements=@-8\n",
    "hload q=0.1 elements=1-@\n",
    "solve maxit=@\n",
    "solve steps=@\n",
    "solve cutbacks=@\n",
    "solve arcsteps=@\n",
    "step one substeps=@\n",
    "displace @ y=0.1\n",
};
enum { NSLOTS = sizeof slots / sizeof *slots };

/* The model text with slot `which` spelled `spell` (others "7"). */
static void model_text(int which, const char *spell, char *buf, size_t size)
{
    static const char *const head[] = {
        "units kN m\nmaterial m E=2e8\nsection s material=m A=1e-4 w=0.1\ngravity 0 -1 0\n",
        "node 8 50 0 0 fix=xyz\nnode 9 100 0 0 fix=xyz\n",
    };
    size_t k = (size_t)snprintf(buf, size, "%s%s", head[0], head[1]);
    for (int i = 0; i < NSLOTS && k < size; i++) {
        if (i == 12) k += (size_t)snprintf(buf + k, size - k, "step zero\n");   /* before "step one" */
        const char *p = slots[i];
        for (; *p && k + 32 < size; p++) {
            if (*p == '@') k += (size_t)snprintf(buf + k, size - k, "%s", i == which ? spell : "7");
            else buf[k++] = *p;
        }
        buf[k] = '\0';
    }
}

/* A summary of what the integers set: counts, ids, options, substeps. */
static void fingerprint(const ctn_model *m, const ctn_solve_options *o, long *out)
{
    ctn_solve_options opt = *o;
    ctn_element_info e;
    ctn_node_info n;
    out[0] = (long)ctn_model_node_count(m);
    out[1] = (long)ctn_model_element_count(m);
    out[2] = opt.maxit + 1000L * opt.steps + 1000000L * opt.maxcuts;
    out[3] = opt.arcsteps;
    out[4] = ctn_model_step_substeps(m, 1);
    out[5] = ctn_model_node(m, 0, &n) ? -1 : n.id;
    out[6] = ctn_model_element(m, 0, &e) ? -1 : e.id;
}

static void test_integers(void)
{
    static const char *const good[] = { "7", "+7", "7.0", "7.", "7e0", "70e-1", "0.7e1", "700E-2", "07.000" };
    static const char *const bad[] = { "7.5", "7.000000000000001", "0x7", "7e-1", "inf", "7,0", "7e", "." };
    ctn_ctx *ctx = NULL;
    ctn_ctx_create(&ctx);
    char text[2048];
    long ref[7], got[7];
    ctn_model *m = NULL;
    ctn_solve_options opt;
    model_text(-1, "7", text, sizeof text);
    CHECK_MSG(ctn_read_string(ctx, "ints.cable", text, strlen(text), &m, &opt) == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (m) fingerprint(m, &opt, ref);
    ctn_model_destroy(&m);
    for (int i = 0; i < NSLOTS; i++) {
        for (size_t g = 0; g < sizeof good / sizeof *good; g++) {
            model_text(i, good[g], text, sizeof text);
            int rc = ctn_read_string(ctx, "ints.cable", text, strlen(text), &m, &opt);
            CHECK_MSG(rc == CTN_OK, "slot '%.20s' as '%s': %s", slots[i], good[g], ctn_ctx_message(ctx));
            if (!rc) {
                fingerprint(m, &opt, got);
                CHECK_MSG(!memcmp(got, ref, sizeof got), "slot '%.20s' as '%s': another model", slots[i], good[g]);
            }
            ctn_model_destroy(&m);
        }
        for (size_t b = 0; b < sizeof bad / sizeof *bad; b++) {
            model_text(i, bad[b], text, sizeof text);
            int rc = ctn_read_string(ctx, "ints.cable", text, strlen(text), &m, &opt);
            const char *msg = ctn_ctx_message(ctx);
            CHECK_MSG(rc == CTN_ERR_MODEL, "slot '%.20s' as '%s' accepted", slots[i], bad[b]);
            CHECK_MSG(!strncmp(msg, "ints.cable:", 11) && (strstr(msg, "integer") || strstr(msg, "number")),
                      "slot '%.20s' as '%s': %s", slots[i], bad[b], msg);
            ctn_model_destroy(&m);
        }
    }
    ctn_ctx_destroy(&ctx);
}

typedef struct progress_seen {
    int calls;
    double last, total;
} progress_seen;

static void on_progress(void *data, const char *what, double done, double total)
{
    progress_seen *p = data;
    if (strcmp(what, "reading")) return;
    CHECK(done >= p->last);
    p->calls++;
    p->last = done;
    p->total = total;
}

/* The big text: nodes 1..n on a line, elements between them, line ends cycling through
 * LF, CRLF and CR, a comment of `comment` bytes in the middle; `tail` appended. */
static char *big_model(int n, size_t comment, const char *tail)
{
    static const char *const eol[3] = { "\n", "\r\n", "\r" };
    size_t cap = (size_t)n * 200 + comment + 4096, k = 0;
    char *t = malloc(cap);
    k += (size_t)snprintf(t + k, cap - k, "units kN m\nmaterial steel E=2.0e8\nsection s material=steel A=3.14e-4\n");
    for (int i = 1; i <= n; i++)
        k += (size_t)snprintf(t + k, cap - k, "node %d %.17g 0 0%s%s", i, 0.5 * i, i == 1 || i == n ? " fix=xyz" : "", eol[i % 3]);
    t[k++] = '#';
    for (size_t c = 0; c < comment; c++) t[k++] = 'c';
    t[k++] = '\n';
    for (int i = 1; i < n; i++)
        k += (size_t)snprintf(t + k, cap - k, "element %d %d %d section=s   # e%d%s", i, i, i + 1, i, eol[(i + 1) % 3]);
    snprintf(t + k, cap - k, "%s", tail);
    return t;
}

static void test_file_chunks(void)
{
    const char *path = "test_io_chunks.cable";
    char *text = big_model(6000, 700000, "load 3000 0 -1 0\r");
    FILE *f = fopen(path, "wb");
    CHECK(f && fwrite(text, 1, strlen(text), f) == strlen(text) && !fclose(f));
    ctn_ctx *ctx = NULL;
    ctn_model *a = NULL, *b = NULL;
    progress_seen seen = { 0, 0, 0 };
    ctn_ctx_create(&ctx);
    ctn_ctx_set_progress(ctx, on_progress, &seen);
    CHECK_MSG(ctn_read_file(ctx, path, &a, NULL) == CTN_OK, "%s", ctn_ctx_message(ctx));
    CHECK_MSG(seen.calls > 3 && seen.last == (double)strlen(text) && seen.total == seen.last, "%d calls, %g of %g",
              seen.calls, seen.last, seen.total);
    CHECK(ctn_read_string(ctx, path, text, strlen(text), &b, NULL) == CTN_OK);
    CHECK(a && b && ctn_model_node_count(a) == 6000 && ctn_model_element_count(a) == 5999);
    for (size_t i = 0; a && b && i < ctn_model_node_count(a); i++) {
        ctn_node_info p, q;
        ctn_model_node(a, i, &p);
        ctn_model_node(b, i, &q);
        CHECK(p.id == q.id && p.X[0] == q.X[0] && p.fix == q.fix && p.id == (int)i + 1);
    }
    for (size_t i = 0; a && b && i < ctn_model_element_count(a); i++) {
        ctn_element_info p, q;
        ctn_model_element(a, i, &p);
        ctn_model_element(b, i, &q);
        CHECK(p.id == q.id && p.node[0] == q.node[0] && p.node[1] == q.node[1] && p.l0 == q.l0);
    }
    ctn_model_destroy(&a);
    ctn_model_destroy(&b);
    free(text);
    ctn_ctx_set_progress(ctx, NULL, NULL);
    text = big_model(6000, 700000, "load 3000 0 -1 0\nload 6001 0 0 0\n");
    f = fopen(path, "wb");
    CHECK(f && fwrite(text, 1, strlen(text), f) == strlen(text) && !fclose(f));
    CHECK(ctn_read_file(ctx, path, &a, NULL) == CTN_ERR_MODEL && !a);    /* line 3 + 6000 + 1 + 5999 + 2 */
    CHECK_MSG(strstr(ctn_ctx_message(ctx), "test_io_chunks.cable:12005: undefined node 6001"), "%s",
              ctn_ctx_message(ctx));
    free(text);
    remove(path);
    ctn_ctx_destroy(&ctx);
}

static void test_sparse_ids(void)
{
    static const int ids[] = { 5, 2000000000, 1, 3000, 2, 1025, 2047483647, 4 };
    char text[2048];
    size_t k = (size_t)snprintf(text, sizeof text, "material m E=1\nsection s material=m A=1\n");
    for (int i = 0; i < 8; i++) k += (size_t)snprintf(text + k, sizeof text - k, "node %d %d 0 0 fix=xyz\n", ids[i], i);
    for (int i = 0; i < 7; i++)
        k += (size_t)snprintf(text + k, sizeof text - k, "element %d %d %d section=s\n", ids[7 - i], ids[i], ids[i + 1]);
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_ctx_create(&ctx);
    CHECK_MSG(ctn_read_string(ctx, "ids", text, strlen(text), &m, NULL) == CTN_OK, "%s", ctn_ctx_message(ctx));
    for (int i = 0; m && i < 8; i++) {
        size_t at = 99;
        CHECK(ctn_model_node_index(m, ids[i], &at) == CTN_OK && at == (size_t)i);
    }
    for (int i = 0; m && i < 7; i++) {
        ctn_element_info e;
        CHECK(ctn_model_element(m, (size_t)i, &e) == CTN_OK && e.id == ids[7 - i] && e.node[0] == i && e.node[1] == i + 1);
    }
    size_t at;
    CHECK(m && ctn_model_node_index(m, 3, &at) != CTN_OK && ctn_model_node_index(m, 2000000001, &at) != CTN_OK);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

int main(void)
{
    test_line_ends();
    test_integers();
    test_file_chunks();
    test_sparse_ids();
    CHECK_DONE();
}
