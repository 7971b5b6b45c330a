/* ga/versor.c: versors of G(4,1), and exp, log and split of any bivector and
 * rotor in closed form. docs/versors.md derives every formula here.
 *
 * Notation. B = B1 + B2 with commuting 2-blades, B1^2 = l1, B2^2 = l2
 * (Dorst-Valkenburg 2011 §3). With s = <B^2>_0 and q = <B^2>_4 = 2 B1 B2:
 * l1 + l2 = s and l1 l2 = q.q/4 (q.q = <q q>_0, a scalar since q is a
 * 4-vector of a 5-dimensional space). The entire functions of one real t
 *   C(t) = cosh(sqrt t) = sum t^k/(2k)!         (cos sqrt(-t) for t < 0)
 *   S(t) = sinh(sqrt t)/sqrt t = sum t^k/(2k+1)!
 *   K(t) = (C - 1)/t,  T(t) = (S - 1)/t,  E(t) = (C - S)/t
 * give exp(Bi) = C(li) + S(li) Bi, whatever the sign of li (l = 0: 1 + Bi).
 */
#include <garotor/versor.h>

#include <garotor/conformal.h>
#include <garotor/rotor.h>
#include <float.h>
#include <math.h>

/* ---- the functions of t ------------------------------------------------------ */

/* sum_{j>=0} t^j / (d0 + 2j)! for |t| <= 1: C is d0 = 0, S d0 = 1,
   K d0 = 2, T d0 = 3. The terms fall by 1/((d0+2j+1)(d0+2j+2)) each, so
   18 terms leave less than 1/36! < 1e-41 of the first. */
static double series(double t, int d0)
{
    double term = 1.0, sum = 0.0;
    for (int k = 2; k <= d0; k++) term /= k;
    for (int j = 0; j < 18; j++) {
        sum += term;
        term *= t / ((d0 + 2 * j + 1) * (double)(d0 + 2 * j + 2));
    }
    return sum;
}

typedef struct {
    double c, s, k, t, e; /* C, S, K, T, E at one t */
} fns;

static fns fns_at(double t)
{
    fns f;
    if (fabs(t) <= 1.0) {
        f.c = series(t, 0);
        f.s = series(t, 1);
        /* K = sum_{k>=1} t^(k-1)/(2k)!, T = sum_{k>=1} t^(k-1)/(2k+1)! */
        f.k = series(t, 2);
        f.t = series(t, 3);
        f.e = f.k - f.t; /* (C - 1 - (S - 1))/t */
        return f;
    }
    double r = sqrt(fabs(t));
    f.c = t > 0 ? cosh(r) : cos(r);
    f.s = (t > 0 ? sinh(r) : sin(r)) / r;
    f.k = (f.c - 1.0) / t;
    f.t = (f.s - 1.0) / t;
    f.e = (f.c - f.s) / t;
    return f;
}

/* ---- small helpers ---------------------------------------------------------- */

static ga_mv lin(double a, ga_mv x, double b, ga_mv y)
{
    ga_mv r;
    for (int i = 0; i < 32; i++) r.c[i] = a * x.c[i] + b * y.c[i];
    return r;
}

static int finite_mv(ga_mv a) { return ga_mv_isfinite(a); }

/* s = <B^2>_0, q = <B^2>_4, qq = <q q>_0, Bq = <B q>_2 */
typedef struct {
    ga_mv b, q, bq;
    double s, qq;
} bsquare;

static bsquare square_of(ga_mv B)
{
    bsquare r;
    r.b = ga_mv_grade(B, 2);
    ga_mv b2 = ga_mv_gp(r.b, r.b);
    r.s = b2.c[0];
    r.q = ga_mv_grade(b2, 4);
    r.qq = ga_mv_sp(r.q, r.q);
    r.bq = ga_mv_grade(ga_mv_gp(r.b, r.q), 2);
    return r;
}

/* l1, l2: the roots of l^2 - s l + qq/4, |l1| >= |l2|, without cancellation;
   d = s^2 - qq clamped at 0 (it is >= 0 for every bivector of G(4,1):
   docs/versors.md). */
static void roots(double s, double qq, double *l1, double *l2)
{
    double d = fmax(s * s - qq, 0.0);
    double big = 0.5 * (s + copysign(sqrt(d), s));
    *l1 = big;
    *l2 = big != 0.0 ? 0.25 * qq / big : 0.0;
}

/* ---- exp --------------------------------------------------------------------- */

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

/* fns_at(t) times 2^-*e, *e = 0 (and fns_at itself) unless sqrt(t) > BIG_R. */
static fns fns_scaled(double t, int *e)
{
    if (!(t > BIG_R * BIG_R)) {
        *e = 0;
        return fns_at(t);
    }
    double r = sqrt(t);
    fns f;
    f.c = half_exp_big(r, e);
    double one = ldexp(1.0, -*e); /* 1 times 2^-e: 0 for the "huge" e */
    f.s = f.c / r;
    f.k = (f.c - one) / t;
    f.t = (f.s - one) / t;
    f.e = (f.c - f.s) / t;
    return f;
}

/* f times 2^-d (d >= 0): a factor brought to a larger common scale */
static fns fns_shift(fns f, int d)
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
           below would divide 0 by 0 once s^2 underflows (B = 0.25 (e14 -
           e15) + 2e-162 e23 gave NaN; found by fuzz/fuzz_numeric,
           fuzz/regress/numeric/mv-exp-null-blade-subnormal-square) */
        k.alpha = 1.0, k.beta = 1.0, k.gamma = 0.5, k.delta = 1.0 / 6.0;
        return k;
    }
    if (qq < 0.0 || d >= qq) {
        /* every term has one function of l1 and one of l2: each carries its
           own scale (a large hyperbolic part: fns_scaled) */
        double l1, l2;
        int e1, e2;
        roots(s, qq, &l1, &l2);
        fns f1 = fns_scaled(l1, &e1), f2 = fns_scaled(l2, &e2);
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
        fns fa = fns_scaled(a, &ea), fb = fns_scaled(b, &eb);
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
        fns f = fns_at(l);
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
   exp(1000 e45 + 1e-320 e14) has the e14 coefficient 9.85024590787617e110
   (mpmath; ga_mv_exp gives it to the last digit), which g 1e-320 / 1000, a
   subnormal of few digits, and a later 2^n would not. */
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

/* exp(B) for max |B| > 8 (see ga_mv_exp): on B' = 2^-k B (exact, max |B'|
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
/* R (3 - ~R R)/2: Newton-Schulz steps towards the group, each taking
   ~R R = 1 + e (e of grades 0 and 4, |e| < 1/2) to 1 + O(e^2), while e is
   above the rounding of ~R R. Where B splits into 2-blades to rounding
   the factors are on the group already; where a part is rounding noise
   (below u |B|) that is not a 2-blade, its factor is not, usually by ~1e-7.
   From |e| near 1/2 the steps are slow at first (0.497, 0.405, 0.309,
   0.172, 0.050, 3.8e-3, 2.2e-5, 7.2e-10, then rounding, seen before the
   near-null parts of the ideal route were taken as 0): up to 12 are taken.
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
        R = lin(1.0, R, -0.5, ga_mv_gp(R, e));
    }
    return R;
}

static ga_mv exp_huge_parts(ga_mv B);
static ga_mv exp_huge(ga_mv B) { return onto_group(exp_huge_parts(B)); }

static ga_mv exp_huge_parts(ga_mv B)
{
    int k = ilogb(ga_mv_maxabs(B)) - 239;
    ga_mv Bp;
    for (int i = 0; i < 32; i++) Bp.c[i] = ldexp(B.c[i], -k);
    bsquare sq = square_of(Bp);
    double m2 = ga_mv_maxabs(sq.b) * ga_mv_maxabs(sq.b), noise = 64.0 * DBL_EPSILON * m2;
    double d = fmax(sq.s * sq.s - sq.qq, 0.0);
    if (fabs(sq.s) <= noise && fabs(sq.qq) <= noise * noise) {
        /* both parts null to rounding: 1 + B + q/2 + Bq/6, huge as it is */
        ga_mv r;
        for (int i = 0; i < 32; i++)
            r.c[i] = ldexp(sq.b.c[i], k) + ldexp(0.5 * sq.q.c[i], 2 * k) + ldexp(sq.bq.c[i] / 6.0, 3 * k);
        r.c[0] += 1.0;
        return r;
    }
    double c1, c2;
    int e1, e2;
    if (sq.qq < 0.0 || d >= sq.qq) {
        double l1, l2;
        roots(sq.s, sq.qq, &l1, &l2);
        double dl = l1 - l2;
        ga_mv X1 = lin(l1 / dl, sq.b, -0.5 / dl, sq.bq), X2 = lin(0.5 / dl, sq.bq, -l2 / dl, sq.b);
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
           whose factor C + S X would be off the group by up to 1 (fuzz/
           regress/numeric/mv-exp-huge-isoclinic-*): taken as 0, the factor P */
        if (ga_mv_maxabs(X) <= 64.0 * DBL_EPSILON * ga_mv_maxabs(Bp))
            X = ga_mv_zero();
        /* X^2 = a P (<P>_0 = 1/2): a from X, not s +- sqrt(q.q), which
           cancels for near-equal parts (a = -(t1 - t2)^2) */
        int i = sgn > 0 ? 0 : 1;
        ga_mv V = scaled_factor(X, k, 2.0, 1000, &c1, &e[i]);
        term[i] = lin(c1, P, 1.0, V);
    }
    /* the two ideals' terms at the larger of their scales (a part of an
       ideal is hyperbolic only by rounding: both parts of near-equal size
       are elliptic, G(4,1) having one timelike direction) */
    int e0 = e[0] > e[1] ? e[0] : e[1];
    ga_mv out = lin(1.0, lin(1.0, ga_mv_zero(), 1.0, mv_ldexp(term[0], e[0] - e0)), 1.0,
                    mv_ldexp(term[1], e[1] - e0));
    return mv_ldexp(out, e0);
}

static int exp_null_part(ga_mv b, ga_mv *out);

ga_mv ga_mv_exp(ga_mv B)
{
    /* Beyond max |B| = 8 the coefficients below lose u |B|^2 to the
       cancellations of s +- sqrt(q.q) and s^2 - q.q (R ~R = 1 + 1.5e-8 for
       parts of 1e4, unbounded beyond 1e8), and beyond 2^240 they overflow:
       there B is split into its factors (exp_huge), except where both parts
       are near null (|li| <= 2^-20 |B|^2), which the split cannot separate
       and the coefficients handle (their limits at l = 0). */
    ga_mv b = ga_mv_grade(B, 2);
    double m = ga_mv_maxabs(b);
    if (ga_mv_isfinite(b) && m > 8.0) {
        if (m > 0x1p240)
            return exp_huge(b);
        bsquare h = square_of(b);
        double m2 = m * m;
        /* a null part larger than the others (both squares below |B|^2/64):
           there both forms lose ~u |B|^2 (4e-9 for a turn beside a null part
           of 300), and its rigid frame has the exp exact (a part whose
           square is that of B, as a huge rotation, is left to exp_huge: the
           frame's rounding would change its angle by u |B|). Only for
           <B^2>_0 < 0 (a turn beside it): a large blade that is slightly
           hyperbolic (c e1 n + t e45, t^2 below the rounding of c^2 in a
           conjugated B, exact here) has no null part to make rigid, and the
           frame would drop its t, a factor e^t */
        ga_mv r;
        if (h.s < 0.0 && -h.s <= m2 / 64.0 && sqrt(fabs(h.qq)) <= m2 / 64.0 && exp_null_part(b, &r))
            return r;
        if (!(fabs(h.s) <= 0x1p-20 * m2 && fabs(h.qq) <= 0x1p-40 * m2 * m2))
            return exp_huge(b);
    }
    bsquare sq = square_of(B);
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
    ga_mv r = lin(k.beta, sq.b, k.delta, sq.bq);
    r = lin(1.0, r, k.gamma, sq.q);
    r.c[0] += k.alpha;
    return mv_ldexp(r, k.e);
}

/* ---- log --------------------------------------------------------------------- */

/* R = R1 R2, Ri = ci + Pi, Pi = S(li) Bi, mi = Pi^2 = ci^2 - 1. With
   R0 = <R>_0, R2 = <R>_2, R4 = <R>_4 and W = <R2 R4>_2:
     R0 = c1 c2,  R2 = c2 P1 + c1 P2,  R4 = P1 P2,  W = c1 m2 P1 + c2 m1 P2,
     <R4 R4>_0 = m1 m2,  <R2 R2>_0 - 2 <R4 R4>_0 = m1 + m2,
   so m1, m2 are the roots of a quadratic (Dorst-Valkenburg 2011 §4 reach the
   same split through the polar decomposition), and solving the two linear
   equations for P1, P2 and adding Bi = Pi / S(li) gives
     B = kR R2 + kW W,
     kR = (c2 S1 l1 - c1 S2 l2)/(m1 - m2),  kW = (l2 E2/S2 - l1 E1/S1)/(m1 - m2)
   ("m form", with c/S = 1 + l E/S). Near m1 = m2 (two rotations by nearly
   equal angles t1, t2, R0 > 0) the ab form of the same coefficients, with
   u = t1 + t2, v = t2 - t1, a = -u^2, b = -v^2:
     kR = (1/S(a) + 1/S(b))/2,
     kW = (a T(a) - b T(b)) / ((b K(b) - a K(a)) S(a) S(b)),
   where cos u = R0 - sqrt(m1 m2), sin^2 u = -<R2 R2>_0 + 2 sqrt(m1 m2) R0, and
   v likewise with the signs of sqrt(m1 m2) turned. */

/* An elliptic unit 2-blade that commutes with the 2-blade P (any, for P = 0):
   a 2-blade inside the complement P* = P I^-1 of P's plane; e_k _| P* for the
   basis vector that gives the most negative square (docs/versors.md). */
static ga_mv commuting_plane(ga_mv P)
{
    if (ga_mv_maxabs(P) == 0.0)
        return ga_mv_blade(GA_BLADE_E12);
    ga_mv K = ga_mv_dual(P), best = ga_mv_zero();
    double bestsq = 0.0;
    for (int k = 1; k <= 5; k++) {
        ga_mv E = ga_mv_lc(ga_mv_blade(k), K);
        double e2 = ga_mv_gp(E, E).c[0];
        if (e2 < bestsq)
            bestsq = e2, best = E;
    }
    return bestsq < 0.0 ? ga_mv_scale(best, 1.0 / sqrt(-bestsq)) : ga_mv_zero();
}

/* the angle data of one factor from m = c^2 - 1 and the sign of c */
static double factor_l(double m, double c)
{
    if (m > 0.0) { /* hyperbolic: c = cosh t > 1 */
        double t = asinh(sqrt(m));
        return t * t;
    }
    double th = atan2(sqrt(-m), c);
    return -th * th;
}

/* Two rotations in one Euclidean 4-space with unit pseudoscalar J (J^2 = 1,
   J = E1 E2 for the unit planes of the parts): Spin(4) = SU(2) x SU(2)
   through the central idempotents P+- = (1 +- J)/2 (Dorst-Valkenburg 2011 §5
   use the same commuting split of the even algebra of a 4-space). With
   B = t1 E1 + t2 E2, E1 J = -E2 and E2 J = -E1, so
     R P+ = cos(t1 - t2) P+ + sin(t1 - t2) (E1 - E2)/2,
     R P- = cos(t1 + t2) P- + sin(t1 + t2) (E1 + E2)/2,
   each a unit quaternion in its ideal (U = (E1 -+ E2)/2 has U^2 = -P+-,
   <U^2>_0 = -1/2). Its principal log, phi in [0, pi] from
   cos phi = 2 <R P>_0 and sin phi = sqrt(-2 <V V>_0), V = <R P>_2, is
   (phi / sin phi) V, and log R is the sum of the two: t1, t2 = (phi- +- phi+)/2
   in [0, pi], and t1, t2 < pi/2 gives back B. A factor at -P (phi = pi, sin phi = 0)
   takes pi U for any unit U of its ideal, as exp(pi U) = -P whatever U is.
   Unlike the m and ab forms this divides by neither m1 - m2 nor a + b: it is
   the form for two rotations with cos t1 = -cos t2 (R0 <= 0) and near the
   conjugate point t1 + t2 = pi of exp, where only the direction of a factor
   at -P is lost, and exp does not depend on it. */
/* An orthonormal basis U[0..2] of the bivectors of the ideal of P in the
   4-space of J (<Ui Uj>_0 = -1/2 for i = j, else 0): Gram-Schmidt on the
   parts <(e_ij _| J) P>_2 of the basis 2-blades, largest first. The
   coordinates of a bivector in it put it in the ideal to rounding of its
   own size, which a projection does not do for a bivector that is itself
   rounding noise (a factor at -P). */
static void ideal_basis(ga_mv J, ga_mv P, ga_mv U[3])
{
    ga_mv cand[10];
    for (int i = 0; i < 10; i++)
        cand[i] = ga_mv_grade(ga_mv_gp(ga_mv_lc(ga_mv_blade(GA_BLADE_E12 + i), J), P), 2);
    for (int k = 0; k < 3; k++) {
        double bn = 0.0;
        int bi = 0;
        for (int i = 0; i < 10; i++) {
            ga_mv c = cand[i];
            for (int l = 0; l < k; l++) c = lin(1.0, c, 2.0 * ga_mv_sp(c, U[l]), U[l]);
            cand[i] = c;
            double n = -2.0 * ga_mv_sp(c, c);
            if (n > bn)
                bn = n, bi = i;
        }
        U[k] = bn > 0.0 ? ga_mv_scale(cand[bi], 1.0 / sqrt(bn)) : ga_mv_zero();
    }
}

static ga_mv spin4_log(ga_mv R, ga_mv J)
{
    ga_mv B = ga_mv_zero();
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        ga_mv P = ga_mv_scale(J, 0.5 * sgn), U[3];
        P.c[0] += 0.5;
        ideal_basis(J, P, U);
        ga_mv X = ga_mv_gp(R, P), V = ga_mv_zero();
        double s2 = 0.0;
        for (int k = 0; k < 3; k++) {
            double v = -2.0 * ga_mv_sp(X, U[k]);
            V = lin(1.0, V, v, U[k]);
            s2 += v * v;
        }
        double cphi = 2.0 * X.c[0], sphi = sqrt(s2), phi = atan2(sphi, cphi);
        if (sphi > 0.0) /* phi / sphi, not 1/S(-phi^2): near pi, sin of the
                           rounded phi is not the sphi that V carries */
            B = lin(1.0, B, phi / sphi, V);
        else if (cphi < 0.0) /* X = -P: pi U for any unit U of the ideal */
            B = lin(1.0, B, 3.14159265358979323846, U[0]);
    }
    return B;
}

/* The unit 4-vector J = q / sqrt(<q q>_0) of a 4-vector q with <q q>_0 > 0
   (the 4-space of two elliptic parts: q = 2 B1 B2 = 2 t1 t2 J, R4 = s1 s2 J) */
static ga_mv unit4(ga_mv q) { return ga_mv_scale(q, 1.0 / sqrt(ga_mv_sp(q, q))); }

/* ---- a null part: the frame in which it is rigid ------------------------------- */

/* A rotation E by a small angle t beside a null part N (R = +-exp(tE) exp(N),
   or B = tE + N) is a rigid screw seen in another frame: both fix the null
   vector n of N's plane (n.n = 0, n.E = n.N = 0), and a rotor V that takes n
   to the point at infinity (V n ~V ~ e4 + e5) turns them into a rigid rotor
   or generator, whose log and split are exact for every angle
   (ga_rotor_log_literal; the screw's axis). The m and l forms find E from
   t^2 = -<B^2>_0, which is known only to u |N|^2, and lose u (|N|/t)^3 or
   more. Here n is taken from M, the 5x5 matrix of the vector map
   x -> R x ~R - x (or x -> x _| B): n spans its kernel and, since R keeps
   the metric, n.M y = 0 for every y, so n is the metric normal of M's
   columns, found by Gaussian elimination with complete pivoting on M^T
   (backward stable: an error in n lies in E's plane, u |M| / t of it, which
   R moves by only t times that; docs/versors.md). For t below u^(1/3) of
   |M| those columns are too near a rank of 2; then the columns of M^2,
   ~ (x.n) n with t^2 of E's plane beside it, give n. For a rotor, M is
   also that of x -> x _| <R>_2 (R = (c + sE)(1 + N) has <R>_2 = sE + cN,
   with the same null vector and entries of size |R|, not |R|^2), except
   where c ~ 0. */

/* The metric normal n (n.c = 0, n5 >= 0) of the columns c of M, or 0 where
   M has rank below 4 (candidate 0), or the largest column of M^2
   (candidate 1). */
static int null_normal(double M[5][5], int cand, double n[5])
{
    double A[5][5];
    if (cand == 1) {
        double best = 0.0;
        for (int j = 0; j < 5; j++) {
            double col[5], nn = 0.0;
            for (int i = 0; i < 5; i++) {
                col[i] = 0.0;
                for (int k = 0; k < 5; k++) col[i] += M[i][k] * M[k][j];
                nn += col[i] * col[i];
            }
            if (nn > best) {
                best = nn;
                for (int i = 0; i < 5; i++) n[i] = col[i];
            }
        }
        if (!(best > 0.0))
            return 0;
    } else {
        int perm[5] = {0, 1, 2, 3, 4};
        for (int i = 0; i < 5; i++)
            for (int j = 0; j < 5; j++) A[i][j] = M[j][i];
        for (int k = 0; k < 4; k++) {
            int pi = k, pj = k;
            for (int i = k; i < 5; i++)
                for (int j = k; j < 5; j++)
                    if (fabs(A[i][j]) > fabs(A[pi][pj]))
                        pi = i, pj = j;
            if (!(fabs(A[pi][pj]) > 0.0))
                return 0;
            for (int j = 0; j < 5; j++) {
                double t = A[k][j];
                A[k][j] = A[pi][j], A[pi][j] = t;
            }
            for (int i = 0; i < 5; i++) {
                double t = A[i][k];
                A[i][k] = A[i][pj], A[i][pj] = t;
            }
            int t = perm[k];
            perm[k] = perm[pj], perm[pj] = t;
            for (int i = k + 1; i < 5; i++) {
                double f = A[i][k] / A[k][k];
                for (int j = k; j < 5; j++) A[i][j] -= f * A[k][j];
            }
        }
        double y[5];
        y[4] = 1.0;
        for (int k = 3; k >= 0; k--) {
            double acc = 0.0;
            for (int j = k + 1; j < 5; j++) acc += A[k][j] * y[j];
            y[k] = -acc / A[k][k];
        }
        for (int k = 0; k < 5; k++) n[perm[k]] = y[k];
        n[4] = -n[4]; /* the metric: n = diag(1, 1, 1, 1, -1) x */
    }
    if (n[4] < 0.0)
        for (int i = 0; i < 5; i++) n[i] = -n[i];
    for (int i = 0; i < 5; i++)
        if (!isfinite(n[i]))
            return 0;
    return 1;
}

/* A rotor V of the Euclidean 4-space e1..e4 (so its action on the 32
   coefficients is orthogonal: it magnifies no error) with V n ~V along
   e4 + e5, for n = n5 e5 + w, n5 > 0, n null (|w| = n5): V turns w/|w| into
   e4, through a half turn in a plane e_j e4 first where w points away from e4. */
static int to_infinity(const double n[5], ga_mv *V)
{
    double w[4], nw = 0.0;
    for (int i = 0; i < 4; i++) nw = fmax(nw, fabs(n[i]));
    if (!(nw > 0.0))
        return 0;
    double len = 0.0;
    for (int i = 0; i < 4; i++) w[i] = n[i] / nw, len += w[i] * w[i];
    len = sqrt(len);
    for (int i = 0; i < 4; i++) w[i] /= len;
    ga_mv V1 = ga_mv_scalar(1.0);
    if (w[3] < 0.0) {
        int j = 0;
        for (int i = 1; i < 3; i++)
            if (fabs(w[i]) < fabs(w[j]))
                j = i;
        V1 = ga_mv_gp(ga_mv_blade(GA_BLADE_E1 + j), ga_mv_blade(GA_BLADE_E4));
        w[j] = -w[j], w[3] = -w[3];
    }
    /* (1 + e4 w)/sqrt(2 (1 + w4)) takes w to e4 */
    ga_mv wv = ga_mv_zero();
    for (int i = 0; i < 4; i++) wv.c[GA_BLADE_E1 + i] = w[i];
    ga_mv V2 = ga_mv_gp(ga_mv_blade(GA_BLADE_E4), wv);
    V2.c[0] += 1.0;
    *V = ga_mv_gp(ga_mv_scale(V2, 1.0 / sqrt(2.0 * (1.0 + w[3]))), V1);
    return 1;
}

static ga_mv sandwich(ga_mv V, ga_mv X) { return ga_mv_gp(ga_mv_gp(V, X), ga_mv_reverse(V)); }

static ga_mv generator_mv(ga_generator g)
{
    ga_mv B = ga_mv_zero();
    B.c[GA_BLADE_E12] = g.e12, B.c[GA_BLADE_E13] = g.e13, B.c[GA_BLADE_E23] = g.e23;
    B.c[GA_BLADE_E14] = B.c[GA_BLADE_E15] = g.e1n;
    B.c[GA_BLADE_E24] = B.c[GA_BLADE_E25] = g.e2n;
    B.c[GA_BLADE_E34] = B.c[GA_BLADE_E35] = g.e3n;
    return B;
}

/* The 5x5 matrix of x -> x _| b, whose kernel is b's null vector */
static void contraction_matrix(ga_mv b, double M[5][5])
{
    for (int j = 0; j < 5; j++) {
        ga_mv v = ga_mv_lc(ga_mv_blade(GA_BLADE_E1 + j), b);
        for (int i = 0; i < 5; i++) M[i][j] = v.c[GA_BLADE_E1 + i];
    }
}

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
    double M[5][5], n[5], m = ga_mv_maxabs(b), best = 16.0 * DBL_EPSILON * m;
    contraction_matrix(b, M);
    int found = 0;
    for (int cand = 0; cand < 2; cand++) {
        ga_mv V;
        double rest;
        if (!null_normal(M, cand, n) || !to_infinity(n, &V))
            continue;
        ga_generator g = rigid_part(ga_mv_grade(sandwich(V, b), 2), &rest);
        if (!(rest <= best))
            continue;
        best = rest, found = 1;
        *out = sandwich(ga_mv_reverse(V), ga_rotor_to_mv(ga_rotor_exp(g)));
    }
    return found;
}

/* log R through the rigid frame of its null part, n from <R>_2 (cand 0, 1)
   or from x -> R x ~R - x (2, 3), by the metric normal (even cand) or M^2
   (odd); GA_ERR_DOMAIN where R is not rigid there (no null part, or not
   this n) */
static int log_null_part(ga_mv R, int cand, ga_mv *out)
{
    double M[5][5], n[5];
    ga_mv Rr = ga_mv_reverse(R), V;
    if (cand < 2) {
        contraction_matrix(ga_mv_grade(R, 2), M);
    } else {
        for (int j = 0; j < 5; j++) {
            ga_mv y = ga_mv_gp(ga_mv_gp(R, ga_mv_blade(GA_BLADE_E1 + j)), Rr);
            for (int i = 0; i < 5; i++) M[i][j] = y.c[GA_BLADE_E1 + i] - (i == j);
        }
    }
    if (!null_normal(M, cand % 2, n) || !to_infinity(n, &V))
        return GA_ERR_DOMAIN;
    ga_rotor r;
    ga_generator g;
    int st = ga_rotor_from_mv(sandwich(V, R), 1e-6, &r);
    if (st != GA_OK)
        return GA_ERR_DOMAIN;
    /* A turn t tiny against the rounding of r (|r| u) has an axis b = sin t u
       known to u |r| / t only, and its tilt off the translation p leaks
       |p| u / t of p into a perpendicular part, which the log divides by
       sin t again: an axis ~u |p| / t^2 away (1e4 at t = 1e-10) and a
       generator too large for exp to reproduce r. Where b is along p to
       within that rounding, it is taken along p (and where b itself is
       rounding, as 0): a change of r below its rounding, and the log of the
       screw along p. */
    double b[3] = {r.e23, -r.e13, r.e12}, p[3] = {r.e1n, r.e2n, r.e3n};
    double pp = p[0] * p[0] + p[1] * p[1] + p[2] * p[2], bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    double bp = b[0] * p[0] + b[1] * p[1] + b[2] * p[2];
    double tilt2 = fmax(bb - bp * bp / pp, 0.0), lim = 64.0 * DBL_EPSILON * fmax(1.0, sqrt(pp));
    if (bb <= lim * lim) { /* no turn to rounding: the log's own exact case */
        r.e23 = r.e13 = r.e12 = 0.0;
        if (ga_rotor_normalize(r, &r) != GA_OK)
            return GA_ERR_DOMAIN;
    } else if (pp > 0.0 && tilt2 <= lim * lim) {
        double k = copysign(sqrt(bb / pp), bp);
        r.e23 = k * p[0], r.e13 = -k * p[1], r.e12 = k * p[2];
        if (ga_rotor_normalize(r, &r) != GA_OK)
            return GA_ERR_DOMAIN;
    }
    st = ga_rotor_log_literal(r, &g);
    if (st != GA_OK)
        return GA_ERR_DOMAIN;
    *out = ga_mv_grade(sandwich(ga_mv_reverse(V), generator_mv(g)), 2);
    return GA_OK;
}

/* max |exp(B) - R|, INFINITY where exp(B) is not finite (ga_mv_maxabs
   skips NaN: a log whose exp overflows read as a close one) */
static double log_residual(ga_mv B, ga_mv R)
{
    ga_mv E = ga_mv_exp(B);
    return finite_mv(E) ? ga_mv_maxabs(ga_mv_sub(E, R)) : INFINITY;
}

/* log R by the closed forms (the comment above ga_mv_log's helpers) */
static int log_closed(ga_mv R, double tol, ga_mv *out)
{
    double r0 = R.c[0];
    ga_mv R2 = ga_mv_grade(R, 2), R4 = ga_mv_grade(R, 4);
    ga_mv W = ga_mv_grade(ga_mv_gp(R2, R4), 2);
    double p44 = ga_mv_sp(R4, R4), p22 = ga_mv_sp(R2, R2);
    double sig = p22 - 2.0 * p44, prod = p44;
    double disc = fmax(sig * sig - 4.0 * prod, 0.0);
    ga_mv B;
    /* two rotations (m1, m2 < 0) with |c1| near |c2|: where R0 <= 0 the m
       form divides by m1 - m2 -> 0 (and the ab form by a + b -> 0 at the
       conjugate point), so take the Spin(4) factors. J = R4/s1 s2 where
       s1 s2 = sqrt(prod) >= 1/4 (then |R0| = |c1 c2| is below 1/2 + the
       near-equality); where R0 <= -1/2, J of log(-R), which is in the ab or
       near-null form. */
    int two_rot = prod > 0.0 && sig < 0.0 && sqrt(disc) < sqrt(prod);
    if (two_rot && r0 <= 0.5 && prod >= 1.0 / 16.0) {
        B = spin4_log(R, unit4(R4));
    } else if (two_rot && r0 <= -0.5) {
        ga_mv Lm, q;
        int st = ga_mv_log(ga_mv_scale(R, -1.0), &Lm);
        if (st != GA_OK)
            return st;
        q = ga_mv_grade(ga_mv_gp(Lm, Lm), 4);
        if (ga_mv_sp(q, q) > 0.0) {
            B = spin4_log(R, unit4(q));
        } else { /* -R = exp(Lm) with Lm one 2-blade (or 0): take the sign in a plane commuting with it */
            double lm2 = ga_mv_gp(Lm, Lm).c[0];
            ga_mv E = lm2 < 0.0 ? ga_mv_scale(Lm, 1.0 / sqrt(-lm2)) : commuting_plane(Lm);
            B = lin(1.0, Lm, -3.14159265358979323846, E);
        }
    } else if (r0 > 0.0 && fabs(sig) <= 1e-7 && fabs(prod) <= 1e-14) {
        /* both parts near null (a translation or transversion with at most a
           tiny rotation or boost): m1, m2 are then mostly rounding of
           <R2 R2>_0, but kR and kW are symmetric in them, so analytic in
           sig = m1 + m2 and prod = m1 m2; to first order (the next terms are
           O(sig^2, prod) <= 1e-14) kR = 1 - sig/6, kW = -1/3 + 2 sig/15 */
        B = lin(1.0 - sig / 6.0, R2, -1.0 / 3.0 + 2.0 * sig / 15.0, W);
    } else if (prod > 0.0 && sig < 0.0 && r0 > 0.0 && sqrt(disc) < sqrt(prod)) {
        /* ab form: two rotations by nearly equal angles */
        double sp = sqrt(prod), A = -p22;
        double u = atan2(sqrt(fmax(A + 2.0 * sp * r0, 0.0)), r0 - sp);
        double v = atan2(sqrt(fmax(A - 2.0 * sp * r0, 0.0)), r0 + sp);
        double a = -u * u, b = -v * v;
        fns fa = fns_at(a), fb = fns_at(b);
        double kr = 0.5 * (1.0 / fa.s + 1.0 / fb.s);
        double kw = (a * fa.t - b * fb.t) / ((b * fb.k - a * fa.k) * fa.s * fb.s);
        B = lin(kr, R2, kw, W);
    } else {
        double m1 = 0.5 * (sig + copysign(sqrt(disc), sig));
        double m2 = m1 != 0.0 ? prod / m1 : 0.0;
        if (sig * sig - 4.0 * prod < 0.0)
            m2 = m1 = 0.5 * sig; /* rounding: a double root */
        if (m1 < -1.0 - tol || m2 < -1.0 - tol)
            return GA_ERR_DOMAIN;
        double c1 = sqrt(fmax(1.0 + m1, 0.0)), c2 = sqrt(fmax(1.0 + m2, 0.0));
        /* the factor with the smaller |c| is the one near a half turn, where
           sqrt(1 + m) cancels: take it from R0 = c1 c2 instead */
        int small = c1 <= c2 ? 1 : 2;
        if (small == 1 && c2 > 0.0)
            c1 = fabs(r0) / c2;
        else if (small == 2 && c1 > 0.0)
            c2 = fabs(r0) / c1;
        int flip = 0; /* which factor takes the sign of R0 < 0 */
        if (r0 < 0.0) {
            flip = small;
            if (flip == 1)
                c1 = -c1;
            else
                c2 = -c2;
        }
        double mf = flip == 1 ? m1 : m2;
        if (flip && mf == 0.0) {
            /* that factor is -1 exactly: R = -(c + P) with P the other
               factor's 2-blade; B = log(c + P) + pi E, E commuting with P */
            ga_mv L, P = ga_mv_scale(R2, -1.0);
            double mo = flip == 1 ? m2 : m1, co = fabs(flip == 1 ? c2 : c1);
            double lo = factor_l(mo, co);
            fns f = fns_at(lo);
            L = mo == 0.0 ? P : ga_mv_scale(P, 1.0 / f.s);
            ga_mv E = commuting_plane(P);
            B = lin(1.0, L, 3.14159265358979323846, E);
        } else if (m1 == m2) { /* both 0: R = 1 + N, N^2 = 0 (c1 = c2 = 1) */
            B = lin(1.0, R2, -1.0 / 3.0, W);
        } else {
            double l1 = factor_l(m1, c1), l2 = factor_l(m2, c2);
            fns f1 = fns_at(l1), f2 = fns_at(l2);
            double dm = m1 - m2;
            double kr = (c2 * f1.s * l1 - c1 * f2.s * l2) / dm;
            double kw = (l2 * f2.e / f2.s - l1 * f1.e / f1.s) / dm;
            B = lin(kr, R2, kw, W);
        }
    }
    if (!finite_mv(B))
        return GA_ERR_DOMAIN;
    *out = B;
    return GA_OK;
}

ga_status ga_mv_log(ga_mv R, ga_mv *out)
{
    if (!finite_mv(R))
        return GA_ERR_NOTFINITE;
    double scale = ga_mv_maxabs(R), tol = 1e-9;
    for (int g = 1; g <= 5; g += 2)
        if (ga_mv_maxabs(ga_mv_grade(R, g)) > tol * scale)
            return GA_ERR_DOMAIN;
    ga_mv rr = ga_mv_gp(R, ga_mv_reverse(R));
    rr.c[0] -= 1.0;
    if (!(ga_mv_maxabs(rr) <= tol * fmax(1.0, scale * scale)))
        return GA_ERR_DOMAIN;

    /* Candidates: the closed forms; where they leave more than rounding,
       the log in the rigid frame of a null part, with n from <R>_2 (entries
       ~|R|), log(-R) - pi E (R0 < 0), and the rigid frame with n from
       R x ~R - x (entries ~|R|^2, whose rounding moves the log itself,
       though not exp(log R), further from B), each n by the metric normal
       and by M^2. The first in the order: rigid frame from <R>_2 (exact
       where R has a null part: the closed forms' log of a turn beside a null
       part of 3000 was 3e-7 from B, this one 1e-9), closed forms, log(-R) -
       pi E, the others, whose residual |exp(B) - R| is within twice the
       smallest, or at the floor that exp's own rounding sets, is kept: the
       residuals of good ones differ by that rounding only. */
    ga_mv cand[7];
    double cres[7];
    int nc = 0;
    if (log_closed(R, tol, &cand[nc]) == GA_OK)
        cres[nc] = log_residual(cand[nc], R), nc++;
    if (!(nc == 1 && cres[0] <= 4.0 * DBL_EPSILON * fmax(1.0, scale * scale))) {
        ga_mv Lm, P[2], X;
        /* first in the order */
        if (log_null_part(R, 0, &X) == GA_OK && finite_mv(X)) {
            for (int i = nc; i > 0; i--) cand[i] = cand[i - 1], cres[i] = cres[i - 1];
            cand[0] = X, cres[0] = log_residual(X, R), nc++;
        }
        /* log(-R) - pi E, E the unit plane of log(-R)'s elliptic part with
           the smaller angle (which thus takes the sign, as the principal
           branch says): for two rotations both near a full turn the Spin(4)
           form takes J from q = <log(-R)^2>_4 ~ t1 t2, known to u/(t1 t2) */
        if (R.c[0] < 0.0 && log_closed(ga_mv_scale(R, -1.0), tol, &Lm) == GA_OK &&
            ga_mv_split(Lm, &P[0], &P[1]) == GA_OK) {
            double l[2] = {ga_mv_gp(P[0], P[0]).c[0], ga_mv_gp(P[1], P[1]).c[0]};
            int i = l[0] < 0.0 && (!(l[1] < 0.0) || l[0] >= l[1]) ? 0 : 1;
            if (l[i] < 0.0) {
                cand[nc] = lin(1.0, Lm, -3.14159265358979323846 / sqrt(-l[i]), P[i]);
                cres[nc] = log_residual(cand[nc], R), nc++;
            }
        }
        for (int c = 1; c < 4; c++)
            if (log_null_part(R, c, &cand[nc]) == GA_OK && finite_mv(cand[nc]))
                cres[nc] = log_residual(cand[nc], R), nc++;
    }
    double res = INFINITY;
    for (int i = 0; i < nc; i++) res = fmin(res, cres[i]);
    /* exp of a log of size |B| is known to ~u |B|^2 of |R| (the rounding of
       B, magnified): the floor at which candidates are equally good, and
       the round-trip check below, take size = min(|R|, |B|) (+ 4 in the
       check: a null part |N| gives |R| ~ |N|, a boost of |B| gives |R| ~
       e^|B|; a wrong candidate cannot widen its own check by being large) */
    double size[7];
    for (int i = 0; i < nc; i++) size[i] = fmin(scale, ga_mv_maxabs(cand[i]));
    int pick = 0;
    while (pick < nc &&
           !(cres[pick] <= fmax(2.0 * res, 4.0 * DBL_EPSILON * fmax(1.0, size[pick] * size[pick]) * scale)))
        pick++;
    if (pick == nc)
        return GA_ERR_DOMAIN;
    ga_mv B = cand[pick];
    double sz = size[pick] + 4.0;
    res = cres[pick];
    /* no real log (or not a versor): exp(log R) is not R. exp of a log of
       size |B| is itself known only to ~u |B|^2 of |R| (the rounding of B,
       magnified: a null part of 3000 conjugated by a dilation and a
       transversion, 5e-10), so the check allows 64 u size^2 where that is
       above 1e-9, up to 1e-6 (size ~ 2.6e5), beyond which it cannot tell */
    if (!(res <= fmin(1e-6, fmax(tol, 64.0 * DBL_EPSILON * sz * sz)) * scale))
        return GA_ERR_DOMAIN;
    *out = B;
    return GA_OK;
}

/* ---- split and factorization ------------------------------------------------ */

/* The coefficient-wise dot product (a Euclidean metric on the 32 numbers). */
static double cdot(ga_mv a, ga_mv b)
{
    double r = 0.0;
    for (int i = 0; i < 32; i++) r += a.c[i] * b.c[i];
    return r;
}

/* Split b (max |b| in [1/2, 1)) into commuting 2-blades b1 + b2. */
/* How far x, y are from commuting 2-blades, for x + y = b to 2^-40 (b of
   size 1); a split that misses b by more is no split (INFINITY). */
static double split_residual(ga_mv b, ga_mv x, ga_mv y)
{
    if (!finite_mv(x) || !finite_mv(y))
        return INFINITY;
    double sum = ga_mv_maxabs(ga_mv_sub(lin(1.0, x, 1.0, y), b));
    if (!(sum <= 0x1p-40))
        return INFINITY;
    return fmax(sum, fmax(ga_mv_maxabs(ga_mv_sub(ga_mv_gp(x, y), ga_mv_gp(y, x))),
                          fmax(ga_mv_maxabs(ga_mv_grade(ga_mv_gp(x, x), 4)),
                               ga_mv_maxabs(ga_mv_grade(ga_mv_gp(y, y), 4)))));
}

/* b = tE + N split in the rigid frame of its null part (as log_null_part):
   there b is a generator Omega + T n, and with a the axis of Omega,
   B2 = (T.a) a n / |a|^2 (the translation along the axis, null) and
   B1 = Omega + T_perp n (the rotation about the axis), which commute and are
   2-blades to rounding of |b| whatever t is; the l forms find E from
   t^2 = -<b^2>_0, known only to u |b|^2. 0 where b has no null vector. */
static int split_null_part(ga_mv b, int cand, ga_mv *x, ga_mv *y)
{
    double M[5][5], n[5];
    ga_mv V;
    contraction_matrix(b, M);
    if (!null_normal(M, cand, n) || !to_infinity(n, &V))
        return 0;
    ga_mv br = ga_mv_grade(sandwich(V, b), 2);
    static const int in4[3] = {GA_BLADE_E14, GA_BLADE_E24, GA_BLADE_E34},
                     in5[3] = {GA_BLADE_E15, GA_BLADE_E25, GA_BLADE_E35};
    double a[3] = {br.c[GA_BLADE_E23], -br.c[GA_BLADE_E13], br.c[GA_BLADE_E12]}, t[3];
    double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2], ta = 0.0, pa = 0.0;
    for (int i = 0; i < 3; i++) t[i] = 0.5 * br.c[in4[i]] + 0.5 * br.c[in5[i]], ta += t[i] * a[i];
    ga_mv B1 = ga_mv_zero(), B2 = ga_mv_zero();
    B1.c[GA_BLADE_E12] = br.c[GA_BLADE_E12], B1.c[GA_BLADE_E13] = br.c[GA_BLADE_E13];
    B1.c[GA_BLADE_E23] = br.c[GA_BLADE_E23];
    double tp[3];
    for (int i = 0; i < 3; i++) tp[i] = aa > 0.0 ? t[i] - ta / aa * a[i] : 0.0, pa += tp[i] * a[i];
    for (int i = 0; i < 3; i++) {
        double perp = aa > 0.0 ? tp[i] - pa / aa * a[i] : 0.0; /* once more: T_perp.a is rounding */
        B1.c[in4[i]] = B1.c[in5[i]] = perp;
        B2.c[in4[i]] = B2.c[in5[i]] = t[i] - perp;
    }
    ga_mv Vr = ga_mv_reverse(V);
    *x = ga_mv_grade(sandwich(Vr, B1), 2);
    *y = ga_mv_grade(sandwich(Vr, B2), 2);
    return 1;
}

static void split_unit(ga_mv b, ga_mv *b1, ga_mv *b2)
{
    bsquare sq = square_of(b);
    double tol = 64.0 * DBL_EPSILON, qn = ga_mv_maxabs(sq.q), qc = cdot(sq.q, sq.q);
    if (qn <= tol) { /* b is a 2-blade to rounding */
        *b1 = b;
        *b2 = ga_mv_zero();
        return;
    }
    double ideal_res = INFINITY;
    ga_mv ideal_x = b, ideal_y = ga_mv_zero();
    if (sq.qq > 0x1p-26 * qc && sqrt(sq.qq) > 0x1p20 * DBL_EPSILON) {
        /* two rotations: q spans a Euclidean 4-space, J = q / sqrt(q.q),
           J^2 = 1. In the ideals of P+- = (1 +- J)/2, b = tp Up + tm Um with
           Up^2 = -P+, Um^2 = -P- (each ideal is a quaternion algebra), and
           E1 = Up + Um, E2 = Up - Um are commuting unit 2-blades (E^2 = -1,
           E1 E2 = -J) with b = (tp + tm)/2 E1 + (tp - tm)/2 E2: exact for
           any unit Um, so it holds for isoclinic b (tm = 0) and near it,
           where the roots l1, l2 are too close to divide by. */
        ga_mv J = ga_mv_scale(sq.q, 1.0 / sqrt(sq.qq)), U[2];
        double t[2];
        for (int i = 0; i < 2; i++) {
            ga_mv P = ga_mv_scale(J, i == 0 ? 0.5 : -0.5), B3[3], X = ga_mv_zero();
            P.c[0] += 0.5;
            /* b P in the coordinates of an orthonormal basis of the ideal
               (<B3k B3k>_0 = -1/2): exactly in the ideal to rounding of its
               own size, which a product with P is not for a small part
               (the rounding of b, of |b|, leaves the 4-space of J) */
            ideal_basis(J, P, B3);
            ga_mv bp = ga_mv_gp(b, P);
            double t2 = 0.0;
            for (int k = 0; k < 3; k++) {
                double v = -2.0 * ga_mv_sp(bp, B3[k]);
                X = lin(1.0, X, v, B3[k]);
                t2 += v * v;
            }
            t[i] = sqrt(t2);
            U[i] = t[i] > 0.0 ? ga_mv_scale(X, 1.0 / t[i]) : B3[0]; /* U^2 = -P */
        }
        ga_mv x = ga_mv_scale(lin(1.0, U[0], 1.0, U[1]), 0.5 * (t[0] + t[1]));
        ga_mv y = ga_mv_scale(lin(1.0, U[0], -1.0, U[1]), 0.5 * (t[0] - t[1]));
        /* b outside the 4-space of J (rounding of b, or a J of rounding)
           is dropped by the projection: kept only if the residual says
           so, as the l forms below */
        double res = split_residual(b, x, y);
        if (res <= 64.0 * DBL_EPSILON) {
            *b1 = x;
            *b2 = y;
            return;
        }
        ideal_res = res, ideal_x = x, ideal_y = y;
    }
    /* separated parts (elliptic x hyperbolic, or a null part):
       b1 = (l1 b - bq/2)/(l1 - l2), b2 = (bq/2 - l2 b)/(l1 - l2) with l1, l2
       the roots of l^2 - s l + q.q/4. Beside a null part q.q = 4 l1 l2 is a
       sum of products of q's coefficients that cancel, so l2 = 0, l1 = s is
       tried too. Of these splits and (b, 0) (b a 2-blade to |q|/2), the one
       with the smallest residual (how far from commuting 2-blades summing
       to b) is kept. A rotation t beside a null part N is resolved only to
       u |b|^3 / t^3 of N (s = -t^2 is known to u |b|^2, and b1 is b minus
       b2 ~ N): below t ~ 1e-4 |b| the split is that poor (versor.h). */
    double sv[2] = {sq.s, sq.s};
    double best = 0.5 * qn;
    *b1 = b;
    *b2 = ga_mv_zero();
    if (ideal_res < best) {
        best = ideal_res;
        *b1 = ideal_x;
        *b2 = ideal_y;
    }
    for (int v = 0; v < 2; v++) {
        double l1, l2;
        roots(sv[v % 2], sq.qq, &l1, &l2);
        if (v % 2)
            l1 = sv[v % 2], l2 = 0.0;
        double dl = l1 - l2;
        if (!(fabs(dl) > 0.0))
            continue;
        ga_mv x = lin(l1 / dl, b, -0.5 / dl, sq.bq), y = lin(0.5 / dl, sq.bq, -l2 / dl, b);
        double res = split_residual(b, x, y);
        if (res < best) {
            best = res;
            *b1 = x;
            *b2 = y;
        }
    }
    for (int cand = 0; cand < 2 && best > 8.0 * DBL_EPSILON; cand++) {
        ga_mv x, y;
        double res = split_null_part(b, cand, &x, &y) ? split_residual(b, x, y) : INFINITY;
        if (res < best) {
            best = res;
            *b1 = x;
            *b2 = y;
        }
    }
}

ga_status ga_mv_split(ga_mv B, ga_mv *B1, ga_mv *B2)
{
    ga_mv b = ga_mv_grade(B, 2);
    if (!finite_mv(b))
        return GA_ERR_NOTFINITE;
    double m = ga_mv_maxabs(b);
    if (m == 0.0) {
        *B1 = *B2 = ga_mv_zero();
        return GA_OK;
    }
    int e;
    frexp(m, &e);
    for (int i = 0; i < 32; i++) b.c[i] = ldexp(b.c[i], -e);
    ga_mv x, y;
    split_unit(b, &x, &y);
    for (int i = 0; i < 32; i++) x.c[i] = ldexp(x.c[i], e), y.c[i] = ldexp(y.c[i], e);
    if (!finite_mv(x) || !finite_mv(y))
        return GA_ERR_DOMAIN;
    *B1 = x;
    *B2 = y;
    return GA_OK;
}

ga_status ga_mv_factor(ga_mv R, ga_mv *R1, ga_mv *R2)
{
    ga_mv L, B1, B2;
    int st = ga_mv_log(R, &L);
    if (st == GA_OK)
        st = ga_mv_split(L, &B1, &B2);
    if (st != GA_OK)
        return st;
    *R1 = ga_mv_exp(B1);
    *R2 = ga_mv_exp(B2);
    return GA_OK;
}

/* ---- versors ----------------------------------------------------------------- */

ga_status ga_versor_apply(ga_mv V, ga_mv X, ga_mv *out)
{
    if (!finite_mv(V) || !finite_mv(X))
        return GA_ERR_NOTFINITE;
    double ev = 0.0, od = 0.0;
    for (int i = 0; i < 32; i++) {
        if (ga_blade_grade(i) % 2)
            od = fmax(od, fabs(V.c[i]));
        else
            ev = fmax(ev, fabs(V.c[i]));
    }
    if (ev > 0.0 && od > 0.0)
        return GA_ERR_ARG;
    ga_mv Vi;
    int st = ga_mv_inverse(V, &Vi);
    if (st != GA_OK)
        return st;
    if (od > 0.0)
        X = ga_mv_involute(X);
    *out = ga_mv_gp(ga_mv_gp(V, X), Vi);
    return GA_OK;
}

ga_mv ga_versor_reflection(ga_vec3 normal, double distance) { return ga_plane_dual(normal, distance); }

ga_mv ga_versor_inversion(ga_vec3 centre, double radius) { return ga_sphere_dual(centre, radius); }

ga_status ga_versor_dilation(ga_vec3 c, double s, ga_mv *out)
{
    if (!isfinite(s) || !isfinite(c.x) || !isfinite(c.y) || !isfinite(c.z))
        return GA_ERR_NOTFINITE;
    if (!(s > 0.0))
        return GA_ERR_ARG;
    /* exp(a e45) = cosh a + sinh a e45 scales by e^(-2a) (docs/versors.md) */
    double a = -0.5 * log(s);
    ga_mv D = ga_mv_scalar(cosh(a));
    D.c[GA_BLADE_E45] = sinh(a);
    ga_mv T = ga_versor_translation(c), Ti = ga_versor_translation((ga_vec3){-c.x, -c.y, -c.z});
    *out = ga_mv_gp(ga_mv_gp(T, D), Ti);
    return GA_OK;
}

ga_mv ga_versor_transversion(ga_vec3 b)
{
    /* 1 + nbar b/2, nbar = e4 - e5: the products e4 b and -e5 b */
    ga_mv K = ga_mv_scalar(1.0);
    K.c[GA_BLADE_E14] = -0.5 * b.x; /* e4 e1 = -e14 */
    K.c[GA_BLADE_E24] = -0.5 * b.y;
    K.c[GA_BLADE_E34] = -0.5 * b.z;
    K.c[GA_BLADE_E15] = 0.5 * b.x; /* -e5 e1 = e15 */
    K.c[GA_BLADE_E25] = 0.5 * b.y;
    K.c[GA_BLADE_E35] = 0.5 * b.z;
    return K;
}

ga_mv ga_versor_rotation(ga_vec3 axis, double angle)
{
    return ga_rotor_to_mv(ga_rotor_rotation(axis, angle));
}

ga_mv ga_versor_translation(ga_vec3 a) { return ga_rotor_to_mv(ga_rotor_translation(a)); }
