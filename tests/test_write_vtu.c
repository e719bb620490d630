/* ctn_write_vtu (io/vtu_file.c): one step as one .vtu file, the bytes of the result set's
 * result.vtu (last step) and result_K.vtu (step K) written by ctn_write_results; a step
 * out of range and an unwritable path are errors that leave nothing behind. */
#include "catena.h"
#include "check.h"
#include "files.h"

#include <stdlib.h>

static const char *MODEL =
    "units kN m\ngravity 0 -1 0\nmaterial steel E=2.0e8\nsection strand material=steel A=3.14e-4 w=0.1\n"
    "node 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\ncable 1 2 section=strand n=20 length=200.3340\n"
    "step self-weight\nstep point-load substeps=4\nload 13 0 -5 0\n";

static int same_file(const char *a, const char *b)
{
    size_t na, nb;
    char *x = read_all_len(a, &na), *y = read_all_len(b, &nb);
    int same = x && y && na == nb && na > 0 && !memcmp(x, y, na);
    free(x);
    free(y);
    return same;
}

int main(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    char dir[] = "/tmp/ctn_vtu_XXXXXX", set[64], path[96], ref[96];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(set, sizeof set, "%s/set", dir);
    CHECK(ctn_ctx_create(&ctx) == CTN_OK);
    CHECK(ctn_read_string(ctx, "steps.cable", MODEL, strlen(MODEL), &m, &opt) == CTN_OK);
    CHECK(ctn_solve(ctx, m, &opt, &s) == CTN_OK);
    CHECK(ctn_solution_step_count(s) == 2);
    CHECK(ctn_write_results(ctx, set, m, s) == CTN_OK);
    for (size_t k = 0; k < 2; k++) {                         /* each step: its result_K.vtu */
        snprintf(path, sizeof path, "%s/step%zu.vtu", dir, k);
        snprintf(ref, sizeof ref, "%s/result_%zu.vtu", set, k + 1);
        CHECK(ctn_write_vtu(ctx, path, m, s, k) == CTN_OK);
        CHECK_MSG(same_file(path, ref), "%s differs from %s", path, ref);
        remove(path);
    }
    snprintf(path, sizeof path, "%s/last.vtu", dir);          /* the last step: result.vtu */
    snprintf(ref, sizeof ref, "%s/result.vtu", set);
    CHECK(ctn_write_vtu(ctx, path, m, s, 1) == CTN_OK);
    CHECK(same_file(path, ref));
    remove(path);
    CHECK(ctn_write_vtu(ctx, path, m, s, 2) == CTN_ERR_INVALID);   /* out of range */
    CHECK(strstr(ctn_ctx_message(ctx), "out of range") != NULL);
    snprintf(path, sizeof path, "%s/none/x.vtu", dir);             /* no such directory */
    CHECK(ctn_write_vtu(ctx, path, m, s, 0) == CTN_ERR_IO);
    CHECK(ctn_write_vtu(ctx, NULL, m, s, 0) == CTN_ERR_INVALID);
    CHECK(count_entries(dir) == 1);                                /* only the set: no temporaries */
    remove_dir(set);
    rmdir(dir);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
