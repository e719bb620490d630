/* Internal: the `net` generator (net_gen.c, docs/format.md "net"): a rectangular cable
 * net of nx x ny bays on a plan lx x ly centred at `origin`, flat or a hyperbolic
 * paraboloid, its boundary nodes supported (the corners, which no member reaches, in x, y
 * and z), its members two-node cable elements, and
 * the sets NAME (the members), NAME.edge and NAME.inner (the boundary and the interior
 * nodes). */
#ifndef CTN_MODEL_NET_GEN_H
#define CTN_MODEL_NET_GEN_H

#include "model/model.h"

typedef enum { CTN_NET_FLAT = 0, CTN_NET_HYPAR = 1 } ctn_net_shape;

typedef struct ctn_net_spec {
    const char *name;          /* the sets' names start with it */
    ctn_net_shape shape;       /* flat: z = z0; hypar: z = z0 + h ((2 dx / lx)^2 - (2 dy / ly)^2) */
    int nx, ny;                /* bays along x and y (>= 2 each) */
    double lx, ly;             /* the plan's sides [length] (> 0) */
    double h;                  /* hypar: the rise at the middle of the x sides [length] */
    double origin[3];          /* the plan's centre */
    unsigned fix;              /* the boundary nodes' supports (CTN_FIX_*) */
    const char *section;
    const char *group;         /* NULL: none */
    ctn_prestress prestress;   /* of every member, or CTN_PRESTRESS_NONE (l0 = its length) */
    double prestress_value;
    double q, force;           /* form finding: force density or target force, 0 if none */
} ctn_net_spec;

/* The net's nodes: ids N + i (ny + 1) + j for the grid point (i, j), i = 0..nx along x,
 * j = 0..ny along y, N the largest node id so far plus one; its members: for i, then j,
 * the member to (i + 1, j) and then the one to (i, j + 1), except those along the
 * boundary, ids from the largest element id so far plus one. *first_node and
 * *first_element get N and the first member's id. */
int ctn_model_add_net(ctn_model *m, const ctn_net_spec *s, int *first_node, int *first_element);

#endif
