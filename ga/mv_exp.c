/* ga/mv_exp.c: exp of any bivector of G(4,1) in closed form (ga_mv_exp):
 * the coefficients alpha..delta of its l and ab forms, their scale kept apart
 * where a hyperbolic part overflows, the split into factors for a large
 * bivector, and the rigid frame of a large null part. Notation and the
 * functions of t: ga/internal/bivector_fns.h; docs/versors.md derives every
 * formula.
 */
#include <garotor/versor.h>

#include "internal/bivector_fns.h"
#include "internal/bivector_frames.h"
#include <garotor/rotor.h>
#include <float.h>
#include <math.h>

/* ---- the coefficients -------------------------------------------------------- */

/* exp(B) = exp(B1) exp(B2) = (C1 + S1 B1)(C2 + S2 B2), and with
   B1 = (l1 B - Bq/2)/(l1 - l2), B2 = (Bq/2 - l2 B)/(l1 - l2), B1 B2 = q/2:
     exp(B) = alpha + beta B + gamma q + delta Bq,
     alpha = C1 C2, gamma = S1 S2 / 2,
     beta  = (l1 S1 C2 - l2 S2 C1) / (l1 - l2),
     delta = (l1 E1 S2 - l2 E2 S1) / (2 (l1 - l2))         ("l form").
   With x = sqrt l1, y = sqrt l2 and a = (x+y)^2, b = (x-y)^2 = s +- sqrt(qq)
   (real when qq >= 0) the same coefficients are, by the product-to-sum
   formulas,
     alpha = (C(a) + C(b))/2, beta = (S(a) + S(b))/2,
     gamma = (a K(a) - b K(b))/(a - b), delta = (a T(a) - b T(b))/(a - b)
   ("ab form"). The l form divides by l1 - l2 = sqrt(s^2 - qq), the ab form by
   a - b = 2 sqrt(qq); s^2 = (l1 - l2)^2 + qq, so one of them is at least
   |s|/sqrt 2: we take that one. Every numerator is a difference of terms
   proportional to l (or a, b), so it is relatively exact to a few ulps, and
   the quotient is too. qq < 0 (an elliptic and a hyperbolic part) always
   takes the l form: then l1 - l2 >= max(|s|, sqrt(-qq)). */
typedef struct {
    double alpha, beta, gamma, delta;
    int e; /* exp(B) = 2^e (alpha + ...): 0 unless a hyperbolic part overflows */
} coeffs;

/* ---- overflow: the scale of a large hyperbolic factor kept apart ------------- */

/* Where a hyperbolic part has sqrt(l) = r above BIG_R, cosh r, sinh r and the
   products of the formulas (l S(l) ~ r e^r / 2) would overflow and meet the
   zeros of the other factors as inf * 0 or inf - inf: NaN. There the
   functions are returned times 2^-e and the caller multiplies its result by
   2^e at the end (ldexp: +-Inf for a coefficient beyond DBL_MAX, with its
   sign, 0 for an exact 0, the value itself where it is in range), as exp
   overflows. BIG_R = 600 keeps r e^r / 2 < 2^885 below it. */
#define BIG_R 600.0

/* e^r / 2 = 2^e g for r >= BIG_R, g in [1/2, 1): e = n = floor(r / ln 2) and
   g = exp(r - n ln 2) / 2 with the reduction exact (ln 2 = LN2_HI + LN2_LO,
   LN2_HI with 32 trailing zero bits as in fdlibm, so n LN2_HI is exact for
   n < 2^21 and r - n LN2_HI by Sterbenz' lemma). cosh r and sinh r are e^r/2
   to a relative e^-2r < 2^-1700. Beyond n = 2^19 (r ~ 3.6e5) only "huge":
   g = 1, e = 2^20, and 2^e times any nonzero double overflows, as the true
   value does (2^-1074 e^r / 2 > DBL_MAX from r ~ 1455). */
static double half_exp_big(double r, int *e)
{
    const double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
    double n = floor(r / ln2_hi);
    if (!(n < 0x1p19)) {
        *e = 1 << 20;
        return 1.0;
    }
    double rr = (r - n * ln2_hi) - n * ln2_lo;
    *e = (int)n;
    return 0.5 * exp(rr);
}

/* gab_fns_at(t) times 2^-*e, *e = 0 (and gab_fns_at itself) unless sqrt(t) > BIG_R. */
static gab_fns fns_scaled(double t, int *e)
{
    if (!(t > BIG_R * BIG_R)) {
        *e = 0;
        return gab_fns_at(t);
    }
    double r = sqrt(t);
    gab_fns f;
    f.c = half_exp_big(r, e);
    double one = ldexp(1.0, -*e); /* 1 times 2^-e: 0 for the "huge" e */
    f.s = f.c / r;
    f.k = (f.c - one) / t;
    f.t = (f.s - one) / t;
    f.e = (f.c - f.s) / t;
    return f;
}

/* f times 2^-d (d >= 0): a factor brought to a larger common scale */
static gab_fns fns_shift(gab_fns f, int d)
{
    if (d != 0) {
        f.c = ldexp(f.c, -d), f.s = ldexp(f.s, -d), f.k = ldexp(f.k, -d);
        f.t = ldexp(f.t, -d), f.e = ldexp(f.e, -d);
    }
    return f;
}

/* x times 2^e, componentwise (x as it is for e = 0) */
static ga_mv mv_ldexp(ga_mv x, int e)
{
    if (e != 0)
        for (int i = 0; i < 32; i++) x.c[i] = ldexp(x.c[i], e);
    return x;
}

static coeffs exp_coeffs(double s, double qq)
{
    coeffs k;
    double d = fmax(s * s - qq, 0.0);
    k.e = 0;
    if (fabs(s) <= 0x1p-60 && fabs(qq) <= 0x1p-120) {
        /* |l1|, |l2| <= 2^-60: every coefficient is its limit at l = 0 to
           within |l| < 2^-60 relative, below the rounding of 1 (exp(B) =
           1 + B + q/2 + Bq/6 up to terms of relative size l); the formulas
           below would divide 0 by 0 once s^2 underflows (a null blade
           beside a part whose square is subnormal: NaN) */
        k.alpha = 1.0, k.beta = 1.0, k.gamma = 0.5, k.delta = 1.0 / 6.0;
        return k;
    }
    if (qq < 0.0 || d >= qq) {
        /* every term has one function of l1 and one of l2: each carries its
           own scale (a large hyperbolic part: fns_scaled) */
        double l1, l2;
        int e1, e2;
        gab_roots(s, qq, &l1, &l2);
        gab_fns f1 = fns_scaled(l1, &e1), f2 = fns_scaled(l2, &e2);
        double dl = l1 - l2;
        k.alpha = f1.c * f2.c;
        k.gamma = 0.5 * f1.s * f2.s;
        k.beta = (l1 * f1.s * f2.c - l2 * f2.s * f1.c) / dl;
        k.delta = (l1 * f1.e * f2.s - l2 * f2.e * f1.s) / (2.0 * dl);
        k.e = e1 + e2;
    } else {
        /* sums of a function of a and one of b: both at the larger scale */
        double r = sqrt(qq), a = s + r, b = s - r;
        int ea, eb;
        gab_fns fa = fns_scaled(a, &ea), fb = fns_scaled(b, &eb);
        k.e = ea > eb ? ea : eb;
        fa = fns_shift(fa, k.e - ea);
        fb = fns_shift(fb, k.e - eb);
        k.alpha = 0.5 * (fa.c + fb.c);
        k.beta = 0.5 * (fa.s + fb.s);
        k.gamma = (a * fa.k - b * fb.k) / (2.0 * r);
        k.delta = (a * fa.t - b * fb.t) / (2.0 * r);
    }
    return k;
}

/* ---- exp of a bivector whose square overflows ---------------------------------- */

/* One factor exp(Bi) = C(li) + S(li) Bi of B = 2^k B', given Xi' = 2^-k Bi,
   as its scalar *c and bivector S(li) Bi; li = w <Bi Bi>_0 (w = 1 for a
   2-blade, 2 for a part in an ideal of P, whose <P>_0 = 1/2). Where Bi is
   at most 2^300, li is taken from Bi itself (its square from 2^-k Bi could
   underflow) and the functions of li as they are; beyond, with
   t = 2^k sqrt|li'|, S(li) Bi = (sin t / sqrt(-li')) Xi' keeps every
   intermediate in range. A hyperbolic part with t > BIG_R is returned times
   2^-*e (*c = 2^-e cosh t, the bivector 2^-e (sinh t / t) Bi, finite), for
   the caller to scale at the end; *e = 0 otherwise. */
static ga_mv big_factor(ga_mv Y, double t, double d, int room, double *c, int *e);
static ga_mv factor_scaled(double g, double f, ga_mv Y, int n, int room, double *c, int *e);
static ga_mv scaled_factor(ga_mv Xp, int k, double w, int room, double *c, int *e)
{
    ga_mv X;
    for (int i = 0; i < 32; i++) X.c[i] = ldexp(Xp.c[i], k);
    *e = 0;
    if (ga_mv_isfinite(X) && ga_mv_maxabs(X) <= 0x1p300) {
        double l = w * ga_mv_sp(X, X);
        if (l > BIG_R * BIG_R) {
            double t = sqrt(l);
            return big_factor(X, t, t, room, c, e);
        }
        gab_fns f = gab_fns_at(l);
        *c = f.c;
        return ga_mv_scale(X, f.s);
    }
    double lp = w * ga_mv_sp(Xp, Xp), r = sqrt(fabs(lp)), t = ldexp(r, k);
    if (!isfinite(t))
        t = DBL_MAX; /* an angle beyond DBL_MAX: only known to be huge */
    if (r == 0.0)    /* a null part: exp = 1 + Bi = 2^k (2^-k + Xi'), as large as it is
                        (beyond DBL_MAX, X holds Inf, which met the other factor's zeros) */
        return factor_scaled(ldexp(1.0, -k), 1.0, Xp, k, room, c, e);
    if (lp > 0.0 && t > BIG_R) /* (sinh t / t) 2^k Xp = (sinh t / r) Xp */
        return big_factor(Xp, t, r, room, c, e);
    *c = lp < 0.0 ? cos(t) : cosh(t);
    return ga_mv_scale(Xp, (lp < 0.0 ? sin(t) : sinh(t)) / r);
}

/* cosh t + (sinh t / d) Y (Y = Bi and d = t, or Y = 2^-k Bi and d = 2^-k t),
   as 2^*e (*c + the bivector returned), t > BIG_R: e^t / 2 = 2^n g, of
   which 2^p is applied here, as much as leaves the largest coefficient
   below 2^room, and *e = n - p is left. Applied before the product with
   Y's coefficients, p keeps a small one from becoming subnormal:
   exp(1000 e45 + 1e-320 e14) has an e14 coefficient of ~1e111 to full
   precision, which g 1e-320 / 1000, a subnormal of few digits, and a later
   2^n would not have. */
static ga_mv big_factor(ga_mv Y, double t, double d, int room, double *c, int *e)
{
    int n;
    double g = half_exp_big(t, &n);
    return factor_scaled(g, g / d, Y, n, room, c, e);
}

/* 2^n (g + f Y) as 2^*e (*c + the bivector returned), with 2^p of 2^n
   applied (p as in big_factor) and *e = n - p */
static ga_mv factor_scaled(double g, double f, ga_mv Y, int n, int room, double *c, int *e)
{
    double mx = fmax(fmax(g, ga_mv_maxabs(Y) * f), DBL_MIN);
    int p = room - ilogb(mx);
    p = p < 0 ? 0 : p > n ? n : p;
    ga_mv V;
    for (int i = 0; i < 32; i++) V.c[i] = fabs(Y.c[i]) >= 1.0 ? ldexp(Y.c[i] * f, p) : ldexp(Y.c[i], p) * f;
    *c = ldexp(g, p);
    *e = n - p;
    return V;
}

/* R (3 - ~R R)/2: Newton-Schulz steps towards the group, each taking
   ~R R = 1 + e (e of grades 0 and 4, |e| < 1/2) to 1 + O(e^2), while e is
   above the rounding of ~R R. Where B splits into 2-blades to rounding
   the factors are on the group already; where a part is rounding noise
   (below u |B|) that is not a 2-blade, its factor is not, usually by ~1e-7.
   From |e| near 1/2 the steps are slow at first (the convergence is
   quadratic only once |e| is well below 1/2): up to 12 are taken.
   An R that overflowed (a hyperbolic part beyond ~710), or whose ~R R does,
   is left as it is (a step would turn its infinities into NaN). */
static ga_mv onto_group(ga_mv R)
{
    for (int it = 0; it < 12; it++) {
        ga_mv e = ga_mv_gp(ga_mv_reverse(R), R);
        e.c[0] -= 1.0;
        double m = ga_mv_maxabs(R);
        if (!ga_mv_isfinite(e) || !(ga_mv_maxabs(e) < 0.5) ||
            ga_mv_maxabs(e) <= 64.0 * DBL_EPSILON * fmax(1.0, m * m))
            break;
        R = gab_lin(1.0, R, -0.5, ga_mv_gp(R, e));
    }
    return R;
}

/* exp(B) for max |B| > 8 (see exp_large): on B' = 2^-k B (exact, max |B'|
   in [2^239, 2^240): s^2 ~ |B'|^4 and B' q' ~ |B'|^3 do not overflow), split
   into its commuting parts
   (the l form's B1 = (l1 B - Bq/2)/(l1 - l2), B2 = (Bq/2 - l2 B)/(l1 - l2),
   all homogeneous so that they hold for the scaled quantities), or, where
   l1 - l2 is small against s (near-equal parts, the ab form's case), into
   the ideals of P+- = (1 +- J)/2, J = q / sqrt(q.q): exp(B) P+- =
   (C(a) + S(a) B) P+- with a = s +- sqrt(q.q) (docs/versors.md). Each
   factor is bounded when elliptic, so a bivector with an elliptic part above
   ~1.3e154 (whose square overflows) has its bounded exp; parts are known
   to u max|B|^2 in their squares, as in the unscaled formulas. */

/* both parts null to rounding: 1 + B + q/2 + Bq/6, huge as it is */
static ga_mv exp_huge_null(gab_square sq, int k)
{
    ga_mv r;
    for (int i = 0; i < 32; i++)
        r.c[i] = ldexp(sq.b.c[i], k) + ldexp(0.5 * sq.q.c[i], 2 * k) + ldexp(sq.bq.c[i] / 6.0, 3 * k);
    r.c[0] += 1.0;
    return r;
}

/* the l form's commuting parts, each factor formed on its own */
static ga_mv exp_huge_l_form(gab_square sq, int k)
{
    double c1, c2;
    int e1, e2;
    double l1, l2;
    gab_roots(sq.s, sq.qq, &l1, &l2);
    double dl = l1 - l2;
    ga_mv X1 = gab_lin(l1 / dl, sq.b, -0.5 / dl, sq.bq), X2 = gab_lin(0.5 / dl, sq.bq, -l2 / dl, sq.b);
    /* each factor's square from its own 2-blade (Xi^2 = li): the roots
       lose the smaller one to the rounding of s and q.q when the parts
       differ by more than 1/u in size, and a factor C(l) + S(l) X is on
       the group only with the l of its X */
    /* the factor of the smaller li first (the hyperbolic part, if any,
       is the other): the product of the two stays below 2^1016 when
       the other takes up to 2^(1010 - ilogb max|first|) of its scale */
    int first = l1 < l2;
    ga_mv V1, V2;
    if (first) {
        V1 = scaled_factor(X1, k, 1.0, 1010, &c1, &e1);
        V1.c[0] += c1;
        V2 = scaled_factor(X2, k, 1.0, 1010 - ilogb(fmax(ga_mv_maxabs(V1), DBL_MIN)), &c2, &e2);
        V2.c[0] += c2;
    } else {
        V2 = scaled_factor(X2, k, 1.0, 1010, &c2, &e2);
        V2.c[0] += c2;
        V1 = scaled_factor(X1, k, 1.0, 1010 - ilogb(fmax(ga_mv_maxabs(V2), DBL_MIN)), &c1, &e1);
        V1.c[0] += c1;
    }
    /* the product of the finite scaled factors, then what is left of
       their scale */
    return mv_ldexp(ga_mv_gp(V1, V2), e1 + e2);
}

/* near-equal parts: the factors in the ideals of P+- */
static ga_mv exp_huge_ideals(ga_mv Bp, gab_square sq, int k)
{
    double c1;
    double r = sqrt(sq.qq);
    ga_mv J = ga_mv_scale(sq.q, 1.0 / r), term[2];
    int e[2];
    for (int sgn = 1; sgn >= -1; sgn -= 2) {
        ga_mv P = ga_mv_scale(J, 0.5 * sgn);
        P.c[0] += 0.5;
        /* B P+- cancels the parts of the other ideal to rounding of |B|, which
           is not small against B P+- for near-equal parts (t1 - t2 << t1):
           projected again, what is left of them is rounding of |B P+-| */
        ga_mv X = ga_mv_grade(ga_mv_gp(Bp, P), 2);
        X = ga_mv_grade(ga_mv_gp(X, P), 2);
        /* a part that is rounding of |B| (t1 - t2 below 64 u |B|): its angle
           cannot be told from zero, and its X is not a 2-blade of P's ideal,
           whose factor C + S X would be off the group by up to 1: taken as
           0, the factor P */
        if (ga_mv_maxabs(X) <= 64.0 * DBL_EPSILON * ga_mv_maxabs(Bp))
            X = ga_mv_zero();
        /* X^2 = a P (<P>_0 = 1/2): a from X, not s +- sqrt(q.q), which
           cancels for near-equal parts (a = -(t1 - t2)^2) */
        int i = sgn > 0 ? 0 : 1;
        ga_mv V = scaled_factor(X, k, 2.0, 1000, &c1, &e[i]);
        term[i] = gab_lin(c1, P, 1.0, V);
    }
    /* the two ideals' terms at the larger of their scales (a part of an
       ideal is hyperbolic only by rounding: both parts of near-equal size
       are elliptic, G(4,1) having one timelike direction) */
    int e0 = e[0] > e[1] ? e[0] : e[1];
    ga_mv out = gab_lin(1.0, gab_lin(1.0, ga_mv_zero(), 1.0, mv_ldexp(term[0], e[0] - e0)), 1.0,
                        mv_ldexp(term[1], e[1] - e0));
    return mv_ldexp(out, e0);
}

static ga_mv exp_huge_parts(ga_mv B)
{
    int k = ilogb(ga_mv_maxabs(B)) - 239;
    ga_mv Bp;
    for (int i = 0; i < 32; i++) Bp.c[i] = ldexp(B.c[i], -k);
    gab_square sq = gab_square_of(Bp);
    double m2 = ga_mv_maxabs(sq.b) * ga_mv_maxabs(sq.b), noise = 64.0 * DBL_EPSILON * m2;
    double d = fmax(sq.s * sq.s - sq.qq, 0.0);
    if (fabs(sq.s) <= noise && fabs(sq.qq) <= noise * noise)
        return exp_huge_null(sq, k);
    if (sq.qq < 0.0 || d >= sq.qq)
        return exp_huge_l_form(sq, k);
    return exp_huge_ideals(Bp, sq, k);
}

static ga_mv exp_huge(ga_mv B) { return onto_group(exp_huge_parts(B)); }

/* ---- a large null part: exp in its rigid frame --------------------------------- */

/* The generator of a bivector held in a rigid frame, and the largest part of
   it that is not rigid (e45, e_i4 - e_i5): rounding when the frame is right */
static ga_generator rigid_part(ga_mv br, double *rest)
{
    ga_generator g = {br.c[GA_BLADE_E12],
                      br.c[GA_BLADE_E13],
                      br.c[GA_BLADE_E23],
                      0.5 * br.c[GA_BLADE_E14] + 0.5 * br.c[GA_BLADE_E15],
                      0.5 * br.c[GA_BLADE_E24] + 0.5 * br.c[GA_BLADE_E25],
                      0.5 * br.c[GA_BLADE_E34] + 0.5 * br.c[GA_BLADE_E35]};
    *rest = fmax(fabs(br.c[GA_BLADE_E45]),
                 fmax(fabs(0.5 * br.c[GA_BLADE_E14] - 0.5 * br.c[GA_BLADE_E15]),
                      fmax(fabs(0.5 * br.c[GA_BLADE_E24] - 0.5 * br.c[GA_BLADE_E25]),
                           fabs(0.5 * br.c[GA_BLADE_E34] - 0.5 * br.c[GA_BLADE_E35]))));
    return g;
}

/* exp(b) through the rigid frame of its null part (ga_rotor_exp there, exact
   for any angle and translation): 0 where b has none, that is where the part
   of V b ~V that is not rigid exceeds rounding of |b| (two rotations, a
   boost) for both candidates of n */
static int exp_null_part(ga_mv b, ga_mv *out)
{
    double M[5][5], m = ga_mv_maxabs(b), best = 16.0 * DBL_EPSILON * m;
    gabf_contraction_matrix(b, M);
    int found = 0;
    for (int cand = 0; cand < 2; cand++) {
        ga_mv V;
        double rest;
        if (!gabf_rigid_frame(M, cand, &V))
            continue;
        ga_generator g = rigid_part(ga_mv_grade(gabf_sandwich(V, b), 2), &rest);
        if (!(rest <= best))
            continue;
        best = rest, found = 1;
        *out = gabf_sandwich(ga_mv_reverse(V), ga_rotor_to_mv(ga_rotor_exp(g)));
    }
    return found;
}

/* ---- exp --------------------------------------------------------------------- */

/* Beyond max |B| = 8 the coefficients lose u |B|^2 to the cancellations of
   s +- sqrt(q.q) and s^2 - q.q, and beyond 2^240 they overflow: there B is
   split into its factors (exp_huge), except where both parts are near null
   (|li| <= 2^-20 |B|^2), which the split cannot separate and the
   coefficients handle (their limits at l = 0). exp(b) in *out, or 0 where
   the coefficients are kept. */
static int exp_large(ga_mv b, double m, ga_mv *out)
{
    if (m > 0x1p240) {
        *out = exp_huge(b);
        return 1;
    }
    gab_square h = gab_square_of(b);
    double m2 = m * m;
    /* a null part larger than the others (both squares below |B|^2/64):
       there both forms lose ~u |B|^2, and its rigid frame has the exp
       exact (a part whose square is that of B, as a huge rotation, is left
       to exp_huge: the frame's rounding would change its angle by u |B|).
       Only for <B^2>_0 < 0 (a turn beside it): a large blade that is
       slightly hyperbolic (c e1 n + t e45, t^2 below the rounding of c^2 in
       a conjugated B, exact here) has no null part to make rigid, and the
       frame would drop its t, a factor e^t */
    if (h.s < 0.0 && -h.s <= m2 / 64.0 && sqrt(fabs(h.qq)) <= m2 / 64.0 && exp_null_part(b, out))
        return 1;
    if (!(fabs(h.s) <= 0x1p-20 * m2 && fabs(h.qq) <= 0x1p-40 * m2 * m2)) {
        *out = exp_huge(b);
        return 1;
    }
    return 0;
}

ga_mv ga_mv_exp(ga_mv B)
{
    ga_mv b = ga_mv_grade(B, 2), r;
    double m = ga_mv_maxabs(b);
    if (ga_mv_isfinite(b) && m > 8.0 && exp_large(b, m, &r))
        return r;
    gab_square sq = gab_square_of(B);
    coeffs k = exp_coeffs(sq.s, sq.qq);
    if (k.e != 0) {
        /* a hyperbolic part beyond BIG_R beside a near-null one: as much of
           2^e on the coefficients as leaves every term below 2^1010, before
           they meet small coefficients of B (as in big_factor) */
        double mx = fmax(fmax(fabs(k.alpha), fabs(k.beta) * ga_mv_maxabs(sq.b)),
                         fmax(fabs(k.gamma) * ga_mv_maxabs(sq.q), fabs(k.delta) * ga_mv_maxabs(sq.bq)));
        int p = 1010 - ilogb(mx);
        p = p < 0 ? 0 : p > k.e ? k.e : p;
        k.alpha = ldexp(k.alpha, p), k.beta = ldexp(k.beta, p);
        k.gamma = ldexp(k.gamma, p), k.delta = ldexp(k.delta, p);
        k.e -= p;
    }
    r = gab_lin(k.beta, sq.b, k.delta, sq.bq);
    r = gab_lin(1.0, r, k.gamma, sq.q);
    r.c[0] += k.alpha;
    return mv_ldexp(r, k.e);
}
