/* The dimension of each value of the .cable format that may carry a unit (docs/format.md,
 * "Units"): force^f length^l, by the name the reader gives the value in messages. */
#include "io/parse.h"

#include <string.h>

typedef struct key_dim {
    const char *what;
    int f, l, t;     /* powers of force, length and time (2 for masses) */
} key_dim;

static const key_dim dims[] = {
    { "a coordinate", 0, 1, 0 },      { "a force component", 1, 0, 0 }, { "a moment component", 1, 1, 0 },
    { "'E'", 1, -2, 0 },              { "'G'", 1, -2, 0 },              { "'s0'", 1, -2, 0 },
    { "'A'", 0, 2, 0 },               { "'Asy'", 0, 2, 0 },             { "'Asz'", 0, 2, 0 },
    { "'Iy'", 0, 4, 0 },              { "'Iz'", 0, 4, 0 },              { "'J'", 0, 4, 0 },
    { "'w'", 1, -1, 0 },              { "'q'", 1, -1, 0 },              { "'qx'", 1, -1, 0 },
    { "'qy'", 1, -1, 0 },             { "'qz'", 1, -1, 0 },             { "'mbl'", 1, 0, 0 },
    { "'N0'", 1, 0, 0 },              { "'H'", 1, 0, 0 },               { "'tension'", 1, 0, 0 },
    { "'force'", 1, 0, 0 },           { "'length'", 0, 1, 0 },          { "'l0'", 0, 1, 0 },
    { "'sag'", 0, 1, 0 },             { "'x'", 0, 1, 0 },               { "'y'", 0, 1, 0 },
    { "'z'", 0, 1, 0 },               { "'arclength'", 0, 1, 0 },       { "'thickness'", 0, 1, 0 },
    { "'d'", 0, 1, 0 },               { "'density'", 1, -4, 2 },     { "'rho'", 1, -4, 2 },
    { "'pressure'", 1, -2, 0 },       { "'mass'", 1, -1, 2 },        { "'mass' per length", 1, -2, 2 },
    { "'fy'", 1, -2, 0 },        { "'Wy'", 0, 3, 0 },         { "'Wz'", 0, 3, 0 },
    { "'lx'", 0, 1, 0 },         { "'ly'", 0, 1, 0 },         { "'h'", 0, 1, 0 },
};

int ctn_parse_unit_dim(const char *what, int *f, int *l, int *t)
{
    for (size_t i = 0; i < sizeof dims / sizeof *dims; i++)
        if (!strcmp(dims[i].what, what)) {
            *f = dims[i].f;
            *l = dims[i].l;
            *t = dims[i].t;
            return 1;
        }
    return 0;
}
