/* ga/object_between.c: the rotors between two objects of one kind, rigid
 * (ga_rotor_between) or with a dilation (ga_versor_between), and the objects
 * along them (ga_object_interp). See object.h. */
#include <garotor/conformal.h>
#include <garotor/object.h>
#include <garotor/versor.h>
#include <math.h>

#include "internal/object.h"
#include "internal/vec3.h"

static double norm3(ga_vec3 a) { return sqrt(ga__v3_dot(a, a)); }

/* The shortest rotation taking unit a to unit b (a half turn about a
   perpendicular axis when b = -a). */
static ga_rotor turn(ga_vec3 a, ga_vec3 b)
{
    ga_vec3 x = ga__v3_cross(a, b);
    double sn = sqrt(ga__v3_dot(x, x)), cs = ga__v3_dot(a, b);
    if (sn == 0.0 && cs < 0.0)
        x = ga__v3_cross(a, fabs(a.x) < 0.5 ? ga__v3(1, 0, 0) : ga__v3(0, 1, 0));
    return ga_rotor_rotation(x, atan2(sn, cs));
}

ga_status ga_rotor_between(ga_mv A, ga_mv B, ga_rotor *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_object a, b;
    int st = gao_read_real_pair(A, B, &a, &b);
    if (st != GA_OK)
        return st;
    if (a.kind != b.kind)
        return GA_ERR_ARG;
    /* relative to the scene, L = max(1, |c| + |r|) of either (object.h): a
       sphere of radius 80 built from points has r^2 only to ~u r^4 */
    double La = norm3(a.centre) + sqrt(fabs(a.r2)), Lb = norm3(b.centre) + sqrt(fabs(b.r2));
    double L2 = fmax(1.0, fmax(La * La, Lb * Lb));
    if (fabs(a.r2 - b.r2) > GA_POINT_TOL * L2)
        return GA_ERR_NOTRIGID;
    ga_rotor R = a.kind == GA_OBJECT_SPHERE || a.kind == GA_OBJECT_FLATPOINT ? ga_rotor_identity()
                                                                             : turn(a.direction, b.direction);
    *out = ga_rotor_mul(ga_rotor_translation(b.centre),
                        ga_rotor_mul(R, ga_rotor_translation(ga__v3_scale(a.centre, -1.0))));
    return GA_OK;
}

/* The dilation about the origin by s > 0 as a rotor: exp(-ln(s)/2 e45) =
   cosh(h) - sinh(h) e45, h = ln(s)/2, written through sqrt(s) (no log, no
   exp: cosh h = (sqrt s + 1/sqrt s)/2, sinh h = (sqrt s - 1/sqrt s)/2). */
static ga_mv dilation_about_origin(double s)
{
    double q = sqrt(s);
    ga_mv D = ga_mv_zero();
    D.c[0] = 0.5 * (q + 1.0 / q);
    D.c[GA_BLADE_E45] = -0.5 * (q - 1.0 / q);
    return D;
}

/* The parts of ga_versor_between: V = head D(s); s = 1 where no dilation is
   needed, and then head is ga_rotor_between's motion T(cB) R T(-cA), bit for
   bit. Otherwise T(cB) R D(s) T(-cA) is written T(cB - s R cA) R D(s) (D(s)
   T(v) = T(s v) D(s), R T(v) = T(R v) R): one product of a rigid rotor and
   D(s), no sum of the large products of T(cB) and T(-cA) that cancel, so that
   V ~V = 1 to a few u |V|^2 (as a product of three factors it was off by up
   to ~2e3 u for spheres 40 to 90 from the origin). */
static int between_parts(ga_mv A, ga_mv B, ga_rotor *head, double *s)
{
    ga_object a, b;
    int st = gao_read_real_pair(A, B, &a, &b);
    if (st != GA_OK)
        return st;
    if (a.kind != b.kind)
        return GA_ERR_ARG;
    *s = 1.0;
    if (a.kind >= GA_OBJECT_POINTPAIR) {
        int ta = a.reality == GA_REALITY_TANGENT, tb = b.reality == GA_REALITY_TANGENT;
        if (ta != tb)
            return GA_ERR_DOMAIN; /* a point (radius 0) and a round of radius > 0 */
        /* the same size to the bounds the read-backs state: no dilation */
        if (!ta && !(fabs(a.r2 - b.r2) <= a.r2_err + b.r2_err))
            *s = sqrt(b.r2 / a.r2);
        if (!(*s > 0.0) || !isfinite(*s) || !isfinite(1.0 / *s))
            return GA_ERR_DOMAIN;
    }
    ga_rotor R = a.kind == GA_OBJECT_SPHERE || a.kind == GA_OBJECT_FLATPOINT ? ga_rotor_identity()
                                                                             : turn(a.direction, b.direction);
    if (*s == 1.0) /* ga_rotor_between's motion, bit for bit */
        *head = ga_rotor_mul(ga_rotor_translation(b.centre),
                             ga_rotor_mul(R, ga_rotor_translation(ga__v3_scale(a.centre, -1.0))));
    else
        *head = ga_rotor_mul(ga_rotor_translation(ga__v3_axpy(-*s, ga_rotor_apply(R, a.centre), b.centre)),
                             R);
    return GA_OK;
}

/* V = head D(s) */
static ga_mv between_versor(ga_rotor head, double s)
{
    return s == 1.0 ? ga_rotor_to_mv(head) : ga_mv_gp(ga_rotor_to_mv(head), dilation_about_origin(s));
}

/* Round <-> flat of one grade (object.h, ga_versor_between). The round a
   (centre c, radius r) through p = c - r u is translated by -p, inverted in
   the sphere of radius 2r about the origin (p goes to infinity, the round to
   the flat through 2r u, perpendicular to u for a sphere, along w x u for a
   circle of normal w, the point 2r u for a point pair) and reflected in the
   plane through the origin of normal u (two vectors of positive square: V0 is
   even, V0 ~V0 = 1), which leaves the flat through q = -2r u; then the rigid
   motion M = T(cB) R T(-q) takes that flat to B. The flat's orientation is
   taken from the image of A against a reference flat built exactly at q (a
   sign, never a read-back of the image); a reversed flat point, which no
   rigid motion turns, is avoided by sending the other point to infinity. */
static ga_vec3 perp_unit(ga_vec3 w)
{
    ga_vec3 x = ga__v3_cross(w, fabs(w.x) < 0.5 ? ga__v3(1, 0, 0) : ga__v3(0, 1, 0));
    return ga__v3_div(x, ga__v3_norm(x));
}

/* the grade of X's largest part */
static int main_grade(ga_mv X)
{
    int g = 0;
    double best = -1.0;
    for (int k = 0; k <= 5; k++) {
        double n = ga_mv_norm2(ga_mv_grade(X, k));
        if (n > best) {
            best = n;
            g = k;
        }
    }
    return g;
}

static int round_to_flat(ga_mv A, ga_mv B, const ga_object *a, const ga_object *b, ga_mv *out)
{
    double r = sqrt(a->r2);
    ga_vec3 u, t = ga__v3(0, 0, 0);
    if (a->kind == GA_OBJECT_SPHERE)
        u = b->direction;
    else if (a->kind == GA_OBJECT_CIRCLE) {
        /* u in the circle's plane, chosen so that w x u is B's direction
           where B's direction is not along w */
        ga_vec3 x = ga__v3_cross(b->direction, a->direction);
        double nx = ga__v3_norm(x);
        u = nx > 0.5 ? ga__v3_div(x, nx) : perp_unit(a->direction);
        t = ga__v3_cross(a->direction, u);
    } else
        u = a->direction;
    /* a flat point's orientation is its weight's sign, against F(cB) ^ n */
    double sb = 1.0;
    if (a->kind == GA_OBJECT_POINTPAIR) {
        ga_mv G = ga_mv_op(ga_point_up(b->centre), ga_mv_n());
        if (main_grade(B) != main_grade(G))
            G = ga_mv_dual(G);
        sb = 0.0;
        for (int i = 0; i < 32; i++) sb += B.c[i] * G.c[i];
    }
    for (int attempt = 0; attempt < 2; attempt++) {
        ga_vec3 p = ga__v3_axpy(-r, u, a->centre), q = ga__v3_scale(u, -2.0 * r);
        ga_mv V0 = ga_mv_scale(gao_gp_exact(gao_gp_exact(ga_versor_reflection(u, 0.0),
                                                         ga_versor_inversion(ga__v3(0, 0, 0), 2.0 * r)),
                                            ga_versor_translation(ga__v3_scale(p, -1.0))),
                               0.5 / r);
        ga_mv F, X;
        if (a->kind == GA_OBJECT_SPHERE) {
            ga_vec3 e1 = perp_unit(u), e2 = ga__v3_cross(u, e1);
            F = ga_plane_from_points(q, ga__v3_add(q, e1), ga__v3_add(q, e2));
        } else if (a->kind == GA_OBJECT_CIRCLE)
            F = ga_line_from_points(q, ga__v3_add(q, t));
        else
            F = ga_mv_op(ga_point_up(q), ga_mv_n());
        if (main_grade(A) != main_grade(F))
            F = ga_mv_dual(F); /* A held as a dual (or direct) blade */
        int st = ga_versor_apply(V0, A, &X);
        if (st != GA_OK)
            return st;
        double k = 0.0;
        for (int i = 0; i < 32; i++) k += X.c[i] * F.c[i];
        ga_object f;
        if ((st = gao_read_real(F, &f)) != GA_OK)
            return st;
        if (!(k * sb > 0.0) && a->kind == GA_OBJECT_POINTPAIR) {
            u = ga__v3_scale(u, -1.0); /* the other point to infinity */
            continue;
        }
        if (!(k != 0.0))
            return GA_ERR_DOMAIN;
        ga_vec3 d = k > 0.0 ? f.direction : ga__v3_scale(f.direction, -1.0);
        ga_rotor R = a->kind == GA_OBJECT_POINTPAIR ? ga_rotor_identity() : turn(d, b->direction);
        ga_rotor M = ga_rotor_mul(ga_rotor_translation(b->centre),
                                  ga_rotor_mul(R, ga_rotor_translation(ga__v3_scale(f.centre, -1.0))));
        *out = gao_gp_exact(ga_rotor_to_mv(M), V0);
        return ga_mv_isfinite(*out) ? GA_OK : GA_ERR_DOMAIN;
    }
    return GA_ERR_DOMAIN;
}

/* ga_versor_between for a round and a flat of one grade, either way round
   (a flat to a round: the reverse of the round to the flat). */
static int between_kinds(ga_mv A, ga_mv B, const ga_object *a, const ga_object *b, ga_mv *out)
{
    int ra = a->kind >= GA_OBJECT_POINTPAIR, rb = b->kind >= GA_OBJECT_POINTPAIR;
    if (ra == rb || a->kind == GA_OBJECT_EMPTY || b->kind == GA_OBJECT_EMPTY ||
        (ra ? a->kind - 3 != b->kind : b->kind - 3 != a->kind))
        return GA_ERR_ARG;
    const ga_object *o = ra ? a : b;
    if (o->reality == GA_REALITY_TANGENT)
        return GA_ERR_DOMAIN; /* a round of radius 0 is no flat's image */
    if (ra)
        return round_to_flat(A, B, a, b, out);
    ga_mv W;
    int st = round_to_flat(B, A, b, a, &W);
    if (st == GA_OK)
        *out = ga_mv_reverse(W);
    return st;
}

ga_status ga_versor_between(ga_mv A, ga_mv B, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_object a, b;
    int st = gao_read_real_pair(A, B, &a, &b);
    if (st != GA_OK)
        return st;
    if (a.kind != b.kind)
        return between_kinds(A, B, &a, &b, out);
    ga_rotor head;
    double s;
    if ((st = between_parts(A, B, &head, &s)) != GA_OK)
        return st;
    ga_mv V = between_versor(head, s);
    if (!ga_mv_isfinite(V))
        return GA_ERR_DOMAIN;
    *out = V;
    return GA_OK;
}

ga_status ga_object_interp(ga_mv A, ga_mv B, double t, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!isfinite(t))
        return GA_ERR_NOTFINITE;
    ga_rotor head;
    double s;
    ga_mv X;
    int st = between_parts(A, B, &head, &s);
    if (st != GA_OK)
        return st;
    if (s == 1.0) {
        /* a rigid motion: its screw, exp(t log R), and the exact translation
           of ga_rotor_apply_mv (a flat stays a flat to the bit) */
        ga_generator g;
        if ((st = ga_rotor_log(head, &g)) != GA_OK)
            return st;
        g = (ga_generator){t * g.e12, t * g.e13, t * g.e23, t * g.e1n, t * g.e2n, t * g.e3n};
        X = ga_rotor_apply_mv(ga_rotor_exp(g), A);
    } else {
        ga_mv Vt, V = between_versor(head, s);
        if ((st = ga_mv_pow(V, t, &Vt)) != GA_OK || (st = ga_versor_apply(Vt, A, &X)) != GA_OK)
            return st;
    }
    if (!ga_mv_isfinite(X))
        return GA_ERR_DOMAIN;
    *out = X;
    return GA_OK;
}
