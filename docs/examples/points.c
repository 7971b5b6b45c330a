/* points.c: points are null vectors (docs/conformal.md, "Points are null
 * vectors"). Build from the repository: cc -std=c11 -Iinclude -Ibuild/include
 * docs/examples/points.c build/libgarotor.a -lm -o points */
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
    printf("%s = %s\n", what, text);
}

int main(void)
{
    ga_vec3 x = {1, 2, 3}, y = {4, 6, 3};
    ga_mv X = ga_point_up(x), Y = ga_point_up(y), n = ga_mv_n();
    show("F(x)", X);
    printf("F(x).F(x) = %g\n", ga_mv_sp(X, X));
    printf("F(x).n = %g\n", ga_mv_sp(X, n));
    printf("-2 F(x).F(y) = %g\n", -2 * ga_mv_sp(X, Y));
    ga_vec3 back;
    int st = ga_point_down(ga_mv_scale(X, -3.5), &back);
    printf("down(-3.5 F(x)) = (%g, %g, %g), %s\n", back.x, back.y, back.z, ga_status_string(st));
    st = ga_point_down(n, &back);
    printf("down(n): %s\n", ga_status_string(st));
    return 0;
}
