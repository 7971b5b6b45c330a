/* fuzz/fuzz_reader.h: arbitrary bytes as doubles, for the numeric fuzz targets.
 *
 * A value is one tag byte, then (for some tags) more bytes. The tags make the
 * values that break numerical code one byte away, so the fuzzer reaches them
 * at once instead of searching 2^64 bit patterns for them:
 *
 *   tag & 15   value
 *   0          the next 8 bytes as a raw IEEE double (any NaN payload,
 *              subnormals, +-DBL_MAX...)
 *   1, 2       +0, -0
 *   3, 4       +1, -1
 *   5          NaN
 *   6, 7       +Inf, -Inf
 *   8          +-1e308 (the sign from bit 4 of the tag)
 *   9          +-k * 4.9e-324 (a subnormal; k = 1 + the next byte)
 *   10         +-1e-12 * (1 + next byte)       (tiny)
 *   11         +-pi, and bit 5: pi - 1e-9      (half turns and just short)
 *   12         +-1e6 * (1 + next byte) / 256   (the edge of the valid range)
 *   13         +-(signed next byte) / 16       (small, exact)
 *   14         +-DBL_MAX
 *   15         +-1e-300 * (1 + next byte)      (tiny, still normal)
 *
 * Past the end of the input every value is 0 and every byte 0, so any input
 * decodes to a complete call. Nothing here allocates or has state beyond the
 * cursor. */
#ifndef GAROTOR_FUZZ_READER_H
#define GAROTOR_FUZZ_READER_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const uint8_t *p;
    size_t n, k;
} fz_reader;

static inline fz_reader fz_begin(const uint8_t *data, size_t size)
{
    fz_reader r = {data, size, 0};
    return r;
}

static inline uint8_t fz_byte(fz_reader *r) { return r->k < r->n ? r->p[r->k++] : 0; }

static inline double fz_double_(fz_reader *r);
/* FZ_TRACE=1 in the environment prints every value read (to triage a crash:
 * FZ_TRACE=1 build-fuzz/fuzz/fuzz_numeric crash-...). */
static inline double fz_double(fz_reader *r)
{
    static int trace = -1;
    if (trace < 0) {
        const char *e = getenv("FZ_TRACE");
        trace = e && *e && *e != '0';
    }
    double x = fz_double_(r);
    if (trace)
        fprintf(stderr, "fz: value %.17g\n", x);
    return x;
}

static inline double fz_double_(fz_reader *r)
{
    uint8_t tag = fz_byte(r);
    double sign = (tag & 16) ? -1.0 : 1.0;
    switch (tag & 15) {
    case 0: {
        uint8_t b[8];
        for (int i = 0; i < 8; i++) b[i] = fz_byte(r);
        double x;
        memcpy(&x, b, sizeof x);
        return x;
    }
    case 1: return 0.0;
    case 2: return -0.0;
    case 3: return 1.0;
    case 4: return -1.0;
    case 5: return NAN;
    case 6: return INFINITY;
    case 7: return -INFINITY;
    case 8: return sign * 1e308;
    case 9: return sign * 4.9406564584124654e-324 * (1 + fz_byte(r));
    case 10: return sign * 1e-12 * (1 + fz_byte(r));
    case 11: return sign * ((tag & 32) ? 3.141592653589793 - 1e-9 : 3.141592653589793);
    case 12: return sign * 1e6 * (1 + fz_byte(r)) / 256.0;
    case 13: return sign * (double)(int8_t)fz_byte(r) / 16.0;
    case 14: return sign * DBL_MAX;
    default: return sign * 1e-300 * (1 + fz_byte(r));
    }
}

static inline void fz_doubles(fz_reader *r, double *x, int n)
{
    for (int i = 0; i < n; i++) x[i] = fz_double(r);
}

static inline int fz_all_finite(const double *x, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

/* The largest |x_i|; NaN if any x_i is NaN (fmax alone would skip it). */
static inline double fz_maxabs(const double *x, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; i++) {
        if (isnan(x[i]))
            return NAN;
        m = fmax(m, fabs(x[i]));
    }
    return m;
}

#endif
