/* The version of the library (catena/version.h, generated from CMakeLists.txt). */
#include "catena/version.h"

const char *ctn_version(void)
{
    return CATENA_VERSION_STRING;
}
