/* ga/mv_log.c: the principal log of any rotor of G(4,1) (ga_mv_log): the
 * closed forms (m, ab, near-null and Spin(4)), the log in the rigid frame of
 * a null part, log(-R) - pi E, and the choice among these candidates by
 * their residual |exp(B) - R|. Notation and the functions of t:
 * ga/internal/bivector_fns.h; docs/versors.md derives every formula.
 */
#include <garotor/versor.h>

#include "internal/bivector_fns.h"
#include "internal/bivector_frames.h"
#include <garotor/rotor.h>
#include <float.h>
#include <math.h>

/* ---- the closed forms ---------------------------------------------------------- */

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
static ga_mv spin4_log(ga_mv R, ga_mv J)
{
    ga_mv B = ga_mv_zero();
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        ga_mv P = ga_mv_scale(J, 0.5 * sgn), U[3];
        P.c[0] += 0.5;
        gabf_ideal_basis(J, P, U);
        ga_mv X = ga_mv_gp(R, P), V = ga_mv_zero();
        double s2 = 0.0;
        for (int k = 0; k < 3; k++) {
            double v = -2.0 * ga_mv_sp(X, U[k]);
            V = gab_lin(1.0, V, v, U[k]);
            s2 += v * v;
        }
        double cphi = 2.0 * X.c[0], sphi = sqrt(s2), phi = atan2(sphi, cphi);
        if (sphi > 0.0) /* phi / sphi, not 1/S(-phi^2): near pi, sin of the
                           rounded phi is not the sphi that V carries */
            B = gab_lin(1.0, B, phi / sphi, V);
        else if (cphi < 0.0) /* X = -P: pi U for any unit U of the ideal */
            B = gab_lin(1.0, B, 3.14159265358979323846, U[0]);
    }
    return B;
}

/* The unit 4-vector J = q / sqrt(<q q>_0) of a 4-vector q with <q q>_0 > 0
   (the 4-space of two elliptic parts: q = 2 B1 B2 = 2 t1 t2 J, R4 = s1 s2 J) */
static ga_mv unit4(ga_mv q) { return ga_mv_scale(q, 1.0 / sqrt(ga_mv_sp(q, q))); }

/* two rotations with R0 <= -1/2: from log(-R) (log_closed says why) */
static int log_minus_two_rotations(ga_mv R, ga_mv *B)
{
    ga_mv Lm, q;
    int st = ga_mv_log(ga_mv_scale(R, -1.0), &Lm);
    if (st != GA_OK)
        return st;
    q = ga_mv_grade(ga_mv_gp(Lm, Lm), 4);
    if (ga_mv_sp(q, q) > 0.0) {
        *B = spin4_log(R, unit4(q));
    } else { /* -R = exp(Lm) with Lm one 2-blade (or 0): take the sign in a plane commuting with it */
        double lm2 = ga_mv_gp(Lm, Lm).c[0];
        ga_mv E = lm2 < 0.0 ? ga_mv_scale(Lm, 1.0 / sqrt(-lm2)) : commuting_plane(Lm);
        *B = gab_lin(1.0, Lm, -3.14159265358979323846, E);
    }
    return GA_OK;
}

/* ab form: two rotations by nearly equal angles */
static ga_mv log_ab_form(ga_mv R2, ga_mv W, double r0, double p22, double prod)
{
    double sp = sqrt(prod), A = -p22;
    double u = atan2(sqrt(fmax(A + 2.0 * sp * r0, 0.0)), r0 - sp);
    double v = atan2(sqrt(fmax(A - 2.0 * sp * r0, 0.0)), r0 + sp);
    double a = -u * u, b = -v * v;
    gab_fns fa = gab_fns_at(a), fb = gab_fns_at(b);
    double kr = 0.5 * (1.0 / fa.s + 1.0 / fb.s);
    double kw = (a * fa.t - b * fb.t) / ((b * fb.k - a * fa.k) * fa.s * fb.s);
    return gab_lin(kr, R2, kw, W);
}

/* m form, and its two exact cases: a factor that is -1, and R = 1 + N */
static int log_m_form(ga_mv R2, ga_mv W, double r0, double sig, double prod, double disc, double tol,
                      ga_mv *B)
{
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
        gab_fns f = gab_fns_at(lo);
        L = mo == 0.0 ? P : ga_mv_scale(P, 1.0 / f.s);
        ga_mv E = commuting_plane(P);
        *B = gab_lin(1.0, L, 3.14159265358979323846, E);
    } else if (m1 == m2) { /* both 0: R = 1 + N, N^2 = 0 (c1 = c2 = 1) */
        *B = gab_lin(1.0, R2, -1.0 / 3.0, W);
    } else {
        double l1 = factor_l(m1, c1), l2 = factor_l(m2, c2);
        gab_fns f1 = gab_fns_at(l1), f2 = gab_fns_at(l2);
        double dm = m1 - m2;
        double kr = (c2 * f1.s * l1 - c1 * f2.s * l2) / dm;
        double kw = (l2 * f2.e / f2.s - l1 * f1.e / f1.s) / dm;
        *B = gab_lin(kr, R2, kw, W);
    }
    return GA_OK;
}

/* log R by the closed forms (the comment at the top of this section) */
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
        int st = log_minus_two_rotations(R, &B);
        if (st != GA_OK)
            return st;
    } else if (r0 > 0.0 && fabs(sig) <= 1e-7 && fabs(prod) <= 1e-14) {
        /* both parts near null (a translation or transversion with at most a
           tiny rotation or boost): m1, m2 are then mostly rounding of
           <R2 R2>_0, but kR and kW are symmetric in them, so analytic in
           sig = m1 + m2 and prod = m1 m2; to first order (the next terms are
           O(sig^2, prod) <= 1e-14) kR = 1 - sig/6, kW = -1/3 + 2 sig/15 */
        B = gab_lin(1.0 - sig / 6.0, R2, -1.0 / 3.0 + 2.0 * sig / 15.0, W);
    } else if (prod > 0.0 && sig < 0.0 && r0 > 0.0 && sqrt(disc) < sqrt(prod)) {
        B = log_ab_form(R2, W, r0, p22, prod);
    } else {
        int st = log_m_form(R2, W, r0, sig, prod, disc, tol, &B);
        if (st != GA_OK)
            return st;
    }
    if (!ga_mv_isfinite(B))
        return GA_ERR_DOMAIN;
    *out = B;
    return GA_OK;
}

/* ---- a null part: the log in its rigid frame ------------------------------------ */

/* A turn t tiny against the rounding of r (|r| u) has an axis b = sin t u
   known to u |r| / t only, and its tilt off the translation p leaks
   |p| u / t of p into a perpendicular part, which the log divides by
   sin t again: an axis ~u |p| / t^2 away (1e4 at t = 1e-10) and a
   generator too large for exp to reproduce r. Where b is along p to
   within that rounding, it is taken along p (and where b itself is
   rounding, as 0): a change of r below its rounding, and the log of the
   screw along p. */
static int align_tiny_turn(ga_rotor *rp)
{
    ga_rotor r = *rp;
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
    *rp = r;
    return GA_OK;
}

/* log R through the rigid frame of its null part, n from <R>_2 (cand 0, 1)
   or from x -> R x ~R - x (2, 3), by the metric normal (even cand) or M^2
   (odd); GA_ERR_DOMAIN where R is not rigid there (no null part, or not
   this n) */
static int log_null_part(ga_mv R, int cand, ga_mv *out)
{
    double M[5][5];
    ga_mv Rr = ga_mv_reverse(R), V;
    if (cand < 2) {
        gabf_contraction_matrix(ga_mv_grade(R, 2), M);
    } else {
        for (int j = 0; j < 5; j++) {
            ga_mv y = ga_mv_gp(ga_mv_gp(R, ga_mv_blade(GA_BLADE_E1 + j)), Rr);
            for (int i = 0; i < 5; i++) M[i][j] = y.c[GA_BLADE_E1 + i] - (i == j);
        }
    }
    if (!gabf_rigid_frame(M, cand % 2, &V))
        return GA_ERR_DOMAIN;
    ga_rotor r;
    ga_generator g;
    int st = ga_rotor_from_mv(gabf_sandwich(V, R), 1e-6, &r);
    if (st != GA_OK)
        return GA_ERR_DOMAIN;
    if (align_tiny_turn(&r) != GA_OK)
        return GA_ERR_DOMAIN;
    st = ga_rotor_log_literal(r, &g);
    if (st != GA_OK)
        return GA_ERR_DOMAIN;
    *out = ga_mv_grade(gabf_sandwich(ga_mv_reverse(V), ga_generator_to_mv(g)), 2);
    return GA_OK;
}

/* ---- the candidates ------------------------------------------------------------ */

/* max |exp(B) - R|, INFINITY where exp(B) is not finite (ga_mv_maxabs
   skips NaN: a log whose exp overflows read as a close one) */
static double log_residual(ga_mv B, ga_mv R)
{
    ga_mv E = ga_mv_exp(B);
    return ga_mv_isfinite(E) ? ga_mv_maxabs(ga_mv_sub(E, R)) : INFINITY;
}

/* R is a rotor to a relative tol: no odd grades, R ~R = 1 */
static int is_rotor(ga_mv R, double scale, double tol)
{
    for (int g = 1; g <= 5; g += 2)
        if (ga_mv_maxabs(ga_mv_grade(R, g)) > tol * scale)
            return 0;
    ga_mv rr = ga_mv_gp(R, ga_mv_reverse(R));
    rr.c[0] -= 1.0;
    return ga_mv_maxabs(rr) <= tol * fmax(1.0, scale * scale);
}

/* Candidates: the closed forms; where they leave more than rounding,
   the log in the rigid frame of a null part, with n from <R>_2 (entries
   ~|R|), log(-R) - pi E (R0 < 0), and the rigid frame with n from
   R x ~R - x (entries ~|R|^2, whose rounding moves the log itself,
   though not exp(log R), further from B), each n by the metric normal
   and by M^2. The first in the order: rigid frame from <R>_2 (exact
   where R has a null part, beside which the closed forms lose
   u (|N|/t)^3), closed forms, log(-R) - pi E, the others, whose residual
   |exp(B) - R| is within twice the smallest, or at the floor that exp's own
   rounding sets, is kept: the residuals of good ones differ by that
   rounding only. */
static int log_candidates(ga_mv R, double tol, double scale, ga_mv cand[7], double cres[7])
{
    int nc = 0;
    if (log_closed(R, tol, &cand[nc]) == GA_OK)
        cres[nc] = log_residual(cand[nc], R), nc++;
    if (!(nc == 1 && cres[0] <= 4.0 * DBL_EPSILON * fmax(1.0, scale * scale))) {
        ga_mv Lm, P[2], X;
        /* first in the order */
        if (log_null_part(R, 0, &X) == GA_OK && ga_mv_isfinite(X)) {
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
                cand[nc] = gab_lin(1.0, Lm, -3.14159265358979323846 / sqrt(-l[i]), P[i]);
                cres[nc] = log_residual(cand[nc], R), nc++;
            }
        }
        for (int c = 1; c < 4; c++)
            if (log_null_part(R, c, &cand[nc]) == GA_OK && ga_mv_isfinite(cand[nc]))
                cres[nc] = log_residual(cand[nc], R), nc++;
    }
    return nc;
}

ga_status ga_mv_log(ga_mv R, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!ga_mv_isfinite(R))
        return GA_ERR_NOTFINITE;
    double scale = ga_mv_maxabs(R), tol = 1e-9;
    if (!is_rotor(R, scale, tol))
        return GA_ERR_DOMAIN;
    ga_mv cand[7];
    double cres[7];
    int nc = log_candidates(R, tol, scale, cand, cres);
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
       magnified), so the check allows 64 u size^2 (u = DBL_EPSILON) where
       that is above 1e-9, up to 1e-6 (size about 8.4e3), beyond which it
       cannot tell */
    if (!(res <= fmin(1e-6, fmax(tol, 64.0 * DBL_EPSILON * sz * sz)) * scale))
        return GA_ERR_DOMAIN;
    *out = B;
    return GA_OK;
}
