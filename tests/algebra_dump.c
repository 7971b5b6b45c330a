/* tests/algebra_dump.c: inputs and what garotor computes from them, one case
 * a line, for tests/algebra_check.py to recompute exactly (rationals),
 * with mpmath or with scipy.
 *
 *   algebra_dump WHAT SEED
 *
 * WHAT is one of
 *   inverse      "inv CASE STATUS a X": a with dyadic coefficients, by CASE:
 *                0-2 small integers over 4; 3, 4 near zero divisors
 *                (1 + e45) Y + 2^-20 W and (1 + e1) Y + 2^-30 W; 5 zero
 *                divisors (1 + e45) Y or (1 + e1) Y; 6, 7 versors and blades
 *                of integer vectors; X = ga_mv_inverse(a)
 *   products     "reg a b r", "com a b r": small-integer a, b, r their
 *                regressive and commutator products
 *   projection   "proj STATUS a B P R": an integer vector a, a blade B of
 *                integer vectors, P and R its projection and rejection
 *   powers       "pow KIND t B R P": a bivector B (principal: elliptic
 *                half-angles below pi/2), R = ga_mv_exp(B), P = ga_mv_pow(R, t)
 *   fits         "fit KIND SIGMA N TRUTH... RESULT...", then N lines of
 *                points: noisy points on spheres, circles, planes and lines
 * Every number is printed as a C99 hexadecimal float (%a), which Python's
 * float.fromhex reads back exactly; a multivector is its 32 coefficients.
 */
#include "testkit.h"

#include <stdlib.h>

static void put_mv(ga_mv a)
{
    for (int i = 0; i < 32; i++) printf(" %a", a.c[i]);
}
static ga_mv int_mv(tk_rng *r, int lo, int hi, double scale)
{
    ga_mv a;
    for (int i = 0; i < 32; i++) a.c[i] = (double)((int)(tk_next(r) % (uint64_t)(hi - lo + 1)) + lo) * scale;
    return a;
}
static ga_mv int_vector(tk_rng *r)
{
    ga_mv v = ga_mv_zero();
    for (int i = 1; i <= 5; i++) v.c[i] = (double)((int)(tk_next(r) % 7) - 3);
    return v;
}
static double gauss(tk_rng *r)
{
    double u1 = tk_uni(r), u2 = tk_uni(r);
    return sqrt(-2 * log(1 - u1)) * cos(2 * TK_PI * u2);
}

static void dump_inverse(tk_rng *r)
{
    ga_mv one_e45 = ga_mv_add(ga_mv_scalar(1), ga_mv_blade(GA_BLADE_E45));
    ga_mv one_e1 = ga_mv_add(ga_mv_scalar(1), ga_mv_blade(GA_BLADE_E1));
    for (int t = 0; t < 400; t++) {
        ga_mv a;
        switch (t % 8) {
        case 0:
        case 1:
        case 2: a = int_mv(r, -8, 8, 0.25); break;
        case 3: a = ga_mv_add(ga_mv_gp(one_e45, int_mv(r, -4, 4, 1)), int_mv(r, -4, 4, 0x1p-20)); break;
        case 4: a = ga_mv_add(ga_mv_gp(one_e1, int_mv(r, -4, 4, 1)), int_mv(r, -4, 4, 0x1p-30)); break;
        case 5: a = ga_mv_gp(t % 16 == 5 ? one_e45 : one_e1, int_mv(r, -4, 4, 1)); break;
        case 6: {
            a = ga_mv_scalar(1);
            for (int k = 1 + t % 5; k > 0; k--) a = ga_mv_gp(a, int_vector(r));
            break;
        }
        default: {
            a = ga_mv_scalar(1);
            for (int k = 1 + t % 4; k > 0; k--) a = ga_mv_op(a, int_vector(r));
            break;
        }
        }
        ga_mv X = ga_mv_zero();
        int st = ga_mv_inverse(a, &X);
        printf("inv %d %d", t % 8, st);
        put_mv(a);
        put_mv(X);
        putchar('\n');
    }
}

static void dump_products(tk_rng *r)
{
    for (int t = 0; t < 300; t++) {
        ga_mv a = int_mv(r, -4, 4, 1), b = int_mv(r, -4, 4, 1);
        printf("reg");
        put_mv(a);
        put_mv(b);
        put_mv(ga_mv_regressive(a, b));
        printf("\ncom");
        put_mv(a);
        put_mv(b);
        put_mv(ga_mv_commutator(a, b));
        putchar('\n');
    }
}

static void dump_projection(tk_rng *r)
{
    for (int t = 0; t < 300; t++) {
        ga_mv a = int_vector(r), B = ga_mv_scalar(1), P = ga_mv_zero(), R = ga_mv_zero();
        for (int k = 1 + t % 4; k > 0; k--) B = ga_mv_op(B, int_vector(r));
        int st = ga_mv_project(a, B, &P), st2 = ga_mv_reject(a, B, &R);
        printf("proj %d", st != GA_OK ? st : st2);
        put_mv(a);
        put_mv(B);
        put_mv(P);
        put_mv(R);
        putchar('\n');
    }
}

/* a bivector of kind f, elliptic half-angles below 1.4: commuting blades
   conjugated by a rotor of small-integer vectors (exactly: an even versor
   of integer vectors, its inverse ~V / (V ~V)) */
static ga_mv kind_bivector(tk_rng *r, int f)
{
    double t1 = tk_range(r, 0.05, 1.4), t2 = tk_range(r, 0.05, 1.4), h = tk_range(r, -1.5, 1.5);
    double c = tk_range(r, -2, 2);
    ga_mv B = ga_mv_zero();
    switch (f) {
    case 0: B.c[GA_BLADE_E12] = t1; break;
    case 1: B.c[GA_BLADE_E45] = h; break;
    case 2: B.c[GA_BLADE_E14] = B.c[GA_BLADE_E15] = c; break;
    case 3: B.c[GA_BLADE_E12] = t1, B.c[GA_BLADE_E34] = t2; break;
    case 4: B.c[GA_BLADE_E23] = t1, B.c[GA_BLADE_E45] = h; break;
    default: B.c[GA_BLADE_E23] = t1, B.c[GA_BLADE_E14] = B.c[GA_BLADE_E15] = c; break;
    }
    for (;;) {
        ga_mv v = int_vector(r), w = int_vector(r), V = ga_mv_gp(v, w), Vi;
        if (ga_mv_sp(v, v) == 0 || ga_mv_sp(w, w) == 0 || ga_mv_inverse(V, &Vi) != GA_OK)
            continue;
        return ga_mv_grade(ga_mv_gp(ga_mv_gp(V, B), Vi), 2);
    }
}

static void dump_powers(tk_rng *r)
{
    static const double ts[] = {0.5, -1, 0.3, 2.5};
    for (int f = 0; f < 6; f++)
        for (int t = 0; t < 4; t++) {
            ga_mv B = kind_bivector(r, f), R = ga_mv_exp(B), P = ga_mv_zero();
            int st = ga_mv_pow(R, ts[t], &P);
            printf("pow %d %d %a", f, st, ts[t]);
            put_mv(B);
            put_mv(R);
            put_mv(P);
            putchar('\n');
        }
}

/* noisy points on an object of radius 1 about c (|c| = 1e3: the fit's
   centring is in play), N(0, sigma^2) in each coordinate */
static void dump_fits(tk_rng *r)
{
    enum { NPTS = 1000 };
    static ga_vec3 p[NPTS];
    for (int t = 0; t < 84; t++) {
        int kind = t < 30 ? 0 : t < 60 ? 1 : t < 72 ? 2 : 3; /* sphere, circle, plane, line */
        double sigma = kind < 2 ? 0.05 : 0.02, R = 1.0;
        ga_vec3 c = tk_scale(tk_unit(r), 1e3), nrm = tk_unit(r), e1 = tk_unit(r);
        double d = e1.x * nrm.x + e1.y * nrm.y + e1.z * nrm.z;
        e1 = (ga_vec3){e1.x - d * nrm.x, e1.y - d * nrm.y, e1.z - d * nrm.z};
        e1 = tk_scale(e1, 1 / tk_norm(e1));
        ga_vec3 e2 = {nrm.y * e1.z - nrm.z * e1.y, nrm.z * e1.x - nrm.x * e1.z, nrm.x * e1.y - nrm.y * e1.x};
        for (int i = 0; i < NPTS; i++) {
            ga_vec3 x;
            if (kind == 0) {
                x = tk_scale(tk_unit(r), R);
            } else if (kind == 1) {
                double a = tk_range(r, 0, 2 * TK_PI);
                x = (ga_vec3){R * (cos(a) * e1.x + sin(a) * e2.x), R * (cos(a) * e1.y + sin(a) * e2.y),
                              R * (cos(a) * e1.z + sin(a) * e2.z)};
            } else if (kind == 2) {
                double a = tk_range(r, -1, 1), b = tk_range(r, -1, 1);
                x = (ga_vec3){a * e1.x + b * e2.x, a * e1.y + b * e2.y, a * e1.z + b * e2.z};
            } else {
                x = tk_scale(nrm, tk_range(r, -1, 1));
            }
            double gx = gauss(r), gy = gauss(r), gz = gauss(r);
            p[i] = (ga_vec3){c.x + x.x + sigma * gx, c.y + x.y + sigma * gy, c.z + x.z + sigma * gz};
        }
        ga_vec3 oc = {0, 0, 0}, on = {0, 0, 0};
        double orad = 0;
        int st = kind == 0 ? ga_fit_sphere(p, NPTS, &oc, &orad)
               : kind == 1 ? ga_fit_circle(p, NPTS, &oc, &orad, &on)
               : kind == 2 ? ga_fit_plane(p, NPTS, &on, &orad)
                           : ga_fit_line(p, NPTS, &on, &oc);
        printf("fit %d %d %a %d  %a %a %a %a %a %a %a  %a %a %a %a %a %a %a\n", kind, st, sigma, NPTS, c.x,
               c.y, c.z, R, nrm.x, nrm.y, nrm.z, oc.x, oc.y, oc.z, orad, on.x, on.y, on.z);
        for (int i = 0; i < NPTS; i++) printf("%a %a %a\n", p[i].x, p[i].y, p[i].z);
    }
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: algebra_dump inverse|products|projection|powers|fits [SEED]\n");
        return 2;
    }
    tk_rng r = {argc > 2 ? (uint64_t)atoll(argv[2]) : 25};
    if (!strcmp(argv[1], "inverse"))
        dump_inverse(&r);
    else if (!strcmp(argv[1], "products"))
        dump_products(&r);
    else if (!strcmp(argv[1], "projection"))
        dump_projection(&r);
    else if (!strcmp(argv[1], "powers"))
        dump_powers(&r);
    else if (!strcmp(argv[1], "fits"))
        dump_fits(&r);
    else {
        fprintf(stderr, "algebra_dump: unknown section %s\n", argv[1]);
        return 2;
    }
    return 0;
}
