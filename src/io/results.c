/* Result files in a directory: result.json, nodes.csv, elements.csv, result.vtu (the
 * last step), modes.csv when the solution has modes, buckling.csv when it has buckling
 * factors, history.csv when it has a dynamics analysis, and for a run of several steps
 * result_K.vtu for every step and
 * result.pvd listing them; for each load case and combination NAME, cases/NAME/ with its
 * nodes.csv, elements.csv and result.vtu; sag_tension.csv for a model with a
 * sag-tension chart; a dynamics analysis's VTU series (dynamics/frame_K.vtu,
 * dynamics.pvd) when it kept frames. Each is streamed by its writer (io/writer.h) into a staged
 * temporary (io/atomic.h), synced; only when all are staged is any renamed onto its
 * target. In an MPI job of N > 1 ranks (the context's communicator) every rank also
 * writes its VTU piece, result_rR.vtu, and rank 0 result.pvtu (io/vtu.h) beside the set;
 * the ranks agree (a reduction) that all staged before any renames, so a failure on one
 * leaves no file of the set on any; once the set is in place, rank 0 removes the pieces
 * of an earlier run with more ranks (or, in one process, every piece and the .pvtu). */
#include "io/atomic.h"
#include "io/vtu.h"
#include "dist/comm.h"
#include "catena/analysis.h"
#include "catena/io.h"
#include "core/ctx.h"
#include "core/threads.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define NFIXED 4
#define NCASE 3          /* files per case: nodes.csv, elements.csv, result.vtu */
#define CASES_DIR "cases"

/* One file of the set: its writer, the step it writes (one-step writers), its name
 * (relative to the directory) and the solution it writes (NULL: the run's; else a
 * case's). */
typedef struct job {
    const ctn_writer_ops *ops;
    size_t step;
    char name[CTN_VTU_NAME_MAX + 80];
    const ctn_solution *sol;
    int kind;            /* JOB_WRITER (ops), JOB_FRAME (frame `step` of the dynamics'
                            VTU series), JOB_FRAMES_PVD (their collection) */
    const ctn_solution *base;   /* a case's result.vtu: the run's solution, whose step */
    size_t base_step;           /* base_step is the case's installed state; else NULL */
} job;

enum { JOB_WRITER = 0, JOB_FRAME = 1, JOB_FRAMES_PVD = 2 };

/* The set for solution s of n steps: NFIXED files, modes.csv when s has modes,
 * buckling.csv when it has buckling factors, and n + 1
 * more (result_K.vtu, result.pvd) when n > 1. */
static job *plan(ctn_ctx *ctx, const ctn_solution *s, size_t *count)
{
    static const ctn_writer_ops *const fixed[NFIXED] = {
        &ctn_writer_json, &ctn_writer_nodes_csv, &ctn_writer_elements_csv, &ctn_writer_vtu
    };
    size_t n = ctn_solution_step_count(s), nm = ctn_solution_mode_count(s) > 0;
    size_t nb = ctn_solution_buckling_count(s) > 0, nh = ctn_solution_history(s, NULL, NULL) != NULL;
    size_t nf = NFIXED + nm + nb + nh;
    *count = nf + (n > 1 ? n + 1 : 0);
    job *j = ctn_calloc(ctx, *count, sizeof *j);
    if (!j) return NULL;
    for (size_t i = 0; i < *count; i++) {
        const ctn_writer_ops *ops = i < NFIXED ? fixed[i] : i < NFIXED + nm ? &ctn_writer_modes_csv
                                    : i < NFIXED + nm + nb ? &ctn_writer_buckling_csv
                                    : i < nf ? &ctn_writer_history_csv
                                    : i + 1 < *count ? &ctn_writer_vtu : &ctn_writer_pvd;
        j[i].ops = ops;
        j[i].step = i < nf || i + 1 == *count ? n - 1 : i - nf;
        if (i < nf || i + 1 == *count) snprintf(j[i].name, sizeof j[i].name, "%s", ops->name);
        else ctn_vtu_step_name(j[i].name, j[i].step, n);
    }
    return j;
}

/* The set with each case's files after the run's (cases/NAME/...). */
static job *plan_cases(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s, size_t *count)
{
    static const ctn_writer_ops *const per[NCASE] = { &ctn_writer_nodes_csv, &ctn_writer_elements_csv, &ctn_writer_vtu };
    size_t n0 = 0, nc = ctn_solution_case_count(s), chart = ctn_model_chart_count(m) > 0;
    job *j0 = plan(ctx, s, &n0);
    if (!j0 || !nc) {
        *count = n0;
        return j0;
    }
    job *j = ctn_calloc(ctx, n0 + NCASE * nc + chart, sizeof *j);
    if (j) memcpy(j, j0, n0 * sizeof *j);
    ctn_free(j0);
    if (!j) return NULL;
    for (size_t i = 0; i < nc; i++)
        for (size_t f = 0; f < NCASE; f++) {
            job *t = &j[n0 + NCASE * i + f];
            const char *name = "";
            int from = 0;
            ctn_model_case_info(m, i, &name, &from, NULL);
            t->ops = per[f];
            t->step = 0;
            t->sol = ctn_solution_case(s, i);
            t->base = per[f] == &ctn_writer_vtu ? s : NULL;       /* drawn from its installed state */
            t->base_step = (size_t)from;
            snprintf(t->name, sizeof t->name, "%s/%s/%s", CASES_DIR, name, per[f]->name);
        }
    if (chart) {                                    /* sag_tension.csv, last */
        job *t = &j[n0 + NCASE * nc];
        t->ops = &ctn_writer_chart_csv;
        t->step = ctn_solution_step_count(s) - 1;
        snprintf(t->name, sizeof t->name, "%s", t->ops->name);
    }
    *count = n0 + NCASE * nc + chart;
    return j;
}

/* The set with the dynamics analysis's VTU series last (dynamics/frame_K.vtu and
 * dynamics.pvd), when it kept frames. */
static job *plan_frames(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s, size_t *count)
{
    size_t n0 = 0, nf = ctn_solution_frame_count(s);
    job *j0 = plan_cases(ctx, m, s, &n0);
    if (!j0 || !nf) {
        *count = n0;
        return j0;
    }
    job *j = ctn_calloc(ctx, n0 + nf + 1, sizeof *j);
    if (j) memcpy(j, j0, n0 * sizeof *j);
    ctn_free(j0);
    if (!j) return NULL;
    for (size_t k = 0; k <= nf; k++) {
        job *t = &j[n0 + k];
        t->kind = k < nf ? JOB_FRAME : JOB_FRAMES_PVD;
        t->step = k;
        if (k < nf) ctn_frame_name(t->name, k, nf);
        else snprintf(t->name, sizeof t->name, "%s", CTN_FRAMES_PVD);
    }
    *count = n0 + nf + 1;
    return j;
}

/* The files of this rank: rank 0 the set, and in a job of several ranks each rank its
 * VTU piece and rank 0 result.pvtu (both of the last step). */
static job *plan_rank(ctn_ctx *ctx, const ctn_model *m, const ctn_solution *s, int rank, int size, size_t *count)
{
    size_t n0 = 0, extra = rank == 0 ? 2 : 1, last = ctn_solution_step_count(s) - 1;
    job *j0 = rank == 0 ? plan_frames(ctx, m, s, &n0) : NULL;
    *count = n0;
    if (size == 1 || (rank == 0 && !j0)) return j0;
    job *j = ctn_calloc(ctx, n0 + extra, sizeof *j);
    if (j && n0) memcpy(j, j0, n0 * sizeof *j);
    ctn_free(j0);
    if (!j) return NULL;
    j[n0].ops = &ctn_writer_vtu_piece;
    j[n0].step = last;
    ctn_vtu_piece_name(j[n0].name, rank);
    if (rank == 0) {
        j[n0 + 1].ops = &ctn_writer_pvtu;
        j[n0 + 1].step = last;
        snprintf(j[n0 + 1].name, sizeof j[n0 + 1].name, "%s", ctn_writer_pvtu.name);
    }
    *count = n0 + extra;
    return j;
}

/* rc, or an error when another rank of the job failed (every rank calls it: a
 * reduction of the failures). */
static int agree(ctn_ctx *ctx, const char *dir, int rc)
{
    const ctn_comm *c = ctn_ctx_comm(ctx);
    double failed = rc != CTN_OK;
    if (ctn_comm_size(c) == 1) return rc;
    if (c->ops->allreduce(c->impl, &failed, 1, CTN_REDUCE_MAX) && !rc)
        return ctn_error(ctx, CTN_ERR_IO, "%s: the ranks could not agree on the result set", dir);
    if (!rc && failed > 0)
        rc = ctn_error(ctx, CTN_ERR_IO, "%s: another rank could not stage its part of the result set", dir);
    return rc;
}

static int make_dir(ctn_ctx *ctx, const char *path)
{
    if (mkdir(path, 0755) && errno != EEXIST)
        return ctn_error(ctx, CTN_ERR_IO, "%s: cannot create directory: %s", path, strerror(errno));
    return CTN_OK;
}

/* dir/cases and dir/cases/NAME for each case and combination. */
static int make_case_dirs(ctn_ctx *ctx, const char *dir, const ctn_model *m, const ctn_solution *s)
{
    char path[4096];
    size_t nc = ctn_solution_case_count(s);
    if (!nc) return CTN_OK;
    snprintf(path, sizeof path, "%s/%s", dir, CASES_DIR);
    int rc = make_dir(ctx, path);
    for (size_t i = 0; i < nc && !rc; i++) {
        const char *name = "";
        ctn_model_case_info(m, i, &name, NULL, NULL);
        if ((size_t)snprintf(path, sizeof path, "%s/%s/%s", dir, CASES_DIR, name) >= sizeof path)
            return ctn_error(ctx, CTN_ERR_IO, "%s: path too long", dir);
        rc = make_dir(ctx, path);
    }
    return rc;
}

static int target(ctn_ctx *ctx, const char *dir, const char *name, char *path, size_t size)
{
    if ((size_t)snprintf(path, size, "%s/%s", dir, name) < size) return CTN_OK;
    return ctn_error(ctx, CTN_ERR_IO, "%s: path too long", dir);
}

/* Every target may be replaced (ctn_atomic_check), checked before anything is written. */
static int check_targets(ctn_ctx *ctx, const char *dir, const job *jobs, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        char path[4096];
        int rc = target(ctx, dir, jobs[i].name, path, sizeof path);
        if (!rc) rc = ctn_atomic_check(ctx, path);
        if (rc) return rc;
    }
    return CTN_OK;
}

/* Stream one file into its temporary beside dir/name and sync it. On failure the
 * caller aborts f. */
static int stage(ctn_ctx *ctx, const char *dir, const job *j, const ctn_model *m,
                 const ctn_solution *s, ctn_atomic_file *f)
{
    char path[4096];
    int rc = target(ctx, dir, j->name, path, sizeof path);
    if (!rc) rc = ctn_atomic_open(ctx, path, f);
    if (rc) return rc;
    ctn_sink sink = ctn_atomic_sink(f);
    if (j->kind == JOB_FRAME) rc = ctn_write_frame_vtu(ctx, j->step, &sink, m, s);
    else if (j->kind == JOB_FRAMES_PVD) rc = ctn_write_frames_pvd(ctx, &sink, m, s);
    else if (j->base) rc = ctn_writer_run_case(ctx, j->ops, 1, &sink, m, j->sol, j->base, j->base_step);
    else rc = ctn_writer_run_step(ctx, j->ops, 1, j->step, &sink, m, j->sol ? j->sol : s);
    return rc ? rc : ctn_atomic_close(f);
}

/* Files lo .. hi - 1 of the set, staged in order; stops at the first failure. */
typedef struct part {
    ctn_ctx *ctx;
    const char *dir;
    const job *jobs;
    size_t lo, hi;
    const ctn_model *m;
    const ctn_solution *s;
    ctn_atomic_file *f;
    int rc;
} part;

static void stage_part(void *arg)
{
    part *p = arg;
    for (size_t i = p->lo; i < p->hi && !p->rc; i++) p->rc = stage(p->ctx, p->dir, &p->jobs[i], p->m, p->s, &p->f[i]);
}

/* A large set (the thread policy's CTN_THR_WRITE, under the solve's threads=) is staged
 * by two threads: result.json (about half the bytes) on the caller's, the other files on
 * the context's helper, which reports through a context of its own (same limits, no
 * progress callback, no helpers) whose error, if any, becomes the caller's. The writers
 * only read the model and the solution. Measured on the K = 1000 net of
 * bench/RESULTS.md (1.4 GB of files). Small sets, and a context set to fail an
 * allocation (the fault-injection tests), stay on one thread, in order. */
static int stage_all(ctn_ctx *ctx, const char *dir, const job *jobs, size_t n, const ctn_model *m,
                     const ctn_solution *s, ctn_atomic_file *f)
{
    part main = { ctx, dir, jobs, 0, n, m, s, f, CTN_OK };
    size_t size = ctn_model_node_count(m) + ctn_model_element_count(m);
    if (n < 2 || ctx->alloc_fail_at || !ctn_thr_allows(ctx, ctn_solution_threads(s), CTN_THR_WRITE, (double)size)) {
        stage_part(&main);
        return main.rc;
    }
    ctn_ctx other = *ctx;
    other.code = CTN_OK;
    other.msg[0] = '\0';
    other.progress = NULL;
    other.threads = 1;
    other.pool = NULL;
    part rest = { &other, dir, jobs, 1, n, m, s, f, CTN_OK };
    int ticket = ctn_thr_start(ctx, ctn_solution_threads(s), CTN_THR_WRITE, (double)size, stage_part, &rest);
    main.hi = ticket ? 1 : n;
    stage_part(&main);
    if (!ticket) return main.rc;
    ctn_thr_wait(ctx, ticket);
    if (!main.rc && rest.rc) return ctn_error(ctx, rest.rc, "%s", other.msg);
    return main.rc;
}

/* Every file is staged before any replaces an older one, so a failure leaves the
 * previous set (or nothing) in place, never a mix. */
static int write_set(ctn_ctx *ctx, const char *dir, const job *jobs, size_t n, const ctn_model *m,
                     const ctn_solution *s, ctn_atomic_file *f, int rc)
{
    if (!rc) rc = check_targets(ctx, dir, jobs, n);
    for (size_t i = 0; i < n; i++) f[i] = (ctn_atomic_file)CTN_ATOMIC_FILE_INIT;
    if (!rc) rc = stage_all(ctx, dir, jobs, n, m, s, f);
    rc = agree(ctx, dir, rc);
    for (size_t i = 0; i < n; i++) {
        if (!rc) rc = ctn_atomic_commit(&f[i]);
        else ctn_atomic_abort(&f[i]);
    }
    return rc;
}

/* After a one-step set: an earlier run's result.pvd would list other steps' files. */
static int remove_stale(ctn_ctx *ctx, const char *dir)
{
    char path[4096];
    int rc = target(ctx, dir, ctn_writer_pvd.name, path, sizeof path);
    if (!rc && unlink(path) && errno != ENOENT)
        rc = ctn_error(ctx, CTN_ERR_IO, "%s: cannot remove: %s", path, strerror(errno));
    return rc;
}

int ctn_write_results(ctn_ctx *ctx, const char *dir, const ctn_model *m,
                      const ctn_solution *s)
{
    if (!dir || !m || !s) return ctn_error(ctx, CTN_ERR_INVALID, "ctn_write_results: bad arguments");
    const ctn_comm *c = ctn_ctx_comm(ctx);
    int rank = ctn_comm_rank(c), size = ctn_comm_size(c);
    int rc = ctn_result_check(ctx, m, s);
    if (rc && size == 1) return rc;
    if (!rc) rc = make_dir(ctx, dir);
    if (!rc && rank == 0) rc = make_case_dirs(ctx, dir, m, s);
    char frames[4096];
    size_t n = 0, nf = ctn_solution_frame_count(s);
    if (!rc && rank == 0 && nf && !(rc = target(ctx, dir, CTN_FRAMES_DIR, frames, sizeof frames)))
        rc = make_dir(ctx, frames);
    job *jobs = rc ? NULL : plan_rank(ctx, m, s, rank, size, &n);
    ctn_atomic_file *f = jobs ? ctn_calloc(ctx, n, sizeof *f) : NULL;
    if (!rc && !f) rc = CTN_ERR_NOMEM;
    if (size == 1 && rc) {
        ctn_free(jobs);
        return rc;
    }
    rc = write_set(ctx, dir, jobs, f ? n : 0, m, s, f, rc);      /* every rank: agree() */
    if (!rc && rank == 0 && ctn_solution_step_count(s) == 1) rc = remove_stale(ctx, dir);
    if (!rc && rank == 0) rc = ctn_frames_remove_stale(ctx, dir, nf);
    if (!rc && rank == 0) rc = ctn_vtu_pieces_remove_stale(ctx, dir, size);
    ctn_free(f);
    ctn_free(jobs);
    return rc;
}
