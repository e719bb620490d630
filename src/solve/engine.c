/* The solution engine: setup, residual and potential at a load parameter t,
 * factorization with an optional shift, solves. */
#include "solve/engine.h"

#include <math.h>
#include <string.h>
#include <time.h>

double ctn_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double ctn_dot(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) s += a[i] * b[i];
    return s;
}

double ctn_norm(const double *v, size_t n) { return sqrt(ctn_dot(v, v, n)); }

/* Diagonal of the bounding box of the reference nodes. */
static double model_size(const ctn_model *m)
{
    double lo[3], hi[3], s = 0;
    for (int k = 0; k < 3; k++) lo[k] = hi[k] = m->nodes.v[0].X[k];
    for (size_t i = 1; i < m->nodes.n; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], m->nodes.v[i].X[k]);
            hi[k] = fmax(hi[k], m->nodes.v[i].X[k]);
        }
    for (int k = 0; k < 3; k++) s += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    return sqrt(s);
}

static int alloc_vectors(ctn_engine *e)
{
    ctn_ctx *ctx = e->ctx;
    double **v3[] = { &e->fint, &e->fext, &e->f0, &e->f1, &e->p0, &e->p1, &e->dsave };
    double **vn[] = { &e->r, &e->dd, &e->w };
    for (size_t i = 0; i < sizeof v3 / sizeof *v3; i++)
        if (!(*v3[i] = ctn_calloc(ctx, e->n3, sizeof(double)))) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < sizeof vn / sizeof *vn; i++)
        if (!(*vn[i] = ctn_calloc(ctx, e->ndof, sizeof(double)))) return CTN_ERR_NOMEM;
    return CTN_OK;
}

int ctn_engine_setup(ctn_engine *e, ctn_ctx *ctx, const ctn_model *m,
                     const ctn_solve_options *opt, ctn_solve_summary *sum)
{
    memset(e, 0, sizeof *e);
    e->ctx = ctx;
    e->m = m;
    e->opt = *opt;
    e->sum = sum;
    int rc = ctn_asm_create(ctx, m, &e->a);
    if (rc) return rc;
    e->n3 = 3 * e->a->nn;
    e->ndof = e->a->ndof;
    if (e->ndof == 0) return ctn_error(ctx, CTN_ERR_MODEL, "%s: the model has no free degree of freedom", m->file);
    int indefinite = opt->method == CTN_METHOD_ARCLENGTH;
    if ((rc = ctn_chol_create_ex(ctx, e->ndof, e->a->colptr, e->a->rowind, opt->ordering,
                                 indefinite, &e->ch)))
        return rc;
    if ((rc = alloc_vectors(e))) return rc;
    e->lref = model_size(m);
    for (size_t i = 0; i < e->a->ne; i++)
        e->kscale = fmax(e->kscale, e->a->props[i].EA / e->a->props[i].l0);
    return CTN_OK;
}

void ctn_engine_teardown(ctn_engine *e)
{
    ctn_asm_destroy(&e->a);
    ctn_chol_destroy(&e->ch);
    double **v[] = { &e->fint, &e->fext, &e->f0, &e->f1, &e->p0, &e->p1, &e->dsave,
                     &e->r, &e->dd, &e->w };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++) {
        ctn_free(*v[i]);
        *v[i] = NULL;
    }
}

void ctn_engine_set_t(ctn_engine *e, double t, double *d)
{
    for (size_t i = 0; i < e->n3; i++) {
        e->fext[i] = e->f0[i] + t * (e->f1[i] - e->f0[i]);
        if (e->a->eq[i] < 0) d[i] = e->p0[i] + t * (e->p1[i] - e->p0[i]);
    }
}

int ctn_engine_residual(ctn_engine *e, const double *d, int with_K, double *rnorm, double *pi)
{
    double t0 = ctn_now(), U = 0, work = 0;
    int rc = ctn_asm_eval_energy(e->a, d, e->fint, with_K ? ctn_chol_values(e->ch) : NULL,
                                 pi ? &U : NULL, NULL);
    if (!rc) {
        double rr = 0;
        for (size_t i = 0; i < e->n3; i++) {
            int q = e->a->eq[i];
            if (q < 0) continue;
            double ri = e->fext[i] - e->fint[i];
            e->r[q] = ri;
            rr += ri * ri;
            if (pi) work += e->fext[i] * d[i];
        }
        *rnorm = sqrt(rr);
        if (pi) *pi = U - work;
        if (!isfinite(*rnorm) || (pi && !isfinite(*pi))) rc = CTN_ERR_DOMAIN;
    }
    e->sum->t_assemble += ctn_now() - t0;
    return rc;
}

double ctn_engine_fref(const ctn_engine *e)
{
    double ff = 0, fr = 0;
    for (size_t i = 0; i < e->n3; i++) {
        if (e->a->eq[i] >= 0) ff += e->fext[i] * e->fext[i];
        else fr += e->fint[i] * e->fint[i];
    }
    return ff > 0 ? sqrt(ff) : fr > 0 ? sqrt(fr) : 1.0;
}

int ctn_engine_factor(ctn_engine *e, double shift, int *posdef, long *fail_col)
{
    double t0 = ctn_now();
    int rc = ctn_chol_factorize_shifted(e->ch, shift, fail_col);
    e->sum->t_factor += ctn_now() - t0;
    *posdef = !rc;
    if (rc && *fail_col >= 0) {
        ctn_ctx_clear(e->ctx);
        return CTN_OK;
    }
    return rc;
}

int ctn_engine_solve(ctn_engine *e, const double *b, double *x)
{
    double t0 = ctn_now();
    int rc = ctn_chol_solve(e->ch, b, x);
    e->sum->t_solve += ctn_now() - t0;
    return rc;
}

void ctn_engine_axpy(const ctn_engine *e, double *d, double alpha, const double *v)
{
    for (size_t i = 0; i < e->n3; i++) {
        int q = e->a->eq[i];
        if (q >= 0) d[i] += alpha * v[q];
    }
}

/* Reactions and element states at d (fext at the step's reached t) into step k. */
void ctn_engine_fill_step(ctn_engine *e, ctn_solution *s, size_t k, const double *d)
{
    ctn_step_state *st = &s->steps[k];
    memcpy(st->d, d, e->n3 * sizeof(double));
    if (ctn_asm_eval(e->a, d, e->fint, NULL, NULL)) return;    /* collapsed: zeros stay */
    for (size_t i = 0; i < e->n3; i++) st->react[i] = e->a->eq[i] < 0 ? e->fint[i] - e->fext[i] : 0.0;
    for (size_t i = 0; i < e->a->ne; i++) {
        double X[CTN_EDOF], u[CTN_EDOF], f[CTN_EDOF];
        ctn_elem_state es;
        memset(&es, 0, sizeof es);
        ctn_asm_gather(e->a, i, d, X, u);
        e->a->ops->eval(&e->a->props[i], X, u, f, NULL, &es);
        st->elem[i].length = es.l;
        st->elem[i].strain = es.strain;
        st->elem[i].force = es.N;
        st->elem[i].stress = es.N / e->m->sections.v[e->m->elements.v[i].section].A;
        st->elem[i].slack = es.slack;
    }
}

