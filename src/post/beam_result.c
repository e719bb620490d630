/* A beam's end forces rebuilt from a step's displacements and rotations (the public
 * accessor ctn_solution_beam, for the writers). Under a uniform load q per unstressed
 * length (its weight, lineloads) the member's end forces are the kernel's less the
 * consistent nodal loads its nodes took for it (the fixed-end actions), in the current
 * local axes; its bending moment along the chord is then the parabola through them. */
#include "element/beam3.h"
#include "problem/solution.h"

#include <math.h>
#include <string.h>

/* The uniform load on element i at step k (global axes): the step's selection (or the
 * case's) at the load fraction the step reached, from the previous step's. */
static int step_line(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, double q[3])
{
    if (s->of_case) {
        int tags[CTN_MAX_CASE_TERMS];
        double f[CTN_MAX_CASE_TERMS];
        ctn_loadsel sel;
        if (ctn_model_case_terms(m, s->of_case - 1) > CTN_MAX_CASE_TERMS) return CTN_ERR_INVALID;
        ctn_model_case_sel(m, s->of_case - 1, &sel, tags, f);
        ctn_model_element_line(m, &sel, i, q);
        return CTN_OK;
    }
    ctn_loadsel sel = ctn_loadsel_step(k);
    double t = s->steps[k].t, q0[3] = { 0, 0, 0 };
    ctn_model_element_line(m, &sel, i, q);
    if (t == 1) return CTN_OK;
    if (k > 0) {
        ctn_loadsel prev = ctn_loadsel_step(k - 1);
        ctn_model_element_line(m, &prev, i, q0);
    }
    for (int j = 0; j < 3; j++) q[j] = q0[j] + t * (q[j] - q0[j]);
    return CTN_OK;
}

/* f (12, local) less the consistent nodal loads of q on element i (ctn_beam_line_loads:
 * q L0 / 2, +-(L0^2 / 12) e1 x q, a hinge's share moved) in the current local axes R;
 * ql gets q in them. */
static void less_fixed_end(const ctn_model *m, size_t e, const double q[3], const double R[3][3], double *f,
                           double ql[3])
{
    double F[2][3], M[2][3];
    ctn_beam_line_loads(m, e, q, F, M);
    for (int i = 0; i < 3; i++) {
        ql[i] = 0;
        for (int j = 0; j < 3; j++) {
            ql[i] += R[i][j] * q[j];
            for (int a = 0; a < 2; a++) {
                f[6 * a + i] -= R[i][j] * F[a][j];
                f[6 * a + 3 + i] -= R[i][j] * M[a][j];
            }
        }
    }
}

/* The bending moment |M(x)| at x along the chord of length l from the end forces f at
 * node 1 and the load w (local, per unit current length): the part [0, x] in balance,
 * My(x) = -(My1 + x Fz1 + wz x^2 / 2), Mz(x) = -(Mz1 - x Fy1 - wy x^2 / 2). */
static double moment_at(const double *f, const double w[3], double x)
{
    double My = -(f[4] + x * f[2] + 0.5 * w[2] * x * x), Mz = -(f[5] - x * f[1] - 0.5 * w[1] * x * x);
    return hypot(My, Mz);
}

/* The combined stress |N| / A + |My| / Wy + |Mz| / Wz at x (c: 1 / A, 1 / Wy, 1 / Wz),
 * N linear between the ends' (-f[0] at node 1, f[6] at node 2). */
static double stress_at(const double *f, const double w[3], double l, const double c[3], double x)
{
    double My = -(f[4] + x * f[2] + 0.5 * w[2] * x * x), Mz = -(f[5] - x * f[1] - 0.5 * w[1] * x * x);
    double N = -f[0] + (f[6] + f[0]) * x / l;
    return c[0] * fabs(N) + c[1] * fabs(My) + c[2] * fabs(Mz);
}

/* The largest |M| over the chord, and of the combined stress when c is given: the ends,
 * each component's vertex, and 64 points between (exact for a load in one plane, the
 * vertex; else to the sampling: a parabola's share of q l^2 / 8 between samples, 1e-4 of
 * it at most). */
static double moment_max(const double *f, const double w[3], double l, const double *c, double *smax)
{
    double M = fmax(hypot(f[4], f[5]), hypot(f[10], f[11]));
    if (c) *smax = fmax(stress_at(f, w, l, c, 0), stress_at(f, w, l, c, l));
    if (w[1] == 0 && w[2] == 0) return M;
    const double xv[2] = { w[2] != 0 ? -f[2] / w[2] : -1, w[1] != 0 ? f[1] / w[1] : -1 };
    for (int a = 0; a < 2; a++)
        if (xv[a] > 0 && xv[a] < l) {
            M = fmax(M, moment_at(f, w, xv[a]));
            if (c) *smax = fmax(*smax, stress_at(f, w, l, c, xv[a]));
        }
    for (int k = 1; k < 64; k++) {
        M = fmax(M, moment_at(f, w, l * k / 64));
        if (c) *smax = fmax(*smax, stress_at(f, w, l, c, l * k / 64));
    }
    return M;
}

int ctn_solution_beam(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, ctn_beam_result *out)
{
    ctn_beam_props p;
    double X[6], u[12], f[12], R[3][3], q[3], ql[3] = { 0, 0, 0 }, w[3] = { 0, 0, 0 };
    if (!out || out->size < sizeof *out || !m || !s || k >= s->nsteps || i >= m->elements.n || i >= s->ne ||
        m->nodes.n != s->nn || ctn_element_family(m->elements.v[i].type) != &ctn_beam3_ops || !s->steps[k].rot)
        return CTN_ERR_INVALID;
    const int *nd = ctn_elem_nodes(m, i);
    for (int a = 0; a < 2; a++)
        for (int j = 0; j < 3; j++) {
            X[3 * a + j] = m->nodes.v[nd[a]].X[j];
            u[6 * a + j] = s->steps[k].d[3 * (size_t)nd[a] + (size_t)j];
            u[6 * a + 3 + j] = s->steps[k].rot[3 * (size_t)nd[a] + (size_t)j];
        }
    ctn_beam3_ops.setup(m, i, &p);
    if (step_line(m, s, k, i, q)) return CTN_ERR_INVALID;
    if (ctn_beam_end_forces(&p, X, u, f, R)) return CTN_ERR_NOCONV;
    double l = 0;
    for (int j = 0; j < 3; j++) l += pow((X[3 + j] + u[6 + j]) - (X[j] + u[j]), 2);
    l = sqrt(l);
    if (q[0] != 0 || q[1] != 0 || q[2] != 0) {
        less_fixed_end(m, i, q, R, f, ql);
        for (int j = 0; j < 3; j++) w[j] = ql[j] * p.L0 / l;   /* per unit current length */
    }
    memset(out, 0, sizeof *out);
    out->size = sizeof *out;
    for (int j = 0; j < 12; j++) f[j] += 0.0;          /* no negative zeros */
    memcpy(out->end[0], f, 6 * sizeof *f);
    memcpy(out->end[1], f + 6, 6 * sizeof *f);
    out->N = f[6];
    out->T = f[9];
    const ctn_section *sec = &m->sections.v[m->elements.v[i].section];
    const double c[3] = { 1 / sec->A, sec->Wy > 0 ? 1 / sec->Wy : 0, sec->Wz > 0 ? 1 / sec->Wz : 0 };
    int moduli = sec->Wy > 0 && sec->Wz > 0;
    out->M_max = moment_max(f, w, l, moduli ? c : NULL, &out->stress);
    out->fy = m->materials.v[sec->material].fy;
    out->utilisation = out->fy > 0 && moduli ? out->stress / out->fy : 0;
    return CTN_OK;
}

int ctn_solution_worst_beam(const ctn_model *m, const ctn_solution *s, size_t k, size_t *e, ctn_beam_result *out)
{
    if (!m || !s || !e || !out || out->size < sizeof *out) return CTN_ERR_INVALID;
    int found = 0;
    for (size_t i = 0; i < m->elements.n; i++) {
        ctn_beam_result b = { .size = sizeof b };
        if (ctn_element_family(m->elements.v[i].type) != &ctn_beam3_ops ||
            !(m->materials.v[m->sections.v[m->elements.v[i].section].material].fy > 0) ||
            ctn_solution_beam(m, s, k, i, &b))
            continue;
        if (!found || b.utilisation > out->utilisation) {
            *out = b;
            *e = i;
            found = 1;
        }
    }
    return found ? CTN_OK : CTN_ERR_INVALID;
}
