/* powers.c: square roots and powers of rotors, and the mean of rigid
 * motions (docs/conformal.md, "More algebra"). Build from the repository:
 * cc -std=c11 -Iinclude -Ibuild/include docs/examples/powers.c
 * build/libgarotor.a -lm -o powers */
#include <math.h>
#include <stdio.h>

#include <garotor/garotor.h>

/* a number as %.6g, with what is rounding below 1e-12 (and -0) shown as 0 */
static double clean(double v) { return fabs(v) < 1e-12 ? 0.0 : v; }

static void show(const char *what, ga_mv X)
{
    char text[GA_MV_TEXT_MAX];
    size_t len;
    for (int i = 0; i < 32; i++) X.c[i] = clean(X.c[i]);
    if (ga_mv_format(X, text, sizeof text, &len) == GA_OK)
        printf("%-26s %s\n", what, text);
}

/* a rigid motion as its rotation (angle about an axis) and translation */
static void motion(const char *what, ga_rotor R)
{
    ga_screw s;
    ga_vec3 t = ga_rotor_to_translation(R);
    if (ga_rotor_to_screw(R, &s) != GA_OK)
        return;
    printf("%-26s turn %.6g deg about (%.6g, %.6g, %.6g), then move by (%.6g, %.6g, %.6g)\n", what,
           clean(s.angle * 180 / 3.14159265358979323846), clean(s.axis.x), clean(s.axis.y), clean(s.axis.z),
           clean(t.x), clean(t.y), clean(t.z));
}

int main(void)
{
    const double deg = 3.14159265358979323846 / 180;
    ga_vec3 zaxis = {0, 0, 1};
    /* the square root of a quarter turn about z is an eighth of a turn */
    ga_mv R = ga_rotor_to_mv(ga_rotor_rotation(zaxis, 90 * deg)), S, P;
    show("R: 90 deg about z", R);
    if (ga_mv_sqrt(R, &S) == GA_OK) {
        show("sqrt(R)", S);
        show("sqrt(R) sqrt(R)", ga_mv_gp(S, S));
    }
    if (ga_mv_pow(R, 1.0 / 3, &P) == GA_OK)
        show("R^(1/3): 30 deg", P);
    /* a translation: its powers translate by a multiple */
    ga_mv T = ga_rotor_to_mv(ga_rotor_translation((ga_vec3){2, 0, 0}));
    show("T: move by (2, 0, 0)", T);
    if (ga_mv_pow(T, 0.25, &P) == GA_OK)
        show("T^(1/4)", P);
    /* a dilation by 4 about the origin, exp(-log(4)/2 e45): its square root
       dilates by 2 */
    ga_mv D, Ds;
    if (ga_versor_dilation((ga_vec3){0, 0, 0}, 4, &D) == GA_OK && ga_mv_sqrt(D, &Ds) == GA_OK) {
        ga_mv X;
        ga_vec3 y;
        if (ga_versor_apply(Ds, ga_point_up((ga_vec3){1, 1, 0}), &X) == GA_OK &&
            ga_point_down(X, &y) == GA_OK)
            printf("%-26s (%.6g, %.6g, %.6g)\n", "sqrt(D) moves (1, 1, 0) to", y.x, y.y, y.z);
    }
    printf("%-26s %s\n", "sqrt(2)", ga_status_string(ga_mv_sqrt(ga_mv_scalar(2), &S)));

    /* the mean of three turns about z: the mean angle */
    ga_rotor turns[3] = {ga_rotor_rotation(zaxis, 10 * deg), ga_rotor_rotation(zaxis, 20 * deg),
                         ga_rotor_rotation(zaxis, 60 * deg)};
    double w[3] = {1, 1, 1}, w2[2] = {1, 3};
    ga_rotor M;
    if (ga_rotor_mean(turns, w, 3, &M) == GA_OK)
        motion("mean of 10, 20, 60 deg", M);
    /* of the identity and a screw, weighted 1 and 3: three quarters of the
       way along the screw */
    ga_rotor two[2] = {ga_rotor_identity(), ga_rotor_mul(ga_rotor_translation((ga_vec3){0, 0, 4}),
                                                         ga_rotor_rotation(zaxis, 120 * deg))};
    motion("screw", two[1]);
    if (ga_rotor_mean(two, w2, 2, &M) == GA_OK)
        motion("mean of 1, screw (1:3)", M);
    return 0;
}
