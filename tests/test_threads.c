/* The library's threads and the process's state (core/threads.h):
 *   - a context left at its default (1), or a solve with threads=1, starts no thread at
 *     all, OpenMP's included: the process's thread count (/proc/self/status) never
 *     rises, before, during (sampled at every iteration) and after a solve, its modal
 *     analysis and its result files, with every site's size threshold taken as met;
 *   - a context that allows two threads starts at most CTN_THR_HELPERS threads of its
 *     own over any number of solves (the policy's count and the process's), and joins
 *     them at ctn_ctx_destroy; a chain's results are those of one thread;
 *   - nothing process-wide changes: OpenMP's settings (max-active-levels, threads,
 *     thread limit, dynamic), SuiteSparse_config's allocator, glibc's mmap threshold;
 *   - a helper that cannot be made (its allocation fails) means serial, not an error. */
#define _GNU_SOURCE                      /* RTLD_DEFAULT, mallinfo2 */
#include "check.h"
#include "files.h"
#include "taut_chain.h"

#include <catena.h>

#include "core/ctx.h"
#include "core/threads.h"

#include <SuiteSparse_config.h>
#include <dlfcn.h>
#include <malloc.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

/* The process's threads now. */
static int os_threads(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    int n = -1;
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "Threads: %d", &n) == 1) break;
    if (f) fclose(f);
    return n;
}

static void sample(void *data, const ctn_iterate *it)
{
    int *most = data, n = os_threads();
    (void)it;
    if (n > *most) *most = n;
}

/* A K x K hypar net (bench/hypar_net.py's, two-way strands, with mass and 4 modes by the
 * block solver) or a chain solved by pure Newton (its factorization beside its
 * assembly), as model text. */
static char *net_text(int k, const char *solve)
{
    size_t cap = (size_t)k * k * 200 + 1000, n = 0;
    char *t = malloc(cap);
    if (!t) return NULL;
    n += (size_t)snprintf(t + n, cap - n, "units kN m\nmaterial strand E=1.6e8\nsection s material=strand A=1.5e-4 "
                          "mass=0.0012\nmodes count=4 solver=block\n%s\n", solve);
    double h = 100.0 / k;
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++) {
            double x = -50 + i * h, y = -50 + j * h;
            int edge = i == 0 || j == 0 || i == k || j == k;
            n += (size_t)snprintf(t + n, cap - n, "node %d %.17g %.17g %.17g%s\n", i * (k + 1) + j + 1, x, y,
                                  10 * (x * x - y * y) / 2500, edge ? " fix=xyz" : "");
        }
    int e = 1;
    for (int i = 0; i <= k; i++)
        for (int j = 0; j <= k; j++)
            for (int d = 0; d < 2; d++) {
                int i2 = i + (d == 0), j2 = j + (d == 1);
                if (i2 > k || j2 > k || ((i == 0 || i == k) && d == 1) || ((j == 0 || j == k) && d == 0)) continue;
                n += (size_t)snprintf(t + n, cap - n, "element %d %d %d section=s eps0=2e-3\n", e++,
                                      i * (k + 1) + j + 1, i2 * (k + 1) + j2 + 1);
            }
    for (int i = 1; i < k; i++)
        for (int j = 1; j < k; j++)
            n += (size_t)snprintf(t + n, cap - n, "load %d 0 0 %.17g\n", i * (k + 1) + j + 1, -0.2 * h * h);
    return t;
}

static const char *chain_text = TAUT_CHAIN(3000) "solve method=newton\n";

/* Solve a model text, write its results into dir: the status; the most threads seen
 * at an iteration into *most. */
static int run(ctn_ctx *ctx, const char *text, const char *dir, int *most, ctn_solution **out, ctn_model **mout)
{
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    int rc = ctn_read_string(ctx, "t.cable", text, strlen(text), &m, &opt);
    opt.monitor = sample;
    opt.monitor_data = most;
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    ctn_solve_summary sum;
    if (!rc) ctn_solution_summary(s, &sum);
    if (!rc && sum.reason != CTN_CONVERGED) rc = -1;
    if (!rc && dir) rc = ctn_write_results(ctx, dir, m, s);
    if (out && !rc) *out = s;
    else ctn_solution_destroy(&s);
    if (mout && !rc) *mout = m;
    else ctn_model_destroy(&m);
    return rc;
}

typedef struct omp_state {
    int levels, threads, limit, dynamic;
    void *(*mf)(size_t), *(*cf)(size_t, size_t), *(*rf)(void *, size_t);
    void (*ff)(void *);
} omp_state;

static int omp_get(const char *name)
{
    typedef int (*get_fn)(void);
    get_fn f = (get_fn)(uintptr_t)dlsym(RTLD_DEFAULT, name);
    return f ? f() : -7;
}

static omp_state state_now(void)
{
    omp_state s = { omp_get("omp_get_max_active_levels"), omp_get("omp_get_max_threads"),
                    omp_get("omp_get_thread_limit"), omp_get("omp_get_dynamic"), SuiteSparse_config.malloc_func,
                    SuiteSparse_config.calloc_func, SuiteSparse_config.realloc_func, SuiteSparse_config.free_func };
    return s;
}

static int same_state(const omp_state *a, const omp_state *b)
{
    return a->levels == b->levels && a->threads == b->threads && a->limit == b->limit &&
           a->dynamic == b->dynamic && a->mf == b->mf && a->cf == b->cf && a->rf == b->rf && a->ff == b->ff;
}

/* glibc still maps a large block of its own (nobody set M_MMAP_MAX to 0): 1, or 0 (also
 * under an allocator of a sanitizer's or valgrind's, which mallinfo2 does not see). */
static int mmap_still_used(void)
{
    struct mallinfo2 before = mallinfo2();
    void *p = malloc((size_t)64 << 20);
    struct mallinfo2 during = mallinfo2();
    free(p);
    return p && during.hblks == before.hblks + 1;
}

static int same_files(const char *d1, const char *d2)
{
    const char *names[] = { "result.json", "nodes.csv", "elements.csv" };
    int same = 1;
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        char p1[256], p2[256];
        size_t n1 = 0, n2 = 0;
        snprintf(p1, sizeof p1, "%s/%s", d1, names[i]);
        snprintf(p2, sizeof p2, "%s/%s", d2, names[i]);
        char *a = read_all_len(p1, &n1), *b = read_all_len(p2, &n2);
        same = same && a && b && n1 == n2 && !memcmp(a, b, n1);
        free(a);
        free(b);
    }
    return same;
}

/* Every site in reach (thresholds met), with a context that allows `limit` threads
 * and solve lines `solve`: the threads the library started. */
static long solve_all(int limit, const char *solve, const char *dir, int *before, int *most, int *after)
{
    ctn_ctx *ctx = NULL;
    CHECK(ctn_ctx_create(&ctx) == CTN_OK);
    CHECK(ctn_ctx_threads(ctx) == 1);                     /* the library's default */
    CHECK(ctn_ctx_set_threads(ctx, limit) == CTN_OK && ctn_ctx_threads(ctx) == limit);
    ctx->thr_any_size = 1;
    char *net = net_text(12, solve), d1[200], d2[200];
    snprintf(d1, sizeof d1, "%s/net", dir);
    snprintf(d2, sizeof d2, "%s/chain", dir);
    char *chain = malloc(strlen(chain_text) + strlen(solve) + 2);
    if (chain) snprintf(chain, strlen(chain_text) + strlen(solve) + 2, "%s%s\n", chain_text, solve);
    *before = *most = os_threads();
    for (int r = 0; r < 2; r++) {                         /* the helpers are kept between solves */
        int rc = net ? run(ctx, net, d1, most, NULL, NULL) : -2;
        CHECK_MSG(rc == CTN_OK, "net: %d %s", rc, ctn_ctx_message(ctx));
        rc = chain ? run(ctx, chain, d2, most, NULL, NULL) : -2;
        CHECK_MSG(rc == CTN_OK, "chain: %d %s", rc, ctn_ctx_message(ctx));
    }
    int now = os_threads();
    if (now > *most) *most = now;
    long started = ctn_thr_started(ctx);
    ctn_ctx_destroy(&ctx);
    *after = os_threads();
    free(net);
    free(chain);
    return started;
}

/* One solve of text in a context that allows two threads, the n-th allocation made to
 * fail (0: none): its status; *count: the allocations it made. */
static int solve_failing(const char *text, long n, long *count)
{
    ctn_ctx *ctx = NULL;
    if (ctn_ctx_create(&ctx)) return CTN_ERR_NOMEM;
    ctn_ctx_set_threads(ctx, 2);
    ctx->thr_any_size = 1;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    int rc = ctn_read_string(ctx, "t.cable", text, strlen(text), &m, &opt);
    long start = ctn_ctx_alloc_count(ctx);
    ctn_ctx_fail_alloc_at(ctx, n);
    if (!rc) rc = ctn_solve(ctx, m, &opt, &s);
    if (!rc && ctn_ctx_code(ctx) != CTN_OK) rc = -1;     /* an error left behind */
    *count = ctn_ctx_alloc_count(ctx) - start;
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return rc;
}

/* Every allocation of a solve made to fail in turn: a clean CTN_ERR_NOMEM, or, for the
 * helpers' pool (and the modes' second scratch), a solve that goes on serially with no
 * error left in the context. */
static void test_pool_fails(void)
{
    char *net = net_text(6, "solve");
    long total = 0, count = 0;
    CHECK(net && solve_failing(net, 0, &total) == CTN_OK && total > 10);
    int serial = 0, bad = 0;
    for (long n = 1; net && n <= total; n++) {
        int rc = solve_failing(net, n, &count);
        serial += rc == CTN_OK;
        bad += rc != CTN_OK && rc != CTN_ERR_NOMEM;
    }
    CHECK_MSG(bad == 0, "%d of %ld failures not out of memory", bad, total);
    CHECK_MSG(serial >= 1 || sysconf(_SC_NPROCESSORS_ONLN) < 2, "%d solves went on", serial);
    free(net);
}

int main(void)
{
    char base[64], one[96], two[96], cli1[96];
    snprintf(base, sizeof base, "/tmp/catena-threads.XXXXXX");
    CHECK(mkdtemp(base) != NULL);
    snprintf(one, sizeof one, "%s/one", base);
    snprintf(two, sizeof two, "%s/two", base);
    snprintf(cli1, sizeof cli1, "%s/cli1", base);
    for (size_t i = 0; i < 3; i++) {
        char d[128];
        snprintf(d, sizeof d, "%s/%s", base, i == 0 ? "one" : i == 1 ? "two" : "cli1");
        CHECK(mkdir(d, 0755) == 0);
    }
    omp_state s0 = state_now();
    int mmap0 = mmap_still_used();

    int before, most, after;
    long started = solve_all(1, "solve", one, &before, &most, &after);   /* the default */
    CHECK_MSG(started == 0, "%ld threads started", started);
    CHECK_MSG(most == before && after == before, "threads: %d before, %d at most, %d after", before, most, after);

    started = solve_all(0, "solve threads=1", cli1, &before, &most, &after);   /* the CLI's, threads=1 */
    CHECK_MSG(started == 0, "%ld threads started", started);
    CHECK_MSG(most == before && after == before, "threads: %d before, %d at most, %d after", before, most, after);

    started = solve_all(2, "solve", two, &before, &most, &after);            /* two allowed */
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    CHECK_MSG(cpus < 2 ? started == 0 : started >= 1 && started <= CTN_THR_HELPERS, "%ld threads started", started);
    CHECK_MSG(most <= before + CTN_THR_HELPERS && after == before, "threads: %d before, %d at most, %d after", before,
              most, after);
    char a[160], b[160];                  /* the chain's (the net's solves are CHOLMOD's on */
    snprintf(a, sizeof a, "%s/chain", one);   /* one thread, catena's own schedule on two) */
    snprintf(b, sizeof b, "%s/chain", two);
    CHECK_MSG(same_files(a, b), "%s and %s differ", a, b);

    omp_state s1 = state_now();
    CHECK_MSG(same_state(&s0, &s1), "OpenMP levels %d -> %d, threads %d -> %d, limit %d -> %d, dynamic %d -> %d",
              s0.levels, s1.levels, s0.threads, s1.threads, s0.limit, s1.limit, s0.dynamic, s1.dynamic);
    CHECK(mmap_still_used() == mmap0);
    test_pool_fails();

    ctn_ctx *ctx = NULL;
    CHECK(ctn_ctx_create(&ctx) == CTN_OK);
    CHECK(ctn_ctx_set_threads(ctx, -1) == CTN_ERR_INVALID && ctn_ctx_threads(ctx) == 1);
    CHECK(ctn_ctx_set_threads(NULL, 2) == CTN_ERR_INVALID);
    ctn_ctx_destroy(&ctx);
    const char *tops[] = { one, two, cli1 };
    for (size_t i = 0; i < 3; i++) {
        char d[200];
        for (int k = 0; k < 2; k++) {
            snprintf(d, sizeof d, "%s/%s", tops[i], k ? "chain" : "net");
            remove_dir(d);
        }
        remove_dir(tops[i]);
    }
    remove_dir(base);
    CHECK_DONE();
}
