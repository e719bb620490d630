/* Internal to linalg/: the CHOLMOD backends' state (cholmod_backend.c) and the choice of
 * the fill-reducing ordering (cholmod_order.c). CHOLMOD is used through its long-integer
 * interface (cholmod_l_*): a factor of more than 2^31 entries (a 3-million-DOF net in
 * the natural ordering) is indexed, not an overflow. */
#ifndef CTN_LINALG_CHOL_H
#define CTN_LINALG_CHOL_H

#include "core/feed.h"
#include "linalg/linsolve.h"

#include <cholmod.h>

typedef struct chol {
    ctn_ctx *ctx;
    cholmod_common cm;
    cholmod_sparse *A;                  /* pattern only between factorizations */
    cholmod_factor *L;
    cholmod_dense *B, *Y, *E;           /* right-hand side (its shape) and solve2 workspace */
    ctn_la_ordering ordering;
    unsigned plain;                     /* CTN_LA_PLAIN_* (linsolve.h): library calls
                                           instead of catena's kernels (benchmarks) */
    double lnz;                         /* non-zeros of L from the analysis */
    double fl;                          /* flops of one factorization, from the analysis */
    int indefinite;                     /* simplicial LDL' instead of LL' */
    int threads;                        /* the solve's threads= (0 auto, 1, n): what the
                                           thread policy is asked with (core/threads.h) */
    cholmod_dense *Yk, *Ek;             /* solve2 workspace of the block solves */
    struct ctn_psolve *ps;              /* the block solves on two threads (cholmod_psolve.c):
                                           planned at the first block solve, NULL if not used */
    int ps_planned;                     /* 1: the plan was made (ps may still be NULL) */
} chol;

/* Record a CHOLMOD failure (status in c->cm) with its meaning in words: CTN_ERR_NOMEM
 * for an allocation, else CTN_ERR_LINALG. */
int ctn_chol_error(chol *c, const char *what);
/* The meaning of a CHOLMOD status. */
const char *ctn_chol_status(int status);
/* Choose the ordering (ord, or by the analyses' flops for CTN_LA_ORDER_AUTO) and do the
 * symbolic analysis: c->L, c->ordering, c->lnz, c->fl. */
int ctn_chol_analyze(chol *c, ctn_la_ordering ord);
/* Write one byte of every page of a new factor's values, on two threads, before its
 * first factorization (cholmod_touch.c), when the thread policy allows it. */
void ctn_chol_touch(chol *c);
/* Plan the solves on two threads (cholmod_psolve.c) once, at the first solve of a
 * supernodal LL' factor the thread policy allows it for (CTN_THR_PSOLVE): c->ps, or
 * NULL (cholmod_l_solve2 then). */
int ctn_chol_psolve_plan(chol *c);

/* cholmod_feed.c: whether the next factorization can follow the assembly row block by
 * row block (a simplicial LDL' factor in the natural ordering, already factorized once),
 * and that factorization (K + shift I; the same factor as chol's factor op). The first
 * pivot d <= 0 of an LDL' factor among rows j0 .. j1 - 1, -1 if none. */
int ctn_chol_feedable(const chol *c);
int ctn_chol_factor_feed(chol *c, const double *Kx, double shift, ctn_feed *feed, ctn_factor_info *info);
long ctn_chol_first_nonpositive(const cholmod_factor *L, size_t j0, size_t j1);

/* The quotient graph of c->A (cholmod_quotient.c): ns supervariables, runs of
 * consecutive columns with identical patterns (a node's DOFs), supervariable s holding
 * columns first[s] .. first[s + 1] - 1; G its upper pattern (NULL when ns = n: nothing
 * merged). Expand a permutation of the supervariables into one of the columns. */
typedef struct ctn_chol_quot {
    size_t ns;
    SuiteSparse_long *first;            /* ns + 1 */
    cholmod_sparse *G;
} ctn_chol_quot;
int ctn_chol_quotient(chol *c, ctn_chol_quot *q);
void ctn_chol_quotient_expand(const ctn_chol_quot *q, const SuiteSparse_long *sperm, SuiteSparse_long *perm);
void ctn_chol_quotient_free(chol *c, ctn_chol_quot *q);
/* The symbolic analysis (c->L; c->cm.fl and c->cm.lnz) for the ordering sperm of q->G,
 * given the elimination tree sparent and column counts scount of G(sperm, sperm) (from
 * cholmod_l_analyze_ordering), without permuting the full pattern (cholmod_symbolic.c):
 * the factor cholmod_l_analyze_p gives for sperm postordered and expanded. */
int ctn_chol_symbolic(chol *c, const ctn_chol_quot *q, const SuiteSparse_long *sperm,
                      const SuiteSparse_long *sparent, const SuiteSparse_long *scount);

#endif
