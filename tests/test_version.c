/* The version: ctn_version() (the library) against the CATENA_VERSION_* macros (the
 * header generated from CMakeLists.txt's project(VERSION)). */
#include "catena.h"

#include "check.h"

#include <stdio.h>
#include <string.h>

int main(void)
{
    const char *v = ctn_version();
    CHECK(v != NULL);
    CHECK_MSG(v && !strcmp(v, CATENA_VERSION_STRING), "ctn_version() = '%s', header '%s'", v ? v : "(null)",
              CATENA_VERSION_STRING);
    char built[64];
    snprintf(built, sizeof built, "%d.%d.%d", CATENA_VERSION_MAJOR, CATENA_VERSION_MINOR, CATENA_VERSION_PATCH);
    CHECK_MSG(!strcmp(built, CATENA_VERSION_STRING), "macros give '%s', CATENA_VERSION_STRING is '%s'", built,
              CATENA_VERSION_STRING);
    CHECK(CATENA_VERSION_MAJOR >= 0 && CATENA_VERSION_MINOR >= 0 && CATENA_VERSION_PATCH >= 0);
    CHECK(CATENA_VERSION_NUMBER ==
          CATENA_VERSION_MAJOR * 10000 + CATENA_VERSION_MINOR * 100 + CATENA_VERSION_PATCH);
    /* a static string: the same pointer every time */
    CHECK(ctn_version() == v);
    CHECK_DONE();
}
