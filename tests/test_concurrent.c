/* Two solves at once in two threads, each with its own context (issue 28, item 4): the
 * library is reentrant whatever they ask for. Each thread solves a net with a modal
 * analysis by ARPACK (whose Fortran state is process-wide: the library serializes it),
 * then by block Lanczos, then the paper's cable, three rounds; every answer (the
 * displacements, every frequency and mode shape, the BLAS name) equals the one-thread
 * run's bit for bit. Under ASan/TSan a race or heap corruption shows as a report. */
#include "check.h"

#include <catena.h>

#include <pthread.h>
#include <stdlib.h>

#define ROUNDS 3

static const char *net_path = "tests/models/modes/net4.cable";

typedef struct answer {
    int rc;
    size_t nd, nf;
    double d[512], f[64], shape[64];
    char blas[64];
} answer;

/* Solve the file with its modes by `solver` (arpack or block): its displacements, its
 * frequencies, and the first entries of every shape. */
static void run_modal(const char *solver, answer *a)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    ctn_solution *s = NULL;
    ctn_solve_options opt;
    memset(a, 0, sizeof *a);
    ctn_ctx_create(&ctx);
    a->rc = ctn_read_file(ctx, net_path, &m, &opt);
    opt.modal.solver = !strcmp(solver, "arpack") ? CTN_EIGEN_ARPACK : CTN_EIGEN_BLOCK;
    if (!a->rc) a->rc = ctn_solve(ctx, m, &opt, &s);
    if (!a->rc) {
        a->nd = 3 * ctn_model_node_count(m);
        if (a->nd > 512) a->nd = 512;
        memcpy(a->d, ctn_solution_displacements(s), a->nd * sizeof(double));
        ctn_modal_summary ms;
        ctn_solution_modal_summary(s, &ms);
        a->nf = ms.count > 64 ? 64 : (size_t)ms.count;
        for (size_t k = 0; k < a->nf; k++) {
            ctn_mode md;
            if (ctn_solution_mode(s, k, &md)) { a->rc = -1; break; }
            a->f[k] = md.frequency;
            a->shape[k] = md.shape[3 * 5 + 1];
        }
        ctn_solve_summary sum;
        ctn_solution_summary(s, &sum);
        snprintf(a->blas, sizeof a->blas, "%s", sum.blas);
    }
    ctn_solution_destroy(&s);
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
}

static int same(const answer *a, const answer *b)
{
    return a->rc == 0 && b->rc == 0 && a->nd == b->nd && a->nf == b->nf && a->nf > 0 &&
           !memcmp(a->d, b->d, a->nd * sizeof(double)) && !memcmp(a->f, b->f, a->nf * sizeof(double)) &&
           !memcmp(a->shape, b->shape, a->nf * sizeof(double)) && !strcmp(a->blas, b->blas);
}

typedef struct job {
    answer arpack[ROUNDS], block[ROUNDS];
} job;

static void *run(void *arg)
{
    job *j = arg;
    for (int r = 0; r < ROUNDS; r++) {
        run_modal("arpack", &j->arpack[r]);
        run_modal("block", &j->block[r]);
    }
    return NULL;
}

int main(void)
{
    static answer ref_arpack, ref_block;
    static job jobs[2];
    run_modal("arpack", &ref_arpack);
    run_modal("block", &ref_block);
    CHECK_MSG(ref_arpack.rc == 0 && ref_arpack.nf == 27, "rc %d, %zu modes", ref_arpack.rc, ref_arpack.nf);
    CHECK(ref_block.rc == 0 && ref_block.nf == 27);
    pthread_t t[2];
    int started[2];
    for (int i = 0; i < 2; i++) started[i] = !pthread_create(&t[i], NULL, run, &jobs[i]);
    for (int i = 0; i < 2; i++)
        if (started[i]) pthread_join(t[i], NULL);
    CHECK(started[0] && started[1]);
    for (int i = 0; i < 2; i++)
        for (int r = 0; r < ROUNDS; r++) {
            CHECK_MSG(same(&jobs[i].arpack[r], &ref_arpack), "thread %d round %d: ARPACK differs (rc %d)", i, r,
                      jobs[i].arpack[r].rc);
            CHECK_MSG(same(&jobs[i].block[r], &ref_block), "thread %d round %d: block Lanczos differs", i, r);
        }
    CHECK_DONE();
}
