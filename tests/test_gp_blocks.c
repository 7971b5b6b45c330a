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

#ifdef GA_DENSE_BLOCKS
/* the other vector forms (mv_dot_blocks, mv_gpe_blocks, mv_gpo_blocks) at
   each width: kind 0 dot, 1 gp with a even, 2 gp with a odd */
#define FORMS(W, tgt)                                                                                        \
    tgt static void forms##W(int kind, const double *a, const double *b, double *r)                          \
    {                                                                                                        \
        if (kind == 0)                                                                                       \
            mv_dot_blocks##W(a, b, r);                                                                       \
        else if (kind == 1)                                                                                  \
            mv_gpe_blocks##W(a, b, r);                                                                       \
        else                                                                                                 \
            mv_gpo_blocks##W(a, b, r);                                                                       \
    }
FORMS(8, __attribute__((target("avx512f"))))
FORMS(4, __attribute__((target("avx2"))))
FORMS(2, )

/* the sign of the product of blades with masks a and b (e5 e5 = -1) */
static double blade_sign(unsigned a, unsigned b)
{
    int swaps = 0;
    for (unsigned x = a >> 1; x; x >>= 1) swaps += __builtin_popcount(x & b);
    if (a & b & 0x10u)
        swaps++;
    return swaps & 1 ? -1.0 : 1.0;
}

/* the fat dot as ga/mv.c's loop computed it */
static void dot_loop(const double *a, const double *b, double *r)
{
    int index[32];
    for (int i = 0; i < 32; i++) index[ga_blade_mask(i)] = i;
    for (int i = 0; i < 32; i++) r[i] = 0.0;
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++) {
            unsigned ma = ga_blade_mask(i), mb = ga_blade_mask(j);
            if ((ma & mb) == ma || (ma & mb) == mb)
                r[index[ma ^ mb]] += blade_sign(ma, mb) * a[i] * b[j];
        }
}

/* equal numbers (+0 = -0), or both NaN */
static int same_numbers(const double *x, const double *y)
{
    for (int i = 0; i < 32; i++)
        if (!(x[i] == y[i] || (isnan(x[i]) && isnan(y[i]))))
            return 0;
    return 1;
}

/* each against the loop or the dense product it stands for: the same
   numbers (the sign of a zero may differ: the terms left out are zeros) */
static void section_forms(void)
{
    __builtin_cpu_init();
    int has[3] = {1, __builtin_cpu_supports("avx2"), __builtin_cpu_supports("avx512f")};
    static const char *const kinds[3] = {"mv_dot_blocks = the dot's loop",
                                         "mv_gpe_blocks = mv_gp_dense, a even",
                                         "mv_gpo_blocks = mv_gp_dense, a odd"};
    static const int widths[3] = {2, 4, 8};
    tk_rng r = {17};
    for (int kind = 0; kind < 3; kind++)
        for (int w = 0; w < 3; w++) {
            tk_check c = has[w]
                           ? tk_beginf(0, "%s, width %d (10^4 pairs)", kinds[kind], widths[w])
                           : tk_beginf(0, "%s, width %d: not on this CPU, not run", kinds[kind], widths[w]);
            for (int n = 0; has[w] && n < 10000; n++) {
                double a[32], b[32], want[32], got[32];
                for (int i = 0; i < 32; i++) {
                    a[i] = coef(&r);
                    b[i] = coef(&r);
                    if (kind > 0 && ga_blade_grade(i) % 2 != kind - 1)
                        a[i] = 0.0; /* a of the parity the form reads */
                }
                if (kind == 0)
                    dot_loop(a, b, want);
                else
                    mv_gp_dense(a, b, want);
                if (w == 0)
                    forms2(kind, a, b, got);
                else if (w == 1)
                    forms4(kind, a, b, got);
                else
                    forms8(kind, a, b, got);
                tk_add_bool(&c, same_numbers(got, want));
            }
            tk_end(&c);
        }
}
#endif

static const tk_section sections[] = {
    {"blocks", section_blocks, 0},
#ifdef GA_DENSE_BLOCKS
    {"forms", section_forms, 0},
#endif
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_gp_blocks", sections, TK_COUNT(sections));
}
