/* Internal: the properties of the spring family (spring2.c), for its tests. */
#ifndef CTN_ELEMENT_SPRING2_H
#define CTN_ELEMENT_SPRING2_H

#include "element/element.h"

/* Properties of a two-node axial spring (spring2.c). */
typedef struct ctn_spring_props {
    double k;           /* stiffness [force/length] */
    double l0;          /* free length [length] */
} ctn_spring_props;

#endif
