/* The beam family's model side (beam3.c has the kernel): the checks of a definition,
 * the orientation kept in the element record, the properties, self-weight and mass.
 * The orient= vector is kept as its direction, two angles in par[] (azimuth, polar;
 * polar -1: the default orientation), and its end releases in par[2]. */
#include "element/beam3.h"

#include <math.h>
#include <string.h>

static void beam_params(const ctn_element_spec *s, double *par)
{
    const double *v = s->orient;
    double n = hypot(hypot(v[0], v[1]), v[2]);
    par[0] = n > 0 ? atan2(v[1], v[0]) : 0;
    par[1] = n > 0 ? acos(fmax(-1, fmin(1, v[2] / n))) : -1;
    par[2] = s->release;
}

/* The member's unit axis e1 and the orientation vector v of element e. */
static void axis_orient(const ctn_model *m, const ctn_element *e, double e1[3], double v[3])
{
    const int *nd = m->conn.v + e->conn;
    const double *X1 = m->nodes.v[nd[0]].X, *X2 = m->nodes.v[nd[1]].X;
    double L = 0;
    for (int k = 0; k < 3; k++) {
        e1[k] = X2[k] - X1[k];
        L += e1[k] * e1[k];
    }
    for (int k = 0; k < 3; k++) e1[k] /= sqrt(L);
    if (e->par[1] >= 0) {
        v[0] = sin(e->par[1]) * cos(e->par[0]);
        v[1] = sin(e->par[1]) * sin(e->par[0]);
        v[2] = cos(e->par[1]);
        for (int k = 0; k < 3; k++) v[k] = fabs(v[k]) < 1e-15 ? 0 : v[k];   /* the direction given */
    } else {                                           /* global z; global x if vertical */
        int vertical = hypot(e1[0], e1[1]) < 1e-6;
        v[0] = vertical;
        v[1] = 0;
        v[2] = !vertical;
    }
}

/* |a x b| for unit vectors: the sine of their angle. */
static double sine(const double a[3], const double b[3])
{
    double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
    return hypot(hypot(c[0], c[1]), c[2]);
}

static int beam_check(const ctn_model *m, const ctn_element *e)
{
    const ctn_section *s = &m->sections.v[e->section];
    const ctn_material *mat = &m->materials.v[s->material];
    double e1[3], v[3];
    if (!(s->Iy > 0 && s->Iz > 0 && s->J > 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "beam %d: section '%s' has no bending properties (Iy=%g, Iz=%g, J=%g: "
                               "each must be positive)", e->id, s->name, s->Iy, s->Iz, s->J);
    if (!(mat->G > 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "beam %d: material '%s' has no shear modulus (give G= or nu=)", e->id,
                               mat->name);
    if (mat->fy > 0 && !(s->Wy > 0 && s->Wz > 0))
        return ctn_model_error(m, CTN_ERR_MODEL, "beam %d: material '%s' has fy= but section '%s' no section moduli "
                               "(Wy=%g, Wz=%g): give Wy= and Wz=, or the section by its shape", e->id, mat->name, s->name,
                               s->Wy, s->Wz);
    if (!(e->l0 > 0) || !isfinite(e->l0))
        return ctn_model_error(m, CTN_ERR_MODEL, "beam %d: length must be positive and finite (got %g)", e->id, e->l0);
    if (!(e->par[2] >= 0 && e->par[2] < 64))
        return ctn_model_error(m, CTN_ERR_MODEL, "beam %d: release must be a set of CTN_RELEASE_* bits (got %g)", e->id,
                               e->par[2]);
    axis_orient(m, e, e1, v);
    if (sine(e1, v) < 1e-6)
        return ctn_model_error(m, CTN_ERR_MODEL, "beam %d: orient (direction %g, %g, %g) is parallel to the member: it must "
                               "point across it, in the local x-z plane", e->id, v[0], v[1], v[2]);
    return CTN_OK;
}

/* Bending energy coefficients c0, c1 of EI over L with the shear parameter phi. */
static void bending(double EI, double L, double phi, double *c0, double *c1)
{
    double k = EI / (L * (1 + phi));
    *c0 = 0.5 * k * (4 + phi);
    *c1 = k * (2 - phi);
}

static void beam_setup(const ctn_model *m, size_t e, void *props)
{
    const ctn_element *el = &m->elements.v[e];
    const ctn_section *s = &m->sections.v[el->section];
    const ctn_material *mat = &m->materials.v[s->material];
    ctn_beam_props *p = props;
    double e1[3], v[3], L = el->l0, E = mat->E, G = mat->G, d = 0, n = 0;
    memset(p, 0, sizeof *p);
    axis_orient(m, el, e1, v);
    for (int k = 0; k < 3; k++) d += v[k] * e1[k];
    for (int k = 0; k < 3; k++) {
        p->e3[k] = v[k] - d * e1[k];
        n += p->e3[k] * p->e3[k];
    }
    for (int k = 0; k < 3; k++) p->e3[k] /= sqrt(n);
    for (int k = 0; k < 3; k++) p->e2[k] = p->e3[(k + 1) % 3] * e1[(k + 2) % 3] - p->e3[(k + 2) % 3] * e1[(k + 1) % 3];
    double phiy = s->Asz > 0 ? 12 * E * s->Iy / (G * s->Asz * L * L) : 0;
    double phiz = s->Asy > 0 ? 12 * E * s->Iz / (G * s->Asy * L * L) : 0;
    p->L0 = L;
    p->A = s->A;
    p->EA = E * s->A;
    bending(E * s->Iy, L, phiy, &p->cy0, &p->cy1);
    bending(E * s->Iz, L, phiz, &p->cz0, &p->cz1);
    p->rel = (unsigned)el->par[2];
    const int *nd = ctn_elem_nodes(m, e);
    for (int a = 0; a < 2; a++) p->spin |= (unsigned)ctn_beam_spin_node(m->nodes.v[nd[a]].fix) << a;
    p->kt = p->rel & (CTN_RELEASE_RX1 | CTN_RELEASE_RX2) ? 0 : G * s->J / L;
    p->rhoA = ctn_model_section_mass(m, el->section);
    p->rhoJ = p->rhoA > 0 ? p->rhoA * (s->Iy + s->Iz) / s->A : 0;
    p->rhoIy = p->rhoA > 0 ? p->rhoA * s->Iy / s->A : 0;
    p->rhoIz = p->rhoA > 0 ? p->rhoA * s->Iz / s->A : 0;
}

/* Mass (modal analysis): the translations' rhoA L0 and the rotations' rotary inertia
 * (rho (Iy + Iz) about the member, rho Iy and rho Iz about its local y and z, per length,
 * as a tensor in global axes) shared between the nodes by linear interpolation
 * (consistent: L0/3 at a node, L0/6 between them) or half at each node (lumped). The
 * bending's Hermite mass is not taken: the translations are interpolated as the cable's,
 * so the modes converge at O(h^2), from above (consistent) or below (lumped). */
static void beam_mass(const void *props, const double *X, int lumped, double *M)
{
    const ctn_beam_props *p = props;
    (void)X;
    const double *e2 = p->e2, *e3 = p->e3;
    const double e1[3] = { e2[1] * e3[2] - e2[2] * e3[1], e2[2] * e3[0] - e2[0] * e3[2], e2[0] * e3[1] - e2[1] * e3[0] };
    double d = lumped ? 0.5 : 1.0 / 3, o = lumped ? 0.0 : 1.0 / 6, J[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            J[i][j] = p->L0 * (p->rhoJ * e1[i] * e1[j] + p->rhoIy * e2[i] * e2[j] + p->rhoIz * e3[i] * e3[j]);
    for (int t = 0; t < 78; t++) M[t] = 0.0;
    double m = p->rhoA * p->L0;
    for (int a = 0; a < 2; a++)
        for (int b = a; b < 2; b++) {
            double w = a == b ? d : o;
            for (int i = 0; i < 3; i++) {
                M[ctn_packed_index(12, 6 * a + i, 6 * b + i)] = w * m;
                for (int j = 0; j < 3; j++)
                    if (a < b || j >= i) M[ctn_packed_index(12, 6 * a + 3 + i, 6 * b + 3 + j)] = w * J[i][j];
            }
        }
}


static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* A hinge at end a about the local axis ek (a unit vector) takes no load moment: the
 * moment Mr = M[a] . ek it would take goes, by the condensation of the linear bending
 * energy c0 (t1^2 + t2^2) + c1 t1 t2 (t = theta - psi, psi the chord's rotation about
 * ek), rho = c1 / (2 c0) of it against the other end (unless released too) and
 * (1 + rho) Mr onto psi, i.e. the forces -+(1 + rho) Mr (ek x e1) / L at the nodes (a
 * propped cantilever: q L^2 / 8 at the clamp, shears 3 q L / 8 and 5 q L / 8). */
static void release_load(int a, int other, double rho, const double ek[3], const double e1[3], double L,
                         double F[2][3], double M[2][3])
{
    double Mr = M[a][0] * ek[0] + M[a][1] * ek[1] + M[a][2] * ek[2], n[3];
    double Q = other ? Mr : (1 + rho) * Mr;
    cross(ek, e1, n);
    for (int k = 0; k < 3; k++) {
        M[a][k] -= Mr * ek[k];
        if (!other) M[1 - a][k] -= rho * Mr * ek[k];
        F[0][k] -= Q * n[k] / L;
        F[1][k] += Q * n[k] / L;
    }
}

void ctn_beam_line_loads(const ctn_model *m, size_t e, const double q[3], double F[2][3], double M[2][3])
{
    const ctn_element *el = &m->elements.v[e];
    ctn_beam_props p;
    double e1[3], v[3], c[3], L = el->l0;
    axis_orient(m, el, e1, v);
    cross(e1, q, c);
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) {
            F[a][k] = 0.5 * L * q[k];
            M[a][k] = (a ? -1 : 1) * L * L / 12 * c[k];
        }
    unsigned rel = (unsigned)el->par[2];
    if (!(rel & CTN_BEAM_REL_BEND)) return;
    beam_setup(m, e, &p);
    for (int k = 1; k < 3; k++) {
        const double *ek = k == 1 ? p.e2 : p.e3;
        double rho = k == 1 ? p.cy1 / (2 * p.cy0) : p.cz1 / (2 * p.cz0);
        int r[2] = { (rel >> k) & 1, (rel >> (3 + k)) & 1 };
        for (int a = 0; a < 2; a++)
            if (r[a]) release_load(a, r[1 - a], rho, ek, e1, L, F, M);
    }
}

/* A uniform load q per unstressed length in a fixed global direction (lineload, weight):
 * the beam's consistent nodal loads on the reference chord (ctn_beam_line_loads; fixed,
 * like the load: conservative, so the tangent and the energy need no load term). */
static void beam_line_load(const ctn_model *m, size_t e, const double q[3], double *f, double *M)
{
    const int *nd = ctn_elem_nodes(m, e);
    double Fe[2][3], Me[2][3];
    ctn_beam_line_loads(m, e, q, Fe, Me);
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < 3; k++) {
            size_t i = 3 * (size_t)nd[a] + (size_t)k;
            if (f) f[i] += Fe[a][k];
            if (M) M[i] += Me[a][k];
        }
}

/* Self-weight: the uniform load w g, its forces (the moments: ctn_model_add_line_moments). */
static void beam_load(const ctn_model *m, size_t e, double *f)
{
    double w = m->sections.v[m->elements.v[e].section].w;
    const double q[3] = { w * m->gravity[0], w * m->gravity[1], w * m->gravity[2] };
    if (w > 0) beam_line_load(m, e, q, f, NULL);
}

static double beam_stiffness(const void *props)
{
    const ctn_beam_props *p = props;
    return p->EA / p->L0;
}

/* A turn db of the chord (an error eps (|u_a| + |u_b| + 2 L) / L) moves both local end
 * rotations by db: end moments dU/dt = (2 c0 + c1) db about each axis, shears twice
 * that over L; 2 c0 + c1 = 6 E I / L for Euler-Bernoulli, so 12 E I / L^3 per unit of
 * chord error. */
static double beam_round_stiffness(const void *props)
{
    const ctn_beam_props *p = props;
    double b = fmax(2 * p->cy0 + p->cy1, 2 * p->cz0 + p->cz1) * 2 / (p->L0 * p->L0);
    return fmax(p->EA / p->L0, b);
}

const ctn_element_ops ctn_beam3_ops = {
    .name = "beam", .nnodes = 2, .ndof_node = 6, .props_size = sizeof(ctn_beam_props),
    .flags = CTN_ELEM_SECTION | CTN_ELEM_FINITE_ROTATION,
    .check = beam_check, .params = beam_params, .setup = beam_setup, .eval = ctn_beam_eval, .load = beam_load,
    .stiffness = beam_stiffness, .mass = beam_mass, .line_load = beam_line_load,
    .round_stiffness = beam_round_stiffness,
};
