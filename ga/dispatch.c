/* ga/dispatch.c: the kernels of ga/internal/dispatch.h in their three forms,
 * baseline x86-64 (SSE2), AVX2 and AVX-512F (256- and 512-bit vectors, no
 * FMA: the same bits), and the pick between them (the widest the CPU runs), made once when the library is
 * loaded (an ifunc: glibc's loader calls the resolver, which asks the CPU). Where GAD_IFUNC is 0
 * (-Ddispatch=off, musl, another architecture or compiler) each kernel is its baseline form alone.
 * docs/benchmarks.md ("Dispatch at load time") has which kernels gained and which were left alone.
 */
#include "internal/dispatch.h"

#if GAD_IFUNC
typedef void (*mat4_apply_fn)(const double *, const ga_vec3 *, size_t, ga_vec3 *);

static void mat4_apply_base(const double *a, const ga_vec3 *in, size_t n, ga_vec3 *out)
{
    gad_mat4_apply_kernel(a, in, n, out);
}
__attribute__((target("avx2"))) static void mat4_apply_avx2(const double *a, const ga_vec3 *in, size_t n,
                                                            ga_vec3 *out)
{
    gad_mat4_apply_kernel(a, in, n, out);
}
__attribute__((target("avx512f"))) static void mat4_apply_avx512f(const double *a, const ga_vec3 *in,
                                                                  size_t n, ga_vec3 *out)
{
    gad_mat4_apply_kernel(a, in, n, out);
}

GAD_RESOLVER static mat4_apply_fn mat4_apply_resolve(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") ? mat4_apply_avx512f
         : __builtin_cpu_supports("avx2")    ? mat4_apply_avx2
                                             : mat4_apply_base;
}
void gad_mat4_apply(const double *a, const ga_vec3 *in, size_t n, ga_vec3 *out)
    __attribute__((ifunc("mat4_apply_resolve")));
#else
void gad_mat4_apply(const double *a, const ga_vec3 *in, size_t n, ga_vec3 *out)
{
    gad_mat4_apply_kernel(a, in, n, out);
}
#endif
