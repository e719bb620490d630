/* Post-processing of a solution: the sag of generated cables (solve/sag.h). */
#include "model/model.h"
#include "post/sag.h"
#include "problem/solution.h"

#include <math.h>

/* Node index k (0 or 1) of element e: the one place that knows element storage. */
/* Node k of a two-node element: 0 its first, 1 its last. */
static size_t elem_node(const ctn_model *m, size_t e, int k)
{
    return (size_t)ctn_elem_nodes(m, e)[k ? m->elements.v[e].nnodes - 1 : 0];
}

typedef struct cable_chain {
    const ctn_model *m;
    const ctn_solution *s;
    const ctn_cable *c;
    const double *d;          /* the displacements of the state measured, 3 per node */
} cable_chain;

/* Node index of node j of the cable's chain (its elements run from end 0 to end 1). */
static size_t chain_node(const cable_chain *cc, size_t j)
{
    return j == 0 ? (size_t)cc->c->node[0] : elem_node(cc->m, cc->c->first + j - 1, 1);
}

static void point(const void *ud, size_t j, double x[3])
{
    const cable_chain *cc = ud;
    size_t i = chain_node(cc, j);
    for (int k = 0; k < 3; k++) x[k] = cc->m->nodes.v[i].X[k] + cc->d[3 * i + (size_t)k];
}

static int kink(const void *ud, size_t j)
{
    const cable_chain *cc = ud;
    double F[3];
    ctn_sag_node_load(cc->m, chain_node(cc, j), F);
    return F[0] != 0 || F[1] != 0 || F[2] != 0;
}

static int cable_chain_of(const ctn_model *m, const ctn_solution *s, size_t i, cable_chain *cc,
                          ctn_sag_chain *ch)
{
    if (!m || !s || i >= m->cables.n || s->nn != m->nodes.n) return CTN_ERR_INVALID;
    cc->m = m;
    cc->s = s;
    cc->c = &m->cables.v[i];
    cc->d = ctn_solution_displacements(s);
    ch->n = cc->c->count;
    ch->point = point;
    ch->kink = kink;
    ch->ud = cc;
    ctn_sag_down(m, ch->down);
    return CTN_OK;
}

int ctn_solution_cable_sag(const ctn_model *m, const ctn_solution *s, size_t i, double *sag)
{
    cable_chain cc;
    ctn_sag_chain ch;
    int rc = sag ? cable_chain_of(m, s, i, &cc, &ch) : CTN_ERR_INVALID;
    return rc ? rc : ctn_sag_mid(&ch, sag);
}

int ctn_solution_cable_max_sag_from_chord(const ctn_model *m, const ctn_solution *s, size_t i, double *d)
{
    cable_chain cc;
    ctn_sag_chain ch;
    int rc = d ? cable_chain_of(m, s, i, &cc, &ch) : CTN_ERR_INVALID;
    if (!rc) *d = ctn_sag_max_from_chord(&ch);
    return rc ? rc : isfinite(*d) ? CTN_OK : CTN_ERR_DOMAIN;
}

int ctn_solution_step_cable_sag(const ctn_model *m, const ctn_solution *s, size_t k, size_t i, double *sag)
{
    cable_chain cc;
    ctn_sag_chain ch;
    ctn_step_result st;
    int rc = sag ? cable_chain_of(m, s, i, &cc, &ch) : CTN_ERR_INVALID;
    if (!rc) rc = ctn_solution_step(s, k, &st);
    if (!rc) cc.d = st.d;
    return rc ? rc : ctn_sag_mid(&ch, sag);
}
