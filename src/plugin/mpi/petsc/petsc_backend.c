/* The PETSc linear solvers (petsc.h): "petsc" (MUMPS, LL' semantics), "petsc-ldl"
 * (MUMPS LDL', indefinite, with inertia) and "petsc-cg" (CG + GAMG). PETSc's error
 * handler is the returning one around every call (the library prints nothing); a PETSc
 * error becomes a status with PETSc's message in the context. */
#include "plugin/mpi/petsc/petsc.h"

#include "plugin/mpi/comm_mpi.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct ctn_petsc {
    ctn_ctx *ctx;
    ctn_petsc_kind kind;
    MPI_Comm comm;
    PetscInt n;
    ctn_petsc_rows rows;       /* the owned rows [lo, hi) (only lo and hi by columns) */
    const int *colptr;         /* the pattern (the diagonal ends each column) */
    int by_cols;               /* distributed by columns: pcols this process's, Kx theirs */
    ctn_pattern pcols;
    PetscInt *crow;            /* by columns: scratch of the longest column */
    PetscScalar *cval;
    Mat A;
    Vec b, x;
    int *counts;               /* every rank's rows: count, then first (the solution's
                                  MPI_Allgatherv straight into the caller's vector: no
                                  gathered copy held beside it) */
    KSP ksp;
    Mat F;                     /* MUMPS's factor (NULL for a Krylov solve) */
    int relax;                 /* MUMPS's ICNTL(14): workspace above its estimate, % */
    char label[64];
} ctn_petsc;

static int fail(ctn_petsc *c, const char *what, PetscErrorCode e)
{
    const char *text = NULL;
    PetscInt g1 = 0, g2 = 0;
    PetscErrorMessage(e, &text, NULL);
    if (c->F && e == PETSC_ERR_LIB && !MatMumpsGetInfog(c->F, 1, &g1) && !MatMumpsGetInfog(c->F, 2, &g2))
        return ctn_error(c->ctx, CTN_ERR_IO, "PETSc: %s failed (MUMPS INFOG(1) = %d, INFOG(2) = %d)", what, (int)g1, (int)g2);
    return ctn_error(c->ctx, CTN_ERR_IO, "PETSc: %s failed (%s)", what, text ? text : "error");
}

#define PCALL(call)                                                                                            \
    do {                                                                                                       \
        PetscErrorCode e_ = (call);                                                                            \
        if (e_) {                                                                                              \
            rc = fail(c, #call, e_);                                                                           \
            goto done;                                                                                         \
        }                                                                                                      \
    } while (0)

static void split(PetscInt n, int rank, int size, PetscInt *lo, PetscInt *hi)
{
    *lo = (PetscInt)((long long)n * rank / size);
    *hi = (PetscInt)((long long)n * (rank + 1) / size);
}

static int gather_counts(ctn_petsc *c)
{
    int size = 1, mine[2] = { (int)(c->rows.hi - c->rows.lo), (int)c->rows.lo };
    MPI_Comm_size(c->comm, &size);
    int *all = ctn_malloc(c->ctx, 2 * (size_t)size, sizeof(int));
    if (!(c->counts = ctn_malloc(c->ctx, 2 * (size_t)size, sizeof(int))) || !all) {
        ctn_free(all);
        return CTN_ERR_NOMEM;
    }
    int rc = MPI_Allgather(mine, 2, MPI_INT, all, 2, MPI_INT, c->comm) == MPI_SUCCESS
                 ? CTN_OK : ctn_error(c->ctx, CTN_ERR_IO, "PETSc: the ranks' rows could not be exchanged");
    for (int r = 0; r < size; r++) {
        c->counts[r] = all[2 * r];
        c->counts[size + r] = all[2 * r + 1];
    }
    ctn_free(all);
    return rc;
}

static int make_matrix(ctn_petsc *c)
{
    int rc = CTN_OK;
    ctn_petsc_rows *r = &c->rows;
    PetscInt m = r->hi - r->lo, *d = NULL;
    int full = c->kind == CTN_PETSC_CG;
    PCALL(MatCreate(c->comm, &c->A));
    PCALL(MatSetSizes(c->A, m, m, c->n, c->n));
    PCALL(MatSetType(c->A, full ? MATAIJ : MATSBAIJ));
    if (c->by_cols) {
        if (!(d = ctn_calloc(c->ctx, 2 * (size_t)(m > 0 ? m : 1), sizeof *d))) {
            rc = CTN_ERR_NOMEM;
            goto done;
        }
        if ((rc = ctn_petsc_cols_count(c->ctx, c->comm, &c->pcols, c->n, r->lo, d, d + (m > 0 ? m : 1)))) goto done;
        PCALL(MatSeqSBAIJSetPreallocation(c->A, 1, 0, d));
        PCALL(MatMPISBAIJSetPreallocation(c->A, 1, 0, d, 0, d + (m > 0 ? m : 1)));
    } else if (full) {
        PCALL(MatSeqAIJSetPreallocationCSR(c->A, r->ptr, r->col, NULL));
        PCALL(MatMPIAIJSetPreallocationCSR(c->A, r->ptr, r->col, NULL));
    } else {
        PCALL(MatSeqSBAIJSetPreallocationCSR(c->A, 1, r->ptr, r->col, NULL));
        PCALL(MatMPISBAIJSetPreallocationCSR(c->A, 1, r->ptr, r->col, NULL));
    }
    PCALL(MatSetOption(c->A, MAT_SYMMETRIC, PETSC_TRUE));
    PCALL(MatSetOption(c->A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
    PCALL(MatCreateVecs(c->A, &c->x, &c->b));
    rc = gather_counts(c);
done:
    ctn_free(d);
    return rc;
}

static int make_ksp(ctn_petsc *c)
{
    int rc = CTN_OK;
    PC pc;
    PCALL(KSPCreate(c->comm, &c->ksp));
    PCALL(KSPGetPC(c->ksp, &pc));
    if (c->kind == CTN_PETSC_CG) {
        PCALL(KSPSetType(c->ksp, KSPCG));
        PCALL(PCSetType(pc, PCGAMG));
        PCALL(KSPSetTolerances(c->ksp, 1e-12, 1e-300, PETSC_DEFAULT, 10000));
    } else {
        PCALL(KSPSetType(c->ksp, KSPPREONLY));
        PCALL(PCSetType(pc, PCCHOLESKY));
        PCALL(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    }
    PCALL(KSPSetFromOptions(c->ksp));          /* -ksp_type, -pc_type, ... (PETSC_OPTIONS) */
done:
    return rc;
}

static void destroy(void *impl)
{
    ctn_petsc *c = impl;
    if (!c) return;
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    KSPDestroy(&c->ksp);
    VecDestroy(&c->x);
    VecDestroy(&c->b);
    MatDestroy(&c->A);
    PetscPopErrorHandler();
    ctn_petsc_rows_free(&c->rows);
    ctn_free(c->crow);
    ctn_free(c->cval);
    ctn_free(c->counts);
    ctn_free(c);
}

/* cols: NULL, or this process's columns [cols[0], cols[1]) of the n x n matrix p is a
 * share of (by columns: petsc_cols.c) */
static int create_kind(ctn_ctx *ctx, const ctn_pattern *p, size_t n, const size_t *cols, ctn_petsc_kind kind,
                       void **impl)
{
    PetscBool init = PETSC_FALSE;
    PetscInitialized(&init);
    if (!init) return ctn_error(ctx, CTN_ERR_INVALID, "the PETSc linear solvers need PETSc initialised by the caller "
                                                      "(PetscInitialize; the catena command does it)");
    ctn_petsc *c = ctn_calloc(ctx, 1, sizeof *c);
    if (!c) return CTN_ERR_NOMEM;
    c->ctx = ctx;
    c->kind = kind;
    c->comm = ctn_comm_mpi_handle(ctn_ctx_comm(ctx));
    c->n = (PetscInt)n;
    c->colptr = p->colptr;
    c->relax = 30;
    int rank = 0, size = 1, rc;
    MPI_Comm_rank(c->comm, &rank);
    MPI_Comm_size(c->comm, &size);
    PetscInt lo, hi;
    split(c->n, rank, size, &lo, &hi);
    if (cols) {
        int longest = 0;
        c->by_cols = 1;
        c->pcols = *p;
        c->rows.lo = (PetscInt)cols[0];
        c->rows.hi = (PetscInt)cols[1];
        for (size_t j = 0; j < p->n; j++)
            if (p->colptr[j + 1] - p->colptr[j] > longest) longest = p->colptr[j + 1] - p->colptr[j];
        c->crow = ctn_malloc(ctx, (size_t)longest + 1, sizeof *c->crow);
        c->cval = ctn_malloc(ctx, (size_t)longest + 1, sizeof *c->cval);
        rc = c->crow && c->cval ? CTN_OK : CTN_ERR_NOMEM;
    } else rc = ctn_petsc_rows_build(ctx, p, lo, hi, kind == CTN_PETSC_CG, &c->rows);
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    if (!rc) rc = make_matrix(c);
    if (!rc) rc = make_ksp(c);
    PetscPopErrorHandler();
    if (rc) {
        destroy(c);
        return rc;
    }
    *impl = c;
    return CTN_OK;
}

static int cols_mumps(ctn_ctx *ctx, const ctn_pattern *p, size_t n, size_t c0, size_t c1, const ctn_la_options *o,
                     void **impl)
{
    size_t cols[2] = { c0, c1 };
    (void)o;
    return create_kind(ctx, p, n, cols, CTN_PETSC_MUMPS, impl);
}

static int create_mumps(ctn_ctx *ctx, const ctn_pattern *p, const ctn_la_options *o, void **impl)
{
    (void)o;
    return create_kind(ctx, p, p->n, NULL, CTN_PETSC_MUMPS, impl);
}

static int cols_ldl(ctn_ctx *ctx, const ctn_pattern *p, size_t n, size_t c0, size_t c1, const ctn_la_options *o,
                     void **impl)
{
    size_t cols[2] = { c0, c1 };
    (void)o;
    return create_kind(ctx, p, n, cols, CTN_PETSC_MUMPS_LDL, impl);
}

static int create_ldl(ctn_ctx *ctx, const ctn_pattern *p, const ctn_la_options *o, void **impl)
{
    (void)o;
    return create_kind(ctx, p, p->n, NULL, CTN_PETSC_MUMPS_LDL, impl);
}

static int cols_inertia(ctn_ctx *ctx, const ctn_pattern *p, size_t n, size_t c0, size_t c1, const ctn_la_options *o,
                     void **impl)
{
    size_t cols[2] = { c0, c1 };
    (void)o;
    return create_kind(ctx, p, n, cols, CTN_PETSC_INERTIA, impl);
}

static int create_inertia(ctn_ctx *ctx, const ctn_pattern *p, const ctn_la_options *o, void **impl)
{
    (void)o;
    return create_kind(ctx, p, p->n, NULL, CTN_PETSC_INERTIA, impl);
}

static int create_cg(ctn_ctx *ctx, const ctn_pattern *p, const ctn_la_options *o, void **impl)
{
    (void)o;
    return create_kind(ctx, p, p->n, NULL, CTN_PETSC_CG, impl);
}

/* The largest diagonal entry of K + shift I (every process holds K whole): the scale
 * of MUMPS's null pivots, 1e-12 of it, as the stability check counts zero pivots. */
static double max_diag(const ctn_petsc *c, const double *Kx, double shift)
{
    double m = 0, all = 0;
    PetscInt n = c->by_cols ? (PetscInt)c->pcols.n : c->n;
    for (PetscInt j = 0; j < n; j++)
        if (c->colptr[j + 1] > c->colptr[j]) m = fmax(m, fabs(Kx[c->colptr[j + 1] - 1] + shift));
    if (c->by_cols && MPI_Allreduce(&m, &all, 1, MPI_DOUBLE, MPI_MAX, c->comm) == MPI_SUCCESS) m = all;
    return m > 0 ? m : 1.0;
}

/* MUMPS's settings on its factor: the inertia over every process (ICNTL(13) = 1: no
 * ScaLAPACK root); for "petsc-inertia", null pivots detected (ICNTL(24)) below 1e-12 of the
 * largest diagonal entry (CNTL(3) < 0: absolute), the zero eigenvalues of the stability
 * check; "petsc" fails as CHOLMOD's LL' does, on a negative or a zero pivot. */
static int mumps_settings(ctn_petsc *c, double tol)
{
    int rc = CTN_OK;
    PC pc;
    PCALL(KSPGetPC(c->ksp, &pc));
    PetscBool is_mumps = PETSC_FALSE;
    MatSolverType st = NULL;
    PCALL(PCFactorSetUpMatSolverType(pc));
    PCALL(PCFactorGetMatSolverType(pc, &st));
    is_mumps = st && !strcmp(st, MATSOLVERMUMPS);
    c->F = NULL;
    if (!is_mumps) goto done;
    PCALL(PCFactorGetMatrix(pc, &c->F));
    PCALL(MatMumpsSetIcntl(c->F, 13, 1));
    PCALL(MatMumpsSetIcntl(c->F, 14, c->relax));
    if (c->kind == CTN_PETSC_INERTIA) {        /* a null pivot fixed alters the solves */
        PCALL(MatMumpsSetIcntl(c->F, 8, 0));   /* pivots of K itself, not of a scaled K */
        PCALL(MatMumpsSetIcntl(c->F, 24, 1));
        PCALL(MatMumpsSetCntl(c->F, 3, -tol));
    }
done:
    return rc;
}

static void set_label(ctn_petsc *c)
{
    KSPType kt = NULL;
    PCType pt = NULL;
    PC pc;
    if (KSPGetType(c->ksp, &kt) || KSPGetPC(c->ksp, &pc) || PCGetType(pc, &pt)) return;
    if (c->F && kt && !strcmp(kt, KSPPREONLY))
        snprintf(c->label, sizeof c->label, "petsc-mumps%s", c->kind == CTN_PETSC_MUMPS ? "" : "-ldl");
    else snprintf(c->label, sizeof c->label, "petsc-%s-%s", kt ? kt : "?", pt ? pt : "?");
}

/* MUMPS's negative pivots (INFOG(12)) and, with null pivot detection ("petsc-inertia"),
 * its null pivots (INFOG(28)) */
static int inertia_of(ctn_petsc *c, PetscInt *neg, PetscInt *zero)
{
    int rc = CTN_OK;
    *neg = *zero = 0;
    if (!c->F) return CTN_OK;
    PCALL(MatMumpsGetInfog(c->F, 12, neg));
    if (c->kind == CTN_PETSC_INERTIA) PCALL(MatMumpsGetInfog(c->F, 28, zero));
done:
    return rc;
}

/* K + shift I's owned rows into the matrix */
static int set_values(ctn_petsc *c, const double *Kx, double shift)
{
    int rc = CTN_OK;
    ctn_petsc_rows *r = &c->rows;
    if (c->by_cols) {
        PCALL(ctn_petsc_cols_set(c->A, &c->pcols, r->lo, Kx, shift, c->crow, c->cval));
        PCALL(MatAssemblyBegin(c->A, MAT_FINAL_ASSEMBLY));
        PCALL(MatAssemblyEnd(c->A, MAT_FINAL_ASSEMBLY));
        goto done;
    }
    ctn_petsc_rows_fill(r, Kx, shift);
    for (PetscInt i = r->lo; i < r->hi; i++) {
        PetscInt k0 = r->ptr[i - r->lo], len = r->ptr[i - r->lo + 1] - k0;
        PCALL(MatSetValues(c->A, 1, &i, len, r->col + k0, r->val + k0, INSERT_VALUES));
    }
    PCALL(MatAssemblyBegin(c->A, MAT_FINAL_ASSEMBLY));
    PCALL(MatAssemblyEnd(c->A, MAT_FINAL_ASSEMBLY));
done:
    return rc;
}

/* One factorization of the matrix; *err and MUMPS's INFOG(1) in *g1 when it failed,
 * after which the factor is a fresh one (PETSc skips every later numeric factorization
 * of a MUMPS factor whose INFOG(1) < 0). */
static int factor_once(ctn_petsc *c, double tol, MatFactorError *err, PetscInt *g1)
{
    int rc = CTN_OK;
    *err = MAT_FACTOR_NOERROR;
    *g1 = 0;
    PCALL(KSPSetOperators(c->ksp, c->A, c->A));
    if (c->kind != CTN_PETSC_CG && (rc = mumps_settings(c, tol))) goto done;
    PCALL(KSPSetUp(c->ksp));
    set_label(c);
    if (!c->F) goto done;
    PCALL(MatFactorGetError(c->F, err));
    if (*err == MAT_FACTOR_NOERROR) goto done;
    MatMumpsGetInfog(c->F, 1, g1);
    PCALL(KSPDestroy(&c->ksp));
    c->F = NULL;
    rc = make_ksp(c);
done:
    return rc;
}

/* MUMPS's errors of too little workspace (INFOG(1) = -8, -9, -14, -15, -17, -20):
 * factored again with ICNTL(14) doubled, at most four times. */
static int short_of_space(PetscInt g1) { return g1 == -8 || g1 == -9 || g1 == -14 || g1 == -15 || g1 == -17 || g1 == -20; }

static int factor(void *impl, const double *Kx, double shift, ctn_factor_info *info)
{
    ctn_petsc *c = impl;
    MatFactorError err = MAT_FACTOR_NOERROR;
    PetscInt g1 = 0;
    info->ok = 1;
    info->fail_col = -1;
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    int rc = set_values(c, Kx, shift);
    for (int t = 0; !rc; t++) {
        rc = factor_once(c, 1e-12 * max_diag(c, Kx, shift), &err, &g1);
        if (rc || !short_of_space(g1) || t == 4) break;
        c->relax *= 2;
    }
    if (!rc && err == MAT_FACTOR_NUMERIC_ZEROPIVOT) info->ok = 0;
    else if (!rc && err != MAT_FACTOR_NOERROR)
        rc = ctn_error(c->ctx, CTN_ERR_IO, "MUMPS: factorization failed (INFOG(1) = %d)", (int)g1);
    if (!rc && info->ok && c->F && c->kind == CTN_PETSC_MUMPS) {   /* LL' semantics: definite or failed */
        PetscInt neg, zero;
        rc = inertia_of(c, &neg, &zero);
        info->ok = neg == 0 && zero == 0;
    }
    PetscPopErrorHandler();
    return rc;
}

static int solve(void *impl, const double *bv, double *xv)
{
    ctn_petsc *c = impl;
    int rc = CTN_OK;
    PetscScalar *a;
    const PetscScalar *ca;
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    PCALL(VecGetArray(c->b, &a));
    memcpy(a, bv + c->rows.lo, (size_t)(c->rows.hi - c->rows.lo) * sizeof *a);
    PCALL(VecRestoreArray(c->b, &a));
    PCALL(KSPSolve(c->ksp, c->b, c->x));
    KSPConvergedReason why;
    PCALL(KSPGetConvergedReason(c->ksp, &why));
    if (why < 0) {
        rc = ctn_error(c->ctx, CTN_ERR_IO, "%s: the linear solve did not converge (%s)", c->label, KSPConvergedReasons[why]);
        goto done;
    }
    PCALL(VecGetArrayRead(c->x, &ca));
    int size = 1, e = MPI_Comm_size(c->comm, &size);
    if (!e) e = MPI_Allgatherv(ca, (int)(c->rows.hi - c->rows.lo), MPI_DOUBLE, xv, c->counts, c->counts + size, MPI_DOUBLE,
                               c->comm);
    PCALL(VecRestoreArrayRead(c->x, &ca));
    if (e != MPI_SUCCESS) rc = ctn_error(c->ctx, CTN_ERR_IO, "%s: the ranks could not gather the solution", c->label);
done:
    PetscPopErrorHandler();
    return rc;
}

static int inertia(void *impl, double tol, long *negative, long *zero, long *first)
{
    ctn_petsc *c = impl;
    (void)tol;                                 /* MUMPS counted against its CNTL(3) */
    *first = -1;                               /* MUMPS names no column */
    if (!c->F) return ctn_error(c->ctx, CTN_ERR_INVALID, "linear solver '%s' gives no inertia", c->label);
    PetscInt neg = 0, z = 0;
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    int rc = inertia_of(c, &neg, &z);
    PetscPopErrorHandler();
    *negative = (long)neg;
    *zero = (long)z;
    return rc;
}

static ctn_la_ordering ordering(const void *impl)
{
    const ctn_petsc *c = impl;
    PetscInt o = -1;
    if (!c->F || MatMumpsGetInfog(c->F, 7, &o)) return CTN_LA_ORDER_NATURAL;
    return o == 5 ? CTN_LA_ORDER_METIS : CTN_LA_ORDER_AMD;   /* INFOG(7): 5 METIS; AMD, AMF, QAMD, ... */
}

static size_t factor_nnz(const void *impl)
{
    const ctn_petsc *c = impl;
    PetscInt v = 0;
    if (!c->F || MatMumpsGetInfog(c->F, 29, &v)) return 0;
    return v >= 0 ? (size_t)v : (size_t)(-(long long)v) * 1000000u;   /* < 0: millions */
}

static double flops(const void *impl)
{
    const ctn_petsc *c = impl;
    PetscReal v = 0;
    if (!c->F || MatMumpsGetRinfog(c->F, 3, &v)) return 0;
    return (double)v;
}

static const char *label(const void *impl) { return ((const ctn_petsc *)impl)->label; }

const ctn_linsolve_ops ctn_petsc_mumps_ops = {
    .name = "petsc", .indefinite = 0, .create = create_mumps, .create_cols = cols_mumps, .destroy = destroy,
    .factor = factor, .solve = solve,
    .inertia = inertia, .ordering = ordering, .factor_nnz = factor_nnz, .flops = flops, .label = label,
};

const ctn_linsolve_ops ctn_petsc_ldl_ops = {
    .name = "petsc-ldl", .indefinite = 1, .create = create_ldl, .create_cols = cols_ldl, .destroy = destroy,
    .factor = factor, .solve = solve,
    .inertia = inertia, .ordering = ordering, .factor_nnz = factor_nnz, .flops = flops, .label = label,
};

const ctn_linsolve_ops ctn_petsc_cg_ops = {
    .name = "petsc-cg", .indefinite = 0, .create = create_cg, .destroy = destroy, .factor = factor, .solve = solve,
    .inertia = NULL, .ordering = ordering, .factor_nnz = factor_nnz, .flops = flops, .label = label,
};

const ctn_linsolve_ops ctn_petsc_inertia_ops = {
    .name = "petsc-inertia", .indefinite = 1, .create = create_inertia, .create_cols = cols_inertia, .destroy = destroy,
    .factor = factor,
    .solve = solve, .inertia = inertia, .ordering = ordering, .factor_nnz = factor_nnz, .flops = flops, .label = label,
};
