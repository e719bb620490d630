/* Pre-shaping of slack chains (CTN_METHOD_AUTO, once before the first step; and at the
 * start of a later step or a load case, ctn_preshape_step at the end of this file).
 * A chain is a run of free nodes with exactly two elements each, between two anchor
 * nodes (supported, or joining more than two elements). A chain whose start polyline is
 * shorter than its unstressed length (a cable given straight, or as its unstressed
 * arc) has compressed or unstressed members, and Newton from there either meets an
 * indefinite tangent or wanders. Such a chain is placed as the paper places a cable:
 * on the circular arc through its anchors, sagging along gravity, that is longer than the
 * chain so that every member is stretched by CTN_PRESHAPE_STRAIN (the start `cable`
 * gives a generated cable). This changes only the start, not the equations. */
#include "model/arc.h"
#include "model/cable_start.h"
#include "problem/problem.h"
#include "start/hang.h"

#include <math.h>
#include <string.h>

#define CTN_PRESHAPE_STRAIN 1e-3

typedef struct chains {
    int *deg, *inc;      /* per node: element count, first two incident elements */
    int *nodes, *elems;  /* one chain: anchor, interior..., anchor; its elements */
    unsigned char *seen; /* per element */
} chains;

/* A chain's interior node: two flexible members, free or held in some directions only
 * (a plane model's nodes held out of its plane); every placement below keeps such a node
 * where its supports hold it, or leaves the chain as it is (admits). */
static int interior(const ctn_problem *e, const chains *c, int node)
{
    return c->deg[node] == 2 && (e->m->nodes.v[node].fix & 7u) != 7u;
}

/* A placement that moves node to displacement dn keeps it where its supports hold it. */
static int admits(const ctn_problem *e, int node, const double *dn, double S)
{
    unsigned fix = e->m->nodes.v[node].fix;
    for (int k = 0; k < 3; k++)
        if ((fix & (1u << k)) && !(fabs(dn[k]) <= 1e-12 * S)) return 0;
    return 1;
}

static void current(const ctn_problem *e, const double *d, int node, double x[3])
{
    const double *dn = d + ctn_dofmap_node(&e->a->map, (size_t)node);
    for (int k = 0; k < 3; k++) x[k] = e->m->nodes.v[node].X[k] + dn[k];
}

static double rest_length(const ctn_problem *e, int el)
{
    return ctn_asm_block_of(e->a, (size_t)el)->ops->rest_length(ctn_asm_props(e->a, (size_t)el));
}

/* The node of two-node element el that is not node. */
static int other_end(const ctn_model *m, int el, int node)
{
    const int *nd = ctn_elem_nodes(m, (size_t)el);
    return nd[0] == node ? nd[1] : nd[0];
}

/* Collect the chain through element e0 into c->nodes / c->elems; node count. */
static size_t walk(const ctn_problem *e, chains *c, int e0)
{
    const ctn_model *m = e->m;
    int head = ctn_elem_nodes(m, (size_t)e0)[0], eh = e0;
    while (interior(e, c, head)) {                    /* back up to the first anchor */
        int nxt = c->inc[2 * head] == eh ? c->inc[2 * head + 1] : c->inc[2 * head];
        if (nxt == e0) return 0;                      /* a closed loop: no anchors */
        eh = nxt;
        head = other_end(m, eh, head);
    }
    size_t n = 0;
    int cur = head, ce = eh;
    c->nodes[n] = cur;
    for (;;) {
        c->seen[ce] = 1;
        c->elems[n] = ce;
        cur = other_end(m, ce, cur);
        c->nodes[++n] = cur;
        if (!interior(e, c, cur)) break;
        ce = c->inc[2 * cur] == ce ? c->inc[2 * cur + 1] : c->inc[2 * cur];
    }
    return n + 1;
}

/* A tip: a node of one flexible member, free or held in some directions only (a rope's
 * end on a slide); place_dangling checks that its supports admit the hanging place. */
static int tip(const ctn_problem *e, const chains *c, int node)
{
    return c->deg[node] == 1 && (e->m->nodes.v[node].fix & 7u) != 7u;
}

/* Move node to displacement dn, its held directions left as they are (admits). */
static void place(const ctn_problem *e, double *d, int node, const double *dn)
{
    double *x = d + ctn_dofmap_node(&e->a->map, (size_t)node);
    for (int k = 0; k < 3; k++)
        if (!(e->m->nodes.v[node].fix & (1u << k))) x[k] = dn[k];
}

/* A dangling chain (an anchor, then free nodes to a tip) hangs, whatever its start, in
 * the equilibrium of a funicular from its anchor (hang.c: each member along the force
 * it carries, stretched by it; a tip held in some directions reaches its held
 * coordinates by the reaction found there): place it there, so Newton starts at the
 * hanging state instead of swinging the whole chain through a large rigid rotation.
 * Where the funicular fails (the held tip out of reach, a member without force), the
 * chain is tried on the line along the resultant of its loads, each member stretched by
 * CTN_PRESHAPE_STRAIN (a pendulum; exact when only the tip is loaded). 1 if placed. */
typedef struct funicular {
    const ctn_problem *e;
    const int *elems;   /* the members, anchor to tip */
    const int *flip;    /* per member: its first node is the one nearer the tip */
} funicular;

/* Member j's chord, anchor to tip, from its element's `hang` op (its first node to its
 * second: turned where the element runs from the tip towards the anchor). */
static double member(const void *ud, size_t j, const double S[3], double v[3], double H[9])
{
    const funicular *fu = ud;
    size_t el = (size_t)fu->elems[j];
    const ctn_asm_block *b = ctn_asm_block_of(fu->e->a, el);
    if (!b->ops->hang) return NAN;
    double Sm[3] = { -S[0], -S[1], -S[2] };
    double phi = b->ops->hang(ctn_asm_props(fu->e->a, el), fu->flip[j] ? Sm : S, v, H);
    if (fu->flip[j])
        for (int k = 0; k < 3; k++) v[k] = -v[k];
    return phi;
}

/* anchored: the chain between two anchors (its last node the tip, held in every
 * direction where it is: the exact equilibrium of the chain under the loads, its anchors
 * where they are); else a dangling chain, its tip at node 0 when flip. */
static int place_funicular(const ctn_problem *e, const chains *c, size_t n, int flip, int anchored,
                           const double *loads, const double *fh, double *d)
{
    size_t ne = n - 1;
    double *f = ctn_malloc(e->ctx, 6 * ne, sizeof(double));
    int *el = ctn_malloc(e->ctx, 2 * ne, sizeof(int));
    if (!f || !el) {
        ctn_free(f);
        ctn_free(el);
        return 0;
    }
    double *x = f + 3 * ne, S = 0;
    funicular fu = { e, el, el + ne };
    ctn_hang h = { ne, member, &fu, 0, f, { 0, 0, 0 }, 0, { 0, 0, 0 } };
    for (size_t i = 1; i < n; i++) {
        size_t j = flip ? n - 1 - i : i;
        int node = c->nodes[j], up = c->nodes[flip ? j + 1 : j - 1];
        el[i - 1] = c->elems[flip ? j : j - 1];
        el[ne + i - 1] = ctn_elem_nodes(e->m, (size_t)el[i - 1])[0] != up;   /* runs tip to anchor */
        S += rest_length(e, el[i - 1]);
        size_t sn = ctn_dofmap_node(&e->a->map, (size_t)node);
        for (int q = 0; q < 3; q++)
            f[3 * (i - 1) + (size_t)q] = loads[3 * (size_t)node + (size_t)q] + (fh ? fh[sn + (size_t)q] : 0);
    }
    h.length = S;
    int tipn = c->nodes[flip ? 0 : n - 1], ok;
    current(e, d, c->nodes[flip ? n - 1 : 0], h.a);
    current(e, d, tipn, h.target);
    h.held = anchored ? 7u : e->m->nodes.v[tipn].fix & 7u;
    ok = ctn_hang_place(&h, x);
    for (int pass = 0; ok && pass < 2; pass++)    /* check every node's place, then move */
        for (size_t i = 1; ok && i < n; i++) {
            int node = c->nodes[flip ? n - 1 - i : i];
            double dn[3];
            for (int q = 0; q < 3; q++) dn[q] = x[3 * (i - 1) + (size_t)q] - e->m->nodes.v[node].X[q];
            if (pass == 0 && node != tipn && !admits(e, node, dn, S)) ok = 0;   /* held elsewhere */
            if (pass == 1 && !(anchored && node == tipn)) place(e, d, node, dn);
        }
    ctn_free(f);
    ctn_free(el);
    return ok;
}

/* Loads that follow the geometry (a wind's drag on the chord's projection, an hload on the
 * deformed one) of selection sel: the funicular is placed again under the dead loads and
 * those at its last place, until no node moves by more than CTN_FOLLOW_MOVE of the
 * chain's length (a fixed point: a pendant rope swung by a wind across it, whose drag
 * falls as it swings), at most CTN_FOLLOW_PLACES times. The last place is kept. */
#define CTN_FOLLOW_PLACES 100
#define CTN_FOLLOW_MOVE 1e-10
static int follow_funicular(const ctn_problem *e, const chains *c, size_t n, int flip, int anchored,
                             const ctn_loadsel *sel, const double *loads, double *d)
{
    double *fh = ctn_malloc(e->ctx, e->ns, sizeof(double)), *x = ctn_malloc(e->ctx, 3 * n, sizeof(double)), S = 0;
    int placed = 0;
    for (size_t i = 0; i + 1 < n; i++) S += rest_length(e, c->elems[i]);
    for (int it = 0; fh && x && it < CTN_FOLLOW_PLACES; it++) {
        double move = 0;
        for (size_t i = 0; i < n; i++) current(e, d, c->nodes[i], x + 3 * i);
        ctn_follow_forces_sel(e, d, sel, fh);
        if (!place_funicular(e, c, n, flip, anchored, loads, fh, d)) break;
        placed = 1;
        for (size_t i = 0; i < n; i++) {
            double y[3];
            current(e, d, c->nodes[i], y);
            for (int k = 0; k < 3; k++) move = fmax(move, fabs(y[k] - x[3 * i + (size_t)k]));
        }
        if (move <= CTN_FOLLOW_MOVE * S) break;
    }
    ctn_free(fh);
    ctn_free(x);
    return placed;
}

static int place_dangling(const ctn_problem *e, const chains *c, size_t n, const double *loads, double *d)
{
    int flip = tip(e, c, c->nodes[0]);
    if (n < 2 || !(flip || tip(e, c, c->nodes[n - 1]))) return 0;
    if (place_funicular(e, c, n, flip, 0, loads, NULL, d)) {
        ctn_loadsel first = ctn_loadsel_step(0);
        if (e->fl) follow_funicular(e, c, n, flip, 0, &first, loads, d);
        return 1;
    }
    double R[3] = { 0, 0, 0 }, a[3], rn = 0;
    for (size_t i = 1; i < n; i++) {
        int node = c->nodes[flip ? n - 1 - i : i];
        for (int k = 0; k < 3; k++) R[k] += loads[3 * (size_t)node + (size_t)k];
    }
    rn = sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2]);
    if (!(rn > 0)) return 0;
    current(e, d, c->nodes[flip ? n - 1 : 0], a);
    for (int pass = 0; pass < 2; pass++) {       /* check every node's place, then move */
        double s = 0;
        for (size_t i = 1; i < n; i++) {
            size_t j = flip ? n - 1 - i : i;
            int node = c->nodes[j];
            s += rest_length(e, c->elems[flip ? j : j - 1]) * (1 + CTN_PRESHAPE_STRAIN);
            double dn[3];
            for (int k = 0; k < 3; k++) dn[k] = a[k] + s * R[k] / rn - e->m->nodes.v[node].X[k];
            if (pass == 0 && !admits(e, node, dn, s)) return 0;   /* its supports hold it elsewhere */
            if (pass == 1) place(e, d, node, dn);
        }
    }
    return 1;
}

/* An arch: a node of the chain at d beyond its chord against the load direction g (a
 * von Mises truss, a shallow arch under its load: the hanging shape is another
 * equilibrium, not its start). S: the chain's length (the tolerance's scale). */
static int arch(const ctn_problem *e, const chains *c, size_t n, const double *d, const double g[3], double S)
{
    double a[3], b[3], ch[3], c2 = 0;
    current(e, d, c->nodes[0], a);
    current(e, d, c->nodes[n - 1], b);
    for (int k = 0; k < 3; k++) {
        ch[k] = b[k] - a[k];
        c2 += ch[k] * ch[k];
    }
    for (size_t i = 1; i + 1 < n && c2 > 0; i++) {
        double x[3], t = 0, side = 0;
        current(e, d, c->nodes[i], x);
        for (int k = 0; k < 3; k++) t += (x[k] - a[k]) * ch[k] / c2;
        for (int k = 0; k < 3; k++) side += (x[k] - a[k] - t * ch[k]) * g[k];
        if (side < -1e-12 * S) return 1;
    }
    return 0;
}

/* A chain between two supports (both ends held in every direction) whose members all
 * hang by a law (element.h's `hang` op): its funicular through the anchors is the exact
 * equilibrium of the chain under fixed loads, whatever its start. */
static int anchored(const ctn_problem *e, const chains *c, size_t n)
{
    const ctn_model *m = e->m;
    if (n < 3 || c->nodes[0] == c->nodes[n - 1] || (m->nodes.v[c->nodes[0]].fix & 7u) != 7u ||
        (m->nodes.v[c->nodes[n - 1]].fix & 7u) != 7u)
        return 0;
    for (size_t i = 0; i + 1 < n; i++)
        if (!ctn_asm_block_of(e->a, (size_t)c->elems[i])->ops->hang) return 0;
    return 1;
}

/* Place an anchored chain on its funicular under the dead loads and those of selection
 * sel that follow the geometry (a wind's drag: the fixed point of follow_funicular, from
 * the drag on its current chords). 1 if placed. */
static int place_anchored(const ctn_problem *e, const chains *c, size_t n, const ctn_loadsel *sel,
                          const double *loads, double *d)
{
    if (!anchored(e, c, n)) return 0;
    double *fh = ctn_malloc(e->ctx, e->ns, sizeof(double)), W[3] = { 0, 0, 0 }, S = 0;
    if (!fh) return 0;
    ctn_follow_forces_sel(e, d, sel, fh);          /* the loads' direction, for the arch test */
    for (size_t i = 1; i + 1 < n; i++) {
        size_t q = ctn_dofmap_node(&e->a->map, (size_t)c->nodes[i]);
        for (int k = 0; k < 3; k++) W[k] += loads[3 * (size_t)c->nodes[i] + (size_t)k] + fh[q + (size_t)k];
    }
    ctn_free(fh);
    double wn = sqrt(W[0] * W[0] + W[1] * W[1] + W[2] * W[2]);
    for (size_t i = 0; i + 1 < n; i++) S += rest_length(e, c->elems[i]);
    if (!(wn > 0)) return 0;                       /* no load: no funicular */
    for (int k = 0; k < 3; k++) W[k] /= wn;
    if (arch(e, c, n, d, W, S)) return 0;
    return e->fl ? follow_funicular(e, c, n, 0, 1, sel, loads, d) : place_funicular(e, c, n, 0, 1, loads, NULL, d);
}

/* Place one chain of n nodes on its arc if it is slack; 1 if placed. */
static int place_chain(const ctn_problem *e, const chains *c, size_t n, double *d)
{
    double S = 0, poly = 0, lmax = 0, a[3], b[3], x0[3], x1[3];
    for (size_t i = 0; i + 1 < n; i++) {
        double l0 = rest_length(e, c->elems[i]);
        S += l0;
        lmax = fmax(lmax, l0);
        current(e, d, c->nodes[i], x0);
        current(e, d, c->nodes[i + 1], x1);
        poly += sqrt((x1[0] - x0[0]) * (x1[0] - x0[0]) + (x1[1] - x0[1]) * (x1[1] - x0[1]) +
                     (x1[2] - x0[2]) * (x1[2] - x0[2]));
    }
    current(e, d, c->nodes[0], a);
    current(e, d, c->nodes[n - 1], b);
    ctn_arc arc, start;
    if (n < 3 || poly > S || ctn_arc_make(a, b, e->m->gravity, S, &arc) || arc.alpha == 0 ||
        ctn_arc_stretched(&arc, a, b, e->m->gravity, S, lmax / S, CTN_PRESHAPE_STRAIN, &start))
        return 0;
    for (int pass = 0; pass < 2; pass++) {       /* check every node's place, then move */
        double s = 0;
        for (size_t i = 1; i + 1 < n; i++) {
            double X[3], dn[3];
            s += rest_length(e, c->elems[i - 1]);
            ctn_arc_point(&start, s / S, X);
            for (int k = 0; k < 3; k++) dn[k] = X[k] - e->m->nodes.v[c->nodes[i]].X[k];
            if (pass == 0 && !admits(e, c->nodes[i], dn, S)) return 0;
            if (pass == 1) place(e, d, c->nodes[i], dn);
        }
    }
    return 1;
}

/* Whether a wind of the first step loads an interior node of the chain (its loads with
 * the winds, at the reference geometry, differ from the dead loads). */
static int chain_windy(const chains *c, size_t n, const double *loads, const double *loadsw)
{
    for (size_t i = 1; i + 1 < n; i++)
        for (size_t j = 0; j < 3; j++)
            if (loads[3 * (size_t)c->nodes[i] + j] != loadsw[3 * (size_t)c->nodes[i] + j]) return 1;
    return 0;
}

/* The generated cable element el belongs to, or NULL. */
static const ctn_cable *cable_of(const ctn_model *m, int el)
{
    for (size_t i = 0; i < m->cables.n; i++) {
        const ctn_cable *cb = &m->cables.v[i];
        if ((size_t)el >= cb->first && (size_t)el < cb->first + cb->count) return cb;
    }
    return NULL;
}

/* Whether element el belongs to a generated cable that keeps the start its line asks
 * for (start=arc or catenary given, shape=straight, or a target's state found). */
static int keeps_start(const ctn_model *m, int el)
{
    const ctn_cable *cb = cable_of(m, el);
    return cb && (cb->start != CTN_START_AUTO || cb->shape != CTN_SHAPE_ARC ||
                  (cb->target != CTN_TARGET_NONE && cb->resolved));
}

/* Whether a wind of the first step loads an interior node of cable cb: its loads with
 * the winds (at the reference geometry) differ from the dead loads. */
static int windy(const ctn_model *m, const ctn_cable *cb, const double *loads, const double *loadsw)
{
    for (size_t k = 1; k < cb->count; k++) {
        size_t node = (size_t)ctn_elem_nodes(m, cb->first + k)[0];
        for (int j = 0; j < 3; j++)
            if (loads[3 * node + (size_t)j] != loadsw[3 * node + (size_t)j]) return 1;
    }
    return 0;
}

/* A chain of cable elements of one section and (nearly) one unstressed length whose
 * interior nodes carry only loads of one direction, uniform per length (the weight of a
 * chain of `element`s given as point loads, or any uniform load per length): it hangs
 * as a weighted cable does, so it starts on the elastic catenary of that load through
 * its anchors (issue 29, item 2), as a generated cable under its own weight does. The
 * lengths may differ by less than half the start's stretch (CTN_LOADED_EPS), so every
 * member still starts stretched; the loads per tributary length by CTN_LOADED_SPREAD
 * (a chain of equal point loads on a shallow parabola's chords). The loads include the
 * first step's winds at the reference geometry: a span swung by a wind across it starts
 * in the plane of its weight and the drag (issue 27: a swing of 76 degrees stalled the
 * default method from the catenary of the weight alone). With `mean` (a chain that a
 * wind not uniform along it loads: oblique to the span, or along a sagging span) the
 * loads need not be uniform: the chain starts on the catenary of their mean per length
 * (the drag on the reference chords averaged, plus the weight) if every node's load lies
 * within 60 degrees of that mean. Not where an element takes a
 * horizontal load (per projected length: not uniform per length of a sagging member);
 * nor where a node lies beyond the chord against the
 * load (an arch, a von Mises truss: the hanging shape is another equilibrium). 1 if
 * placed. */
#define CTN_LOADED_EPS 1e-4
#define CTN_LOADED_SPREAD 1e-3
static int place_loaded(const ctn_problem *e, const chains *c, size_t n, const double *loads, int mean, double *d)
{
    const ctn_model *m = e->m;
    if (n < 3 || keeps_start(m, c->elems[0])) return 0;
    const ctn_element *e0 = &m->elements.v[c->elems[0]];
    if (e0->section < 0) return 0;
    double S = 0, l0 = rest_length(e, c->elems[0]);
    for (size_t i = 0; i + 1 < n; i++) {
        size_t el = (size_t)c->elems[i];
        double li = rest_length(e, c->elems[i]);
        if (strcmp(ctn_asm_block_of(e->a, el)->ops->name, "cable") || m->elements.v[el].section != e0->section ||
            !(fabs(li - l0) <= 0.5 * CTN_LOADED_EPS * l0))
            return 0;
        for (size_t h = 0; h < m->hloads.n; h++)
            if (ctn_hload_on(m, &m->hloads.v[h], el)) return 0;
        S += li;
    }
    /* q_i: node i's load per tributary length; one direction, one magnitude */
    double q0[3] = { 0, 0, 0 }, qn = 0, W[3] = { 0, 0, 0 };
    for (size_t i = 1; i + 1 < n; i++) {
        double trib = 0.5 * (rest_length(e, c->elems[i - 1]) + rest_length(e, c->elems[i])), q[3];
        for (int k = 0; k < 3; k++) {
            q[k] = loads[3 * (size_t)c->nodes[i] + (size_t)k] / trib;
            W[k] += loads[3 * (size_t)c->nodes[i] + (size_t)k];
        }
        if (i == 1) {
            memcpy(q0, q, sizeof q0);
            qn = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
            if (!(qn > 0)) return 0;
            continue;
        }
        double x[3] = { q[1] * q0[2] - q[2] * q0[1], q[2] * q0[0] - q[0] * q0[2], q[0] * q0[1] - q[1] * q0[0] };
        double dot = q[0] * q0[0] + q[1] * q0[1] + q[2] * q0[2];
        if (mean) continue;                          /* checked against the mean below */
        if (!(sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) <= 1e-9 * qn * qn && dot > 0 &&
              fabs(dot / qn - qn) <= CTN_LOADED_SPREAD * qn))
            return 0;
    }
    double tribs = S - 0.5 * (rest_length(e, c->elems[0]) + rest_length(e, c->elems[n - 2]));
    double w = sqrt(W[0] * W[0] + W[1] * W[1] + W[2] * W[2]) / tribs, g[3] = { q0[0] / qn, q0[1] / qn, q0[2] / qn };
    if (mean) {                                      /* the mean load per length: every node's */
        if (!(w > 0)) return 0;                      /* within 60 degrees of it */
        for (int k = 0; k < 3; k++) g[k] = W[k] / (w * tribs);
        for (size_t i = 1; i + 1 < n; i++) {
            const double *F = loads + 3 * (size_t)c->nodes[i];
            double f = sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
            if (!(F[0] * g[0] + F[1] * g[1] + F[2] * g[2] >= 0.5 * f)) return 0;
        }
    }
    const ctn_section *sec = &m->sections.v[e0->section];
    double a[3], b[3];
    if (arch(e, c, n, d, g, S)) return 0;
    current(e, d, c->nodes[0], a);
    current(e, d, c->nodes[n - 1], b);
    ctn_catenary_place cat;
    int ne = (int)(n - 1);
    if (ctn_catenary_start(e->ctx, a, b, g, w, m->materials.v[sec->material].E * sec->A, S, ne, CTN_LOADED_EPS, &cat))
        return 0;
    for (int pass = 0; pass < 2; pass++)          /* check every node's place, then move */
        for (size_t i = 1; i + 1 < n; i++) {
            double X[3], dn[3];
            ctn_catenary_start_point(&cat, (int)i, X);
            for (int k = 0; k < 3; k++) dn[k] = X[k] - m->nodes.v[c->nodes[i]].X[k];
            if (pass == 0 && !admits(e, c->nodes[i], dn, S)) return 0;
            if (pass == 1) place(e, d, c->nodes[i], dn);
        }
    return 1;
}

static int incidence(const ctn_problem *e, chains *c)
{
    size_t nn = e->a->nn, ne = e->a->ne;
    ctn_ctx *ctx = e->ctx;
    c->deg = ctn_calloc(ctx, nn, sizeof(int));
    c->inc = ctn_malloc(ctx, 2 * nn, sizeof(int));
    c->nodes = ctn_malloc(ctx, nn + 1, sizeof(int));   /* a chain's two anchors may be one node */
    c->elems = ctn_malloc(ctx, nn, sizeof(int));
    c->seen = ctn_calloc(ctx, ne, 1);
    if (!c->deg || !c->inc || !c->nodes || !c->elems || !c->seen) return CTN_ERR_NOMEM;
    for (size_t i = 0; i < ne; i++) {
        const ctn_asm_block *b = ctn_asm_block_of(e->a, i);
        const int *nd = ctn_elem_nodes(e->m, i);
        int chain = ((b->ops->flags & CTN_ELEM_FLEXIBLE) || b->ops->hang) && b->nnodes == 2;
        if (!chain) c->seen[i] = 1;                /* other members make anchors */
        for (int k = 0; k < b->nnodes; k++) {
            int p = nd[k];
            if (chain && c->deg[p] < 2) c->inc[2 * p + c->deg[p]] = (int)i;
            c->deg[p] += chain ? 1 : 3;
        }
    }
    return CTN_OK;
}

/* The cable carries its own weight only: no load on its interior nodes but the halves of
 * its elements' weights (first step), and no hload on its elements in any step. */
static int weight_only(const ctn_problem *e, const ctn_cable *cb, const double *loads)
{
    const ctn_model *m = e->m;
    const ctn_element *el = &m->elements.v[cb->first];
    double W = m->sections.v[el->section].w * el->l0, scale = 0;
    for (int k = 0; k < 3; k++) scale += W * m->gravity[k] * W * m->gravity[k];
    scale = sqrt(scale);
    for (size_t h = 0; h < m->hloads.n; h++)
        for (size_t k = 0; k < cb->count; k++) {
            int id = m->elements.v[cb->first + k].id;
            if (id >= m->hloads.v[h].first && id <= m->hloads.v[h].last) return 0;
        }
    for (size_t k = 1; k < cb->count; k++) {
        int node = ctn_elem_nodes(m, cb->first + k)[0];
        double wa = 0.5 * m->sections.v[m->elements.v[cb->first + k - 1].section].w * m->elements.v[cb->first + k - 1].l0;
        double wb = 0.5 * m->sections.v[m->elements.v[cb->first + k].section].w * m->elements.v[cb->first + k].l0;
        for (int j = 0; j < 3; j++)
            if (fabs(loads[3 * (size_t)node + (size_t)j] - (wa + wb) * m->gravity[j]) > 1e-9 * scale) return 0;
    }
    for (size_t i = 0; i < m->ploads.n; i++)            /* loads in later steps too */
        for (size_t k = 1; k < cb->count; k++)
            if (m->ploads.v[i].node == ctn_elem_nodes(m, cb->first + k)[0]) return 0;
    return 1;
}

/* A generated arc cable with start=auto and a weight: its interior nodes on the elastic
 * catenary of its span (model/cable_start.c), which Newton leaves in a few iterations at
 * any inclination; its elements are then no chain to pre-shape. 1 if placed. */
static int weight_only(const ctn_problem *e, const ctn_cable *cb, const double *loads);

static int catenary_of_weight(const ctn_problem *e, const ctn_cable *cb, chains *c, const double *loads, double *d);

static int place_catenary(const ctn_problem *e, const ctn_cable *cb, chains *c, const double *loads, double *d)
{
    return !c->seen[cb->first] && catenary_of_weight(e, cb, c, loads, d);
}

static int catenary_of_weight(const ctn_problem *e, const ctn_cable *cb, chains *c, const double *loads, double *d)
{
    const ctn_model *m = e->m;
    if (cb->start != CTN_START_AUTO || cb->shape != CTN_SHAPE_ARC || cb->count < 2) return 0;
    if (cb->target != CTN_TARGET_NONE && cb->resolved) return 0;   /* its start is the state found */
    if (!weight_only(e, cb, loads)) return 0;          /* the catenary of its weight is not its shape */
    if (tip(e, c, cb->node[0]) || tip(e, c, cb->node[1])) return 0;   /* an end that is not held: it hangs */
    const ctn_element *el = &m->elements.v[cb->first];
    if (el->section < 0) return 0;
    const ctn_section *sec = &m->sections.v[el->section];
    ctn_catenary_place cat;
    if (ctn_catenary_start(e->ctx, m->nodes.v[cb->node[0]].X, m->nodes.v[cb->node[1]].X, m->gravity, sec->w,
                           m->materials.v[sec->material].E * sec->A, cb->length, (int)cb->count, 1e-4, &cat))
        return 0;
    for (size_t k = 1; k < cb->count; k++) {
        int node = ctn_elem_nodes(m, cb->first + k)[0];
        double X[3], *dn = d + ctn_dofmap_node(&e->a->map, (size_t)node);
        ctn_catenary_start_point(&cat, (int)k, X);
        for (int j = 0; j < 3; j++) dn[j] = X[j] - m->nodes.v[node].X[j];
    }
    for (size_t k = 0; k < cb->count; k++) c->seen[cb->first + k] = 1;
    return 1;
}

/* Every member of the chain is flexible (a cable's): the arcs and catenaries below place
 * only those; a chain with members that hang by their own law (a catenary element) is
 * placed only when it dangles. */
static int flexible(const ctn_problem *e, const chains *c, size_t n)
{
    for (size_t i = 0; i + 1 < n; i++)
        if (!(ctn_asm_block_of(e->a, (size_t)c->elems[i])->ops->flags & CTN_ELEM_FLEXIBLE)) return 0;
    return 1;
}

static void chains_free(chains *c)
{
    ctn_free(c->deg);
    ctn_free(c->inc);
    ctn_free(c->nodes);
    ctn_free(c->elems);
    ctn_free(c->seen);
}

int ctn_preshape(ctn_problem *e, double *d, int *count)
{
    chains c = { NULL, NULL, NULL, NULL, NULL };
    int rc = incidence(e, &c);
    const ctn_model *m = e->m;
    double *loads = e->v3;                         /* the first step's dead loads */
    double *loadsw = ctn_malloc(e->ctx, 3 * m->nodes.n + 1, sizeof(double));   /* and its winds */
    if (!rc && !loadsw) rc = CTN_ERR_NOMEM;
    *count = 0;
    int junction = 0;
    ctn_loadsel first = ctn_loadsel_step(0);
    if (!rc) ctn_model_step_loads_ex(m, 0, 1, loads, NULL);
    if (!rc) ctn_model_step_loads_ex(m, 0, 0, loadsw, NULL);
    if (!rc) rc = ctn_junction_place(e, loads, d, c.seen, &junction);
    *count += junction;
    for (size_t i = 0; !rc && i < m->cables.n; i++)
        if (!windy(m, &m->cables.v[i], loads, loadsw)) *count += place_catenary(e, &m->cables.v[i], &c, loads, d);
    for (size_t i = 0; !rc && i < e->a->ne; i++) {
        if (c.seen[i]) continue;
        size_t n = walk(e, &c, (int)i);
        c.seen[i] = 1;
        if (!n) continue;
        const ctn_cable *cb = cable_of(m, c.elems[0]);   /* a windy cable's weight at least */
        if (!flexible(e, &c, n)) {                       /* members that only hang (catenary) */
            *count += place_dangling(e, &c, n, loads, d);
            continue;
        }
        *count += place_dangling(e, &c, n, loads, d) || place_loaded(e, &c, n, loadsw, 0, d) ||
                  (chain_windy(&c, n, loads, loadsw) && place_anchored(e, &c, n, &first, loads, d)) ||
                  (chain_windy(&c, n, loads, loadsw) && place_loaded(e, &c, n, loadsw, 1, d)) ||
                  (cb && windy(m, cb, loads, loadsw) && catenary_of_weight(e, cb, &c, loads, d)) ||
                  place_chain(e, &c, n, d);
    }
    ctn_free(loadsw);
    chains_free(&c);
    return rc;
}

/* The direction of the loads on the chain's interior nodes turns by more than
 * CTN_TURN_COS's angle (1 degree) from the step's start (f0: dead loads, h0: those that
 * follow the geometry, at d) to its end (f1, h1): a wind that swings the span. */
#define CTN_TURN_COS 0.99984769515639127     /* cos(1 degree) */
static int turns(const ctn_problem *e, const chains *c, size_t n, const double *f0, const double *h0,
                 const double *f1, const double *h1)
{
    double W0[3] = { 0, 0, 0 }, W1[3] = { 0, 0, 0 }, a = 0, b = 0, ab = 0;
    for (size_t i = 1; i + 1 < n; i++) {
        size_t s = ctn_dofmap_node(&e->a->map, (size_t)c->nodes[i]);
        for (int k = 0; k < 3; k++) {
            W0[k] += f0[s + (size_t)k] + h0[s + (size_t)k];
            W1[k] += f1[s + (size_t)k] + h1[s + (size_t)k];
        }
    }
    for (int k = 0; k < 3; k++) {
        a += W0[k] * W0[k];
        b += W1[k] * W1[k];
        ab += W0[k] * W1[k];
    }
    return b > 0 && !(ab > CTN_TURN_COS * sqrt(a * b));
}

/* The chain's polyline at d is shorter than its unstressed length (at the temperatures
 * the assembly holds): it cannot start in tension (a conductor heated). A chain with a
 * member that hangs by its own law (a catenary element, whose chord is always shorter
 * than it) counts as slack when the step changes a member's temperature. */
static int slack(const ctn_problem *e, const chains *c, size_t n, const double *d)
{
    double S = 0, poly = 0, x0[3], x1[3];
    for (size_t i = 0; i + 1 < n; i++)
        if (!(ctn_asm_block_of(e->a, (size_t)c->elems[i])->ops->flags & CTN_ELEM_FLEXIBLE)) {
            for (size_t j = 0; e->dT0 && j + 1 < n; j++)
                if (e->dT0[c->elems[j]] != e->dT1[c->elems[j]]) return 1;
            return 0;
        }
    for (size_t i = 0; i + 1 < n; i++) {
        S += rest_length(e, c->elems[i]);
        current(e, d, c->nodes[i], x0);
        current(e, d, c->nodes[i + 1], x1);
        poly += sqrt((x1[0] - x0[0]) * (x1[0] - x0[0]) + (x1[1] - x0[1]) * (x1[1] - x0[1]) +
                     (x1[2] - x0[2]) * (x1[2] - x0[2]));
    }
    return poly < S;
}

int ctn_preshape_step(ctn_problem *e, const ctn_loadsel *from, const ctn_loadsel *to, double *d, int *count)
{
    chains c = { NULL, NULL, NULL, NULL, NULL };
    int rc = incidence(e, &c);
    double *h0 = ctn_malloc(e->ctx, e->ns, sizeof(double)), *h1 = ctn_malloc(e->ctx, e->ns, sizeof(double));
    double *loads = e->v3;                         /* the step's end dead loads, per node */
    *count = 0;
    if (!rc && (!h0 || !h1)) rc = CTN_ERR_NOMEM;
    if (!rc) {
        ctn_dofmap_to3(&e->a->map, e->f1, loads);
        ctn_follow_forces_sel(e, d, from, h0);
        ctn_follow_forces_sel(e, d, to, h1);
        if (e->dT1) ctn_asm_set_temperatures(e->a, e->dT1);   /* the end's rest lengths */
    }
    for (size_t i = 0; !rc && i < e->a->ne; i++) {
        if (c.seen[i]) continue;
        size_t n = walk(e, &c, (int)i);
        c.seen[i] = 1;
        if (n && anchored(e, &c, n) && (slack(e, &c, n, d) || turns(e, &c, n, e->f0, h0, e->f1, h1)))
            *count += place_anchored(e, &c, n, to, loads, d);
    }
    if (!rc && e->dT0) ctn_asm_set_temperatures(e->a, e->dT0);
    ctn_free(h0);
    ctn_free(h1);
    chains_free(&c);
    return rc;
}
