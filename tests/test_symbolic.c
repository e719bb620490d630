/* The symbolic analysis from the quotient graph (src/linalg/backends/cholmod/cholmod_symbolic.c) against
 * CHOLMOD's own (cholmod_l_analyze_p of the full pattern with the same permutation):
 * the same factor, array by array: permutation, column counts, non-zeros and flops, and
 * for a supernodal factor its supernodes, their patterns and sizes. On node graphs blown
 * up to DOF patterns with every node of 3 DOFs (counts from the node counts) and with
 * 1, 2 or 3 DOFs (counts from the node factor), several components, both orderings of
 * the node graph, simplicial and supernodal; and a clean out-of-memory error whichever of
 * its allocations fails. */
#include "check.h"
#include "linalg/backends/cholmod/chol.h"

#include <stdlib.h>
#include <string.h>

/* A deterministic generator (the tests must not depend on the C library's rand). */
static unsigned long next(unsigned long *s)
{
    *s = *s * 6364136223846793005UL + 1442695040888963407UL;
    return *s >> 33;
}

/* The upper DOF pattern of a g x g grid of nodes (4 neighbours, plus a diagonal in one
 * cell of 7 and a long edge now and then), cut into `parts` strips with no edge between
 * them, each node of w[v] DOFs, as c->A (rows sorted, diagonal present). */
static int grid_pattern(chol *c, int g, int parts, const int *w)
{
    int m = g * g;
    int *first = malloc((size_t)(m + 1) * sizeof *first);
    char *adj = calloc((size_t)m * (size_t)m, 1);
    if (!first || !adj) {
        free(first);
        free(adj);
        return 0;
    }
    unsigned long seed = 12345;
    for (int r = 0; r < g; r++)
        for (int q = 0; q < g; q++) {
            int v = r * g + q, strip = r * parts / g;
            if (q + 1 < g) adj[v * m + v + 1] = adj[(v + 1) * m + v] = 1;
            if (r + 1 < g && (r + 1) * parts / g == strip) adj[v * m + v + g] = adj[(v + g) * m + v] = 1;
            if (r + 1 < g && q + 1 < g && (r + 1) * parts / g == strip && next(&seed) % 7 == 0)
                adj[v * m + v + g + 1] = adj[(v + g + 1) * m + v] = 1;
            if (next(&seed) % 23 == 0) {
                int u = (int)(next(&seed) % (unsigned long)m);
                if (u / g * parts / g == strip && u != v) adj[v * m + u] = adj[u * m + v] = 1;
            }
        }
    first[0] = 0;
    for (int v = 0; v < m; v++) first[v + 1] = first[v] + w[v];
    size_t n = (size_t)first[m], nz = 0;
    for (int pass = 0; pass < 2; pass++) {
        SuiteSparse_long *Ap = pass ? c->A->p : NULL, *Ai = pass ? c->A->i : NULL;
        nz = 0;
        for (int v = 0; v < m; v++)
            for (int a = 0; a < w[v]; a++) {
                if (Ap) Ap[first[v] + a] = (SuiteSparse_long)nz;
                for (int u = 0; u <= v; u++)
                    if (u == v || adj[u * m + v])
                        for (int b = 0; b < (u == v ? a + 1 : w[u]); b++) {
                            if (Ai) Ai[nz] = first[u] + b;
                            nz++;
                        }
            }
        if (Ap) Ap[n] = (SuiteSparse_long)nz;
        if (!pass && !(c->A = cholmod_l_allocate_sparse(n, n, nz, 1, 1, 1, CHOLMOD_PATTERN, &c->cm))) break;
    }
    free(first);
    free(adj);
    return c->A != NULL;
}

static int same(const SuiteSparse_long *a, const SuiteSparse_long *b, size_t n)
{
    return (!n || (a && b)) && (!n || !memcmp(a, b, n * sizeof *a));
}

/* The two analyses of c->A for the node graph ordered by `method` (CHOLMOD_AMD or
 * CHOLMOD_METIS), compared. */
static void compare(chol *c, int method, const char *what)
{
    ctn_chol_quot q;
    cholmod_common *cm = &c->cm;
    CHECK(ctn_chol_quotient(c, &q) == CTN_OK && q.G);
    if (!q.G) return;
    size_t m = q.ns;
    SuiteSparse_long *a[6];                      /* perm, parent, post, count, first, level */
    int ok = 1;
    for (int i = 0; i < 6; i++) ok &= (a[i] = malloc(m * sizeof(SuiteSparse_long))) != NULL;
    ok = ok && (method == CHOLMOD_AMD ? cholmod_l_amd(q.G, NULL, 0, a[0], cm) : cholmod_l_metis(q.G, NULL, 0, 0, a[0], cm));
    ok = ok && cholmod_l_analyze_ordering(q.G, method, a[0], NULL, 0, a[1], a[2], a[3], a[4], a[5], cm);
    CHECK_MSG(ok, "%s: ordering the node graph", what);
    if (ok && ctn_chol_symbolic(c, &q, a[0], a[1], a[3]) == CTN_OK) {
        cholmod_factor *L = c->L;
        double fl = cm->fl, lnz = cm->lnz;
        c->L = NULL;
        cm->nmethods = 1;
        cm->method[0].ordering = CHOLMOD_GIVEN;
        cm->postorder = 0;                   /* L->Perm is postordered: CHOLMOD keeps it */
        cholmod_factor *R = cholmod_l_analyze_p(c->A, L->Perm, NULL, 0, cm);
        size_t n = c->A->ncol;
        CHECK_MSG(R != NULL, "%s: CHOLMOD's analysis", what);
        if (R) {
            CHECK_MSG(same(L->Perm, R->Perm, n) && same(L->ColCount, R->ColCount, n), "%s: counts", what);
            CHECK_MSG(fl == cm->fl && lnz == cm->lnz, "%s: flops %g / %g, lnz %g / %g", what, fl, cm->fl, lnz, cm->lnz);
            CHECK_MSG(L->is_super == R->is_super && (cm->supernodal == CHOLMOD_AUTO ||
                                                     L->is_super == (cm->supernodal == CHOLMOD_SUPERNODAL)),
                      "%s: supernodal %d / %d", what, L->is_super, R->is_super);
            if (L->is_super && R->is_super) {
                size_t ns = L->nsuper;
                CHECK_MSG(ns == R->nsuper && L->ssize == R->ssize && L->xsize == R->xsize &&
                              L->maxcsize == R->maxcsize && L->maxesize == R->maxesize,
                          "%s: supernodes %zu / %zu", what, ns, R->nsuper);
                if (ns == R->nsuper && L->ssize == R->ssize)
                    CHECK_MSG(same(L->super, R->super, ns + 1) && same(L->pi, R->pi, ns + 1) &&
                                  same(L->px, R->px, ns + 1) && same(L->s, R->s, L->ssize),
                              "%s: supernodal patterns", what);
            }
        }
        cholmod_l_free_factor(&R, cm);
        cholmod_l_free_factor(&L, cm);
        cm->nmethods = 0;
        cm->postorder = 1;
    } else if (ok)
        CHECK_MSG(0, "%s: %s", what, ctn_ctx_message(c->ctx));
    int failures = 0;                   /* every allocation failing in turn: a clean error */
    for (long k = 1; ok && k < 60; k++) {
        ctn_ctx_fail_alloc_at(c->ctx, k);
        int rc = ctn_chol_symbolic(c, &q, a[0], a[1], a[3]);
        ctn_ctx_fail_alloc_at(c->ctx, 0);
        CHECK_MSG(rc == CTN_OK || (rc == CTN_ERR_NOMEM && !c->L), "%s: allocation %ld failing gives %d", what, k, rc);
        failures += rc == CTN_ERR_NOMEM;
        cholmod_l_free_factor(&c->L, cm);
        if (rc == CTN_OK) break;
    }
    CHECK_MSG(!ok || failures >= 6, "%s: %d allocations", what, failures);
    for (int i = 0; i < 6; i++) free(a[i]);
    ctn_chol_quotient_free(c, &q);
}

static void run(int g, int parts, int mixed, int supernodal)
{
    chol c;
    memset(&c, 0, sizeof c);
    CHECK(ctn_ctx_create(&c.ctx) == CTN_OK);
    cholmod_l_start(&c.cm);
    c.cm.print = 0;
    c.cm.supernodal = supernodal;
    int *w = malloc((size_t)(g * g) * sizeof *w);
    unsigned long seed = 99;
    for (int v = 0; w && v < g * g; v++) w[v] = mixed ? 1 + (int)(next(&seed) % 3) : 3;
    char what[96];
    if (w && grid_pattern(&c, g, parts, w)) {
        snprintf(what, sizeof what, "%dx%d grid, %d parts, %s DOFs, %s, AMD", g, g, parts, mixed ? "1-3" : "3",
                 supernodal == CHOLMOD_SIMPLICIAL ? "simplicial" : supernodal == CHOLMOD_AUTO ? "auto" : "supernodal");
        compare(&c, CHOLMOD_AMD, what);
        memcpy(what + strlen(what) - 3, "METIS", 6);
        compare(&c, CHOLMOD_METIS, what);
    } else
        CHECK(0);
    free(w);
    cholmod_l_free_sparse(&c.A, &c.cm);
    cholmod_l_finish(&c.cm);
    ctn_ctx_destroy(&c.ctx);
}

int main(void)
{
    run(24, 1, 0, CHOLMOD_SUPERNODAL);
    run(24, 3, 0, CHOLMOD_SUPERNODAL);
    run(30, 2, 1, CHOLMOD_SUPERNODAL);
    run(30, 1, 1, CHOLMOD_SIMPLICIAL);
    run(8, 1, 1, CHOLMOD_AUTO);
    CHECK_DONE();
}
