/* tests/test_dispatch.c: the kernels that ga/dispatch.c picks per CPU at
 * load time (ga/internal/dispatch.h), each in its forms, baseline, AVX2 and
 * AVX-512F, compiled here from the same source with the same attributes (and
 * the build's -ffp-contract=off) as the library compiles them, against the
 * baseline bit for bit; and the public calls, whichever form the loader
 * picked, against the baseline form. A form runs only where the CPU has its
 * instructions (and only with gcc or clang on x86-64); elsewhere the public
 * calls are checked against the baseline.
 *
 * Inputs: 4x4 matrices and points with coefficients of either sign from
 * 1e-300 to 1e300, subnormals, zeros of both signs, and some infinities and
 * NaNs (only there may the bits differ: equal numbers, or both NaN);
 * batches of 0 to 67 points (every remainder of a vector loop), written to
 * another array and in place (in == out).
 */
#include <string.h>

#include "testkit.h"

#include "../ga/internal/dispatch.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define TD_AVX2 1
__attribute__((target("avx2"))) static void apply_avx2(const double *a, const ga_vec3 *in, size_t n,
                                                       ga_vec3 *out)
{
    gad_mat4_apply_kernel(a, in, n, out);
}
__attribute__((target("avx512f"))) static void apply_avx512f(const double *a, const ga_vec3 *in, size_t n,
                                                             ga_vec3 *out)
{
    gad_mat4_apply_kernel(a, in, n, out);
}
typedef void (*apply_fn)(const double *, const ga_vec3 *, size_t, ga_vec3 *);
#endif
static void apply_base(const double *a, const ga_vec3 *in, size_t n, ga_vec3 *out)
{
    gad_mat4_apply_kernel(a, in, n, out);
}

static double coef(tk_rng *r, int special)
{
    switch (tk_next(r) % (special ? 12 : 10)) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return (tk_uni(r) < 0.5 ? -1 : 1) * tk_loguni(r, 1e-300, 1e300);
    case 3: return tk_range(r, -1, 1) * 0x1p-1060; /* subnormal */
    case 10: return tk_uni(r) < 0.5 ? -INFINITY : INFINITY;
    case 11: return NAN;
    default: return tk_range(r, -10, 10);
    }
}

/* the same bits; with NaNs or infinities in, equal numbers or both NaN */
static int same(const ga_vec3 *x, const ga_vec3 *y, size_t n, int special)
{
    if (!special)
        return memcmp(x, y, n * sizeof *x) == 0;
    const double *a = &x->x, *b = &y->x;
    for (size_t i = 0; i < 3 * n; i++)
        if (!(memcmp(a + i, b + i, sizeof *a) == 0 || (isnan(a[i]) && isnan(b[i]))))
            return 0;
    return 1;
}

#define MAXN 67

static void section_mat4(void)
{
    tk_rng r = {29};
#ifdef TD_AVX2
    __builtin_cpu_init();
    static const char *const name[2] = {"AVX2", "AVX-512F"};
    const apply_fn form[2] = {apply_avx2, apply_avx512f};
    const int has[2] = {__builtin_cpu_supports("avx2"), __builtin_cpu_supports("avx512f")};
    tk_check c_form[2], c_inplace[2], c_special[2];
    for (int f = 0; f < 2; f++) {
        if (has[f]) {
            c_form[f] = tk_beginf(0, "%s form = baseline form, bit for bit (finite inputs)", name[f]);
            c_inplace[f] = tk_beginf(0, "%s form in place (in == out) = baseline form", name[f]);
            c_special[f] = tk_beginf(0,
                                     "%s form = baseline form with NaN and infinities in (equal or both NaN)",
                                     name[f]);
        } else {
            c_form[f] = tk_beginf(0, "%s form: not on this CPU, not run", name[f]);
            c_inplace[f] = tk_beginf(0, "%s form in place: not on this CPU, not run", name[f]);
            c_special[f] = tk_beginf(0, "%s form with NaN and infinities: not on this CPU, not run", name[f]);
        }
    }
#endif
    tk_check c_pub = tk_begin("ga_mat4_apply_many (the picked form) = baseline form, bit for bit", 0);
    tk_check c_rot = tk_begin("ga_rotor_apply_many = baseline form on ga_rotor_to_mat4, bit for bit", 0);
    for (int k = 0; k < 20000; k++) {
        int special = k % 4 == 3;
        size_t n = (size_t)(k % (MAXN + 1));
        ga_mat4 m;
        ga_vec3 in[MAXN], want[MAXN], got[MAXN];
        for (int i = 0; i < 16; i++) m.m[i] = coef(&r, special);
        for (size_t i = 0; i < n; i++) {
            in[i].x = coef(&r, special);
            in[i].y = coef(&r, special);
            in[i].z = coef(&r, special);
        }
        apply_base(m.m, in, n, want);
        memset(got, 0x55, sizeof got);
        TK_OK(ga_mat4_apply_many(m, in, n, got));
        tk_add_bool(&c_pub, same(got, want, n, special));
#ifdef TD_AVX2
        for (int f = 0; f < 2; f++)
            if (has[f]) {
                memset(got, 0x55, sizeof got);
                form[f](m.m, in, n, got);
                tk_add_bool(special ? &c_special[f] : &c_form[f], same(got, want, n, special));
                memcpy(got, in, n * sizeof *in);
                form[f](m.m, got, n, got);
                tk_add_bool(&c_inplace[f], same(got, want, n, special));
            }
#endif
        if (!special && k % 8 == 0) {
            ga_rotor R = ga_rotor_exp(ga_twist_to_generator(tk_twist(&r, k / 8 % TK_FAMILIES)));
            for (size_t i = 0; i < n; i++) {
                ga_vec3 u = tk_unit(&r); /* one draw a statement: argument order is the compiler's */
                in[i] = tk_scale(u, tk_loguni(&r, 1e-6, 1e6));
            }
            apply_base(ga_rotor_to_mat4(R).m, in, n, want);
            TK_OK(ga_rotor_apply_many(R, in, n, got));
            tk_add_bool(&c_rot, same(got, want, n, 0));
        }
    }
#ifdef TD_AVX2
    for (int f = 0; f < 2; f++) {
        tk_end(&c_form[f]);
        tk_end(&c_inplace[f]);
        tk_end(&c_special[f]);
    }
#endif
    tk_end(&c_pub);
    tk_end(&c_rot);
}

static const tk_section sections[] = {
    {"mat4_apply", section_mat4, 0},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_dispatch", sections, TK_COUNT(sections)); }
