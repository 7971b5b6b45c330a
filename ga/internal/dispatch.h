/* ga/internal/dispatch.h (internal, not installed): the kernels that
 * ga/dispatch.c compiles three times, for baseline x86-64 (SSE2), AVX2 and
 * AVX-512F, and picks once per process, when the library is loaded. Prefix
 * gad_.
 *
 * GAD_IFUNC is 1 where the pick is made: x86-64, glibc (its loader runs the
 * resolvers of IRELATIVE relocations; musl has none), a compiler with the
 * ifunc attribute, and a build that asked for it (-Ddispatch=auto, the
 * default, defines GA_HAVE_IFUNC where the compiler has the attribute).
 * Elsewhere GAD_IFUNC is 0 and each kernel is its baseline form alone.
 * ga/mv.c picks the width of ga_mv_gp's vectors under the same condition.
 *
 * Each kernel is written once, here, as an always-inline function: compiled
 * into a function with target("avx2") or target("avx512f"), it runs in 256-
 * or 512-bit vectors. No product is fused into a sum: the build passes
 * -ffp-contract=off to every file (and the AVX2 form's target has no "fma"),
 * so every form rounds each multiplication and each addition as the baseline
 * does, and all give the same bits for every input (tests/test_dispatch.c
 * checks it).
 */
#ifndef GA_INTERNAL_DISPATCH_H
#define GA_INTERNAL_DISPATCH_H

#include <garotor/types.h>
#include <stddef.h>
#include <stdint.h> /* a C library header: glibc's defines __GLIBC__ */

#if defined(GA_HAVE_IFUNC) && defined(__GLIBC__) && defined(__x86_64__) &&                                   \
    (defined(__GNUC__) || defined(__clang__))
#define GAD_IFUNC 1
#else
#define GAD_IFUNC 0
#endif

/* A resolver runs while the loader relocates the library, before any
   constructor (so it calls __builtin_cpu_init itself) and before a
   sanitizer's runtime has mapped its shadow memory: instrumented, it dies
   there (clang -fsanitize=address: SIGSEGV while loading), so it is left
   uninstrumented. "used": clang 14 does not count the ifunc attribute as a
   use of a static function (-Wunused-function). */
#if defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 8)
#define GAD_RESOLVER __attribute__((used, no_sanitize("address", "undefined")))
#else
#define GAD_RESOLVER __attribute__((used))
#endif

#if defined(__GNUC__)
#define GAD_KERNEL static inline __attribute__((always_inline)) /* into each form that uses it */
#else
#define GAD_KERNEL static inline
#endif

/* out[i] = the rows 0..2 of the 4x4 a (row-major) times (in[i], 1), one
   point after the other, each read whole before it is written (so in == out
   works): 9 multiplications and 9 additions a point, in this order. */
GAD_KERNEL void gad_mat4_apply_kernel(const double *a, const ga_vec3 *in, size_t n, ga_vec3 *out)
{
    const double a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3], a4 = a[4], a5 = a[5];
    const double a6 = a[6], a7 = a[7], a8 = a[8], a9 = a[9], a10 = a[10], a11 = a[11];
    for (size_t i = 0; i < n; i++) {
        double x = in[i].x, y = in[i].y, z = in[i].z;
        out[i].x = ((a0 * x + a1 * y) + a2 * z) + a3;
        out[i].y = ((a4 * x + a5 * y) + a6 * z) + a7;
        out[i].z = ((a8 * x + a9 * y) + a10 * z) + a11;
    }
}

/* gad_mat4_apply_kernel in the form picked for this CPU (ga/dispatch.c):
   the loop of ga_mat4_apply_many, so of ga_rotor_apply_many */
void gad_mat4_apply(const double *a, const ga_vec3 *in, size_t n, ga_vec3 *out);

#endif
