/* The junction start (CTN_METHOD_AUTO, once before the first step, before the other
 * pre-shaping of preshape.c).
 *
 * Meshed cables meeting at a free node (a Y or bridle junction, a guy cluster, a mooring
 * spread, a net of meshed strands) are given by the user as straight lines, or arcs, to a
 * guessed junction position. Every chain of `cable` elements is then shaped between its
 * anchors where they are, but the junction itself is where it was guessed: if that is
 * metres away from its equilibrium, Newton must move the junction by swinging whole
 * fine meshes, whose transverse stiffness is tiny and whose axial stiffness is huge,
 * through a strongly non-linear landscape, and it crawls or fails.
 *
 * So the free anchors are placed first, on a reduced model of the same structure: every
 * chain of two or more cable elements becomes one exact elastic catenary (Irvine; the
 * catenary element's law, element/catenary.h) with the chain's unstressed length, axial
 * rigidity and total weight; every other member is itself. Its unknowns are the free DOFs
 * of the anchors (junctions, free tips, and free chain nodes carrying a load of their
 * own, where a chain is split); its potential is convex for catenaries and tension-only
 * members, so damped Newton (a Levenberg-Marquardt shift, an Armijo backtracking on the
 * potential) finds its minimum from any start. The chains' interior nodes are then laid
 * on their catenaries. Only the start changes, never the equations: when the reduced
 * model does not converge, the start is left as it was. */
#include "element/catenary.h"
#include "linalg/lapack.h"
#include "problem/problem.h"

#include <math.h>
#include <string.h>

#define CTN_JUNCTION_MAX_UNKNOWNS 900   /* dense reduced tangent: at most 6.5 MB */
#define CTN_JUNCTION_MAXIT 200
#define CTN_JUNCTION_TOL 1e-10          /* |r| relative to the reduced loads */
#define CTN_JUNCTION_NEAR 1e-6          /* ... good enough for a start where Newton stalls */
#define CTN_JUNCTION_ARMIJO 1e-4
#define CTN_JUNCTION_HALVINGS 40
#define CTN_JUNCTION_FAR 1e3            /* model sizes: a motion without bound */

typedef struct member {
    const ctn_element_ops *ops;
    const void *props;          /* the element's, or cat below */
    ctn_catenary_props cat;     /* a chain of two or more cable elements */
    int a, b;                   /* node indices (ends of the chain) */
    size_t first, count;        /* the chain's entries in junction.chain_e / chain_n */
} member;

typedef struct junction {
    ctn_problem *e;
    int *deg, *start, *adj;     /* per node: cable elements, CSR of incident ones */
    unsigned char *other;       /* per node: reached by a member that is no cable element */
    unsigned char *anchor;      /* per node */
    int *unk;                   /* 3 per node: unknown index or -1 */
    double *F;                  /* 3 per node: reduced loads */
    int *chain_e, *chain_n;     /* chains' elements and interior nodes, concatenated */
    member *mem;
    size_t nmem, nchain;
    int nu;                     /* unknowns */
    double *K, *r, *dx, *dsave; /* nu x nu, nu, nu, ns */
    double *fmag;               /* nu: |member forces| summed per unknown, or NULL */
} junction;

static int is_cable(const ctn_problem *e, size_t el)
{
    const ctn_asm_block *b = ctn_asm_block_of(e->a, el);
    return (b->ops->flags & CTN_ELEM_FLEXIBLE) && b->nnodes == 2 && b->ops->ndof_node == 3;
}

static void node_x(const ctn_problem *e, const double *d, int node, double x[3])
{
    const double *dn = d + ctn_dofmap_node(&e->a->map, (size_t)node);
    for (int k = 0; k < 3; k++) x[k] = e->m->nodes.v[node].X[k] + dn[k];
}

/* Per node: cable elements (CSR), other members; 0 if a member is not a translation-only
 * two-node element (then there is no reduced model: the start stays). */
static int incidence(junction *j)
{
    const ctn_problem *e = j->e;
    size_t nn = e->a->nn, ne = e->a->ne;
    for (size_t i = 0; i < ne; i++) {
        const ctn_asm_block *b = ctn_asm_block_of(e->a, i);
        const int *nd = ctn_elem_nodes(e->m, i);
        if (b->nnodes != 2 || b->ops->ndof_node != 3) return 0;
        for (int k = 0; k < 2; k++) {
            if (is_cable(e, i)) j->deg[nd[k]]++;
            else j->other[nd[k]] = 1;
        }
    }
    for (size_t n = 0; n < nn; n++) j->start[n + 1] = j->start[n] + j->deg[n];
    memset(j->deg, 0, nn * sizeof(int));
    for (size_t i = 0; i < ne; i++) {
        if (!is_cable(e, i)) continue;
        const int *nd = ctn_elem_nodes(e->m, i);
        for (int k = 0; k < 2; k++) j->adj[j->start[nd[k]] + j->deg[nd[k]]++] = (int)i;
    }
    return 1;
}

/* Anchors: supported nodes, nodes that are not the joint of exactly two cable elements,
 * nodes reached by other members, and free nodes with a load of their own (more than the
 * weight of their elements: a clamp, a hanger), where the catenary of a chain would not
 * hold. The loads of the first step (dead loads) are in loads; the reduced loads F are
 * the loads less the elements' weights (added back per member). */
static void anchors(junction *j, const double *loads)
{
    const ctn_problem *e = j->e;
    const ctn_model *m = e->m;
    size_t nn = e->a->nn;
    double scale = 0;
    memcpy(j->F, loads, 3 * nn * sizeof(double));
    for (size_t i = 0; i < e->a->ne; i++) {
        const ctn_element_ops *ops = ctn_asm_block_of(e->a, i)->ops;
        if (!ops->load) continue;
        ops->load(m, i, j->r);          /* nodal scratch (3 nn, zero): see ctn_junction_place */
        const int *nd = ctn_elem_nodes(m, i);
        for (int a = 0; a < 2; a++)
            for (int k = 0; k < 3; k++) {
                size_t at = 3 * (size_t)nd[a] + (size_t)k;
                j->F[at] -= j->r[at];
                j->r[at] = 0;
            }
    }
    for (size_t k = 0; k < 3 * nn; k++) scale = fmax(scale, fabs(loads[k]));
    for (size_t n = 0; n < nn; n++) {
        const double *f = j->F + 3 * n;
        int own = fabs(f[0]) + fabs(f[1]) + fabs(f[2]) > 1e-9 * scale;
        j->anchor[n] = m->nodes.v[n].fix != 0 || j->deg[n] != 2 || j->other[n] || own;
    }
}

/* Walk the chain from anchor node a along cable element el0 to the next anchor; the
 * interior nodes and elements are appended to chain_n / chain_e. The far anchor, or -1
 * for a loop that never meets one. */
static int walk(junction *j, int a, int el0, size_t *count)
{
    const ctn_model *m = j->e->m;
    int cur = a, el = el0;
    *count = 0;
    for (;;) {
        const int *nd = ctn_elem_nodes(m, (size_t)el);
        int next = nd[0] == cur ? nd[1] : nd[0];
        j->chain_e[j->nchain + *count] = el;
        ++*count;
        if (j->anchor[next]) return next;
        if (*count > j->e->a->ne) return -1;
        j->chain_n[j->nchain + *count - 1] = next;
        const int *in = j->adj + j->start[next];
        el = in[0] == el ? in[1] : in[0];
        cur = next;
        if (el == el0) return -1;
    }
}

/* The catenary of a chain: its unstressed length (current rest lengths), the rigidity of
 * its first element's section, its total weight; its own weight goes half to each end. */
static void chain_catenary(junction *j, member *c)
{
    const ctn_problem *e = j->e;
    const ctn_model *m = e->m;
    double g = sqrt(m->gravity[0] * m->gravity[0] + m->gravity[1] * m->gravity[1] + m->gravity[2] * m->gravity[2]);
    double L = 0, w = 0;
    for (size_t k = 0; k < c->count; k++) {
        size_t el = (size_t)j->chain_e[c->first + k];
        const ctn_element *me = &m->elements.v[el];
        L += ctn_asm_block_of(e->a, el)->ops->rest_length(ctn_asm_props(e->a, el));
        w += m->sections.v[me->section].w * me->l0;
    }
    const ctn_section *s = &m->sections.v[m->elements.v[j->chain_e[c->first]].section];
    c->ops = &ctn_catenary2_ops;
    c->cat = (ctn_catenary_props){ .EA = m->materials.v[s->material].E * s->A, .l0 = L, .A = s->A, .W = w * g,
                                   .l0_ref = L };
    for (int k = 0; k < 3; k++) {
        c->cat.up[k] = c->cat.W > 0 ? -m->gravity[k] / g : 0;
        j->F[3 * (size_t)c->a + (size_t)k] += 0.5 * w * m->gravity[k];
        j->F[3 * (size_t)c->b + (size_t)k] += 0.5 * w * m->gravity[k];
    }
}

/* The reduced members: every chain of two or more cable elements with a free anchor as a
 * catenary, every other element itself (its own weight back at its nodes). */
static int members(junction *j)
{
    const ctn_problem *e = j->e;
    const ctn_model *m = e->m;
    unsigned char *done = (unsigned char *)j->dsave;      /* per element, scratch */
    memset(done, 0, e->a->ne);
    for (size_t n = 0; n < e->a->nn; n++) {
        if (!j->anchor[n]) continue;
        for (int q = j->start[n]; q < j->start[n + 1]; q++) {
            int el = j->adj[q];
            if (done[el]) continue;
            size_t count;
            int b = walk(j, (int)n, el, &count);
            if (b < 0) return 0;
            for (size_t k = 0; k < count; k++) done[j->chain_e[j->nchain + k]] = 1;
            member *c = &j->mem[j->nmem++];
            *c = (member){ .a = (int)n, .b = b, .first = j->nchain, .count = count };
            j->nchain += count;
            if (count == 1) {
                c->ops = ctn_asm_block_of(e->a, (size_t)el)->ops;
                c->props = ctn_asm_props(e->a, (size_t)el);
                c->ops->load(m, (size_t)el, j->F);
            } else {
                chain_catenary(j, c);
                c->props = &c->cat;
            }
        }
    }
    for (size_t i = 0; i < e->a->ne; i++) {
        if (is_cable(e, i)) continue;
        const int *nd = ctn_elem_nodes(m, i);
        member *c = &j->mem[j->nmem++];
        *c = (member){ .ops = ctn_asm_block_of(e->a, i)->ops, .props = ctn_asm_props(e->a, i), .a = nd[0], .b = nd[1] };
        if (c->ops->load) c->ops->load(m, i, j->F);
    }
    return 1;
}

/* The potential, the residual r = F - f_int on the unknowns and (K != NULL) the dense
 * tangent at d; 1 if a member collapsed or is not finite. */
static int evaluate(junction *j, const double *d, double *pi, double *K)
{
    const ctn_problem *e = j->e;
    const ctn_model *m = e->m;
    int nu = j->nu;
    double fe[6], Ke[21], X[6], u[6];
    ctn_elem_state st;
    *pi = 0;
    for (int i = 0; i < nu; i++) j->r[i] = 0;
    if (K) memset(K, 0, (size_t)nu * (size_t)nu * sizeof(double));
    for (size_t n = 0; n < e->a->nn; n++)
        for (int k = 0; k < 3; k++) {
            int q = j->unk[3 * n + (size_t)k];
            if (q < 0) continue;
            j->r[q] += j->F[3 * n + (size_t)k];
            *pi -= j->F[3 * n + (size_t)k] * d[ctn_dofmap_node(&e->a->map, n) + (size_t)k];
        }
    for (size_t c = 0; c < j->nmem; c++) {
        const member *mb = &j->mem[c];
        int nd[2] = { mb->a, mb->b };
        for (int a = 0; a < 2; a++)
            for (int k = 0; k < 3; k++) {
                X[3 * a + k] = m->nodes.v[nd[a]].X[k];
                u[3 * a + k] = d[ctn_dofmap_node(&e->a->map, (size_t)nd[a]) + (size_t)k];
            }
        if (mb->ops->eval(mb->props, 0, X, u, fe, K ? Ke : NULL, &st) || !isfinite(st.energy)) return 1;
        *pi += st.energy;
        for (int p = 0; p < 6; p++) {
            int qp = j->unk[3 * (size_t)nd[p / 3] + (size_t)(p % 3)];
            if (qp < 0) continue;
            j->r[qp] -= fe[p];
            if (j->fmag) j->fmag[qp] += fabs(fe[p]);
            if (!K) continue;
            for (int s = 0; s < 6; s++) {
                int qs = j->unk[3 * (size_t)nd[s / 3] + (size_t)(s % 3)];
                if (qs >= 0) K[(size_t)qs * (size_t)nu + (size_t)qp] += Ke[ctn_packed_index(6, p < s ? p : s, p < s ? s : p)];
            }
        }
    }
    for (int i = 0; i < nu; i++)
        if (!isfinite(j->r[i])) return 1;
    return !isfinite(*pi);
}

/* d (state) += alpha dx on the unknowns. */
static void move(const junction *j, double *d, double alpha)
{
    for (size_t n = 0; n < j->e->a->nn; n++)
        for (int k = 0; k < 3; k++) {
            int q = j->unk[3 * n + (size_t)k];
            if (q >= 0) d[ctn_dofmap_node(&j->e->a->map, n) + (size_t)k] += alpha * j->dx[q];
        }
}

/* (K + mu I) dx = r by LAPACK's Cholesky, mu raised until it is definite. 0 if none is. */
static int shifted_step(junction *j, double *mu, double maxdiag)
{
    int nu = j->nu, info = 1, one = 1;
    double *A = j->K + (size_t)nu * (size_t)nu;
    for (int tries = 0; tries < 60; tries++) {
        memcpy(A, j->K, (size_t)nu * (size_t)nu * sizeof(double));
        for (int i = 0; i < nu; i++) A[(size_t)i * (size_t)nu + (size_t)i] += *mu;
        dpotrf_("U", &nu, A, &nu, &info, 1);
        if (!info) break;
        *mu = *mu > 0 ? 4 * *mu : 1e-8 * maxdiag;
    }
    if (info) return 0;
    memcpy(j->dx, j->r, (size_t)nu * sizeof(double));
    dpotrs_("U", &nu, &one, A, &nu, j->dx, &nu, &info, 1);
    return !info;
}

/* Damped Newton on the reduced potential; 1 if it converged (d holds the anchors). */
static int solve_reduced(junction *j, double *d)
{
    int nu = j->nu;
    double pi, fscale = 0, mu = 0, maxdiag = 0;
    for (size_t n = 0; n < j->e->a->nn; n++)
        for (int k = 0; k < 3; k++)
            if (j->unk[3 * n + (size_t)k] >= 0) fscale += j->F[3 * n + (size_t)k] * j->F[3 * n + (size_t)k];
    if (!(fscale > 0)) return 0;
    j->fmag = j->dx;                                 /* the scale also counts the forces */
    memset(j->fmag, 0, (size_t)nu * sizeof(double)); /* that meet at the anchors */
    int bad = evaluate(j, d, &pi, j->K);
    j->fmag = NULL;
    fscale = sqrt(fscale) + ctn_vec_norm(j->dx, (size_t)nu);
    if (bad) return 0;
    int stalls = 0;
    for (int it = 0; it < CTN_JUNCTION_MAXIT; it++) {
        double slope = 0;
        if (ctn_vec_norm(j->r, (size_t)nu) <= CTN_JUNCTION_TOL * fscale) return 1;
        for (int i = 0; i < nu; i++) maxdiag = fmax(maxdiag, j->K[(size_t)i * (size_t)nu + (size_t)i]);
        if (!shifted_step(j, &mu, maxdiag)) break;
        for (int i = 0; i < nu; i++) slope += j->r[i] * j->dx[i];
        memcpy(j->dsave, d, j->e->ns * sizeof(double));
        double alpha = 1, pnew = pi;
        int h = 0;
        for (; h < CTN_JUNCTION_HALVINGS; h++, alpha *= 0.5) {
            memcpy(d, j->dsave, j->e->ns * sizeof(double));
            move(j, d, alpha);
            if (!evaluate(j, d, &pnew, NULL) && pnew <= pi - CTN_JUNCTION_ARMIJO * alpha * slope) break;
        }
        if (h == CTN_JUNCTION_HALVINGS) {                 /* no descent: back, more shift */
            memcpy(d, j->dsave, j->e->ns * sizeof(double));
            if (ctn_vec_norm(j->r, (size_t)nu) <= CTN_JUNCTION_NEAR * fscale || mu > 1e12 * maxdiag)
                break;                                    /* at round-off, or stuck */
            mu = mu > 0 ? 4 * mu : 1e-8 * maxdiag;
        } else if (!(pnew < pi) && ++stalls >= 3) {
            break;                                        /* steps at round-off */
        } else if (h == 0) {
            mu = mu < 1e-14 * maxdiag ? 0 : mu / 4;
        }
        if (evaluate(j, d, &pi, j->K)) return 0;
    }
    return ctn_vec_norm(j->r, (size_t)nu) <= CTN_JUNCTION_NEAR * fscale;
}

/* The discrete chain in equilibrium with end forces H (horizontal, along ex) and Va
 * (upward at end a): element k carries T_k = H ex - V_k up, V_k = Va - (W / L) s_k at its
 * mid-point s_k (the lumped weights of its nodes are then balanced exactly), stretched
 * to l0 (1 + |T_k| / EA). Marched from xa: its end in *end, its interior nodes written
 * into d when d != NULL. 0 if a member has no tension. */
static int march(const junction *j, const member *mb, double H, double Va, const double ex[3], const double xa[3],
                 double end[3], double *d)
{
    const ctn_problem *e = j->e;
    const ctn_catenary_props *cp = &mb->cat;
    double s = 0;
    for (int q = 0; q < 3; q++) end[q] = xa[q];
    for (size_t k = 0; k < mb->count; k++) {
        size_t el = (size_t)j->chain_e[mb->first + k];
        double l0 = ctn_asm_block_of(e->a, el)->ops->rest_length(ctn_asm_props(e->a, el));
        double V = Va - cp->W / cp->l0 * (s + 0.5 * l0), T[3], tn = 0;
        for (int q = 0; q < 3; q++) {
            T[q] = H * ex[q] - V * cp->up[q];
            tn += T[q] * T[q];
        }
        tn = sqrt(tn);
        if (!(tn > 0)) return 0;
        for (int q = 0; q < 3; q++) end[q] += l0 * (1 + tn / cp->EA) * T[q] / tn;
        s += l0;
        if (d && k + 1 < mb->count) {
            int node = j->chain_n[mb->first + k];
            double *dn = d + ctn_dofmap_node(&e->a->map, (size_t)node);
            for (int q = 0; q < 3; q++) dn[q] = end[q] - e->m->nodes.v[node].X[q];
        }
    }
    return 1;
}

/* The chain's nodes as the discrete chain (march) whose end forces make it end at xb:
 * from the catenary's, corrected by Newton steps with the catenary's flexibility (the
 * discrete chain differs from it by the mesh's discretization error). The members are
 * then stretched by their tension, where nodes on the curve itself would give chords
 * shorter than the arcs between them: compressed members on coarse or low-tension
 * chains. 0 if it does not close (a vertical or folded chain): the caller takes the
 * curve's points. */
static int shoot(const junction *j, const member *mb, const ctn_ecat *cat, const double ex[3], const double xa[3],
                 const double xb[3], double *d)
{
    double H = cat->H, Vb = cat->Vb, end[3];
    double det = cat->Fhh * cat->Fvv - cat->Fhv * cat->Fhv;
    if (!(cat->l > 0) || !isfinite(det) || !(det > 0)) return 0;
    for (int it = 0; it < 30; it++) {
        if (!march(j, mb, H, cat->W - Vb, ex, xa, end, NULL)) return 0;
        double dl = 0, dh = 0, miss = 0;
        for (int q = 0; q < 3; q++) {
            dl += (xb[q] - end[q]) * ex[q];
            dh += (xb[q] - end[q]) * mb->cat.up[q];
            miss += (xb[q] - end[q]) * (xb[q] - end[q]);
        }
        if (sqrt(miss) <= 1e-12 * mb->cat.l0) return march(j, mb, H, cat->W - Vb, ex, xa, end, d);
        H += (cat->Fvv * dl - cat->Fhv * dh) / det;
        Vb += (cat->Fhh * dh - cat->Fhv * dl) / det;
        if (!(H > 0)) return 0;
    }
    return 0;
}

/* Lay the interior nodes of each catenary chain by its catenary (shoot above). */
static void lay(junction *j, double *d)
{
    const ctn_problem *e = j->e;
    for (size_t c = 0; c < j->nmem; c++) {
        const member *mb = &j->mem[c];
        if (mb->count < 2) continue;
        double X[6], u[6], ex[3], xa[3], xb[3], s = 0;
        int bar;
        ctn_ecat cat;
        node_x(e, d, mb->a, xa);
        node_x(e, d, mb->b, xb);
        for (int k = 0; k < 3; k++) {
            X[k] = xa[k];
            X[3 + k] = xb[k];
            u[k] = u[3 + k] = 0;
        }
        if (ctn_catenary_state(&mb->cat, X, u, &cat, ex, &bar) || (!bar && shoot(j, mb, &cat, ex, xa, xb, d)))
            continue;
        for (size_t k = 0; k + 1 < mb->count; k++) {
            size_t el = (size_t)j->chain_e[mb->first + k];
            int node = j->chain_n[mb->first + k];
            s += ctn_asm_block_of(e->a, el)->ops->rest_length(ctn_asm_props(e->a, el));
            double x = 0, z = 0, P[3];
            if (!bar) ctn_ecat_point(&cat, s, &x, &z);
            for (int q = 0; q < 3; q++)
                P[q] = bar ? xa[q] + s / mb->cat.l0 * (xb[q] - xa[q]) : xa[q] + x * ex[q] + z * mb->cat.up[q];
            double *dn = d + ctn_dofmap_node(&e->a->map, (size_t)node);
            for (int q = 0; q < 3; q++) dn[q] = P[q] - e->m->nodes.v[node].X[q];
        }
    }
}

/* A junction: a free anchor where three or more members meet, one of them a chain of two
 * or more cable elements. Without one the model is left to preshape.c. meet: per node. */
static int has_junction(const junction *j, int *meet)
{
    const ctn_problem *e = j->e;
    for (size_t c = 0; c < j->nmem; c++) {
        meet[j->mem[c].a]++;
        meet[j->mem[c].b]++;
    }
    for (size_t c = 0; c < j->nmem; c++) {
        const member *mb = &j->mem[c];
        int ends[2] = { mb->a, mb->b };
        for (int a = 0; a < 2 && mb->count >= 2; a++) {
            size_t at = ctn_dofmap_node(&e->a->map, (size_t)ends[a]);
            int free = e->a->map.eq[at] >= 0 || e->a->map.eq[at + 1] >= 0 || e->a->map.eq[at + 2] >= 0;
            if (free && meet[ends[a]] >= 3) return 1;
        }
    }
    return 0;
}

/* Number the free DOFs of the members' nodes; 0 if there are too many. */
static int number(junction *j)
{
    const ctn_problem *e = j->e;
    j->nu = 0;
    for (size_t i = 0; i < 3 * e->a->nn; i++) j->unk[i] = -1;
    for (size_t c = 0; c < j->nmem; c++) {
        int ends[2] = { j->mem[c].a, j->mem[c].b };
        for (int a = 0; a < 2; a++)
            for (int k = 0; k < 3; k++) {
                size_t at = 3 * (size_t)ends[a] + (size_t)k;
                if (j->unk[at] < 0 && e->a->map.eq[ctn_dofmap_node(&e->a->map, (size_t)ends[a]) + (size_t)k] >= 0)
                    j->unk[at] = j->nu++;
            }
    }
    return j->nu > 0 && j->nu <= CTN_JUNCTION_MAX_UNKNOWNS;
}

/* The reduced model did not converge. If an anchor went further than CTN_JUNCTION_FAR
 * model sizes from its start, the potential fell without bound along a motion nothing
 * restrains (a load on a mechanism): no equilibrium exists, which the problem records
 * (e->mech_node, mech_dir) for the driver to report if the solve then fails. */
static void unbounded(const junction *j, const double *d, const double *dstart)
{
    ctn_problem *e = j->e;
    double far = 0;
    for (size_t n = 0; n < e->a->nn; n++)
        for (int k = 0; k < 3; k++) {
            size_t at = ctn_dofmap_node(&e->a->map, n) + (size_t)k;
            double moved = fabs(d[at] - dstart[at]);
            if (j->unk[3 * n + (size_t)k] < 0 || !(moved > far)) continue;
            far = moved;
            e->mech_node = (int)n;
            e->mech_dir = k;
        }
    if (!(far > CTN_JUNCTION_FAR * e->lref)) e->mech_node = e->mech_dir = -1;
}

/* In *any, 1 if some node joins three elements or more: without one no three members
 * meet, and there is no junction to place. */
static int some_node_of_three(const ctn_problem *e, int *any)
{
    size_t nn = e->a->nn, ne = e->a->ne;
    unsigned char *deg = ctn_calloc(e->ctx, nn ? nn : 1, 1);
    if (!deg) return CTN_ERR_NOMEM;
    *any = 0;
    for (size_t i = 0; i < ne && !*any; i++) {
        const int *nd = ctn_elem_nodes(e->m, i);
        for (int k = 0; k < e->m->elements.v[i].nnodes; k++) *any |= ++deg[nd[k]] >= 3;
    }
    ctn_free(deg);
    return CTN_OK;
}

int ctn_junction_place(ctn_problem *e, const double *loads, double *d, unsigned char *seen, int *placed)
{
    ctn_ctx *ctx = e->ctx;
    size_t nn = e->a->nn, ne = e->a->ne;
    int any = 0;
    *placed = 0;
    if (some_node_of_three(e, &any)) return CTN_ERR_NOMEM;
    if (!any) return CTN_OK;                   /* a chain, or chains apart: no junction */
    size_t nd = 3 * nn + 3 * nn + 1 + e->ns + ne + 1, nm = ne + 1;
    size_t ni = nn + nn + 1 + 2 * ne + 1 + 3 * nn + 2 * (ne + 1);
    junction j = { .e = e };
    /* one block (the solver runs this before every solve, target searches included) */
    unsigned char *block = ctn_calloc(ctx, nd * sizeof(double) + nm * sizeof(member) + ni * sizeof(int) + 2 * nn, 1);
    if (!block) return CTN_ERR_NOMEM;
    double *dp = (double *)(void *)block;
    j.F = dp, dp += 3 * nn;
    j.r = dp, dp += 3 * nn + 1;
    j.dsave = dp, dp += e->ns + ne + 1;
    j.mem = (member *)(void *)dp;
    int *ip = (int *)(void *)(j.mem + nm);
    j.deg = ip, ip += nn;
    j.start = ip, ip += nn + 1;
    j.adj = ip, ip += 2 * ne + 1;
    j.unk = ip, ip += 3 * nn;
    j.chain_e = ip, ip += ne + 1;
    j.chain_n = ip, ip += ne + 1;
    j.other = (unsigned char *)ip;
    j.anchor = j.other + nn;
    int rc = CTN_OK;
    if (incidence(&j)) {
        anchors(&j, loads);
        memset(j.deg, 0, nn * sizeof(int));               /* reused: members per node */
        if (members(&j) && has_junction(&j, j.deg) && number(&j)) {
            size_t nu = (size_t)j.nu;
            double *work = ctn_malloc(ctx, 2 * nu * nu + nu + e->ns, sizeof(double));
            if (!work) rc = CTN_ERR_NOMEM;
            else {
                double *dstart = work + 2 * nu * nu + nu;
                j.K = work;
                j.dx = work + 2 * nu * nu;
                memcpy(dstart, d, e->ns * sizeof(double));
                if (solve_reduced(&j, d)) {
                    lay(&j, d);
                    for (size_t c = 0; c < j.nmem; c++)
                        for (size_t k = 0; k < j.mem[c].count; k++) seen[j.chain_e[j.mem[c].first + k]] = 1;
                    *placed = 1;
                } else {
                    unbounded(&j, d, dstart);
                    memcpy(d, dstart, e->ns * sizeof(double));
                }
            }
            ctn_free(work);
        }
    }
    ctn_free(block);
    return rc;
}
