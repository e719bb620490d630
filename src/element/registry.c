/* The registered element families, by index (the model's element type) and by name. */
#include "element/element.h"

#include <string.h>

static const ctn_element_ops *const families[] = { &ctn_cable2_ops, &ctn_spring2_ops, &ctn_catenary2_ops,
                                                     &ctn_pulley_ops, &ctn_rspring_ops,
                                                     &ctn_beam3_ops };

int ctn_element_family_count(void) { return (int)(sizeof families / sizeof *families); }

const ctn_element_ops *ctn_element_family(int type)
{
    return type >= 0 && type < ctn_element_family_count() ? families[type] : NULL;
}

int ctn_element_family_find(const char *name)
{
    for (int i = 0; name && i < ctn_element_family_count(); i++)
        if (!strcmp(families[i]->name, name)) return i;
    return -1;
}
