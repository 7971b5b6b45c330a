/* garotor/status.c: the words for the status codes of types.h. */
#include "types.h"

const char *ga_strerror(int status)
{
    switch (status) {
    case GA_OK: return "ok";
    case GA_ENOTFINITE: return "not finite (NaN or infinity)";
    case GA_ESINGULAR: return "not invertible";
    case GA_ENOTPOINT: return "not a finite conformal point";
    case GA_ENOTRIGID: return "not a rigid motion";
    case GA_EDOMAIN: return "outside the domain";
    case GA_EARG: return "invalid argument";
    case GA_ENOTBLADE: return "not an object of the expected kind";
    default: return "unknown status";
    }
}
