/* garotor/mv.c: the full multivector of G(4,1), computed blade by blade.
 *
 * A basis blade is a set of basis vectors, held as a bit mask (bit k-1 for
 * e_k). The product of two blades A and B is +-(A xor B): the sign is the
 * parity of the transpositions that sort the concatenated vectors, times
 * e_k e_k = +1 for k <= 4 and -1 for k = 5 for every vector they share.
 * Everything below is that rule, applied to all 32 x 32 pairs.
 */
#include <garotor/mv.h>
#include <garotor/numtext.h>

#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal/blade.h"
#include "internal/mv_kernels.h"

static const char *const blade_names[32] = {
    "1",    "e1",   "e2",   "e3",   "e4",    "e5",    "e12",   "e13",   "e14",   "e15",   "e23",
    "e24",  "e25",  "e34",  "e35",  "e45",   "e123",  "e124",  "e125",  "e134",  "e135",  "e145",
    "e234", "e235", "e245", "e345", "e1234", "e1235", "e1245", "e1345", "e2345", "e12345"};

int ga_blade_grade(int i) { return (i >= 0 && i < 32) ? gabl_popcount5(gabl_mask[i]) : -1; }
const char *ga_blade_name(int i) { return (i >= 0 && i < 32) ? blade_names[i] : "?"; }
unsigned ga_blade_mask(int i) { return (i >= 0 && i < 32) ? gabl_mask[i] : 0u; }

ga_mv ga_mv_zero(void)
{
    ga_mv r = {{0}};
    return r;
}

ga_mv ga_mv_scalar(double s)
{
    ga_mv r = {{0}};
    r.c[GA_BLADE_SCALAR] = s;
    return r;
}

ga_mv ga_mv_blade(int i)
{
    ga_mv r = {{0}};
    if (i >= 0 && i < 32)
        r.c[i] = 1.0;
    return r;
}

ga_mv ga_mv_vector(double x1, double x2, double x3, double x4, double x5)
{
    ga_mv r = {{0}};
    r.c[GA_BLADE_E1] = x1;
    r.c[GA_BLADE_E2] = x2;
    r.c[GA_BLADE_E3] = x3;
    r.c[GA_BLADE_E4] = x4;
    r.c[GA_BLADE_E5] = x5;
    return r;
}

ga_mv ga_mv_add(ga_mv a, ga_mv b)
{
    for (int i = 0; i < 32; i++) a.c[i] += b.c[i];
    return a;
}

ga_mv ga_mv_sub(ga_mv a, ga_mv b)
{
    for (int i = 0; i < 32; i++) a.c[i] -= b.c[i];
    return a;
}

ga_mv ga_mv_scale(ga_mv a, double s)
{
    for (int i = 0; i < 32; i++) a.c[i] *= s;
    return a;
}

int ga_mv_isfinite(ga_mv a) { return gak_isfinite(a.c); }

double ga_mv_maxabs(ga_mv a) { return gak_maxabs(a.c); }

/* The products, every term written out by gen/generate.py from the blade rule
 * above (`python3 gen/generate.py` rewrites ga/mv_products.inc). Each
 * component sums its blade pairs in the order of the loop
 *
 *     for i, for j: r[index(mask_i ^ mask_j)] += sign(mask_i, mask_j) a[i] b[j]
 *
 * (a's blade, then b's; op keeps disjoint pairs, lc the pairs with a's blade
 * a subset of b's), so each sum is rounded as that loop rounds it. */
/* With gcc on x86-64 (GA_DENSE_BLOCKS), ga_mv_gp is the same product in
 * vectors, compiled for SSE2 (2 doubles), AVX2 (4) and AVX-512F (8); where the
 * C library resolves ifuncs (glibc), the compiler has the attribute and the
 * build asks for it (GAD_IFUNC of internal/dispatch.h: -Ddispatch=auto), the
 * dynamic loader picks the widest the CPU runs. Elsewhere (musl, which has
 * no IRELATIVE relocations; -Ddispatch=off) the SSE2 form serves every
 * CPU. All give mv_gp_dense's bits (docs/benchmarks.md has the speeds). */
#include "internal/dispatch.h"
#include "internal/gp_dense.h"
#if defined(GA_DENSE_BLOCKS) && GAD_IFUNC
#define GA_GP_IFUNC 1
#endif

#ifdef GA_GP_IFUNC
__attribute__((target("avx512f"))) static ga_mv gp_avx512f(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_gp_blocks8(a.c, b.c, r.c);
    return r;
}
__attribute__((target("avx2"))) static ga_mv gp_avx2(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_gp_blocks4(a.c, b.c, r.c);
    return r;
}
static ga_mv gp_sse2(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_gp_blocks2(a.c, b.c, r.c);
    return r;
}
typedef ga_mv (*gp_fn)(ga_mv, ga_mv);
GAD_RESOLVER static gp_fn gp_resolve(void)
{
    __builtin_cpu_init(); /* a resolver runs before the constructors that would */
    return __builtin_cpu_supports("avx512f") ? gp_avx512f
         : __builtin_cpu_supports("avx2")    ? gp_avx2
                                             : gp_sse2;
}
ga_mv ga_mv_gp(ga_mv a, ga_mv b) __attribute__((ifunc("gp_resolve")));
#elif defined(GA_DENSE_BLOCKS)
ga_mv ga_mv_gp(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_gp_blocks2(a.c, b.c, r.c);
    return r;
}
#else
ga_mv ga_mv_gp(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_gp_dense(a.c, b.c, r.c);
    return r;
}
#endif

/* The pointer forms of gp, op and lc (ga/internal/mv_kernels.h): not
   exported; garotor-bench links them to measure what passing 256-byte values
   costs (docs/benchmarks.md, "By value or by pointer"). */
#ifdef GA_GP_IFUNC
__attribute__((target("avx512f"))) static void gp_p_avx512f(const ga_mv *a, const ga_mv *b, ga_mv *r)
{
    mv_gp_blocks8(a->c, b->c, r->c);
}
__attribute__((target("avx2"))) static void gp_p_avx2(const ga_mv *a, const ga_mv *b, ga_mv *r)
{
    mv_gp_blocks4(a->c, b->c, r->c);
}
static void gp_p_sse2(const ga_mv *a, const ga_mv *b, ga_mv *r) { mv_gp_blocks2(a->c, b->c, r->c); }
typedef void (*gp_p_fn)(const ga_mv *, const ga_mv *, ga_mv *);
GAD_RESOLVER static gp_p_fn gp_p_resolve(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") ? gp_p_avx512f
         : __builtin_cpu_supports("avx2")    ? gp_p_avx2
                                             : gp_p_sse2;
}
void gak_gp_p(const ga_mv *a, const ga_mv *b, ga_mv *r) __attribute__((ifunc("gp_p_resolve")));
#elif defined(GA_DENSE_BLOCKS)
void gak_gp_p(const ga_mv *a, const ga_mv *b, ga_mv *r) { mv_gp_blocks2(a->c, b->c, r->c); }
#else
void gak_gp_p(const ga_mv *a, const ga_mv *b, ga_mv *r) { mv_gp_dense(a->c, b->c, r->c); }
#endif
void gak_op_p(const ga_mv *a, const ga_mv *b, ga_mv *r) { mv_op_dense(a->c, b->c, r->c); }

/* The fat dot and the products with a of one parity in vectors
   (mv_dot_blocks, mv_gpe_blocks, mv_gpo_blocks of ga/mv_products.inc), the
   width picked as ga_mv_gp's: gak_dot_blocks is ga_mv_dot (ga/mv_kernels.c),
   gak_gp_even and gak_gp_odd serve gak_gp. Without the vector forms, the
   straight-line dot and the dense product. */
#ifdef GA_GP_IFUNC
#define GA_BLOCKS_IFUNC(fn, kernel)                                                                          \
    __attribute__((target("avx512f"))) static void fn##_avx512f(const double *a, const double *b, double *r) \
    {                                                                                                        \
        kernel##8(a, b, r);                                                                                  \
    }                                                                                                        \
    __attribute__((target("avx2"))) static void fn##_avx2(const double *a, const double *b, double *r)       \
    {                                                                                                        \
        kernel##4(a, b, r);                                                                                  \
    }                                                                                                        \
    static void fn##_sse2(const double *a, const double *b, double *r) { kernel##2(a, b, r); }               \
    GAD_RESOLVER static gak_kernel_fn fn##_resolve(void)                                                     \
    {                                                                                                        \
        __builtin_cpu_init();                                                                                \
        return __builtin_cpu_supports("avx512f") ? fn##_avx512f                                              \
             : __builtin_cpu_supports("avx2")    ? fn##_avx2                                                 \
                                                 : fn##_sse2;                                                   \
    }                                                                                                        \
    void fn(const double *a, const double *b, double *r) __attribute__((ifunc(#fn "_resolve")));
GA_BLOCKS_IFUNC(gak_dot_blocks, mv_dot_blocks)
GA_BLOCKS_IFUNC(gak_gp_even, mv_gpe_blocks)
GA_BLOCKS_IFUNC(gak_gp_odd, mv_gpo_blocks)
/* ga_mv_dot picked as ga_mv_gp is, each form writing its result where the
   caller wants it (through gak_dot_blocks, one more call and a copy of the
   256-byte result: 1.35 times the time by pointer, docs/benchmarks.md) */
__attribute__((target("avx512f"))) static ga_mv dot_avx512f(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_dot_blocks8(a.c, b.c, r.c);
    return r;
}
__attribute__((target("avx2"))) static ga_mv dot_avx2(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_dot_blocks4(a.c, b.c, r.c);
    return r;
}
static ga_mv dot_sse2(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_dot_blocks2(a.c, b.c, r.c);
    return r;
}
GAD_RESOLVER static gp_fn dot_resolve(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") ? dot_avx512f
         : __builtin_cpu_supports("avx2")    ? dot_avx2
                                             : dot_sse2;
}
ga_mv ga_mv_dot(ga_mv a, ga_mv b) __attribute__((ifunc("dot_resolve")));
#elif defined(GA_DENSE_BLOCKS)
void gak_dot_blocks(const double *a, const double *b, double *r) { mv_dot_blocks2(a, b, r); }
void gak_gp_even(const double *a, const double *b, double *r) { mv_gpe_blocks2(a, b, r); }
void gak_gp_odd(const double *a, const double *b, double *r) { mv_gpo_blocks2(a, b, r); }
ga_mv ga_mv_dot(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_dot_blocks2(a.c, b.c, r.c);
    return r;
}
#else
void gak_dot_blocks(const double *a, const double *b, double *r) { gak_dot_dense(a, b, r); }
void gak_gp_even(const double *a, const double *b, double *r) { mv_gp_dense(a, b, r); }
void gak_gp_odd(const double *a, const double *b, double *r) { mv_gp_dense(a, b, r); }
ga_mv ga_mv_dot(ga_mv a, ga_mv b)
{
    ga_mv r;
    gak_dot_dense(a.c, b.c, r.c);
    return r;
}
#endif
void gak_lc_p(const ga_mv *a, const ga_mv *b, ga_mv *r) { mv_lc_dense(a->c, b->c, r->c); }

ga_mv ga_mv_op(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_op_dense(a.c, b.c, r.c);
    return r;
}

ga_mv ga_mv_lc(ga_mv a, ga_mv b)
{
    ga_mv r;
    mv_lc_dense(a.c, b.c, r.c);
    return r;
}

/* ga_mv_sp and ga_mv_ip: ga/mv_kernels.c (generated, as the products above); ga_mv_dot above. */

/* Multiply the grade-k part by sign[k]. */
static ga_mv grade_signs(ga_mv a, const double sign[6])
{
    /* the grades are consecutive in the canonical order: 0 | 1..5 | 6..15 |
       16..25 | 26..30 | 31 (loops of fixed length, in vectors) */
    a.c[0] *= sign[0];
    for (int i = 1; i < 6; i++) a.c[i] *= sign[1];
    for (int i = 6; i < 16; i++) a.c[i] *= sign[2];
    for (int i = 16; i < 26; i++) a.c[i] *= sign[3];
    for (int i = 26; i < 31; i++) a.c[i] *= sign[4];
    a.c[31] *= sign[5];
    return a;
}

ga_mv ga_mv_reverse(ga_mv a)
{
    static const double s[6] = {1, 1, -1, -1, 1, 1}; /* (-1)^(k(k-1)/2) */
    return grade_signs(a, s);
}

ga_mv ga_mv_involute(ga_mv a)
{
    static const double s[6] = {1, -1, 1, -1, 1, -1}; /* (-1)^k */
    return grade_signs(a, s);
}

ga_mv ga_mv_conjugate(ga_mv a)
{
    static const double s[6] = {1, -1, -1, 1, 1, -1}; /* product of the two */
    return grade_signs(a, s);
}

ga_mv ga_mv_grade(ga_mv a, int k)
{
    for (int i = 0; i < 32; i++)
        if (gabl_popcount5(gabl_mask[i]) != k)
            a.c[i] = 0.0;
    return a;
}

ga_mv ga_mv_dual(ga_mv a)
{
    /* I^-1 = -I, since I^2 = -1 in G(4,1) */
    return ga_mv_scale(ga_mv_gp(a, ga_mv_blade(GA_BLADE_E12345)), -1.0);
}

ga_mv ga_mv_undual(ga_mv a) { return ga_mv_gp(a, ga_mv_blade(GA_BLADE_E12345)); }

double ga_mv_norm2(ga_mv a) { return ga_mv_sp(a, ga_mv_reverse(a)); }

double ga_mv_norm(ga_mv a) { return sqrt(fabs(ga_mv_norm2(a))); }

/* ---- text ------------------------------------------------------------------ */

/* One term: " - " / " + " between terms ("-" first), the coefficient in
   ga_double_format's shortest form unless it is +-1 on a blade, then the blade's name. */
ga_status ga_mv_format(ga_mv a, char *buf, size_t cap, size_t *len)
{
    if (!buf || !len)
        return GA_ERR_ARG;
    if (!ga_mv_isfinite(a))
        return GA_ERR_NOTFINITE;
    char tmp[GA_MV_TEXT_MAX];
    size_t n = 0;
    for (int i = 0; i < 32; i++) {
        double v = a.c[i];
        if (v == 0.0)
            continue;
        const char *sep = signbit(v) ? (n ? " - " : "-") : (n ? " + " : "");
        char num[GA_DOUBLE_TEXT_MAX];
        size_t k = i > 0 && fabs(v) == 1.0 ? 0 : ga_double_format(fabs(v), num);
        size_t ls = strlen(sep), ln = strlen(blade_names[i]);
        if (ls + k + ln >= sizeof tmp - n)
            return GA_ERR_ARG; /* cannot happen: GA_MV_TEXT_MAX is the longest text */
        memcpy(tmp + n, sep, ls);
        memcpy(tmp + n + ls, num, k);
        n += ls + k;
        if (i > 0) {
            memcpy(tmp + n, blade_names[i], ln);
            n += ln;
        }
    }
    if (n == 0)
        tmp[n++] = '0';
    tmp[n] = '\0';
    if (n + 1 > cap)
        return GA_ERR_ARG;
    memcpy(buf, tmp, n + 1);
    *len = n;
    return GA_OK;
}

static const char *skip_blanks(const char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r') s++;
    return s;
}

/* A blade name at s ("e" and its digits): its index, or -1. */
static int read_blade(const char **s)
{
    const char *p = *s;
    if (*p != 'e' || !(p[1] >= '0' && p[1] <= '9'))
        return -1;
    size_t k = 1;
    while (p[k] >= '0' && p[k] <= '9') k++;
    for (int i = 1; i < 32; i++)
        if (strlen(blade_names[i]) == k && strncmp(blade_names[i], p, k) == 0) {
            *s = p + k;
            return i;
        }
    return -1;
}

/* A decimal number at s: digits, an optional fraction, and an exponent only
   as 'e' or 'E' with a sign, or 'E' with digits ("e" and a digit begins a
   blade name). 1 and its value, or 0. */
static int read_number(const char **s, double *out)
{
    const char *p = *s;
    size_t k = 0, digits = 0;
    while (p[k] >= '0' && p[k] <= '9') k++, digits++;
    if (p[k] == '.') {
        k++;
        while (p[k] >= '0' && p[k] <= '9') k++, digits++;
    }
    if (digits == 0)
        return 0;
    if ((p[k] == 'e' || p[k] == 'E') && (p[k + 1] == '+' || p[k + 1] == '-') && p[k + 2] >= '0' &&
        p[k + 2] <= '9') {
        k += 2;
        while (p[k] >= '0' && p[k] <= '9') k++;
    } else if (p[k] == 'E' && p[k + 1] >= '0' && p[k + 1] <= '9') {
        k++;
        while (p[k] >= '0' && p[k] <= '9') k++;
    }
    /* strtod on the text itself where it stops where the number does (it
       reads a decimal of any length, as the tool's reader does). Where it
       does not: it would read on ("2e12": 2 e12 here, 2x10^12 to strtod), or
       LC_NUMERIC's decimal point is not '.' and it stopped at the '.' (a
       German locale reads "1.5" as 1); then on a copy of the number alone,
       its '.' replaced by the locale's decimal point, which strtod must read
       whole. So the text is read the same whatever the locale. A
       beyond-range decimal is what strtod makes of it: +-Inf
       (GA_ERR_NOTFINITE in ga_mv_parse), 0 or a subnormal below. */
    char *end;
    double v = strtod(p, &end);
    if (end != p + k) {
        char tmp[400];
        const char *dp = localeconv()->decimal_point;
        if (!dp || !*dp)
            dp = ".";
        size_t ld = strlen(dp), n = 0;
        for (size_t i = 0; i < k; i++) {
            if (n + ld >= sizeof tmp)
                return 0; /* 400 characters or more: glued to a blade name, or a '.' under a ',' locale */
            if (p[i] == '.') {
                memcpy(tmp + n, dp, ld);
                n += ld;
            } else
                tmp[n++] = p[i];
        }
        tmp[n] = '\0';
        v = strtod(tmp, &end);
        if (end != tmp + n)
            return 0;
    }
    *out = v;
    *s = p + k;
    return 1;
}

ga_status ga_mv_parse(const char *text, ga_mv *out)
{
    if (!text || !out)
        return GA_ERR_ARG;
    ga_mv r = ga_mv_zero();
    const char *s = skip_blanks(text);
    int terms = 0, finite = 1;
    while (*s) {
        double sign = 1.0, v = 1.0;
        if (*s == '+' || *s == '-') {
            sign = *s == '-' ? -1.0 : 1.0;
            s = skip_blanks(s + 1);
        } else if (terms > 0)
            return GA_ERR_ARG; /* two terms need a sign between them */
        int has_num = read_number(&s, &v), i = 0;
        if (has_num) {
            const char *t = skip_blanks(s);
            if (*t == '*')
                t = skip_blanks(t + 1);
            else if (*t != 'e')
                t = s;
            i = read_blade(&t);
            if (i < 0 && t != s)
                return GA_ERR_ARG; /* "2 *" or "2 e9" */
            i = i < 0 ? 0 : i;
            s = t;
        } else if ((i = read_blade(&s)) < 0)
            return GA_ERR_ARG;
        r.c[i] += sign * v;
        /* a number beyond the double range, or terms of one blade adding up
           past it ("1e+308 + 1e+308"): GA_ERR_NOTFINITE alike */
        finite &= isfinite(v) && isfinite(r.c[i]);
        terms++;
        s = skip_blanks(s);
    }
    if (terms == 0)
        return GA_ERR_ARG;
    if (!finite)
        return GA_ERR_NOTFINITE;
    *out = r;
    return GA_OK;
}
