/* garotor/meet.c: objects held about a local origin (ga_mv_localize,
 * ga_rotor_apply_about), the meet of two objects in the whole space, and
 * the join and the meet relative to it for objects in any position
 * (Dorst-Fontijne-Mann, "Geometric Algebra for Computer Science", ch. 5,
 * 14-15). See object.h for the conventions and the accuracy model. */
#include <garotor/conformal.h>
#include <garotor/object.h>
#include <math.h>

#include "internal/blade.h"
#include "internal/object.h"
#include "internal/vec3.h"

#define U GAO_U

static int finite3(ga_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

/* ga_mv_localize; strict = 0 (the join's moves) takes a round's move as it
   comes, whatever it has lost */
static int localize(ga_mv X, ga_vec3 origin, double lambda, int strict, ga_mv *out)
{
    if (!ga_mv_isfinite(X) || !finite3(origin) || !isfinite(lambda))
        return GA_ERR_NOTFINITE;
    if (!(lambda > 0.0))
        return GA_ERR_ARG;
    /* an object is of one grade: what rounding left in the others (1e-18 of a
       plane built 1e4 out) is dropped, as the translation would magnify it */
    int k = 0;
    for (int g = 1; g <= 5; g++)
        if (ga_mv_maxabs(ga_mv_grade(X, g)) > ga_mv_maxabs(ga_mv_grade(X, k)))
            k = g;
    int one_grade = gao_off_grade(X, k) <= GA_POINT_TOL * ga_mv_maxabs(X);
    if (one_grade)
        X = ga_mv_grade(X, k);
    ga_object kind;
    ga_mv Y;
    if (gao_classify(X, 0, &kind) == GA_OK && kind.kind <= GA_OBJECT_PLANE) {
        /* A flat has no part A ^ nbar (a dual plane m + d n, a direct flat
           F ^ n): what rounding left there is dropped. Then T X ~T = X +
           (n t X + X t n)/2 exactly, t = -origin (the term n t X t n / 4
           vanishes: n t n = 0), which has no t^2 terms to cancel; the full
           sandwich loses u |t|^2 of X's size where the flat comes near. */
        X = gao_scale_n_nbar(X, 1.0, 0.0);
        ga_mv nt = ga_mv_gp(ga_mv_n(), ga_vec3_to_mv(ga__v3_scale(origin, -1.0)));
        Y = ga_mv_add(X, ga_mv_scale(ga_mv_add(ga_mv_gp(nt, X), ga_mv_gp(X, ga_mv_reverse(nt))), 0.5));
        Y = gao_scale_n_nbar(Y, 1.0 / lambda, 0.0);
        if (kind.kind == GA_OBJECT_LINE) {
            /* w (u e45 + (p ^ u) ^ n): the moment p x u = (b23, -b13, b12),
               b_ij the e_ij4 (= e_ij5) coefficients, is known to u |origin|
               from a line far out, u |origin| / lambda in the units of
               lambda: its part along u, which no line has, is dropped */
            ga_vec3 dir = ga__v3(Y.c[GA_BLADE_E145], Y.c[GA_BLADE_E245], Y.c[GA_BLADE_E345]);
            ga_vec3 M = ga__v3(Y.c[GA_BLADE_E234], -Y.c[GA_BLADE_E134], Y.c[GA_BLADE_E124]);
            double uu = ga__v3_dot(dir, dir);
            if (uu > 0.0)
                M = ga__v3_sub(M, ga__v3_scale(dir, ga__v3_dot(M, dir) / uu));
            Y.c[GA_BLADE_E234] = Y.c[GA_BLADE_E235] = M.x;
            Y.c[GA_BLADE_E134] = Y.c[GA_BLADE_E135] = -M.y;
            Y.c[GA_BLADE_E124] = Y.c[GA_BLADE_E125] = M.z;
        }
    } else {
        /* x -> x / lambda: o -> lambda o, n -> n / lambda, e_i fixed (then
           F(x) -> lambda F(x / lambda)); blades with e45 (o ^ n) and without
           e4, e5 are fixed */
        ga_vec3 mo = ga__v3_scale(origin, -1.0);
        ga_mv Yt = gao_translate(X, mo);
        if (strict) {
            /* X's own rounding, moved: where that is more than
               GAO_LOCALIZE_LOSS times the rounding of the moved coefficients
               (u of the largest), the local form would claim digits the world
               form does not hold (a round built far out has its weight only
               to u of its squared distance): refused */
            ga_mv eY = gao_abs_translate(gao_uncertainty(X, GAO_KAPPA), mo);
            if (ga_mv_maxabs(eY) > GAO_LOCALIZE_LOSS * U * ga_mv_maxabs(Yt))
                return GA_ERR_PRECISION;
        }
        Y = gao_scale_n_nbar(Yt, 1.0 / lambda, lambda);
    }
    if (one_grade)
        Y = ga_mv_grade(Y, k);
    if (!ga_mv_isfinite(Y))
        return GA_ERR_DOMAIN;
    *out = Y;
    return GA_OK;
}

ga_status ga_mv_localize(ga_mv X, ga_vec3 origin, double lambda, ga_mv *out)
{
    return out ? localize(X, origin, lambda, 1, out) : GA_ERR_ARG;
}

ga_status ga_rotor_apply_about(ga_rotor R, ga_vec3 origin, ga_mv X, ga_vec3 *new_origin, ga_mv *out)
{
    if (!new_origin || !out)
        return GA_ERR_ARG;
    double r[8] = {R.s, R.e12, R.e13, R.e23, R.e1n, R.e2n, R.e3n, R.e123n};
    for (int i = 0; i < 8; i++)
        if (!isfinite(r[i]))
            return GA_ERR_NOTFINITE;
    if (!finite3(origin) || !ga_mv_isfinite(X))
        return GA_ERR_NOTFINITE;
    /* R T_o = T_R(o) Q with Q = T_-R(o) R T_o: Q fixes the origin, so it is
       the rotation q of R = T_t q (R(o) = q(o) + t) */
    ga_rotor Q = {R.s, R.e12, R.e13, R.e23, 0.0, 0.0, 0.0, 0.0};
    ga_vec3 o2 = ga_rotor_apply(R, origin);
    ga_mv Y = ga_rotor_apply_mv(Q, X);
    if (!finite3(o2) || !ga_mv_isfinite(Y))
        return GA_ERR_DOMAIN;
    *new_origin = o2;
    *out = Y;
    return GA_OK;
}

static int is_round(ga_mv X)
{
    ga_object o;
    return gao_classify(X, 0, &o) == GA_OK && o.kind >= GA_OBJECT_POINTPAIR;
}

/* ---- the meet in the whole space, and its decision "special position" -------
   W = A* ^ B* (A* = A I^-1) is the meet of A and B as given, exact to its
   rounding (gao_op_exact). In special position it is 0 in exact
   arithmetic, and in floating point a residue of the inputs' rounding: it
   is taken as 0 where every coefficient is within what the inputs'
   uncertainties eA, eB (absolute, coefficient by coefficient) can make of
   it, to first order,

     |W_k| <= (|eA*| |B*| + |A*| |eB*|)_k + u |W_k| + 4 u^2 (|A*| |B*|)_k,

   |.| the abs products of internal/object.h (every term with its sign
   positive), the last two terms W's own rounding. The bound is linear in
   e, of the size of the inputs' rounding: a meet above it is a real one
   and answers (tests/test_meet_special.c: a sphere and itself moved by
   2^13 u L, L = |c| + r, and a line and a plane moved 2^10 u L off it, at
   1 to 1e8 from the origin; the threshold measured there is some 500 u L
   and 130 u L).

   The uncertainty of an input, kappa = GAO_MEET_KAPPA = 32 (a construction
   of a few dozen roundings), is the largest of:
   - e_world: kappa u times the largest coefficient of each class (object.h's
     model, gao_uncertainty): the rounding of X's own coefficients. It does
     not bound what a construction leaves where a coefficient is a
     cancellation of larger terms: a sphere through (or near) the origin
     has e4, e5 parts w (|c|^2 - r^2 -+ 1) / 2, near 0, while the
     constructors of conformal.h build it about one of its points and
     translate it there exactly, which carries their rounding (u of the
     local coefficients) out to u |c| and u |c|^2 of them: measured
     against the construction carried exactly, the spheres of radius 13 k
     through exact points 1e6 from the origin that pass near it are off by
     2.8e3 u of that class's largest coefficient, where e_world allows 32 u
     (and ga_mv_meet left 159 times its threshold of such a sphere met with
     itself built from other points). So, for a round:
   - e_local (meet_uncertainty): X held about its centre c in units of
     lambda, a power of two near its radius r (at least 1), where its
     coefficients are the object's own terms, not their sums (w/2 in the
     weight and w r^2 / 2 in its n part, both w r / 2 in units of r):
     kappa u times the largest coefficient of each class there, moved back
     to the world in null coordinates (n parts times lambda, nbar parts over
     lambda, then the magnitudes of the translation by c,
     gao_abs_translate_null). Where no coefficient cancels (|c| far from r)
     it is e_world to a small factor (both u w |c|^2 in the e4, e5 parts).
     The centre and radius are ga_object_from_mv's (strict): a round whose
     weight is within its rounding of 0 (a small sphere 1e8 out, a plane as
     stored) has none, and keeps e_world, as do flats (a plane or line keeps
     its coefficients to a few u of its classes: object.h, "Accuracy").
   - the defect (with_defect): e scaled up to what X itself shows of its
     error (below): a construction that magnifies the rounding (a circle
     through two points 1/16 of its radius apart) leaves a point pair,
     circle or line further from a blade than e allows, and e is scaled by
     that factor.
   Not seen by any of these: an input whose coefficients carry more than
   the rounding of their own classes from how it was made. conformal.h's
   constructors give each coefficient to about u of itself (built in
   double-double, gao_build_about); before, a plane through points 1e6 out
   that passes 2.6e3 from the origin kept its distance only to u 1e6, and a
   line lying in it met it above the threshold. Objects from a chain of
   operations (a versor applied, a meet) carry that chain's errors. */

/* ga_mv_dual (s = -1: X I^-1 = -X I) and ga_mv_undual (s = 1: X I) of a
   finite X as the signed permutations they are, each zero +0 as the dense
   products give it (they spread NaN and infinity to every coefficient;
   ga_mv_meet takes them for non-finite input) */
static ga_mv dual_perm(ga_mv X, double s)
{
    ga_mv r;
    for (int i = 0; i < 32; i++) {
        /* gabl_sign(m, 31): the swaps sum the indices k of m's bits (odd for
           k = 1, 3), and e5 e5 = -1 adds one */
        unsigned m = gabl_mask[i];
        double sg = ((m >> 1) ^ (m >> 3) ^ (m >> 4)) & 1u ? -s : s;
        r.c[gabl_index_of[m ^ 31u]] = sg * X.c[i] + 0.0;
    }
    return r;
}
static ga_mv dual_f(ga_mv X) { return dual_perm(X, -1.0); }
static ga_mv undual_f(ga_mv X) { return dual_perm(X, 1.0); }

/* Whether X is a nonzero flat exactly: X ^ n = 0, that is no part without e4
   or e5, and each part A e4 equal to its A e5 ((p A e4 + q A e5) ^ n =
   (p - q) A e4 e5) */
static int exact_flat(ga_mv X)
{
    int any = 0;
    for (int i = 0; i < 32; i++) {
        if (!(gabl_mask[i] & 0x18u) && X.c[i] != 0.0)
            return 0;
        if (gabl_pair_e4(i) && X.c[i] != X.c[i + 1])
            return 0;
        any |= X.c[i] != 0.0;
    }
    return any;
}

/* e_world and e_local of X (above): e_world where X is no round with a
   known centre */
static ga_mv meet_uncertainty(ga_mv X)
{
    ga_mv e = gao_uncertainty(X, GAO_MEET_KAPPA);
    ga_object o;
    if (exact_flat(X)) /* a flat: e_world (what gao_classify would decide, cheaper) */
        return e;
    if (gao_classify(X, 1, &o) != GA_OK || o.kind < GA_OBJECT_POINTPAIR)
        return e;
    ga_vec3 c = o.centre;
    double size = sqrt(fabs(o.r2)), lam = size >= 1.0 && isfinite(size) ? ldexp(1.0, ilogb(size)) : 1.0;
    ga_mv Y = gao_scale_n_nbar(gao_translate(X, ga__v3_scale(c, -1.0)), 1.0 / lam, lam);
    ga_mv eN = gao_unc_to_null(gao_uncertainty(Y, GAO_MEET_KAPPA));
    for (int i = 0; i < 32; i++)
        if (gabl_pair_e4(i)) {
            eN.c[i] *= lam;     /* the n part */
            eN.c[i + 1] /= lam; /* the nbar part */
        }
    ga_mv el = gao_unc_from_null(gao_abs_translate_null(eN, c), 1.0, 1.0);
    if (!ga_mv_isfinite(el))
        return e;
    for (int i = 0; i < 32; i++) e.c[i] = fmax(e.c[i], el.c[i]);
    return e;
}

/* e, the uncertainty of X, scaled up to what X's own defect shows: a point
   pair or flat point (grade 2), or the dual bivector of a circle or line
   (grade 3), is a blade exactly when b ^ b = 0, and b ^ b = 2 b ^ db to
   first order for b off a blade by db. Where a coefficient of b ^ b
   (exact, rounded once) exceeds 2 (|b| |eb|) there, X is further from the
   object it stands for than e says (a circle through two points 1/16 of
   its radius apart: its construction magnifies the rounding), and e is
   scaled by the largest such ratio. Spheres and planes (vectors dualised)
   are blades whatever their rounding: they show nothing. */
static ga_mv with_defect(ga_mv X, ga_mv e)
{
    int k = 0;
    for (int i = 0; i < 32; i++)
        if (X.c[i] != 0.0)
            k = gabl_popcount5(gabl_mask[i]);
    if (k != 2 && k != 3)
        return e;
    ga_mv b = ga_mv_grade(k == 2 ? X : dual_f(X), 2), eb = gao_abs(k == 2 ? e : dual_f(e));
    ga_mv d = gao_op_exact(b, b), bound = ga_mv_scale(gao_abs_gp(gao_abs(b), eb), 2.0);
    double f = 1.0;
    for (int i = 0; i < 32; i++)
        if (fabs(d.c[i]) > bound.c[i])
            f = fmax(f, fabs(d.c[i]) / bound.c[i]);
    /* (1 + 2^-20: the bound is summed again in meet_whole, in another
       order; X ^ X must come out within it) */
    return f > 1.0 && isfinite(f) ? ga_mv_scale(e, f * (1.0 + 0x1p-20)) : e;
}

/* The weight of a flat M: its coefficients on blades with both e4 and e5
   (a plane's normal, a line's direction, a flat point's e45 part). Where
   every one is within its bound e (e NULL: within tol) it is set to exactly
   0: the flat at infinity that M is to that accuracy, read back as EMPTY
   (parallel flats). */
static ga_mv weight_to_zero(ga_mv M, const ga_mv *e, double tol)
{
    for (int i = 0; i < 32; i++)
        if ((gabl_mask[i] & 0x18u) == 0x18u && M.c[i] != 0.0 && !(fabs(M.c[i]) <= (e ? e->c[i] : tol)))
            return M;
    for (int i = 0; i < 32; i++)
        if ((gabl_mask[i] & 0x18u) == 0x18u)
            M.c[i] = 0.0;
    return M;
}

/* Whether X is a nonzero flat at infinity: its weight exactly 0 */
static int at_infinity(ga_mv X)
{
    for (int i = 0; i < 32; i++)
        if ((gabl_mask[i] & 0x18u) == 0x18u && X.c[i] != 0.0)
            return 0;
    return ga_mv_maxabs(X) > 0.0;
}

/* ((A I^-1) ^ (B I^-1)) I, A and B direct and finite */
static ga_mv meet_whole(ga_mv A, ga_mv B)
{
    /* The duals are a signed permutation of the coefficients (exact); their
       wedge is exact, rounded once (gao_op_exact): the meet of the objects
       as given, whatever their distance from the origin. */
    ga_mv da = dual_f(A), db = dual_f(B), W = gao_op_exact(da, db);
    /* Special position: W is 0 to the accuracy of the inputs (above) */
    ga_mv ada = gao_abs(da), adb = gao_abs(db);
    ga_mv ea = gao_abs(dual_f(with_defect(A, meet_uncertainty(A))));
    ga_mv eb = gao_abs(dual_f(with_defect(B, meet_uncertainty(B))));
    ga_mv eW = ga_mv_add(gao_abs_gp(ea, adb), gao_abs_gp(ada, eb));
    eW = ga_mv_add(eW, ga_mv_add(ga_mv_scale(gao_abs(W), U), ga_mv_scale(gao_abs_gp(ada, adb), 4.0 * U * U)));
    int zero = ga_mv_isfinite(eW);
    for (int i = 0; i < 32 && zero; i++) zero = fabs(W.c[i]) <= eW.c[i];
    if (zero)
        return ga_mv_zero();
    /* two flats meet in a flat; at infinity where its weight is within what
       the inputs' uncertainties make of it (parallel flats as given) */
    if (exact_flat(A) && exact_flat(B)) {
        ga_mv eM = gao_abs(undual_f(eW));
        return weight_to_zero(undual_f(W), &eM, 0.0);
    }
    return undual_f(W);
}

ga_mv ga_mv_meet(ga_mv A, ga_mv B)
{
    if (ga_mv_maxabs(ga_mv_sub(A, ga_mv_grade(A, 1))) == 0.0)
        A = ga_mv_dual(A);
    if (ga_mv_maxabs(ga_mv_sub(B, ga_mv_grade(B, 1))) == 0.0)
        B = ga_mv_dual(B);
    if (!ga_mv_isfinite(A) || !ga_mv_isfinite(B)) /* NaN or infinity in every coefficient it reaches */
        return ga_mv_undual(gao_op_exact(ga_mv_dual(A), ga_mv_dual(B)));
    return meet_whole(A, B);
}

/* ---- the join, and the meet of objects in special position -------------------
   The subspace of a blade X is {x : x ^ X = 0}. The decisions below are made
   in the Euclidean metric of the coefficients (every e_i squares to +1
   there): the join and the meet as subspaces do not depend on the metric
   (DFM §5.7), and in this metric a blade has orthonormal factors, every
   nonzero blade is invertible (X^-1 = ~X / |X|^2) and the distance of a
   subspace from another is measured by the sines of the principal angles. */

/* One-sided Jacobi (Hestenes) on the n columns (column j at a + j m, each of
   length m) of a small matrix: plane rotations make the columns mutually
   orthogonal; the same rotations turn the n x n matrix v (column j at v + j n)
   from the identity into the right singular vectors, and the columns' norms
   are then the singular values. Each rotation is exact to a few u, and the
   singular values come out to a few u of the largest: an error linear in
   the perturbation, not in its square as through the Gram matrix. */
static void jacobi(double *a, int m, int n, double *v)
{
    for (int i = 0; i < n * n; i++) v[i] = i % (n + 1) == 0 ? 1.0 : 0.0;
    for (int sweep = 0; sweep < 60; sweep++) {
        int rotated = 0;
        for (int p = 0; p < n - 1; p++)
            for (int q = p + 1; q < n; q++) {
                double *x = a + p * m, *y = a + q * m, al = 0.0, be = 0.0, ga = 0.0;
                for (int i = 0; i < m; i++) {
                    al += x[i] * x[i];
                    be += y[i] * y[i];
                    ga += x[i] * y[i];
                }
                if (!(fabs(ga) > 4.0 * U * sqrt(al) * sqrt(be)))
                    continue;
                rotated = 1;
                double ze = (be - al) / (2.0 * ga);
                double t = (ze >= 0.0 ? 1.0 : -1.0) / (fabs(ze) + hypot(1.0, ze));
                double c = 1.0 / hypot(1.0, t), s = c * t;
                for (int i = 0; i < m; i++) {
                    double xi = x[i], yi = y[i];
                    x[i] = c * xi - s * yi;
                    y[i] = s * xi + c * yi;
                }
                double *vx = v + p * n, *vy = v + q * n;
                for (int i = 0; i < n; i++) {
                    double xi = vx[i], yi = vy[i];
                    vx[i] = c * xi - s * yi;
                    vy[i] = s * xi + c * yi;
                }
            }
        if (!rotated)
            break;
    }
}

static double dot5(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] + a[4] * b[4];
}
static double col_norm(const double *a, int m)
{
    double s = 0.0;
    for (int i = 0; i < m; i++) s += a[i] * a[i];
    return sqrt(s);
}
/* the indices 0..n-1 ordered by s, ascending (up = 1) or descending */
static void order(const double *s, int n, int up, int *ord)
{
    for (int i = 0; i < n; i++) {
        int j = i;
        while (j > 0 && (up ? s[ord[j - 1]] > s[i] : s[ord[j - 1]] < s[i])) {
            ord[j] = ord[j - 1];
            j--;
        }
        ord[j] = i;
    }
}

/* An orthonormal basis q[0..k-1] of the subspace of X, a grade-k part
   (1 <= k <= 4), scaled to max |coefficient| ~ 1: the right singular vectors
   of x -> x ^ X for its k smallest singular values. For a blade these are 0
   and the other 5 - k all equal |X| (|x ^ X| = |x| |X| for x orthogonal to
   it), so the k-th smallest over the largest says how far X is from a blade:
   returned. */
static double blade_basis(ga_mv X, int k, double q[5][5])
{
    double a[5 * 10], v[25], s[5];
    int idx[10], m = 0, ord[5];
    for (int i = 0; i < 32; i++)
        if (ga_blade_grade(i) == k + 1)
            idx[m++] = i;
    for (int j = 0; j < 5; j++) {
        ga_mv y = ga_mv_op(ga_mv_blade(1 + j), X);
        for (int i = 0; i < m; i++) a[j * m + i] = y.c[idx[i]];
    }
    jacobi(a, m, 5, v);
    for (int j = 0; j < 5; j++) s[j] = col_norm(a + j * m, m);
    order(s, 5, 1, ord);
    for (int i = 0; i < k; i++)
        for (int j = 0; j < 5; j++) q[i][j] = v[ord[i] * 5 + j];
    return s[ord[4]] > 0.0 ? s[ord[k - 1]] / s[ord[4]] : INFINITY;
}

/* The grade k (1..4) of an object X, after the checks of ga_mv_join. */
static int object_grade(ga_mv X, int *k)
{
    if (ga_mv_maxabs(X) == 0.0)
        return GA_ERR_SINGULAR;
    X = gao_unit_scaled(X);
    double s = ga_mv_maxabs(X), q[5][5];
    int g = 0;
    while (g <= 5 && gao_off_grade(X, g) > GA_POINT_TOL * s) g++;
    if (g > 5)
        return GA_ERR_NOTBLADE; /* mixed grades */
    if (g == 0 || g == 5)
        return GA_ERR_DOMAIN;
    if (!(blade_basis(ga_mv_grade(X, g), g, q) <= GA_OBJECT_JOIN_TOL))
        return GA_ERR_NOTBLADE;
    *k = g;
    return GA_OK;
}

/* The subspaces of a (grade ka) and b (grade kb), both held about a local
   origin: an orthonormal basis of a's, and the directions of b's outside it,
   c[0..kb-1] with the sines s of the principal angles, largest first: the
   left singular vectors of the part of b's basis orthogonal to a's
   (modified Gram-Schmidt, twice). */
typedef struct {
    double qa[5][5], qb[5][5], c[5][5], s[5];
} spans;
static void span_of(ga_mv a, int ka, ga_mv b, int kb, spans *sp)
{
    double(*qb)[5] = sp->qb, R[25], v[25], s[5];
    int ord[5];
    blade_basis(gao_unit_scaled(a), ka, sp->qa);
    blade_basis(gao_unit_scaled(b), kb, qb);
    for (int j = 0; j < kb; j++) {
        double *x = R + 5 * j;
        for (int i = 0; i < 5; i++) x[i] = qb[j][i];
        for (int pass = 0; pass < 2; pass++)
            for (int i = 0; i < ka; i++) {
                double d = dot5(sp->qa[i], x);
                for (int l = 0; l < 5; l++) x[l] -= d * sp->qa[i][l];
            }
    }
    jacobi(R, 5, kb, v);
    for (int j = 0; j < kb; j++) s[j] = col_norm(R + 5 * j, 5);
    order(s, kb, 0, ord);
    for (int i = 0; i < kb; i++) {
        double *c = sp->c[i];
        sp->s[i] = s[ord[i]];
        for (int l = 0; l < 5; l++) c[l] = R[5 * ord[i] + l];
        /* orthogonal again to a's basis and the directions before it */
        for (int pass = 0; pass < 2; pass++) {
            for (int j = 0; j < ka; j++) {
                double d = dot5(sp->qa[j], c);
                for (int l = 0; l < 5; l++) c[l] -= d * sp->qa[j][l];
            }
            for (int j = 0; j < i; j++) {
                double d = dot5(sp->c[j], c);
                for (int l = 0; l < 5; l++) c[l] -= d * sp->c[j][l];
            }
        }
        double nc = col_norm(c, 5);
        for (int l = 0; l < 5; l++) c[l] = nc > 0.0 ? c[l] / nc : 0.0;
    }
}

/* The left contraction a _| b in the Euclidean metric of the coefficients:
   e_A _| e_B = e_A e_B for A a subset of B, the sign that of the swaps that
   sort A B (no e5 e5 = -1). */
static ga_mv lc_euclid(ga_mv a, ga_mv b)
{
    int idx[32];
    for (int i = 0; i < 32; i++) idx[ga_blade_mask(i)] = i;
    ga_mv r = ga_mv_zero();
    for (int i = 0; i < 32; i++) {
        unsigned ma = ga_blade_mask(i);
        if (a.c[i] == 0.0)
            continue;
        for (int j = 0; j < 32; j++) {
            unsigned mb = ga_blade_mask(j);
            if (b.c[j] == 0.0 || (ma & mb) != ma)
                continue;
            int swaps = 0;
            for (unsigned x = ma >> 1; x; x >>= 1)
                for (unsigned y = x & mb; y; y &= y - 1) swaps++;
            r.c[idx[ma ^ mb]] += (swaps & 1 ? -1.0 : 1.0) * a.c[i] * b.c[j];
        }
    }
    return r;
}

/* Whether n lies in the span of the orthonormal q[0..k-1] and c[0..r-1]:
   the residual of n / |n| after projecting them out at most tol. */
static int holds_n(double q[5][5], int k, double c[5][5], int r, double tol)
{
    double x[5] = {0, 0, 0, sqrt(0.5), sqrt(0.5)};
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < k + r; i++) {
            const double *b = i < k ? q[i] : c[i - k];
            double d = dot5(b, x);
            for (int l = 0; l < 5; l++) x[l] -= d * b[l];
        }
    return col_norm(x, 5) <= tol;
}

static ga_mv vec5(const double *x) { return ga_mv_vector(x[0], x[1], x[2], x[3], x[4]); }

/* The local origin o and length lambda (a power of two) of the pair: o the
   centre of A as ga_object_from_mv reads it roughly (its point closest to the
   origin for a flat), else B's, else 0; lambda near the larger of the radii
   and the distance of the two centres (at least 2^-10 |o|), 1 when that is 0. Returns the
   tolerance of the decisions about (o, lambda): GA_OBJECT_JOIN_TOL, or the
   rounding that moving there may add when that is larger: 64 u |o| / lambda
   of a flat's size (its coefficients grow like the distance), 64 u
   (|o| / lambda)^2 with a round or point (like its square). */
static double local_frame(ga_mv A, ga_mv B, ga_vec3 *o, double *lambda)
{
    ga_object oa, ob;
    int ha = gao_classify(A, 0, &oa) == GA_OK && oa.kind != GA_OBJECT_EMPTY && finite3(oa.centre);
    int hb = gao_classify(B, 0, &ob) == GA_OK && ob.kind != GA_OBJECT_EMPTY && finite3(ob.centre);
    double size = 0.0;
    *o = ha ? oa.centre : hb ? ob.centre : ga__v3(0, 0, 0);
    if (ha)
        size = fmax(size, sqrt(fabs(oa.r2)));
    if (hb)
        size = fmax(size, sqrt(fabs(ob.r2)));
    if (ha && hb) {
        ga_vec3 d = ga__v3_sub(oa.centre, ob.centre);
        size = fmax(size, sqrt(ga__v3_dot(d, d)));
    }
    int round = (ha && oa.kind >= GA_OBJECT_POINTPAIR) || (hb && ob.kind >= GA_OBJECT_POINTPAIR) ||
                (!ha && is_round(A)) || (!hb && is_round(B));
    /* not below 2^-10 |o| with a round, 2^-2 |o| for two flats: a flat's
       rounding, u |o| times the condition of its construction (u D / S for
       points S apart at D: 1e4 at D = 1e4, S = 1), stays below
       GA_OBJECT_JOIN_TOL of lambda, so two flats that are the same up to it
       read as such however near their centres (two flats have no size of
       their own: the scene's is their distance from the origin) */
    size = fmax(size, (round ? 0x1p-10 : 0x1p-2) * sqrt(ga__v3_dot(*o, *o)));
    *lambda = isfinite(size) && size > 0.0 ? ldexp(1.0, ilogb(size)) : 1.0;
    double far = sqrt(ga__v3_dot(*o, *o)) / *lambda;
    return fmax(GA_OBJECT_JOIN_TOL, 64.0 * U * (round ? far * far : far));
}

/* The join and the meet of A and B. */
static int join_meet(ga_mv A, ga_mv B, ga_mv *J, ga_mv *M)
{
    int ka, kb, st;
    if (!ga_mv_isfinite(A) || !ga_mv_isfinite(B))
        return GA_ERR_NOTFINITE;
    if ((st = object_grade(A, &ka)) != GA_OK || (st = object_grade(B, &kb)) != GA_OK)
        return st;
    /* the subspaces do not depend on the scale: max |coefficient| ~ 1 (by a
       power of two, exactly), so that nothing below over- or underflows */
    ga_mv a = gao_unit_scaled(ga_mv_grade(A, ka)), b = gao_unit_scaled(ga_mv_grade(B, kb)), al, bl;
    /* about the local origin, in units of the scene (ga_mv_localize); where
       that overflows, about the origin */
    ga_vec3 o;
    double lam;
    double tol = local_frame(a, b, &o, &lam);
    if (localize(a, o, lam, 0, &al) != GA_OK || localize(b, o, lam, 0, &bl) != GA_OK ||
        ga_mv_maxabs(al) == 0.0 || ga_mv_maxabs(bl) == 0.0) {
        o = ga__v3(0, 0, 0);
        lam = 1.0;
        al = a;
        bl = b;
        tol = GA_OBJECT_JOIN_TOL;
    }
    spans sp;
    span_of(al, ka, bl, kb, &sp);
    int r = 0; /* the directions of B outside A */
    while (r < kb && r < 5 - ka && sp.s[r] > tol) r++;
    int m = kb - r; /* the dimension of the meet */
    ga_mv j, mt;
    if (r == 0) { /* B in A */
        j = A;
        mt = B;
    } else if (m == ka) { /* A in B */
        j = B;
        mt = A;
    } else {
        if (m == 0) { /* no common direction: A ^ B */
            j = ga_mv_op(A, B);
        } else { /* A ^ c1 ^ ... ^ cr about the local origin, back in the world */
            ga_mv jl = gao_unit_scaled(al);
            for (int i = 0; i < r; i++) jl = ga_mv_op(jl, vec5(sp.c[i]));
            /* a flat (n in its subspace, as for coplanar circles) has no
               part A ^ nbar: what rounding left there is dropped */
            if (holds_n(sp.qa, ka, sp.c, r, tol))
                jl = gao_scale_n_nbar(jl, 1.0, 0.0);
            if ((st = localize(jl, ga__v3_scale(o, -1.0 / lam), 1.0 / lam, 0, &j)) != GA_OK)
                return st;
        }
        if (ka + r == 5) { /* the whole space: the meet of ga_mv_meet */
            mt = meet_whole(A, B);
        } else { /* (B _| J^-1) _| A about the local origin, the metric Euclidean */
            ga_mv au = gao_unit_scaled(al), jl = au;
            for (int i = 0; i < r; i++) jl = ga_mv_op(jl, vec5(sp.c[i]));
            double jj = 0.0;
            for (int i = 0; i < 32; i++) jj += jl.c[i] * jl.c[i];
            ga_mv ml = lc_euclid(lc_euclid(bl, ga_mv_scale(ga_mv_reverse(jl), 1.0 / jj)), au);
            if (holds_n(sp.qa, ka, sp.c, 0, tol) && holds_n(sp.qb, kb, sp.c, 0, tol)) {
                ml = gao_scale_n_nbar(ml, 1.0, 0.0); /* both flats: so is the meet */
                /* at infinity where its weight is within tol of the terms
                   of the contractions (|bl| |au| / |jl|): the sine of the
                   angle of the flats below tol (parallel to tol) */
                ml = weight_to_zero(ml, NULL, tol * ga_mv_maxabs(bl) * ga_mv_maxabs(au) / sqrt(jj));
            }
            if (m == 0)
                mt = ml; /* a scalar: no common point */
            else if ((st = localize(ml, ga__v3_scale(o, -1.0 / lam), 1.0 / lam, 0, &mt)) != GA_OK)
                return st;
            else if (at_infinity(ml))
                mt = weight_to_zero(mt, NULL, INFINITY); /* a translation keeps it there (up to ~u^2 left) */
        }
    }
    if (!ga_mv_isfinite(j) || !ga_mv_isfinite(mt))
        return GA_ERR_DOMAIN;
    if (J)
        *J = j;
    if (M)
        *M = mt;
    return GA_OK;
}

ga_status ga_mv_join(ga_mv A, ga_mv B, ga_mv *out) { return out ? join_meet(A, B, out, NULL) : GA_ERR_ARG; }

ga_status ga_mv_meet_rel(ga_mv A, ga_mv B, ga_mv *out)
{
    return out ? join_meet(A, B, NULL, out) : GA_ERR_ARG;
}
