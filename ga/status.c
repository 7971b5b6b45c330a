/* garotor/status.c: the words for the status codes of types.h. */
#include <garotor/types.h>

const char *ga_status_string(ga_status status)
{
    switch (status) {
    case GA_OK: return "ok";
    case GA_ERR_NOTFINITE: return "not finite (NaN or infinity)";
    case GA_ERR_SINGULAR: return "not invertible";
    case GA_ERR_NOTPOINT: return "not a finite conformal point";
    case GA_ERR_NOTRIGID: return "not a rigid motion";
    case GA_ERR_DOMAIN: return "outside the domain";
    case GA_ERR_ARG: return "invalid argument";
    case GA_ERR_NOTBLADE: return "not an object of the expected kind";
    case GA_ERR_IMAGINARY: return "an imaginary object (negative squared radius)";
    case GA_ERR_PRECISION: return "would lose digits (too far from the origin for its size)";
    default: return "unknown status";
    }
}
