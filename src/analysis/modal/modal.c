/* Modal analysis about a converged state: K_T phi = omega^2 M phi by shift-invert
 * Lanczos (linalg/eigen/eigen.h), the shifted matrix K_T - sigma M factored once by the
 * problem's linear solver on the problem's pattern (LDL' on the same pattern when LL'
 * fails: an interior shift, or an unstable state). docs/theory.md, "Modal analysis". */
#include "linalg/eigen/eigen.h"
#include "linalg/pcg.h"
#include "analysis/analysis.h"
#include "analysis/modal/modal.h"
#include "dist/comm.h"
#include "problem/la_options.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A model error at the `modes` line (or without a place, from the API). */
static int modal_error(const ctn_problem *p, const ctn_modal_options *o, const char *msg)
{
    if (o->line > 0) return ctn_error_at(p->ctx, CTN_ERR_MODEL, p->m->file, o->line, "%s", msg);
    return ctn_error(p->ctx, CTN_ERR_MODEL, "%s", msg);
}

int ctn_modal_check(ctn_problem *p, const ctn_modal_options *o, double *diag, double tot[3])
{
    char msg[256];
    size_t bad, nmass = 0;
    /* nodes with rotations: their rotary inertia is in M where a family gives it (the
       beam's); the shapes keep the translations (3 per node) */
    if ((size_t)o->count > p->ndof) {
        snprintf(msg, sizeof msg, "modes: count=%d is more than the %zu free DOFs", o->count, p->ndof);
        return modal_error(p, o, msg);
    }
    if (ctn_asm_mass_diag(p->a, diag, tot, &bad)) {
        const ctn_model *m = p->m;
        const ctn_section *sec = &m->sections.v[m->elements.v[bad].section];
        return ctn_error_at(p->ctx, CTN_ERR_MODEL, m->file, sec->line, "section '%s': its weight w=%g gives no mass "
                            "in a model without units: give mass= (or units)", sec->name, sec->w);
    }
    for (size_t q = 0; q < p->ndof; q++) nmass += diag[q] > 0;
    if (nmass == 0) return modal_error(p, o, "modes: no free DOF carries mass (give a section mass= or w= with units, or a node mass=; a rotation takes mass from a beam's section)");
    if ((size_t)o->count > nmass) {
        snprintf(msg, sizeof msg, "modes: count=%d is more than the %zu free DOFs that carry mass", o->count, nmass);
        return modal_error(p, o, msg);
    }
    return CTN_OK;
}

/* Largest K_qq / M_qq over the DOFs with mass: the scale of omega^2. */
static double lambda_scale(const ctn_problem *p, const double *diag)
{
    double s = 0;
    for (size_t q = 0; q < p->ndof; q++)
        if (diag[q] > 0) s = fmax(s, fabs(p->Kx[p->a->colptr[q + 1] - 1]) / diag[q]);
    return s;
}

/* An estimate of the highest natural frequency [Hz], from the largest K_ii / M_ii. */
static double highest_frequency(const ctn_modal *md)
{
    return sqrt(lambda_scale(md->p, md->diag)) / CTN_TWO_PI;
}

/* "shift=F Hz is far above the model's highest frequency ...", when it is, for a message. */
static void far_above(const ctn_modal *md, char *why, size_t size)
{
    double f = highest_frequency(md);
    why[0] = '\0';
    if (md->opt->shift > 10 * f)
        snprintf(why, size, ": shift=%g Hz is far above the model's highest frequency (of the order of %.3g Hz), "
                 "where shift-invert cannot resolve modes; choose a smaller shift=", md->opt->shift, f);
}

/* Modes that fail the residual test are not reported as modes (CTN_ERR_NOCONV). */
static int not_eigenpairs(const ctn_modal *md)
{
    char why[256];
    far_above(md, why, sizeof why);
    return ctn_error(md->p->ctx, CTN_ERR_NOCONV, "eigen-solver: %d of %d modes fail the residual test (|K phi - "
                     "omega^2 M phi| up to %.3g of |K phi| + omega^2 |M phi|)%s", md->failed, md->opt->count,
                     md->worst, why);
}

/* A shift so far above the spectrum (sigma > 1e10 max K_ii / M_ii) that omega^2 - sigma
 * keeps no digit of omega^2 worth having: refused before any work. */
#define CTN_SHIFT_RESOLVABLE 1e10
static int shift_resolvable(const ctn_modal *md, double ls)
{
    if (!(ls > 0) || md->sigma <= CTN_SHIFT_RESOLVABLE * ls) return CTN_OK;
    char why[256];
    far_above(md, why, sizeof why);
    return ctn_error(md->p->ctx, CTN_ERR_NOCONV, "eigen-solver: no mode can be resolved%s", why);
}

/* Factor K - sigma M (values into md->Ax): the problem's solver, else LDL'. Without a
 * shift, when the problem holds LL' of K_T at this state (the stability check factored
 * it: K_T is positive definite), that factor serves with sigma = 0 instead. */
static int factor_shifted(ctn_modal *md, const ctn_solution *s)
{
    ctn_problem *p = md->p;
    ctn_factor_info info = { 0, -1 };
    double t0 = ctn_clock();
    ctn_problem_settle(p);
    if (md->opt->shift == 0 && p->factored_at == s && p->ls && !ctn_linsolve_type(p->ls)->indefinite) {
        md->sigma = 0;
        md->ls = p->ls;
        md->sum.reused_factor = 1;
        return CTN_OK;
    }
    p->factored_at = NULL;
    int finite = 1;
    for (size_t k = 0; k < p->a->nnz; k++) {
        md->Ax[k] = p->Kx[k] - md->sigma * md->Mx[k];
        finite &= isfinite(md->Ax[k]);
    }
    if (!finite)
        return ctn_error(p->ctx, CTN_ERR_MODEL, "modes: K - sigma M overflows at shift=%g Hz: choose a shift "
                         "nearer the model's frequencies (the highest is about %.4g Hz)", md->opt->shift,
                         highest_frequency(md));
    int rc = ctn_linsolve_factor(p->ls, md->Ax, 0.0, &info);
    md->sum.factorizations++;
    md->ls = p->ls;
    if (!rc && !info.ok) {
        ctn_pattern pat = { p->ndof, p->a->colptr, p->a->rowind };
        rc = ctn_linsolve_create_threads(p->ctx, ctn_linsolve_default(p->ctx, "cholmod-ldl"), &pat, ctn_la_ordering_of(p->opt.ordering), p->opt.threads, &md->ldl);
        if (!rc) rc = ctn_linsolve_factor(md->ldl, md->Ax, 0.0, &info);
        md->sum.factorizations++;
        md->ls = md->ldl;
        if (!rc && !info.ok)
            rc = ctn_error(p->ctx, CTN_ERR_LINALG, "modes: K - sigma M is singular at sigma = %g 1/s^2 (a frequency "
                           "equals the shift): choose another shift=", md->sigma);
    }
    md->sum.t_factor += ctn_clock() - t0;
    return rc;
}

static int op_solve(void *ud, const double *b, double *y)
{
    ctn_modal *md = ud;
    double t0 = ctn_clock(), c0 = ctn_cpu_clock();
    int rc = ctn_linsolve_solve(md->ls, b, y);
    md->sum.t_solve += ctn_clock() - t0;
    md->sum.t_solve_cpu += ctn_cpu_clock() - c0;
    md->sum.solves++;
    return rc;
}

/* Y = (K - sigma M)^-1 X for k columns: one pass over the factor. */
static int op_solve_block(void *ud, const double *X, double *Y, int k)
{
    ctn_modal *md = ud;
    double t0 = ctn_clock(), c0 = ctn_cpu_clock();
    int rc = ctn_linsolve_solve_block(md->ls, X, Y, (size_t)k);
    md->sum.t_solve += ctn_clock() - t0;
    md->sum.t_solve_cpu += ctn_cpu_clock() - c0;
    md->sum.solves += k;
    md->sum.block_solves++;
    return rc;
}

static void op_stiffness(void *ud, const double *x, double *y)
{
    ctn_modal *md = ud;
    ctn_problem_symv(md->p, md->p->Kx, x, y);
}

/* y += |K| |x| + |lambda| |M| |x|: the rounding bound of a residual. */
static void op_abs(void *ud, const double *x, double lambda, double *y)
{
    ctn_modal *md = ud;
    ctn_pattern pat = { md->p->ndof, md->p->a->colptr, md->p->a->rowind };
    ctn_sym_matvec_abs_pair(&pat, md->p->Kx, md->Mx, fabs(lambda), x, y);
}

void ctn_modal_mass(const ctn_modal *md, const double *x, double *y)
{
    ctn_pattern pat = { md->p->ndof, md->mcol, md->mrow };
    ctn_sym_matvec(&pat, md->mval, x, y);
}

static void op_mass(void *ud, const double *x, double *y) { ctn_modal_mass(ud, x, y); }

static void op_mass2(void *ud, const double *x0, const double *x1, double *y0, double *y1)
{
    const ctn_modal *md = ud;
    ctn_pattern pat = { md->p->ndof, md->mcol, md->mrow };
    ctn_sym_matvec2(&pat, md->mval, x0, x1, y0, y1);
}

static void op_stiffness2(void *ud, const double *x0, const double *x1, double *y0, double *y1)
{
    const ctn_modal *md = ud;
    ctn_pattern pat = { md->p->ndof, md->p->a->colptr, md->p->a->rowind };
    ctn_sym_matvec2(&pat, md->p->Kx, x0, x1, y0, y1);
}

/* M's nonzeros apart from K's pattern: a cable's consistent mass couples a DOF only to
 * the same direction at the element's other node (lumped: none), so M holds 3 to 5 times
 * fewer entries than K, and the eigen-solver multiplies by it once a column. */
static int mass_pattern(ctn_modal *md)
{
    const ctn_asm *a = md->p->a;
    size_t n = md->p->ndof, mnz = 0;
    for (size_t k = 0; k < a->nnz; k++) mnz += md->Mx[k] != 0;
    md->mcol = ctn_malloc(md->p->ctx, n + 1, sizeof(int));
    md->mrow = ctn_malloc(md->p->ctx, mnz ? mnz : 1, sizeof(int));
    md->mval = ctn_malloc(md->p->ctx, mnz ? mnz : 1, sizeof(double));
    if (!md->mcol || !md->mrow || !md->mval) return CTN_ERR_NOMEM;
    int at = 0;
    for (size_t j = 0; j < n; j++) {
        md->mcol[j] = at;
        for (int k = a->colptr[j]; k < a->colptr[j + 1]; k++)
            if (md->Mx[k] != 0) {
                md->mrow[at] = a->rowind[k];
                md->mval[at++] = md->Mx[k];
            }
    }
    md->mcol[n] = at;
    return CTN_OK;
}

/* The last mode when every free DOF is asked for (ARPACK finds at most n - 1): the
 * M-orthogonal complement of the others (M is then definite), its Rayleigh quotient. */
static void complement(ctn_modal *md, double *V, int have, double *lambda)
{
    size_t n = md->p->ndof;
    double *x = V + n * (size_t)have, *Mx = md->w1;
    for (size_t i = 0; i < n; i++) x[i] = 1.0 + 0.1 * (double)(i % 13);
    for (int pass = 0; pass < 2; pass++)                /* twice is enough (Kahan) */
        for (int k = 0; k < have; k++) {
            const double *v = V + n * (size_t)k;
            op_mass(md, x, Mx);
            double c = ctn_layout_dot(&md->p->eq, v, Mx);
            for (size_t i = 0; i < n; i++) x[i] -= c * v[i];
        }
    op_mass(md, x, Mx);
    double nrm = sqrt(ctn_layout_dot(&md->p->eq, x, Mx));
    for (size_t i = 0; i < n; i++) x[i] /= nrm;
    ctn_problem_symv(md->p, md->p->Kx, x, Mx);
    lambda[have] = ctn_layout_dot(&md->p->eq, x, Mx);
}

/* The context's communicator solves the eigenproblem itself (SLEPc under MPI:
 * dist/comm.h's eigen op) when it has an eigen-solver and fewer modes than DOFs are
 * asked for (a Krylov space of n vectors holds no more than n - 1 restarts' worth). */
static int on_comm(const ctn_modal *md)
{
    return ctn_ctx_comm(md->p->ctx)->ops->eigen && (size_t)md->opt->count < md->p->ndof;
}

/* The shift of the communicator's solver: as factor_shifted's (0 where the stability
 * check found K_T positive definite at this state), the factorization its own. */
static void comm_shift(ctn_modal *md, const ctn_solution *s)
{
    const ctn_problem *p = md->p;
    if (md->opt->shift == 0 && p->factored_at == s && p->ls && !ctn_linsolve_type(p->ls)->indefinite) md->sigma = 0;
}

/* The eigenpairs by the communicator's solver, each vector scaled to phi' M phi = 1. */
static int eigenpairs_comm(ctn_modal *md, double *lambda, double **V)
{
    ctn_problem *p = md->p;
    const ctn_comm *c = ctn_ctx_comm(p->ctx);
    ctn_pattern pat = { p->ndof, p->a->colptr, p->a->rowind };
    ctn_eigen_info info;
    memset(&info, 0, sizeof info);
    double t0 = ctn_clock(), c0 = ctn_cpu_clock();
    int rc = c->ops->eigen(c->impl, p->ctx, &pat, p->Kx, md->Mx, md->opt->count, md->sigma, lambda, V, &info);
    md->sum.solver = CTN_EIGEN_SLEPC;
    md->sum.factorizations = 1;
    md->sum.solves = info.ops;
    md->sum.lanczos_restarts = info.restarts;
    md->sum.t_solve += ctn_clock() - t0;
    md->sum.t_solve_cpu += ctn_cpu_clock() - c0;
    for (int k = 0; !rc && k < md->opt->count; k++) {
        double *v = *V + p->ndof * (size_t)k;
        ctn_modal_mass(md, v, md->w0);
        double nrm = sqrt(ctn_layout_dot(&p->eq, v, md->w0));
        for (size_t i = 0; nrm > 0 && i < p->ndof; i++) v[i] /= nrm;
    }
    return rc;
}

/* The eigenpairs: V (n x ncv, the first count columns the modes), lambda ascending.
 * ARPACK finds at most n - 1 (the last one is then the complement); block Lanczos all. */
static int eigenpairs(ctn_modal *md, double *lambda, double **V)
{
    ctn_problem *p = md->p;
    ctn_eigen_solver asked = md->opt->solver;
    if (asked == CTN_EIGEN_AUTO) asked = p->ndof >= CTN_EIGEN_BLOCK_DOFS ? CTN_EIGEN_BLOCK : CTN_EIGEN_ARPACK;
    int block = asked == CTN_EIGEN_BLOCK;
    int n = (int)p->ndof, count = md->opt->count, nev = count < n || block ? count : n - 1;
    ctn_eigen_ops ops = { .ud = md, .solve = op_solve, .bmul = op_mass, .work = md->w0,
                          .solve_block = op_solve_block, .amul = op_stiffness, .absmul = op_abs,
                          .bmul2 = op_mass2, .amul2 = op_stiffness2,
                          .threads = p->opt.threads == 1 ? 1 : 0, .asked = p->opt.threads };
    ctn_eigen_info info;
    memset(&info, 0, sizeof info);
    int rc = CTN_OK;
    md->sum.solver = asked;
    if (nev > 0 && block) rc = ctn_eigen_block(p->ctx, n, nev, md->sigma, &ops, lambda, V, &info);
    md->sum.block_solves = info.block_solves;
    if (rc == CTN_ERR_NOCONV && block) {                /* ARPACK takes over (reported) */
        ctn_ctx_clear(p->ctx);
        md->sum.solver = CTN_EIGEN_ARPACK;
        block = 0;
        nev = count < n ? count : n - 1;
    }
    if (nev > 0 && !block) rc = ctn_eigen_shift_invert(p->ctx, n, nev, md->sigma, &ops, lambda, V, &info);
    if (nev == 0) *V = ctn_malloc(p->ctx, (size_t)n, sizeof(double));      /* n = 1 */
    md->sum.lanczos_restarts = info.restarts;
    md->sum.block_size = block ? info.block : 0;
    if (!rc && !*V) rc = CTN_ERR_NOMEM;
    if (!rc && nev < count) complement(md, *V, nev, lambda);
    if (!rc && block) md->sum.max_floor = info.max_floor;
    return rc;
}

static void modal_free(ctn_modal *md)
{
    double *v[] = { md->Mx, md->Ax, md->d, md->diag, md->w0, md->w1, md->lambda, md->mval };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) ctn_free(v[i]);
    ctn_free(md->mcol);
    ctn_free(md->mrow);
    ctn_linsolve_destroy(&md->ldl);
}

static int modal_alloc(ctn_modal *md)
{
    ctn_problem *p = md->p;
    size_t nz = p->a->nnz ? p->a->nnz : 1, n = p->ndof ? p->ndof : 1;
    md->Mx = ctn_malloc(p->ctx, nz, sizeof(double));
    md->Ax = ctn_malloc(p->ctx, nz, sizeof(double));
    md->d = ctn_calloc(p->ctx, p->ns, sizeof(double));
    md->diag = ctn_malloc(p->ctx, n, sizeof(double));
    md->w0 = ctn_malloc(p->ctx, n, sizeof(double));
    md->w1 = ctn_malloc(p->ctx, n, sizeof(double));
    md->lambda = ctn_malloc(p->ctx, (size_t)md->opt->count, sizeof(double));
    return md->Mx && md->Ax && md->d && md->diag && md->w0 && md->w1 && md->lambda ? CTN_OK : CTN_ERR_NOMEM;
}

/* Tangent and mass at the solution, the scales, the shift. */
static int prepare(ctn_modal *md, const ctn_solution *s)
{
    ctn_problem *p = md->p;
    double t0 = ctn_clock();
    int rc = ctn_modal_check(p, md->opt, md->diag, md->sum.total_mass);
    if (!rc) rc = ctn_problem_tangent_at(p, s, md->d, "ctn_problem_modes");
    if (!rc) rc = ctn_asm_mass(p->ctx, p->a, md->opt->mass == CTN_MASS_LUMPED, md->Mx);
    if (!rc) rc = mass_pattern(md);
    if (rc) return rc;
    ctn_asm_mass_moving(p->a, md->Mx, md->sum.total_mass);       /* of this M */
    double ls = lambda_scale(p, md->diag), w = CTN_TWO_PI * md->opt->shift;
    md->sigma = md->opt->shift > 0 ? w * w : -(ls > 0 ? 1e-9 * ls : 1.0);   /* below every
                                                   omega^2 >= 0: K - sigma M definite */
    md->ztol = ls > 0 ? 1e-12 * ls : 1e-3 * fabs(md->sigma);
    md->sum.t_assemble = ctn_clock() - t0;
    return shift_resolvable(md, ls);
}

int ctn_problem_modes(ctn_problem *p, ctn_solution *s, const ctn_modal_options *options)
{
    if (!p || !s || !options) return p ? ctn_error(p->ctx, CTN_ERR_INVALID, "ctn_problem_modes: bad arguments") : CTN_ERR_INVALID;
    ctn_modal_options own;
    const ctn_modal_options *opt = &own;
    int rc0 = ctn_modal_options_take(p->ctx, &own, options);
    if (rc0) return rc0;
    char msg[256];
    if (ctn_modal_options_fault(opt, msg, sizeof msg) || opt->count < 1)
        return ctn_error(p->ctx, CTN_ERR_INVALID, "ctn_problem_modes: %s", opt->count < 1 ? "count must be >= 1" : msg);
    if (s->sum.reason != CTN_CONVERGED || !s->nsteps)
        return ctn_error(p->ctx, CTN_ERR_INVALID, "ctn_problem_modes: the solution did not converge");
    double t0 = ctn_clock(), c0 = ctn_cpu_clock(), *V = NULL;
    ctn_modal md;
    memset(&md, 0, sizeof md);
    md.p = p;
    md.opt = opt;
    md.sum.mass = opt->mass;
    md.sum.shift = opt->shift;
    ctn_modes *res = NULL;
    int rc = modal_alloc(&md);
    if (!rc) rc = prepare(&md, s);
    if (!rc && on_comm(&md)) {
        comm_shift(&md, s);
        rc = eigenpairs_comm(&md, md.lambda, &V);
    } else {
        if (!rc) rc = factor_shifted(&md, s);
        if (!rc) rc = eigenpairs(&md, md.lambda, &V);
    }
    if (!rc && !(res = ctn_modes_create(p->ctx, (size_t)opt->count, p->m->nodes.n))) rc = CTN_ERR_NOMEM;
    if (!rc && p->a->map.rot && !(res->rshapes = ctn_calloc(p->ctx, 3 * p->m->nodes.n * (size_t)opt->count, sizeof(double))))
        rc = CTN_ERR_NOMEM;
    if (!rc) {
        md.sum.sigma = md.sigma;
        md.sum.count = opt->count;
        ctn_modes_fill(&md, V, res);
        if (md.failed) {
            rc = not_eigenpairs(&md);
            ctn_modes_destroy(&res);
        }
    }
    if (!rc) {
        md.sum.t_total = ctn_clock() - t0;
        md.sum.t_cpu = ctn_cpu_clock() - c0;
        res->sum = md.sum;
        ctn_modes_destroy(&s->modes);
        s->modes = res;
    }
    ctn_free(V);
    modal_free(&md);
    return rc;
}

/* The analysis object: the modes about the solution's last step, stored in it. */
static void modal_defaults(const ctn_problem *p, void *opt)
{
    (void)p;
    ctn_modal_options_default(opt);
}

static int modal_check(ctn_problem *p, const void *opt)
{
    const ctn_modal_options *o = opt;
    char msg[256];
    if (ctn_modal_options_fault(o, msg, sizeof msg)) return ctn_error(p->ctx, CTN_ERR_INVALID, "%s", msg);
    if (o->count < 1) return ctn_error(p->ctx, CTN_ERR_INVALID, "modal analysis: count must be >= 1 (got %d)", o->count);
    return CTN_OK;
}

static int modal_run(ctn_problem *p, const void *opt, ctn_solution **s) { return ctn_problem_modes(p, *s, opt); }

const ctn_analysis_ops ctn_analysis_modal = {
    "modal", sizeof(ctn_modal_options), 1, modal_defaults, modal_check, modal_run,
};
