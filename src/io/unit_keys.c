/* The dimension of each value of the .cable format that may carry a unit (docs/format.md,
 * "Units"): force^f length^l, by the name the reader gives the value in messages. */
#include "io/parse.h"

#include <string.h>

typedef struct key_dim {
    const char *what;
    int f, l;
} key_dim;

static const key_dim dims[] = {
    { "a coordinate", 0, 1 },      { "a force component", 1, 0 }, { "a moment component", 1, 1 },
    { "'E'", 1, -2 },              { "'G'", 1, -2 },              { "'s0'", 1, -2 },
    { "'A'", 0, 2 },               { "'Asy'", 0, 2 },             { "'Asz'", 0, 2 },
    { "'Iy'", 0, 4 },              { "'Iz'", 0, 4 },              { "'J'", 0, 4 },
    { "'w'", 1, -1 },              { "'q'", 1, -1 },              { "'qx'", 1, -1 },
    { "'qy'", 1, -1 },             { "'qz'", 1, -1 },             { "'mbl'", 1, 0 },
    { "'N0'", 1, 0 },              { "'H'", 1, 0 },               { "'tension'", 1, 0 },
    { "'force'", 1, 0 },           { "'length'", 0, 1 },          { "'l0'", 0, 1 },
    { "'sag'", 0, 1 },             { "'x'", 0, 1 },               { "'y'", 0, 1 },
    { "'z'", 0, 1 },               { "'arclength'", 0, 1 },       { "'thickness'", 0, 1 },
    { "'d'", 0, 1 },               { "'density'", 1, -4 },        { "'rho'", 1, -4 },
    { "'pressure'", 1, -2 },       { "'fy'", 1, -2 },             { "'Wy'", 0, 3 },
    { "'Wz'", 0, 3 },
};

int ctn_parse_unit_dim(const char *what, int *f, int *l)
{
    for (size_t i = 0; i < sizeof dims / sizeof *dims; i++)
        if (!strcmp(dims[i].what, what)) {
            *f = dims[i].f;
            *l = dims[i].l;
            return 1;
        }
    return 0;
}
