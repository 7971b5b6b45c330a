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

/* The parts of ga_versor_between: V = head D(s) tail, head = T(cB) R,
   tail = T(-cA); s = 1 where no dilation is needed. */
static int between_parts(ga_mv A, ga_mv B, ga_rotor *head, double *s, ga_rotor *tail)
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
    *tail = ga_rotor_translation(ga__v3_scale(a.centre, -1.0));
    /* s = 1: ga_rotor_between's motion, bit for bit */
    *head = *s == 1.0 ? ga_rotor_mul(ga_rotor_translation(b.centre), ga_rotor_mul(R, *tail))
                      : ga_rotor_mul(ga_rotor_translation(b.centre), R);
    if (*s == 1.0)
        *tail = ga_rotor_identity();
    return GA_OK;
}

ga_status ga_versor_between(ga_mv A, ga_mv B, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_rotor head, tail;
    double s;
    int st = between_parts(A, B, &head, &s, &tail);
    if (st != GA_OK)
        return st;
    ga_mv V = s == 1.0
                ? ga_rotor_to_mv(head)
                : ga_mv_gp(ga_mv_gp(ga_rotor_to_mv(head), dilation_about_origin(s)), ga_rotor_to_mv(tail));
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
    ga_rotor head, tail;
    double s;
    ga_mv X;
    int st = between_parts(A, B, &head, &s, &tail);
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
        ga_mv Vt,
            V = ga_mv_gp(ga_mv_gp(ga_rotor_to_mv(head), dilation_about_origin(s)), ga_rotor_to_mv(tail));
        if ((st = ga_mv_pow(V, t, &Vt)) != GA_OK || (st = ga_versor_apply(Vt, A, &X)) != GA_OK)
            return st;
    }
    if (!ga_mv_isfinite(X))
        return GA_ERR_DOMAIN;
    *out = X;
    return GA_OK;
}
