/* products.c: the geometric product of basis vectors (docs/conformal.md, "The
 * algebra G(4,1)"). Build from the repository: cc -std=c11 -Iinclude
 * -Ibuild/include docs/examples/products.c build/libgarotor.a -lm -o products */
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

/* a multivector as ga_mv_format writes it: "1 - 7e12" is 1 - 7 e12 */
static void show(const char *what, ga_mv x)
{
    char text[GA_MV_TEXT_MAX];
    size_t len;
    check(ga_mv_format(x, text, sizeof text, &len), "ga_mv_format");
    printf("%-16s = %s\n", what, text);
}

int main(void)
{
    ga_mv e1 = ga_mv_vector(1, 0, 0, 0, 0), e2 = ga_mv_vector(0, 1, 0, 0, 0);
    ga_mv e3 = ga_mv_vector(0, 0, 1, 0, 0), e5 = ga_mv_vector(0, 0, 0, 0, 1);
    show("e1 e1", ga_mv_gp(e1, e1));
    show("e5 e5", ga_mv_gp(e5, e5));
    show("e1 e2", ga_mv_gp(e1, e2));
    show("e2 e1", ga_mv_gp(e2, e1));
    ga_mv e12 = ga_mv_gp(e1, e2);
    show("(e1 e2)(e1 e2)", ga_mv_gp(e12, e12));
    ga_mv u = ga_mv_vector(1, 2, 0, 0, 0), v = ga_mv_vector(3, -1, 0, 0, 0);
    show("u v", ga_mv_gp(u, v));
    show("u.v", ga_mv_scalar(ga_mv_sp(u, v)));
    show("u^v", ga_mv_op(u, v));
    ga_mv I3 = ga_mv_i3();
    show("I3", I3);
    show("I3 I3", ga_mv_gp(I3, I3));
    show("e3 I3", ga_mv_gp(e3, I3));
    return 0;
}
