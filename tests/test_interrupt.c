/* Interruption through the context's callback (ctn_ctx_set_interrupt), at every safe
 * point in turn:
 *   - a solve asked to stop at its k-th poll returns CTN_ERR_INTERRUPTED ("interrupted")
 *     for every k up to the polls of a whole solve, and leaks nothing (ASan);
 *   - the same context, the callback cleared, solves as if never interrupted;
 *   - a result set interrupted at its k-th poll while being written leaves the older set
 *     byte for byte and no temporary, for every k; a set written whole otherwise;
 *   - a model file read interrupted at its first poll gives no model. */
#include "check.h"
#include "files.h"

#include <catena.h>

#include <stdlib.h>

typedef struct countdown {
    long polls, stop_at;   /* stop at poll stop_at (1-based), 0: never */
} countdown;

static int poll_countdown(void *data)
{
    countdown *c = data;
    return ++c->polls == c->stop_at;
}

/* A 2000-element cable from straight: several Newton iterations, a result set of about
 * 0.5 MB (several write buffers). */
static const char *model_text =
    "units kN m\n"
    "material steel E=2.0e8\n"
    "section strand material=steel A=3.14e-4 w=0.1\n"
    "gravity 0 -1 0\n"
    "node 1 0 0 0 fix=xyz\n"
    "node 2 200 0 0 fix=xyz\n"
    "cable 1 2 section=strand n=2000 length=201.3545\n";

static char *file_in(const char *dir, const char *name)
{
    static char p[4][256];
    static int k;
    k = (k + 1) % 4;
    snprintf(p[k], sizeof p[k], "%s/%s", dir, name);
    return p[k];
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL, *m2 = NULL;
    ctn_solution *s = NULL, *s2 = NULL;
    ctn_solve_options opt;
    countdown cd = { 0, 0 };
    ctn_ctx_create(&ctx);
    int rc = ctn_read_string(ctx, "chain.cable", model_text, strlen(model_text), &m, &opt);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (rc) return 1;

    /* A whole solve: how many polls it makes. */
    ctn_ctx_set_interrupt(ctx, poll_countdown, &cd);
    rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    long polls = cd.polls;
    CHECK_MSG(polls >= 3, "%ld polls in a solve", polls);
    ctn_solve_summary ref;
    ctn_solution_summary(s, &ref);

    for (long k = 1; k <= polls; k++) {
        cd = (countdown){ 0, k };
        rc = ctn_solve(ctx, m, &opt, &s2);
        CHECK_MSG(rc == CTN_ERR_INTERRUPTED && s2 == NULL, "stop at poll %ld: rc %d", k, rc);
        CHECK(!strcmp(ctn_ctx_message(ctx), "interrupted"));
        ctn_solution_destroy(&s2);
    }
    ctn_ctx_set_interrupt(ctx, NULL, NULL);
    rc = ctn_solve(ctx, m, &opt, &s2);
    CHECK(rc == CTN_OK);
    if (!rc) {
        ctn_solve_summary sum;
        ctn_solution_summary(s2, &sum);
        CHECK(sum.iterations == ref.iterations && sum.residual == ref.residual);
    }

    /* Result sets: the older set (of a half load) stays whole at every interruption. */
    char base[64];
    snprintf(base, sizeof base, "/tmp/catena-interrupt.XXXXXX");
    CHECK(mkdtemp(base) != NULL);
    const char *names[] = { "result.json", "nodes.csv", "elements.csv", "result.vtu" };
    char *old[4];
    size_t oldn[4];
    CHECK(ctn_write_results(ctx, base, m, s2) == CTN_OK);
    for (int i = 0; i < 4; i++) old[i] = read_all_len(file_in(base, names[i]), &oldn[i]);
    const char *heavier = "units kN m\nmaterial steel E=2.0e8\nsection strand material=steel A=3.14e-4 w=0.2\n"
                          "gravity 0 -1 0\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n"
                          "cable 1 2 section=strand n=2000 length=201.3545\n";
    ctn_solution *s3 = NULL;
    rc = ctn_read_string(ctx, "heavier.cable", heavier, strlen(heavier), &m2, &opt);
    if (!rc) rc = ctn_solve(ctx, m2, &opt, &s3);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    cd = (countdown){ 0, 0 };
    ctn_ctx_set_interrupt(ctx, poll_countdown, &cd);
    char probe[96];
    snprintf(probe, sizeof probe, "%s/probe", base);
    CHECK(ctn_write_results(ctx, probe, m2, s3) == CTN_OK);
    long wpolls = cd.polls;
    CHECK_MSG(wpolls >= 8, "%ld polls in writing a set", wpolls);
    remove_dir(probe);
    rmdir(probe);
    for (long k = 1; k <= wpolls; k++) {
        cd = (countdown){ 0, k };
        rc = ctn_write_results(ctx, base, m2, s3);
        CHECK_MSG(rc == CTN_ERR_INTERRUPTED, "stop at write poll %ld: rc %d", k, rc);
        int same = 1;
        for (int i = 0; i < 4; i++) {
            size_t n;
            char *now = read_all_len(file_in(base, names[i]), &n);
            same = same && now && old[i] && n == oldn[i] && !memcmp(now, old[i], n);
            free(now);
        }
        CHECK_MSG(same, "write poll %ld: the older set changed", k);
        CHECK_MSG(count_entries(base) == 4, "write poll %ld: %d entries", k, count_entries(base));
    }
    ctn_ctx_set_interrupt(ctx, NULL, NULL);
    CHECK(ctn_write_results(ctx, base, m2, s3) == CTN_OK);
    size_t n;
    char *now = read_all_len(file_in(base, "result.json"), &n);
    CHECK(now && (n != oldn[0] || memcmp(now, old[0], n)));          /* the new set */
    free(now);
    for (int i = 0; i < 4; i++) free(old[i]);
    remove_dir(base);
    rmdir(base);

    /* Reading a model file: stopped at its first poll. */
    char path[64];
    snprintf(path, sizeof path, "/tmp/catena-interrupt-model.XXXXXX");
    int fd = mkstemp(path);
    CHECK(fd >= 0 && write(fd, model_text, strlen(model_text)) == (ssize_t)strlen(model_text));
    close(fd);
    ctn_model *m3 = NULL;
    cd = (countdown){ 0, 1 };
    ctn_ctx_set_interrupt(ctx, poll_countdown, &cd);
    rc = ctn_model_read_file(ctx, path, &m3);
    CHECK_MSG(rc == CTN_ERR_INTERRUPTED && !m3, "read: rc %d", rc);
    unlink(path);

    ctn_solution_destroy(&s);
    ctn_solution_destroy(&s2);
    ctn_solution_destroy(&s3);
    ctn_model_destroy(&m);
    ctn_model_destroy(&m2);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
