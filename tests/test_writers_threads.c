/* The result set of a large model, staged by two threads (src/io/results.c):
 *   - byte for byte the files the one-thread path writes (a context set to fail an
 *     allocation far away keeps ctn_write_results on one thread);
 *   - under a file size limit that every file but the smallest exceeds, whichever
 *     thread fails: CTN_ERR_IO with the write error, nothing committed, no temporary. */
/* ctest-cost: 20 (about the seconds it takes under ASan: ctest -j starts it early) */
#include "check.h"
#include "files.h"
#include "taut_chain.h"

#include <catena.h>

#include <dirent.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

/* A taut cable of 100 000 elements: 200 001 nodes and elements, above the threshold. */
static const char *model_text = TAUT_CHAIN(100000);

int main(void)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    char base[64], one[96], two[96], lim_dir[96];
    ctn_ctx_create(&ctx);
    ctn_ctx_set_threads(ctx, 2);                         /* the second thread allowed */
    snprintf(base, sizeof base, "/tmp/catena-wthreads.XXXXXX");
    CHECK(mkdtemp(base) != NULL);
    snprintf(one, sizeof one, "%s/one", base);
    snprintf(two, sizeof two, "%s/two", base);
    snprintf(lim_dir, sizeof lim_dir, "%s/limit", base);
    int rc = ctn_read_string(ctx, "chain.cable", model_text, strlen(model_text), &m, &opt);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    CHECK_MSG(rc == CTN_OK, "%s", ctn_ctx_message(ctx));
    if (!rc) {
        CHECK(ctn_model_node_count(m) + ctn_model_element_count(m) >= 200000);
        CHECK(ctn_write_results(ctx, two, m, s) == CTN_OK);              /* two threads */
        ctn_ctx_fail_alloc_at(ctx, 1L << 40);                            /* one thread */
        CHECK(ctn_write_results(ctx, one, m, s) == CTN_OK);
        ctn_ctx_fail_alloc_at(ctx, 0);
        const char *names[] = { "result.json", "nodes.csv", "elements.csv", "result.vtu" };
        for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
            char p1[160], p2[160];
            size_t n1, n2;
            snprintf(p1, sizeof p1, "%s/%s", one, names[i]);
            snprintf(p2, sizeof p2, "%s/%s", two, names[i]);
            char *a = read_all_len(p1, &n1), *b = read_all_len(p2, &n2);
            CHECK_MSG(a && b && n1 == n2 && n1 > 1000 && !memcmp(a, b, n1), "%s: %zu and %zu bytes", names[i], n1, n2);
            free(a);
            free(b);
        }
        CHECK(count_entries(two) == count_entries(one));

        struct rlimit old, lim;
        if (!getrlimit(RLIMIT_FSIZE, &old)) {
            void (*handler)(int) = signal(SIGXFSZ, SIG_IGN);
            lim = old;
            lim.rlim_cur = 1000000;                 /* 1 MB: result.json and the others fail */
            CHECK(setrlimit(RLIMIT_FSIZE, &lim) == 0);
            rc = ctn_write_results(ctx, lim_dir, m, s);
            setrlimit(RLIMIT_FSIZE, &old);
            signal(SIGXFSZ, handler);
            CHECK_MSG(rc == CTN_ERR_IO && strstr(ctn_ctx_message(ctx), "write failed"), "rc %d: %s", rc,
                      ctn_ctx_message(ctx));
            CHECK_MSG(count_entries(lim_dir) == 0, "%d entries left", count_entries(lim_dir));
        }
    }
    remove_dir(one);
    remove_dir(two);
    remove_dir(lim_dir);
    rmdir(base);
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    CHECK_DONE();
}
