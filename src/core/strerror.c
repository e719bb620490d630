/* Names of status codes. */
#include "catena/core.h"

const char *ctn_strerror(int status)
{
    switch (status) {
    case CTN_OK: return "ok";
    case CTN_ERR_NOMEM: return "out of memory";
    case CTN_ERR_INVALID: return "invalid argument";
    case CTN_ERR_MODEL: return "invalid model";
    case CTN_ERR_IO: return "input/output error";
    case CTN_ERR_LINALG: return "sparse linear algebra failure";
    case CTN_ERR_NOCONV: return "root finder did not converge";
    case CTN_ERR_DOMAIN: return "no solution exists for these inputs";
    case CTN_ERR_INTERRUPTED: return "interrupted";
    default: return "unknown status";
    }
}
