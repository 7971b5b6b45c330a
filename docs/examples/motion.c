/* motion.c: one rotor moves a point and a sphere alike (docs/conformal.md,
 * "Rotors move everything"). Build from the repository: cc -std=c11 -Iinclude
 * -Ibuild/include docs/examples/motion.c build/libgarotor.a -lm -o motion */
#include <stdio.h>
#include <stdlib.h>

#include <garotor/garotor.h>

/* a status other than GA_OK ends the program, naming the call */
static void check(ga_status status, const char *call)
{
    if (status != GA_OK) {
        fprintf(stderr, "%s: %s\n", call, ga_status_string(status));
        exit(1);
    }
}

int main(void)
{
    /* turn 90 degrees about z, then translate by (0, 0, 5): R2 R1 is R1 first */
    ga_rotor turn = ga_rotor_rotation((ga_vec3){0, 0, 1}, 1.5707963267948966);
    ga_rotor R = ga_rotor_mul(ga_rotor_translation((ga_vec3){0, 0, 5}), turn);
    ga_mv s = ga_sphere_dual((ga_vec3){1, 0, 0}, 0.5);
    ga_vec3 c;
    double r;
    check(ga_sphere_params(ga_rotor_apply_mv(R, s), &c, &r), "ga_sphere_params");
    printf("sphere centre (1, 0, 0) radius 0.5 moved: centre (%.3g, %.3g, %.3g), radius %.3g\n", c.x, c.y,
           c.z, r);
    ga_vec3 x = ga_rotor_apply(R, (ga_vec3){1, 0, 0});
    printf("point (1, 0, 0) moved:                   (%.3g, %.3g, %.3g)\n", x.x, x.y, x.z);
    return 0;
}
