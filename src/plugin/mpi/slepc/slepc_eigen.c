/* The modal analysis's eigenproblem on SLEPc (slepc_eigen.h): K x = lambda M x, both on
 * the replicated pattern, each process passing its owned rows (an even split, as the
 * PETSc linear solvers do) into MATSBAIJ matrices over the communicator; Krylov-Schur
 * (EPSKRYLOVSCHUR) on the generalized Hermitian problem (EPS_GHEP) with the spectral
 * transformation shift-and-invert (STSINVERT) at sigma, (K - sigma M)^-1 applied by MUMPS
 * (KSPPREONLY + PCCHOLESKY: LDL', any inertia); the nev eigenvalues nearest sigma
 * (EPS_TARGET_MAGNITUDE) to a relative residual of 1e-12 (SLEPc's EPS_CONV_REL);
 * SLEPc's options (-eps_*, -st_*) pass through. The eigenvectors are gathered whole to
 * every process. PETSc's returning error handler around every call. */
#include "plugin/mpi/slepc/slepc_eigen.h"

#include "plugin/mpi/petsc/petsc.h"

#include <slepceps.h>
#include <string.h>

#define CTN_SLEPC_TOL 1e-12
#define CTN_SLEPC_MAXIT 1000

typedef struct slepc_job {
    ctn_ctx *ctx;
    MPI_Comm comm;
    ctn_petsc_rows rows;
    Mat K, M;
    EPS eps;
    Vec x, xall;
    VecScatter toall;
} slepc_job;

static int fail(slepc_job *j, const char *what, PetscErrorCode e)
{
    const char *text = NULL;
    PetscErrorMessage(e, &text, NULL);
    return ctn_error(j->ctx, CTN_ERR_LINALG, "SLEPc: %s failed (%s)", what, text ? text : "error");
}

#define SCALL(call)                                                                                            \
    do {                                                                                                       \
        PetscErrorCode e_ = (call);                                                                            \
        if (e_) {                                                                                              \
            rc = fail(j, #call, e_);                                                                           \
            goto done;                                                                                         \
        }                                                                                                      \
    } while (0)

/* A = the owned rows of the matrix with values vals on the pattern (upper triangle). */
static int make_matrix(slepc_job *j, PetscInt n, const double *vals, Mat *A)
{
    int rc = CTN_OK;
    ctn_petsc_rows *r = &j->rows;
    ctn_petsc_rows_fill(r, vals, 0.0);
    SCALL(MatCreate(j->comm, A));
    SCALL(MatSetSizes(*A, r->hi - r->lo, r->hi - r->lo, n, n));
    SCALL(MatSetType(*A, MATSBAIJ));
    SCALL(MatSeqSBAIJSetPreallocationCSR(*A, 1, r->ptr, r->col, r->val));
    SCALL(MatMPISBAIJSetPreallocationCSR(*A, 1, r->ptr, r->col, r->val));
    SCALL(MatSetOption(*A, MAT_SYMMETRIC, PETSC_TRUE));
done:
    return rc;
}

/* Krylov-Schur, shift-invert at sigma on MUMPS, the nev eigenvalues nearest sigma. */
static int make_eps(slepc_job *j, int nev, double sigma)
{
    int rc = CTN_OK;
    ST st;
    KSP ksp;
    PC pc;
    SCALL(EPSCreate(j->comm, &j->eps));
    SCALL(EPSSetOperators(j->eps, j->K, j->M));
    SCALL(EPSSetProblemType(j->eps, EPS_GHEP));
    SCALL(EPSSetType(j->eps, EPSKRYLOVSCHUR));
    SCALL(EPSSetDimensions(j->eps, nev, PETSC_DEFAULT, PETSC_DEFAULT));
    SCALL(EPSSetTarget(j->eps, sigma));
    SCALL(EPSSetWhichEigenpairs(j->eps, EPS_TARGET_MAGNITUDE));
    SCALL(EPSSetTolerances(j->eps, CTN_SLEPC_TOL, CTN_SLEPC_MAXIT));
    SCALL(EPSGetST(j->eps, &st));
    SCALL(STSetType(st, STSINVERT));
    SCALL(STSetMatStructure(st, SAME_NONZERO_PATTERN));     /* M on K's pattern */
    SCALL(STGetKSP(st, &ksp));
    SCALL(KSPSetType(ksp, KSPPREONLY));
    SCALL(KSPGetPC(ksp, &pc));
    SCALL(PCSetType(pc, PCCHOLESKY));
    SCALL(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    SCALL(EPSSetFromOptions(j->eps));
done:
    return rc;
}

/* The k-th eigenpair: lambda, and its vector gathered whole into v (n). */
static int pair(slepc_job *j, PetscInt k, PetscInt n, double *lambda, double *v)
{
    int rc = CTN_OK;
    PetscScalar kr, ki;
    const PetscScalar *a;
    SCALL(EPSGetEigenpair(j->eps, k, &kr, &ki, j->x, NULL));
    *lambda = (double)kr;
    SCALL(VecScatterBegin(j->toall, j->x, j->xall, INSERT_VALUES, SCATTER_FORWARD));
    SCALL(VecScatterEnd(j->toall, j->x, j->xall, INSERT_VALUES, SCATTER_FORWARD));
    SCALL(VecGetArrayRead(j->xall, &a));
    memcpy(v, a, (size_t)n * sizeof *v);
    SCALL(VecRestoreArrayRead(j->xall, &a));
done:
    return rc;
}

/* lambda ascending, the columns of V with them (insertion: nev is small) */
static void sort_pairs(int nev, size_t n, double *lambda, double *V, double *tmp)
{
    for (int a = 1; a < nev; a++)
        for (int b = a; b > 0 && lambda[b] < lambda[b - 1]; b--) {
            double t = lambda[b];
            lambda[b] = lambda[b - 1];
            lambda[b - 1] = t;
            memcpy(tmp, V + n * (size_t)b, n * sizeof *tmp);
            memcpy(V + n * (size_t)b, V + n * (size_t)(b - 1), n * sizeof *tmp);
            memcpy(V + n * (size_t)(b - 1), tmp, n * sizeof *tmp);
        }
}

static int solve_pairs(slepc_job *j, PetscInt n, int nev, double *lambda, double *V, ctn_eigen_info *info)
{
    int rc = CTN_OK;
    PetscInt nconv = 0, its = 0;
    SCALL(EPSSolve(j->eps));
    SCALL(EPSGetConverged(j->eps, &nconv));
    SCALL(EPSGetIterationNumber(j->eps, &its));
    info->nconv = (int)nconv;
    info->restarts = (int)its;
    ST st;
    KSP ksp;
    PetscInt solves = 0;
    SCALL(EPSGetST(j->eps, &st));
    SCALL(STGetKSP(st, &ksp));
    SCALL(KSPGetTotalIterations(ksp, &solves));        /* KSPPREONLY: one a solve */
    info->ops = (int)solves;
    if (nconv < nev) {
        rc = ctn_error(j->ctx, CTN_ERR_NOCONV, "SLEPc: %d of %d eigenpairs converged in %d Krylov-Schur restarts",
                       (int)nconv, nev, (int)its);
        goto done;
    }
    SCALL(MatCreateVecs(j->K, &j->x, NULL));
    SCALL(VecScatterCreateToAll(j->x, &j->toall, &j->xall));
    for (int k = 0; k < nev && !rc; k++) rc = pair(j, k, n, lambda + k, V + (size_t)n * (size_t)k);
done:
    return rc;
}

static void job_free(slepc_job *j)
{
    EPSDestroy(&j->eps);
    VecScatterDestroy(&j->toall);
    VecDestroy(&j->xall);
    VecDestroy(&j->x);
    MatDestroy(&j->K);
    MatDestroy(&j->M);
    ctn_petsc_rows_free(&j->rows);
}

int ctn_slepc_eigen(MPI_Comm comm, ctn_ctx *ctx, const ctn_pattern *p, const double *Kx, const double *Mx, int nev,
                    double sigma, double *lambda, double **vecs, ctn_eigen_info *info)
{
    slepc_job job;
    slepc_job *j = &job;
    memset(j, 0, sizeof *j);
    memset(info, 0, sizeof *info);
    *vecs = NULL;
    j->ctx = ctx;
    j->comm = comm;
    int rank = 0, size = 1, rc;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    PetscInt n = (PetscInt)p->n;
    PetscInt lo = (PetscInt)((long long)n * rank / size), hi = (PetscInt)((long long)n * (rank + 1) / size);
    double *V = ctn_malloc(ctx, p->n * (size_t)nev + p->n, sizeof(double));   /* + one column of scratch */
    if (!V) return CTN_ERR_NOMEM;
    rc = ctn_petsc_rows_build(ctx, p, lo, hi, 0, &j->rows);
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    if (!rc) rc = make_matrix(j, n, Kx, &j->K);
    if (!rc) rc = make_matrix(j, n, Mx, &j->M);
    if (!rc) rc = make_eps(j, nev, sigma);
    if (!rc) rc = solve_pairs(j, n, nev, lambda, V, info);
    job_free(j);
    PetscPopErrorHandler();
    if (rc) {
        ctn_free(V);
        return rc;
    }
    sort_pairs(nev, p->n, lambda, V, V + p->n * (size_t)nev);
    *vecs = V;
    return CTN_OK;
}
