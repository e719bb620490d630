/* Element layer. For EVERY registered family (element/registry.c), through its ops table
 * and properties built by its own setup from a model:
 * - tangent against central finite differences of the internal force, random
 *   geometries and parameters (relative error < 1e-6);
 * - objectivity: a rigid rotation + translation leaves the axial force unchanged and
 *   rotates the nodal forces;
 * - energy gradient: dU/du = f (the energy is the potential of the internal forces);
 * - self-equilibrium: the nodal forces sum to zero.
 * Families with any node count (pulley) are sampled with three nodes. The catenary's
 * weight breaks objectivity; these samples have none (tests/test_catenary.c has it).
 * Families of 6 DOFs per node (rspring) are sampled with random rotations too; their
 * objectivity is that of the translations (the rigid motion moves the nodes, the
 * rotation DOFs stay: rspring is a small-rotation family), and their moments sum to
 * zero with the forces. A family of finite rotations (beam: CTN_ELEM_FINITE_ROTATION)
 * has its nodes' rotations composed with the rigid rotation too, its energy unchanged
 * and its moments (from the generalized forces of the rotation vectors) rotated and in
 * balance with its forces.
 * The beam's closed-form kernel against its energy on jets, and rigid motions of it
 * (test_beam_closed_form). Then the closed-form laws of each family: the cable's two
 * strain measures and tension-only slack, the spring's N = k (l - l0). */
#include "check.h"
#include "assemble/dofmap.h"
#include "element/beam3.h"
#include "element/cable2.h"
#include "element/spring2.h"

#include <stdlib.h>

#define MAXN 3                             /* nodes of a sample: 2, or 3 for node-count-free families */
#define MAXD (CTN_ELEM_MAX_DOF_NODE * MAXN)

static double urand(unsigned *seed, double lo, double hi)
{
    *seed = *seed * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*seed >> 8) & 0xffffff) / (double)0xffffff;
}

/* One element of family `type` between two random nodes, with random parameters; the
 * variant picks the strain measure and tension-only flag of a family with a section. */
typedef struct sample {
    ctn_ctx *ctx;
    ctn_model *m;
    const ctn_element_ops *ops;
    double props[32];   /* room for any family's properties (asserted) */
    int nn;             /* nodes: the family's count, 3 when it takes any (pulley) */
    double X[3 * MAXN];
    int spin[MAXN];     /* a finite-rotation family's node whose rotations are composed
                           (all free): its rotation variables are spins (beam3.h); else a
                           quarter of the time a plane model's node (rx, ry fixed), whose
                           are the rotation vector's components, added */
} sample;

/* A beam's material and section "mat", "sec" (random E, G, A, Iy, Iz, J; shear areas
 * half the time) and a random orientation. */
static int beam_section(ctn_model *m, unsigned *seed, double orient[3])
{
    ctn_material_spec ms;
    ctn_section_spec ss;
    ctn_material_spec_init(&ms);
    ctn_section_spec_init(&ss);
    ms.name = "mat";
    ms.E = urand(seed, 1e7, 1e9);
    ms.G = ms.E * urand(seed, 0.3, 0.5);
    ss.name = "sec";
    ss.material = "mat";
    ss.A = urand(seed, 1e-3, 1e-2);
    ss.Iy = ss.A * ss.A * urand(seed, 0.05, 2);
    ss.Iz = ss.A * ss.A * urand(seed, 0.05, 2);
    ss.J = ss.A * ss.A * urand(seed, 0.05, 1);
    if (urand(seed, 0, 1) < 0.5) ss.Asy = ss.Asz = 0.8 * ss.A;
    for (int k = 0; k < 3; k++) orient[k] = urand(seed, -1, 1);
    return ctn_model_add_material_spec(m, &ms) || ctn_model_add_section_spec(m, &ss);
}

/* A random displacement of the sample: translations in +-0.5, rotations in +-0.5, or
 * +-0.3 for a family of finite rotations (its local rotations then stay below 90 deg). */
static void random_u(const sample *s, unsigned *seed, double span, double *u)
{
    int ndn = s->ops->ndof_node;
    double r = s->ops->flags & CTN_ELEM_FINITE_ROTATION ? 0.3 : span;
    for (int k = 0; k < s->nn * ndn; k++) u[k] = k % ndn < 3 ? urand(seed, -span, span) : urand(seed, -r, r);
}

static int make_sample(sample *s, int type, int variant, unsigned *seed)
{
    const ctn_element_ops *ops = ctn_element_family(type);
    ctn_element_spec spec;
    int nodes[MAXN] = { 1, 2, 3 };
    memset(s, 0, sizeof *s);
    s->ops = ops;
    s->nn = ops->nnodes ? ops->nnodes : 3;
    CHECK(ops->props_size <= sizeof s->props && s->nn <= MAXN && (ops->ndof_node == 3 || ops->ndof_node == 6));
    for (int k = 0; k < 3 * s->nn; k++) s->X[k] = urand(seed, -10, 10);
    int rc = ctn_ctx_create(&s->ctx) || ctn_model_create(s->ctx, &s->m);
    for (int a = 0; a < s->nn; a++) {
        unsigned fix = (ops->flags & CTN_ELEM_FINITE_ROTATION) && urand(seed, 0, 1) < 0.25 ? CTN_FIX_RX | CTN_FIX_RY : 0;
        s->spin[a] = (ops->flags & CTN_ELEM_FINITE_ROTATION) && ctn_beam_spin_node(fix);
        rc = rc || ctn_model_add_node(s->m, a + 1, s->X + 3 * a, fix);
    }
    ctn_element_spec_init(&spec);
    if (!rc && (ops->flags & CTN_ELEM_SECTION) && ops->ndof_node == 6)
        rc = beam_section(s->m, seed, spec.orient);
    else if (!rc && (ops->flags & CTN_ELEM_SECTION))
        rc = ctn_model_add_material(s->m, "mat", urand(seed, 1e7, 1e9), (ctn_strain)(variant % 2), variant / 2 % 2) ||
             ctn_model_add_section(s->m, "sec", "mat", urand(seed, 1e-4, 1e-2), 0);
    spec.type = ops->name;
    spec.id = 1;
    spec.nnodes = s->nn;
    spec.nodes = nodes;
    spec.section = ops->flags & CTN_ELEM_SECTION ? "sec" : NULL;
    double chord = 0;
    for (int a = 0; a + 1 < s->nn; a++) chord += sqrt(pow(s->X[3 * a + 3] - s->X[3 * a], 2) + pow(s->X[3 * a + 4] - s->X[3 * a + 1], 2) +
                                                 pow(s->X[3 * a + 5] - s->X[3 * a + 2], 2));
    spec.release = (unsigned)variant >> 4;             /* beams: end releases (test_beam_releases) */
    spec.l0 = chord * urand(seed, 0.8, 1.2);
    spec.k = urand(seed, 1e3, 1e5);
    rc = rc || ctn_model_add_element_spec(s->m, &spec);
    CHECK_MSG(rc == 0, "family %s: %s", ops->name, s->ctx ? ctn_ctx_message(s->ctx) : "");
    if (rc) return 1;
    ops->setup(s->m, 0, s->props);
    return 0;
}

static void free_sample(sample *s)
{
    ctn_model_destroy(&s->m);
    ctn_ctx_destroy(&s->ctx);
}

/* The full symmetric n x n matrix from a packed upper triangle. */
static void unpack(int n, const double *P, double *K)
{
    for (int i = 0; i < n; i++)
        for (int j = i; j < n; j++) K[n * i + j] = K[n * j + i] = P[ctn_packed_index(n, i, j)];
}

/* out = u moved by h in variable j: added, or for a spin (s->spin) composed,
 * exp(psi) <- exp(h e) exp(psi). */
static void perturb(const sample *s, const double *u, int j, double h, double *out)
{
    int ndn = s->ops->ndof_node, n = s->nn * ndn, a = j / ndn, c = j % ndn;
    for (int k = 0; k < n; k++) out[k] = u[k];
    if (c < 3 || !s->spin[a]) {
        out[j] += h;
        return;
    }
    double dw[3] = { 0, 0, 0 };
    dw[c - 3] = h;
    ctn_rot_update_compose(out + ndn * a + 3, dw);
}

/* max |K - K_fd| / max |K| at displacements u. The forces of a spin node are the
 * gradient at the spin 0 of the current rotation, so their central difference along
 * spin e_c is K e_c + (e_c x m) / 2 in that node's rotation rows (m its moment: the
 * first-order term of the left Jacobian of exp, J^-T = I + [h e_c]x / 2), taken off. */
static double tangent_error(const sample *s, const double *u)
{
    int n = s->nn * s->ops->ndof_node;
    double f[MAXD], P[MAXD * (MAXD + 1) / 2], K[MAXD * MAXD], kmax = 0, emax = 0;
    int ndn = s->ops->ndof_node;
    s->ops->eval(s->props, 0, s->X, u, f, P, NULL);
    unpack(n, P, K);
    for (int j = 0; j < n; j++) {
        double up[MAXD], um[MAXD], fp[MAXD], fm[MAXD];
        double h = 1e-6 * (1.0 + (j % ndn < 3 ? fabs(s->X[3 * (j / ndn) + j % ndn]) : 0));
        perturb(s, u, j, h, up);
        perturb(s, u, j, -h, um);
        s->ops->eval(s->props, 0, s->X, up, fp, NULL, NULL);
        s->ops->eval(s->props, 0, s->X, um, fm, NULL, NULL);
        int a = j / ndn, c = j % ndn - 3;
        for (int i = 0; i < n; i++) {
            double fd = (fp[i] - fm[i]) / (2 * h);
            int r = i % ndn - 3;
            if (c >= 0 && s->spin[a] && i / ndn == a && r >= 0 && r != c)   /* (e_c x m)_r / 2 */
                fd -= 0.5 * ((c - r + 3) % 3 == 1 ? 1 : -1) * f[ndn * a + 3 + 3 - c - r];
            emax = fmax(emax, fabs(K[n * i + j] - fd));
            kmax = fmax(kmax, fabs(K[n * i + j]));
        }
    }
    return kmax > 0 ? emax / kmax : emax;
}

static void test_tangent_fd(int type)
{
    unsigned seed = 12345u + (unsigned)type;
    for (int trial = 0; trial < 400; trial++) {
        sample s;
        if (make_sample(&s, type, trial % 2, &seed)) return;   /* both strain measures */
        double u[MAXD];
        random_u(&s, &seed, 0.5, u);
        double err = tangent_error(&s, u);
        CHECK_MSG(err < 1e-6, "%s trial %d: relative tangent error %.3g", s.ops->name, trial, err);
        free_sample(&s);
    }
}

/* Rotation matrix about unit axis n by angle t (Rodrigues). */
static void rotation(const double n[3], double t, double R[9])
{
    double c = cos(t), s = sin(t), C = 1 - c;
    double x = n[0], y = n[1], z = n[2];
    double r[9] = { c + x * x * C, x * y * C - z * s, x * z * C + y * s,
                    y * x * C + z * s, c + y * y * C, y * z * C - x * s,
                    z * x * C - y * s, z * y * C + x * s, c + z * z * C };
    for (int i = 0; i < 9; i++) R[i] = r[i];
}

/* R = exp(psi) (Rodrigues). */
static void rot_exp(const double psi[3], double R[9])
{
    double t = sqrt(psi[0] * psi[0] + psi[1] * psi[1] + psi[2] * psi[2]), n[3] = { 1, 0, 0 };
    for (int k = 0; t > 0 && k < 3; k++) n[k] = psi[k] / t;
    rotation(n, t, R);
}

/* psi = log(R), rotation angle below pi. */
static void rot_log(const double R[9], double psi[3])
{
    double w[3] = { R[7] - R[5], R[2] - R[6], R[3] - R[1] }, s = 0.5 * sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    double t = atan2(s, 0.5 * (R[0] + R[4] + R[8] - 1));
    for (int k = 0; k < 3; k++) psi[k] = s > 0 ? 0.5 * w[k] * t / s : 0;
}

/* The moment m at a node of rotation vector psi from its generalized force fp (the
 * derivative of the energy in psi): fp = J^T m, J = I + (1 - cos t)/t^2 [psi] +
 * (t - sin t)/t^3 [psi]^2 the left Jacobian of exp. Solved by Cramer's rule. */
static void spatial_moment(const double psi[3], const double fp[3], double m[3])
{
    double t = sqrt(psi[0] * psi[0] + psi[1] * psi[1] + psi[2] * psi[2]);
    double a = t > 1e-8 ? (1 - cos(t)) / (t * t) : 0.5, b = t > 1e-8 ? (t - sin(t)) / (t * t * t) : 1.0 / 6;
    double P[9] = { 0, -psi[2], psi[1], psi[2], 0, -psi[0], -psi[1], psi[0], 0 }, J[9], A[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double p2 = 0;
            for (int k = 0; k < 3; k++) p2 += P[3 * i + k] * P[3 * k + j];
            J[3 * i + j] = (i == j) + a * P[3 * i + j] + b * p2;
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) A[3 * i + j] = J[3 * j + i];   /* J^T */
    double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) + A[2] * (A[3] * A[7] - A[4] * A[6]);
    for (int c = 0; c < 3; c++) {
        double B[9];
        memcpy(B, A, sizeof B);
        for (int i = 0; i < 3; i++) B[3 * i + c] = fp[i];
        m[c] = (B[0] * (B[4] * B[8] - B[5] * B[7]) - B[1] * (B[3] * B[8] - B[5] * B[6]) + B[2] * (B[3] * B[7] - B[4] * B[6])) / det;
    }
}

/* A family of finite rotations (beam) under the rigid motion: its nodes' rotations are
 * composed with R too; energy and axial force unchanged, the forces and the moments
 * (from the generalized forces of the rotation vectors) rotated, the moments in
 * balance with the forces about the origin. */
static void check_finite_rotation(const sample *s, const double R[9], double *u, double *ur, const double *f,
                                  const ctn_elem_state *s0)
{
    double fr[MAXD], Q[9], RQ[9], m[MAXN][3], mr[MAXN][3];
    ctn_elem_state s1;
    for (int a = 0; a < s->nn; a++) {
        rot_exp(u + 6 * a + 3, Q);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                RQ[3 * i + j] = R[3 * i] * Q[j] + R[3 * i + 1] * Q[3 + j] + R[3 * i + 2] * Q[6 + j];
        rot_log(RQ, ur + 6 * a + 3);
    }
    CHECK(s->ops->eval(s->props, 0, s->X, ur, fr, NULL, &s1) == 0);
    double scale = fabs(s0->N) + fabs(s0->energy) / s0->l + 1e-9 * s->ops->stiffness(s->props);
    CHECK_CLOSE(s1.N, s0->N, 1e-9, 1e-9 * s->ops->stiffness(s->props));
    CHECK_CLOSE(s1.energy, s0->energy, 1e-9, 1e-9 * scale * s0->l);
    double sum[6] = { 0 };
    for (int a = 0; a < s->nn; a++) {
        for (int i = 0; i < 3; i++) {                  /* a spin node's forces are moments */
            m[a][i] = f[6 * a + 3 + i];
            mr[a][i] = fr[6 * a + 3 + i];
        }
        if (!s->spin[a]) {
            spatial_moment(u + 6 * a + 3, f + 6 * a + 3, m[a]);
            spatial_moment(ur + 6 * a + 3, fr + 6 * a + 3, mr[a]);
        }
        for (int i = 0; i < 3; i++) {
            double rf = 0, rm = 0;
            for (int j = 0; j < 3; j++) {
                rf += R[3 * i + j] * f[6 * a + j];
                rm += R[3 * i + j] * m[a][j];
            }
            CHECK_CLOSE(fr[6 * a + i], rf, 1e-7, 1e-8 * scale);
            CHECK_CLOSE(mr[a][i], rm, 1e-7, 1e-8 * scale * s0->l);
            int p = (i + 1) % 3, q = (i + 2) % 3;
            sum[i] += f[6 * a + i];
            sum[3 + i] += m[a][i] + (s->X[3 * a + p] + u[6 * a + p]) * f[6 * a + q] - (s->X[3 * a + q] + u[6 * a + q]) * f[6 * a + p];
        }
    }
    for (int i = 0; i < 6; i++) CHECK_MSG(fabs(sum[i]) <= 1e-8 * scale * (i < 3 ? 1 : 10 * s0->l + 10), "balance %d: %g", i, sum[i]);
}

static void test_objectivity(int type)
{
    unsigned seed = 777u + (unsigned)type;
    for (int trial = 0; trial < 100; trial++) {
        sample s;
        if (make_sample(&s, type, trial % 2, &seed)) return;
        double u[MAXD], f[MAXD], ur[MAXD], fr[MAXD], R[9], n[3], t[3];
        int ndn = s.ops->ndof_node, nd = ndn * s.nn;
        for (int k = 0; k < nd; k++) u[k] = ur[k] = urand(&seed, -0.3, 0.3);
        for (int k = 0; k < 3; k++) { n[k] = urand(&seed, -1, 1); t[k] = urand(&seed, -100, 100); }
        double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; k++) n[k] /= nn;
        rotation(n, urand(&seed, -3, 3), R);
        ctn_elem_state s0, s1;
        s.ops->eval(s.props, 0, s.X, u, f, NULL, &s0);
        for (int a = 0; a < s.nn; a++)         /* x' = R x + t, as a displacement from X */
            for (int i = 0; i < 3; i++) {
                double xr = t[i];
                for (int j = 0; j < 3; j++) xr += R[3 * i + j] * (s.X[3 * a + j] + u[ndn * a + j]);
                ur[ndn * a + i] = xr - s.X[3 * a + i];
            }
        if (s.ops->flags & CTN_ELEM_FINITE_ROTATION) {
            check_finite_rotation(&s, R, u, ur, f, &s0);
            free_sample(&s);
            continue;
        }
        s.ops->eval(s.props, 0, s.X, ur, fr, NULL, &s1);
        CHECK_CLOSE(s1.N, s0.N, 1e-9, 1e-9 * s.ops->stiffness(s.props));
        for (int a = 0; a < s.nn; a++)
            for (int i = 0; i < 3; i++) {
                double rf = 0;
                for (int j = 0; j < 3; j++) rf += R[3 * i + j] * f[ndn * a + j];
                CHECK_CLOSE(fr[ndn * a + i], rf, 1e-8, 1e-9 * fabs(s0.N) + 1e-9 * s.ops->stiffness(s.props));
            }
        for (int i = 0; i < ndn; i++) {                 /* forces, and moments about the origin */
            double sum = 0;
            for (int a = 0; a < s.nn; a++) {
                sum += f[ndn * a + i];
                if (i < 3) continue;
                const double *x = s.X + 3 * a, *fa = f + ndn * a;
                int p = (i + 1) % 3, q = (i + 2) % 3;       /* (x cross f)_i, x the current position */
                sum += (x[p] + u[ndn * a + p]) * fa[q] - (x[q] + u[ndn * a + q]) * fa[p];
            }
            CHECK(fabs(sum) <= 1e-12 * (fabs(s0.N) + 1) * (i < 3 ? 1 : 100));
        }
        free_sample(&s);
    }
}

/* dU/du = f, central differences; tension-only variants included. */
static void test_energy_gradient(int type)
{
    unsigned seed = 4242u + (unsigned)type;
    for (int trial = 0; trial < 100; trial++) {
        sample s;
        if (make_sample(&s, type, trial % 4, &seed)) return;
        double u[MAXD], f[MAXD];
        int nd = s.ops->ndof_node * s.nn;
        ctn_elem_state st, sp, sm;
        random_u(&s, &seed, 0.5, u);
        s.ops->eval(s.props, 0, s.X, u, f, NULL, &st);
        for (int j = 0; j < nd; j++) {
            double up[MAXD], um[MAXD], fd[MAXD], h = 1e-6;
            perturb(&s, u, j, h, up);
            perturb(&s, u, j, -h, um);
            s.ops->eval(s.props, 0, s.X, up, fd, NULL, &sp);
            s.ops->eval(s.props, 0, s.X, um, fd, NULL, &sm);
            CHECK_CLOSE((sp.energy - sm.energy) / (2 * h), f[j], 1e-6, 1e-6 * fabs(st.N) + 1e-9);
        }
        free_sample(&s);
    }
}

/* Beams with end releases (every set of CTN_RELEASE_* bits but none, in turn, ten times
 * each): the tangent against central differences and the energy's gradient, in tension
 * and compression (l0 0.8 to 1.2 of the chord, as the other samples), and objectivity
 * under a rigid motion (check_finite_rotation). */
static void test_beam_releases(void)
{
    int type = ctn_element_family_find("beam");
    unsigned seed = 99u;
    for (int trial = 0; trial < 630; trial++) {
        sample s;
        unsigned rel = 1 + (unsigned)trial % 63;
        if (make_sample(&s, type, (int)(rel << 4), &seed)) return;
        double u[MAXD], f[MAXD], fp[MAXD], fm[MAXD];
        ctn_elem_state st, sp, sm;
        int tries = 0;
        do random_u(&s, &seed, 0.5, u);                /* a state the kinematics can form */
        while (s.ops->eval(s.props, 0, s.X, u, f, NULL, &st) && ++tries < 10);
        double err = tangent_error(&s, u);
        CHECK_MSG(err < 1e-6, "release %u trial %d: relative tangent error %.3g", rel, trial, err);
        CHECK(s.ops->eval(s.props, 0, s.X, u, f, NULL, &st) == 0);
        for (int j = 0; j < 12; j++) {
            double up[MAXD], um[MAXD], h = 1e-6;
            perturb(&s, u, j, h, up);
            perturb(&s, u, j, -h, um);
            s.ops->eval(s.props, 0, s.X, up, fp, NULL, &sp);
            s.ops->eval(s.props, 0, s.X, um, fm, NULL, &sm);
            CHECK_CLOSE((sp.energy - sm.energy) / (2 * h), f[j], 1e-6, 1e-6 * fabs(st.N) + 1e-9);
        }
        double ur[MAXD], R[9], n[3], t[3];                /* objectivity, as test_objectivity */
        for (int k = 0; k < 12; k++) u[k] = ur[k] = urand(&seed, -0.3, 0.3);
        for (int k = 0; k < 3; k++) { n[k] = urand(&seed, -1, 1); t[k] = urand(&seed, -100, 100); }
        double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; k++) n[k] /= nn;
        rotation(n, urand(&seed, -3, 3), R);
        if (s.ops->eval(s.props, 0, s.X, u, f, NULL, &st) == 0) {
            for (int a = 0; a < 2; a++)
                for (int i = 0; i < 3; i++) {
                    double xr = t[i];
                    for (int j = 0; j < 3; j++) xr += R[3 * i + j] * (s.X[3 * a + j] + u[6 * a + j]);
                    ur[6 * a + i] = xr - s.X[3 * a + i];
                }
            check_finite_rotation(&s, R, u, ur, f, &st);
        }
        free_sample(&s);
    }
}

/* The largest |a_i - b_i| over the largest |b_i|. */
static double rel_diff(int n, const double *a, const double *b)
{
    double d = 0, m = 0;
    for (int i = 0; i < n; i++) {
        d = fmax(d, fabs(a[i] - b[i]));
        m = fmax(m, fabs(b[i]));
    }
    return m > 0 ? d / m : d;
}

/* The beam's closed-form kernel (beam3_cf.c, taken when both nodes take spins) against
 * the energy on second-order jets (ctn_beam_eval_jet, the reference) at 500 random
 * states, a third of them with end releases: the same outcome, forces, tangent, energy
 * and axial force to round-off (1e-10), and at 250 of them the tangent against central
 * differences (tangent_error; test_tangent_fd samples the closed form too, wherever both
 * nodes take spins); and a stress-free member (L0 the chord) moved rigidly by any
 * rotation (up to pi about a random axis) and translation: no force, no moment. */
static void test_beam_closed_form(void)
{
    int type = ctn_element_family_find("beam"), done = 0;
    unsigned seed = 2026u;
    double worst[2] = { 0, 0 };
    for (int trial = 0; done < 500 && trial < 5000; trial++) {
        sample s;
        unsigned rel = trial % 3 ? 0 : 1 + (unsigned)trial % 63;
        if (make_sample(&s, type, (int)(rel << 4), &seed)) return;
        if (!s.spin[0] || !s.spin[1]) {
            free_sample(&s);
            continue;
        }
        const ctn_beam_props *p = (const ctn_beam_props *)s.props;
        double u[12], fc[12], fj[12], Kc[78], Kj[78];
        ctn_elem_state sc, sj;
        random_u(&s, &seed, 0.5, u);
        int rc = ctn_beam_eval_cf(p, CTN_EVAL_STRESS, s.X, u, fc, Kc, &sc);
        CHECK(rc == ctn_beam_eval_jet(p, CTN_EVAL_STRESS, s.X, u, fj, Kj, &sj));
        if (!rc) {
            done++;
            double ef = rel_diff(12, fc, fj), eK = rel_diff(78, Kc, Kj), err = done % 2 ? tangent_error(&s, u) : 0;
            CHECK_MSG(ef < 1e-10 && eK < 1e-10, "trial %d (release %u): forces %.3g, tangent %.3g off the jets'", trial,
                      rel, ef, eK);
            CHECK_MSG(err < 1e-6, "trial %d: relative tangent error %.3g", trial, err);   /* every other state */
            CHECK_CLOSE(sc.N, sj.N, 1e-10, 1e-10 * p->EA);
            CHECK_CLOSE(sc.energy, sj.energy, 1e-10, 1e-12 * p->EA * p->L0);
            CHECK_CLOSE(sc.l, sj.l, 1e-14, 0);
            CHECK_CLOSE(sc.stress, sc.N / p->A, 1e-14, 0);
            worst[0] = fmax(worst[0], ef);
            worst[1] = fmax(worst[1], eK);
        }
        ctn_beam_props q = *p;                          /* stress-free, moved rigidly */
        double R[9], n[3], fr[12], Kr[78], fbig = 0;
        for (int k = 0; k < 3; k++) n[k] = urand(&seed, -1, 1);
        double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), t = urand(&seed, -3.14159265358979323846, 3.14159265358979323846);
        q.L0 = sqrt(pow(s.X[3] - s.X[0], 2) + pow(s.X[4] - s.X[1], 2) + pow(s.X[5] - s.X[2], 2));
        for (int k = 0; k < 3; k++) n[k] /= nn;
        rotation(n, t, R);
        for (int a = 0; a < 2; a++)
            for (int i = 0; i < 3; i++) {
                u[6 * a + i] = 3.0 * (i + 1) - s.X[3 * a + i];
                for (int j = 0; j < 3; j++) u[6 * a + i] += R[3 * i + j] * s.X[3 * a + j];
                u[6 * a + 3 + i] = t * n[i];
            }
        CHECK(ctn_beam_eval_cf(&q, 0, s.X, u, fr, Kr, NULL) == 0);
        for (int k = 0; k < 12; k++) fbig = fmax(fbig, fabs(fr[k]));
        CHECK_MSG(fbig < 1e-13 * q.EA * fmax(1, q.L0), "trial %d: a rigid motion gives the force %.3g", trial, fbig);
        free_sample(&s);
    }
    CHECK(done == 500);
    printf("beam closed form against the jets, 500 states: forces %.3g, tangent %.3g (relative)\n", worst[0], worst[1]);
}

/* Cable: the axial laws of both strain measures against their closed forms. */
static void test_cable_laws(void)
{
    double X[6] = { 0, 0, 0, 3, 4, 0 };             /* reference length 5 */
    for (int k = 0; k < 4; k++) {
        double lam = 0.9 + 0.1 * k;                   /* 0.9 .. 1.2 */
        double u[6] = { 0, 0, 0, 3 * (lam - 1), 4 * (lam - 1), 0 }, f[6];
        ctn_cable_props gl = { 1000, 5, 2.0, CTN_STRAIN_GREEN_LAGRANGE, 0, 5, 0, 0 };
        ctn_cable_props en = { 1000, 5, 2.0, CTN_STRAIN_ENGINEERING, 0, 5, 0, 0 };
        ctn_elem_state s;
        ctn_cable2_ops.eval(&gl, CTN_EVAL_STRESS, X, u, f, NULL, &s);
        CHECK_CLOSE(s.l, 5 * lam, 1e-14, 0);
        CHECK_CLOSE(s.strain, (lam * lam - 1) / 2, 1e-12, 1e-15);
        CHECK_CLOSE(s.N, 1000 * (lam * lam - 1) / 2 * lam, 1e-12, 1e-12);
        CHECK_CLOSE(s.stress, s.N / 2.0, 1e-14, 1e-14);
        CHECK_CLOSE(f[3], s.N * 0.6, 1e-14, 1e-14);
        CHECK_CLOSE(f[1], -s.N * 0.8, 1e-14, 1e-14);
        ctn_cable2_ops.eval(&en, 0, X, u, f, NULL, &s);
        CHECK_CLOSE(s.strain, lam - 1, 1e-12, 1e-15);
        CHECK_CLOSE(s.N, 1000 * (lam - 1), 1e-12, 1e-12);
    }
}

static void test_cable_tension_only(void)
{
    double X[6] = { 0, 0, 0, 10, 0, 0 }, u[6] = { 0, 0, 0, -0.5, 0, 0 }, f[6], K[21];
    ctn_cable_props p = { 1000, 10, 1.0, CTN_STRAIN_GREEN_LAGRANGE, 1, 10, 0, 0 };
    ctn_elem_state s;
    ctn_cable2_ops.eval(&p, 0, X, u, f, K, &s);
    CHECK(s.slack == 1);
    CHECK(s.N == 0);
    double kmax = 0;
    for (int i = 0; i < 21; i++) kmax = fmax(kmax, fabs(K[i]));
    CHECK(kmax == 0);
    u[3] = 0.5;
    ctn_cable2_ops.eval(&p, 0, X, u, f, K, &s);
    CHECK(s.slack == 0 && s.N > 0);
    p.tension_only = 0;                                /* compression cut by the mode */
    u[3] = -0.5;
    ctn_cable2_ops.eval(&p, 0, X, u, f, K, &s);
    CHECK(s.N < 0 && !s.slack);
    ctn_cable2_ops.eval(&p, CTN_EVAL_CUT_COMPRESSION, X, u, f, K, &s);
    CHECK(s.N == 0 && s.slack);
    double u0[6] = { 1, 2, 3, 1, 2, 3 - 10 };      /* collapse: node 2 onto node 1 */
    double X0[6] = { 0, 0, 0, 0, 0, 10 };
    CHECK(ctn_cable2_ops.eval(&p, 0, X0, u0, f, K, &s) == 1);
}

/* Spring: N = k (l - l0) both ways, not cut by the relaxation mode, no stress. */
static void test_spring_law(void)
{
    double X[6] = { 1, 1, 1, 1, 4, 5 };              /* reference length 5 */
    ctn_spring_props p = { 250.0, 4.0 };
    for (int k = 0; k < 3; k++) {
        double lam = 0.6 + 0.4 * k, u[6] = { 0, 0, 0, 0, 3 * (lam - 1), 4 * (lam - 1) }, f[6];
        ctn_elem_state s;
        CHECK(ctn_spring2_ops.eval(&p, CTN_EVAL_CUT_COMPRESSION, X, u, f, NULL, &s) == 0);
        CHECK_CLOSE(s.l, 5 * lam, 1e-14, 0);
        CHECK_CLOSE(s.N, 250.0 * (5 * lam - 4.0), 1e-12, 1e-12);
        CHECK_CLOSE(s.energy, 0.5 * 250.0 * (5 * lam - 4.0) * (5 * lam - 4.0), 1e-12, 1e-12);
        CHECK_CLOSE(f[5], s.N * 0.8, 1e-14, 1e-12);
        CHECK(s.stress == 0 && !s.slack);
    }
}

int main(void)
{
    CHECK(ctn_element_family_count() >= 2);
    CHECK(ctn_element_family_find("cable") >= 0 && ctn_element_family_find("spring") >= 0);
    CHECK(ctn_element_family_find("beam") >= 0);
    for (int t = 0; t < ctn_element_family_count(); t++) {
        test_tangent_fd(t);
        test_objectivity(t);
        test_energy_gradient(t);
    }
    test_beam_releases();
    test_beam_closed_form();
    test_cable_laws();
    test_cable_tension_only();
    test_spring_law();
    CHECK_DONE();
}
