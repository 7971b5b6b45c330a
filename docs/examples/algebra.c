/* algebra.c: the inverse of any multivector, the regressive and commutator
 * products, projection and rejection (docs/conformal.md, "More algebra").
 * Build from the repository: cc -std=c11 -Iinclude -Ibuild/include
 * docs/examples/algebra.c build/libgarotor.a -lm -o algebra */
#include <stdio.h>

#include <garotor/garotor.h>

static void show(const char *what, ga_mv X)
{
    char text[GA_MV_TEXT_MAX];
    size_t len;
    if (ga_mv_format(X, text, sizeof text, &len) != GA_OK)
        printf("%-22s (not finite)\n", what);
    else
        printf("%-22s %s\n", what, text);
}

static ga_mv parse(const char *text)
{
    ga_mv X = ga_mv_zero();
    if (ga_mv_parse(text, &X) != GA_OK)
        printf("cannot read %s\n", text);
    return X;
}

int main(void)
{
    /* the inverse of a multivector that is no versor: a ~a is not a scalar */
    ga_mv a = parse("2 + e1 + e23"), ai;
    show("a", a);
    show("a ~a", ga_mv_gp(a, ga_mv_reverse(a)));
    if (ga_mv_inverse(a, &ai) == GA_OK) {
        show("a^-1", ai);
        show("a a^-1", ga_mv_gp(a, ai));
    }
    /* 1 + e45 is a zero divisor: (1 + e45)(1 - e45) = 0 */
    show("(1 + e45)(1 - e45)", ga_mv_gp(parse("1 + e45"), parse("1 - e45")));
    printf("%-22s %s\n", "(1 + e45)^-1", ga_status_string(ga_mv_inverse(parse("1 + e45"), &ai)));

    /* the regressive product: two planes through the origin meet in a line */
    ga_vec3 o = {0, 0, 0}, x = {1, 0, 0}, y = {0, 1, 0}, z = {0, 0, 1}, u, p;
    ga_mv Pz = ga_plane_from_points(o, x, y), Px = ga_plane_from_points(o, y, z);
    ga_mv L = ga_mv_regressive(Pz, Px);
    show("plane z = 0", Pz);
    show("plane x = 0", Px);
    show("their & ", L);
    if (ga_line_params(L, &u, &p) == GA_OK)
        printf("%-22s direction (%g, %g, %g) through (%g, %g, %g)\n", "read back: a line", u.x, u.y, u.z, p.x,
               p.y, p.z);
    show("e1234 & e2345", ga_mv_regressive(ga_mv_blade(GA_BLADE_E1234), ga_mv_blade(GA_BLADE_E2345)));

    /* the commutator product */
    show("e12 x e23", ga_mv_commutator(ga_mv_blade(GA_BLADE_E12), ga_mv_blade(GA_BLADE_E23)));
    show("e12 x (e1 + 2e3)", ga_mv_commutator(ga_mv_blade(GA_BLADE_E12), parse("e1 + 2e3")));

    /* projection and rejection of a vector onto the plane of e1 and e2 + e3 */
    ga_mv v = parse("e1 + 2e2 + 3e3 + e4"), B = ga_mv_op(parse("e1"), parse("e2 + e3")), P, R;
    show("v", v);
    show("B", B);
    if (ga_mv_project(v, B, &P) == GA_OK && ga_mv_reject(v, B, &R) == GA_OK) {
        show("projection of v on B", P);
        show("rejection of v from B", R);
        show("their sum", ga_mv_add(P, R));
    }
    printf("%-22s %s\n", "projection on n ^ e1",
           ga_status_string(ga_mv_project(v, ga_mv_op(ga_mv_n(), parse("e1")), &P)));
    return 0;
}
