/* tests/test_gp_blocks.c: the vector forms of the geometric product
 * (mv_gp_blocks2, 4 and 8 of ga/mv_products.inc, which ga_mv_gp runs on
 * x86-64 with gcc) against the straight-line mv_gp_dense, bit for bit,
 * each width on the instruction set ga/mv.c compiles it for (where the CPU
 * has it); and ga_mv_gp, whichever the loader picked, against mv_gp_dense.
 * Inputs: dense random multivectors, with zeros, negative zeros and
 * coefficients from 1e-300 to 1e300 mixed in (finite: only a NaN's sign may
 * differ). Elsewhere (another compiler or system) only the last comparison
 * runs, and ga_mv_gp is mv_gp_dense itself.
 */
#include <string.h>

#include "testkit.h"

#include "../ga/internal/gp_dense.h"

#ifdef GA_DENSE_BLOCKS
__attribute__((target("avx512f"))) static void gp8(const double *a, const double *b, double *r)
{
    mv_gp_blocks8(a, b, r);
}
__attribute__((target("avx2"))) static void gp4(const double *a, const double *b, double *r)
{
    mv_gp_blocks4(a, b, r);
}
static void gp2(const double *a, const double *b, double *r) { mv_gp_blocks2(a, b, r); }
#endif

static double coef(tk_rng *r)
{
    switch (tk_next(r) % 8) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return (tk_uni(r) < 0.5 ? -1 : 1) * tk_loguni(r, 1e-300, 1e300);
    default: return tk_range(r, -1, 1);
    }
}

/* every product form against the straight-line one, bit for bit */
static void section_blocks(void)
{
    tk_rng r = {16};
    tk_check same = tk_begin("ga_mv_gp = mv_gp_dense, bit for bit (10^5 pairs)", 0);
#ifdef GA_DENSE_BLOCKS
    __builtin_cpu_init();
    int has8 = __builtin_cpu_supports("avx512f"), has4 = __builtin_cpu_supports("avx2");
    tk_check c2 = tk_begin("mv_gp_blocks2 (SSE2) = mv_gp_dense, bit for bit", 0);
    tk_check c4 = tk_begin(
        has4 ? "mv_gp_blocks4 (AVX2) = mv_gp_dense, bit for bit" : "mv_gp_blocks4: no AVX2 here, not run", 0);
    tk_check c8 = tk_begin(has8 ? "mv_gp_blocks8 (AVX-512F) = mv_gp_dense, bit for bit"
                                : "mv_gp_blocks8: no AVX-512F here, not run",
                           0);
#endif
    for (int n = 0; n < 100000; n++) {
        ga_mv a, b, want, got;
        for (int i = 0; i < 32; i++) {
            a.c[i] = coef(&r);
            b.c[i] = coef(&r);
        }
        mv_gp_dense(a.c, b.c, want.c);
        got = ga_mv_gp(a, b);
        tk_add_bool(&same, memcmp(&got, &want, sizeof got) == 0);
#ifdef GA_DENSE_BLOCKS
        gp2(a.c, b.c, got.c);
        tk_add_bool(&c2, memcmp(&got, &want, sizeof got) == 0);
        if (has4) {
            gp4(a.c, b.c, got.c);
            tk_add_bool(&c4, memcmp(&got, &want, sizeof got) == 0);
        }
        if (has8) {
            gp8(a.c, b.c, got.c);
            tk_add_bool(&c8, memcmp(&got, &want, sizeof got) == 0);
        }
#endif
    }
    tk_end(&same);
#ifdef GA_DENSE_BLOCKS
    tk_end(&c2);
    tk_end(&c4);
    tk_end(&c8);
#endif
}

static const tk_section sections[] = {
    {"blocks", section_blocks, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_gp_blocks", sections, TK_COUNT(sections));
}
