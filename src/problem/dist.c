/* The tangent distributed by columns over the ranks of an MPI job (problem.h, p->dist):
 * rank r of N owns the nodes [nn r / N, nn (r + 1) / N) and the columns of their free
 * DOFs (consecutive: the DOFs are numbered node by node), assembles those nodes'
 * internal forces and tangent columns alone (the node-by-node assembly,
 * assemble/gather.c) into a PETSc matrix distributed the same way (linsolve.h,
 * create_cols), and holds only those columns' values. The internal forces are then
 * gathered whole to every rank (an allgather of the owned ranges: the same bits as one
 * process's), so the Newton iteration above runs unchanged on replicated vectors; the
 * energy is summed over the ranks in rank order and the first collapsed element is the
 * least over them. Products with the tangent sum every rank's columns' share (rank
 * order). Taken when the model is assembled node by node alone (cables, bars, springs
 * of two 3-DOF nodes), the solver is MUMPS (petsc, petsc-ldl) and no analysis that
 * reads the tangent as one array follows (modes, buckling, dynamics) nor any follower
 * load; otherwise the tangent is replicated as before (docs/parallel.md). A rank keeps
 * the pattern's row indices of its own columns only (the assembly's whole array is
 * released): the two rare paths that factor the whole tangent with CHOLMOD gather it;
 * and the node-by-node tables of its own nodes (ctn_asm_gather_keep): the internal
 * forces of every node, which the results want, come from the generic element loop. */
#include "problem/problem.h"

#include "problem/dynamics_options.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

static int wanted(const ctn_problem *p, const char *name)
{
    const ctn_comm *c = ctn_ctx_comm(p->ctx);
    return strcmp(c->ops->name, "serial") && c->ops->allgather && name &&
           (!strcmp(name, "petsc") || !strcmp(name, "petsc-ldl")) && p->ndof > 0 && ctn_asm_can_feed(p->a) &&
           p->ns == 3 * p->a->nn && !p->fl && p->opt.modal.count < 1 && p->opt.buckling.count < 1 &&
           !ctn_dynamics_asked(&p->opt.dynamics);
}

/* the first column of node q or a later one */
static size_t first_column(const ctn_asm *a, size_t q)
{
    for (; q < a->nn; q++)
        for (int j = 0; j < 3; j++)
            if (a->map.eq[3 * q + (size_t)j] >= 0) return (size_t)a->map.eq[3 * q + (size_t)j];
    return a->ndof;
}

int ctn_problem_dist_setup(ctn_problem *p, const char *name)
{
    size_t nnz = p->a->nnz;
    p->dist = wanted(p, name);
    if (p->dist) {
        const ctn_comm *c = ctn_ctx_comm(p->ctx);
        size_t r = (size_t)ctn_comm_rank(c), n = (size_t)ctn_comm_size(c), nn = p->a->nn;
        p->q0 = nn * r / n;
        p->q1 = nn * (r + 1) / n;
        p->c0 = first_column(p->a, p->q0);
        p->c1 = first_column(p->a, p->q1);
        size_t m = p->c1 - p->c0;
        if (!(p->lcolptr = ctn_malloc(p->ctx, m + 1, sizeof(int)))) return CTN_ERR_NOMEM;
        for (size_t j = 0; j <= m; j++) p->lcolptr[j] = p->a->colptr[p->c0 + j] - p->a->colptr[p->c0];
        nnz = (size_t)p->lcolptr[m];
        if (m < p->ndof) {                      /* the other ranks' columns' rows released */
            if (!(p->lrowind = ctn_malloc(p->ctx, nnz ? nnz : 1, sizeof(int)))) return CTN_ERR_NOMEM;
            memcpy(p->lrowind, p->a->rowind + p->a->colptr[p->c0], nnz * sizeof(int));
            ctn_free(p->a->rowind);
            p->a->rowind = NULL;
        }
        int rc = ctn_asm_gather_keep(p->a, p->q0, p->q1);   /* the other ranks' nodes' lists */
        if (rc) return rc;
    }
    if (!(p->Kx = ctn_calloc(p->ctx, nnz ? nnz : 1, sizeof(double)))) return CTN_ERR_NOMEM;
    p->K = (ctn_dmat){ &p->eq, p->a->colptr, p->a->rowind, p->Kx };
    return CTN_OK;
}

/* this rank's columns of the pattern */
static ctn_pattern local_pattern(const ctn_problem *p)
{
    return (ctn_pattern){ p->c1 - p->c0, p->lcolptr, p->lrowind ? p->lrowind : p->a->rowind };
}

int ctn_problem_solver_create(ctn_problem *p, const char *name, ctn_la_ordering ord, ctn_linsolve **out)
{
    if (p->dist) {
        ctn_pattern pat = local_pattern(p);
        return ctn_linsolve_create_cols(p->ctx, name, &pat, p->ndof, p->c0, p->c1, p->opt.threads, out);
    }
    ctn_pattern pat = { p->ndof, p->a->colptr, p->a->rowind };
    return ctn_linsolve_create_threads(p->ctx, name, &pat, ord, p->opt.threads, out);
}

int ctn_problem_dist_eval(ctn_problem *p, const double *d, unsigned mode, double *Kx, double *U, size_t *bad)
{
    const ctn_comm *c = ctn_ctx_comm(p->ctx);
    double sums[2] = { 0, 0 }, first = INFINITY;
    size_t b = SIZE_MAX;
    ctn_asm_gather_eval_nodes(p->a, d, mode, p->q0, p->q1, p->fint, Kx, &sums[0], &b);
    sums[1] = b != SIZE_MAX;
    if (b != SIZE_MAX) first = (double)b;
    /* one exchange of the energy and the count of ranks with a collapsed element; the
       least such element only when there is one */
    int rc = c->ops->allgather(c->impl, p->fint, 3 * p->q0, 3 * p->q1);
    if (!rc) rc = c->ops->allreduce(c->impl, sums, 2, CTN_REDUCE_SUM);
    if (!rc && sums[1] > 0) rc = c->ops->allreduce(c->impl, &first, 1, CTN_REDUCE_MIN);
    if (rc) {                                   /* a failed exchange: no valid state */
        p->fint[0] = NAN;
        sums[0] = NAN;
    }
    if (U) *U = sums[0];
    if (isinf(first)) return 0;
    *bad = (size_t)first;
    return 1;
}

double ctn_problem_dist_max_diag(const ctn_problem *p)
{
    const ctn_comm *c = ctn_ctx_comm(p->ctx);
    double m = 0;
    for (size_t j = 0; j < p->c1 - p->c0; j++)
        if (p->lcolptr[j + 1] > p->lcolptr[j]) m = fmax(m, p->Kx[p->lcolptr[j + 1] - 1]);
    if (c->ops->allreduce(c->impl, &m, 1, CTN_REDUCE_MAX)) return NAN;
    return m;
}

void ctn_problem_dist_symv(const ctn_problem *p, const double *Ax, const double *x, double *y)
{
    const ctn_comm *c = ctn_ctx_comm(p->ctx);
    const int *ri = p->lrowind ? p->lrowind : p->a->rowind;
    for (size_t i = 0; i < p->ndof; i++) y[i] = 0;
    for (size_t j = 0; j < p->c1 - p->c0; j++) {
        size_t col = p->c0 + j;
        double xj = x[col], s = 0;
        for (int k = p->lcolptr[j]; k < p->lcolptr[j + 1]; k++) {
            size_t r = (size_t)ri[k];
            y[r] += Ax[k] * xj;
            if (r != col) s += Ax[k] * x[r];
        }
        y[col] += s;
    }
    if (c->ops->allreduce(c->impl, y, p->ndof, CTN_REDUCE_SUM))
        for (size_t i = 0; i < p->ndof; i++) y[i] = NAN;
}

/* every rank's columns' row indices into a new *rows, gathered through buf (nnz: as
 * doubles, exact below 2^53) */
static int whole_rows(ctn_problem *p, double *buf, size_t k0, size_t k1, int **rows)
{
    const ctn_comm *c = ctn_ctx_comm(p->ctx);
    if (!(*rows = ctn_malloc(p->ctx, p->a->nnz ? p->a->nnz : 1, sizeof(int)))) return CTN_ERR_NOMEM;
    for (size_t k = k0; k < k1; k++) buf[k] = p->lrowind[k - k0];
    int rc = c->ops->allgather(c->impl, buf, k0, k1);
    if (rc) {
        ctn_free(*rows);
        *rows = NULL;
        return ctn_error(p->ctx, rc, "the ranks could not gather the tangent's pattern");
    }
    for (size_t k = 0; k < p->a->nnz; k++) (*rows)[k] = (int)buf[k];
    return CTN_OK;
}

int ctn_problem_whole_K(ctn_problem *p, ctn_pattern *pat, double **Kx)
{
    *pat = (ctn_pattern){ p->ndof, p->a->colptr, p->a->rowind };
    *Kx = p->Kx;
    if (!p->dist || p->a->rowind) return CTN_OK;             /* one rank: its columns are all */
    const ctn_comm *c = ctn_ctx_comm(p->ctx);
    size_t k0 = (size_t)p->a->colptr[p->c0], k1 = (size_t)p->a->colptr[p->c1];
    double *all = ctn_malloc(p->ctx, p->a->nnz ? p->a->nnz : 1, sizeof(double));
    if (!all) return CTN_ERR_NOMEM;
    int *rows = NULL, rc = whole_rows(p, all, k0, k1, &rows);
    if (rc) {
        ctn_free(all);
        return rc;
    }
    memcpy(all + k0, p->Kx, (k1 - k0) * sizeof(double));
    rc = c->ops->allgather(c->impl, all, k0, k1);
    if (rc) {
        ctn_free(all);
        ctn_free(rows);
        return ctn_error(p->ctx, rc, "the ranks could not gather the tangent");
    }
    pat->rowind = rows;
    *Kx = all;
    return CTN_OK;
}

void ctn_problem_whole_K_done(const ctn_problem *p, const ctn_pattern *pat, double *Kx)
{
    if (Kx != p->Kx) ctn_free(Kx);
    if (pat->rowind != p->a->rowind) ctn_free((int *)pat->rowind);
}

int ctn_problem_eval_tangent(ctn_problem *p, const double *d)
{
    size_t bad;
    if (p->dist) return ctn_problem_dist_eval(p, d, 0, p->Kx, NULL, &bad);
    return ctn_asm_eval(p->a, d, 0, p->fint, p->Kx, NULL, NULL);
}
