/* translation.c: the translation rotor T_a = 1 + n a/2 (docs/conformal.md,
 * "Rotors move everything"). Build from the repository: cc -std=c11 -Iinclude
 * -Ibuild/include docs/examples/translation.c build/libgarotor.a -lm -o translation */
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

static void show(const char *what, ga_mv x)
{
    char text[GA_MV_TEXT_MAX];
    size_t len;
    check(ga_mv_format(x, text, sizeof text, &len), "ga_mv_format");
    printf("%-9s = %s\n", what, text);
}

int main(void)
{
    ga_vec3 a = {0.5, -1, 2}, x = {1, 2, 3};
    ga_mv T = ga_rotor_to_mv(ga_rotor_translation(a));
    show("T_a", T);
    show("1 + na/2", ga_mv_add(ga_mv_scalar(1), ga_mv_scale(ga_mv_gp(ga_mv_n(), ga_vec3_to_mv(a)), 0.5)));
    /* T_a F(x) ~T_a, against F(x + a) */
    show("T F(x) ~T", ga_mv_gp(ga_mv_gp(T, ga_point_up(x)), ga_mv_reverse(T)));
    show("F(x + a)", ga_point_up((ga_vec3){x.x + a.x, x.y + a.y, x.z + a.z}));
    return 0;
}
