/* Internal: the public solve options translated into linalg's own (linalg/ knows no
 * public solve header). */
#ifndef CTN_PROBLEM_LA_OPTIONS_H
#define CTN_PROBLEM_LA_OPTIONS_H

#include "catena/solve.h"
#include "linalg/linsolve.h"

static inline ctn_la_ordering ctn_la_ordering_of(ctn_ordering o)
{
    return o == CTN_ORDER_NATURAL ? CTN_LA_ORDER_NATURAL : o == CTN_ORDER_AMD ? CTN_LA_ORDER_AMD
         : o == CTN_ORDER_METIS ? CTN_LA_ORDER_METIS : CTN_LA_ORDER_AUTO;
}

static inline ctn_ordering ctn_ordering_of_la(ctn_la_ordering o)
{
    return o == CTN_LA_ORDER_NATURAL ? CTN_ORDER_NATURAL : o == CTN_LA_ORDER_AMD ? CTN_ORDER_AMD
         : o == CTN_LA_ORDER_METIS ? CTN_ORDER_METIS : CTN_ORDER_AUTO;
}

#endif
