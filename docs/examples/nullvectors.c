/* nullvectors.c: n = e4 + e5 and nbar = e4 - e5 (docs/conformal.md, "Two null
 * vectors"). Build from the repository: cc -std=c11 -Iinclude -Ibuild/include
 * docs/examples/nullvectors.c build/libgarotor.a -lm -o nullvectors */
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
    printf("%-11s = %s\n", what, text);
}

int main(void)
{
    ga_mv n = ga_mv_n(), nbar = ga_mv_nbar();
    show("n", n);
    show("nbar", nbar);
    show("n n", ga_mv_gp(n, n));
    show("nbar nbar", ga_mv_gp(nbar, nbar));
    show("n nbar", ga_mv_gp(n, nbar));
    show("n.nbar", ga_mv_scalar(ga_mv_sp(n, nbar)));
    show("F(0)", ga_point_up((ga_vec3){0, 0, 0}));
    return 0;
}
