/* Internal: form finding by force density (catena/formfind.h). The model is the state:
 * the iteration writes the free coordinates into its nodes' X and the unstressed lengths
 * into its elements' l0, so that the loads of the first step (self-weight w l0, hload on
 * the projection) are those a static solve of the found model sees. */
#ifndef CTN_FORMFIND_FF_H
#define CTN_FORMFIND_FF_H

#include "catena/formfind.h"
#include "linalg/linsolve.h"
#include "model/model.h"

/* The equilibrium of the nodes free in one or more coordinates (those with the same
 * free nodes share it): D = C_f' Q C_f, upper triangle in compressed columns. */
typedef struct ctn_ff_system {
    size_t n;               /* equations: one per free node */
    int *eq;                /* per node its equation, -1 where the coordinate is fixed */
    int *colptr, *rowind;   /* the pattern (n + 1, nnz), rows sorted */
    int *slot;              /* per element 3 value positions: (a,a), (b,b), (a,b); -1 none */
    double *Dx;             /* values, pattern order */
    ctn_linsolve *ls;       /* CHOLMOD LL', analysed once */
} ctn_ff_system;

typedef struct ctn_ff {
    ctn_ctx *ctx;
    ctn_model *m;
    size_t nn, ne;
    ctn_ff_system sys[3];
    int which[3];           /* coordinate k is solved by sys[which[k]] */
    double *q;              /* per element: the force density in use */
    double *len;            /* per element: its length in the current shape */
    double *p, *pnew;       /* 3 per node: loads of the first step */
    double *b;              /* right-hand side and solution, nn */
    ctn_la_ordering order;  /* of the systems' factorizations (0: auto) */
    double *x;              /* NULL: the shape is the model's X (the fixed coordinates read
                               there, the free ones written); else 3 per node, read and
                               written here instead, the model left alone (a start) */
    double *X0, *l00;       /* the model's coordinates and l0 as given (restored on failure) */
    int factored;           /* 1 while the factorizations hold the current q */
    int saved;              /* 1 once X0 and l00 hold the model as given */
    size_t targets;         /* members with a target force */
} ctn_ff;

/* The systems of the three coordinates (system.c). */
int ctn_ff_systems_create(ctn_ff *f);
void ctn_ff_systems_destroy(ctn_ff *f);
/* Solve for the free coordinates with the current q and loads into the model's X. */
int ctn_ff_solve_shape(ctn_ff *f, int *factorizations);

/* Checks before iterating (check.c): every member has q or force and two nodes, no
 * prescribed displacement in the first step, every free DOF reaches an anchor. */
int ctn_ff_check_model(ctn_ff *f);
/* Targets that no shape balances at a free node whose members are all targeted. */
int ctn_ff_check_targets(ctn_ff *f);

/* The found net of a `net` line (line, its tokens; raw, its text) as node, element and
 * set lines (write_net.c). */
struct ctn_line;
struct ctn_wbuf;
int ctn_ff_write_net(ctn_ctx *ctx, const ctn_model *m, struct ctn_wbuf *out, const struct ctn_line *line,
                     const char *raw);

/* Length of element e in the model's current geometry (as the element computes it). */
double ctn_ff_length(const ctn_model *m, size_t e);

#endif
