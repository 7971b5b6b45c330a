/* tests/test_products.c: the generated products of ga/mv_kernels.c and the
 * batch actions, against the references they replace.
 *
 *   dense       ga_mv_sp, ga_mv_dot, ga_mv_ip against the blade loops they
 *               replaced (written here), and ga_mv_regressive against
 *               undual(op(dual a, dual b)): bit for bit (== per coefficient,
 *               so only the sign of a zero may differ)
 *   commutator  ga_mv_commutator (the anticommuting pairs, once each)
 *               against (gp(a, b) - gp(b, a)) / 2 within 64 u times the sum
 *               of the terms' sizes at each blade; a x b = -(b x a) and
 *               a x a = 0 bit for bit
 *   sparse      ga_mv_gp_even_vector, _vector_vector, _even_even against
 *               ga_mv_gp of the same grades, bit for bit, other grades in
 *               the inputs ignored
 *   versor      ga_versor_apply (the sparse kernels by X's grades) against
 *               gp(gp(V, X^), V^-1), bit for bit, for even and odd versors
 *               and X of each grade and of mixed grades;
 *               ga_versor_apply_many against ga_versor_apply, in place too
 *   apply_many  ga_rotor_apply_many against ga_mat4_apply_many of the
 *               rotor's matrix (bit for bit) and against ga_rotor_apply
 *               (within rotor.h's 32 u (|x|_1 + |t|_inf)), in place too;
 *               ga_mat4_apply_many against its formula
 */
#include "testkit.h"

static const int N = 4000;

static double coef(tk_rng *r)
{
    switch (tk_next(r) % 8) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return ldexp(tk_range(r, -1, 1), (int)(tk_next(r) % 60) - 30);
    default: return tk_range(r, -1, 1);
    }
}

/* a random multivector whose grades are the bits of grades */
static ga_mv rand_mv(tk_rng *r, unsigned grades)
{
    ga_mv x = ga_mv_zero();
    for (int i = 0; i < 32; i++)
        if (grades >> ga_blade_grade(i) & 1u)
            x.c[i] = coef(r);
    return x;
}

/* the parts of x of the grades given */
static ga_mv grades_of(ga_mv x, unsigned grades)
{
    for (int i = 0; i < 32; i++)
        if (!(grades >> ga_blade_grade(i) & 1u))
            x.c[i] = 0.0;
    return x;
}

/* 1 when every coefficient is the same number (+0 == -0) */
static int same(ga_mv a, ga_mv b)
{
    for (int i = 0; i < 32; i++)
        if (!(a.c[i] == b.c[i]))
            return 0;
    return 1;
}

/* the sign of the product of blades with masks a and b (e5 e5 = -1) */
static double blade_sign(unsigned a, unsigned b)
{
    int swaps = 0;
    for (unsigned x = a >> 1; x; x >>= 1) swaps += __builtin_popcount(x & b);
    if (a & b & 0x10u)
        swaps++;
    return swaps & 1 ? -1.0 : 1.0;
}

static int index_of_mask(unsigned m)
{
    for (int i = 0; i < 32; i++)
        if (ga_blade_mask(i) == m)
            return i;
    return -1;
}

/* ga/mv.c's loop before the generated code: the fat dot (hestenes = 0) or
   Hestenes' inner product */
static ga_mv ref_dot(ga_mv a, ga_mv b, int hestenes)
{
    ga_mv r = ga_mv_zero();
    for (int i = 0; i < 32; i++) {
        unsigned ma = ga_blade_mask(i);
        if (hestenes && ma == 0)
            continue;
        for (int j = 0; j < 32; j++) {
            unsigned mb = ga_blade_mask(j);
            if ((hestenes && mb == 0) || ((ma & mb) != ma && (ma & mb) != mb))
                continue;
            r.c[index_of_mask(ma ^ mb)] += blade_sign(ma, mb) * a.c[i] * b.c[j];
        }
    }
    return r;
}

static double ref_sp(ga_mv a, ga_mv b)
{
    double s = 0.0;
    for (int i = 0; i < 32; i++) s += blade_sign(ga_blade_mask(i), ga_blade_mask(i)) * a.c[i] * b.c[i];
    return s;
}

/* sum |a_i| |b_j| over the pairs whose product falls on each blade */
static ga_mv abs_gp(ga_mv a, ga_mv b)
{
    ga_mv r = ga_mv_zero();
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++)
            r.c[index_of_mask(ga_blade_mask(i) ^ ga_blade_mask(j))] += fabs(a.c[i]) * fabs(b.c[j]);
    return r;
}

static void section_dense(void)
{
    tk_rng r = tk_rng_after(2901, 0);
    tk_check dot = tk_begin("dot = the blade loop, bit for bit", 0.0);
    tk_check ip = tk_begin("ip = the blade loop, bit for bit", 0.0);
    tk_check sp = tk_begin("sp = the blade loop, bit for bit", 0.0);
    tk_check reg = tk_begin("regressive = undual(op(dual a, dual b)), bit for bit", 0.0);
    for (int k = 0; k < N; k++) {
        ga_mv a = rand_mv(&r, 0x3f), b = rand_mv(&r, 0x3f);
        tk_add_bool(&dot, same(ga_mv_dot(a, b), ref_dot(a, b, 0)));
        tk_add_bool(&ip, same(ga_mv_ip(a, b), ref_dot(a, b, 1)));
        tk_add_bool(&sp, ga_mv_sp(a, b) == ref_sp(a, b));
        tk_add_bool(&reg, same(ga_mv_regressive(a, b), ga_mv_undual(ga_mv_op(ga_mv_dual(a), ga_mv_dual(b)))));
    }
    tk_end(&dot);
    tk_end(&ip);
    tk_end(&sp);
    tk_end(&reg);
}

static void section_commutator(void)
{
    tk_rng r = tk_rng_after(2902, 0);
    tk_check ref = tk_begin("commutator = (ab - ba)/2 within 64 u sum |terms|", 0.0);
    tk_check anti = tk_begin("a x b = -(b x a), bit for bit", 0.0);
    tk_check self = tk_begin("a x a = 0, bit for bit", 0.0);
    for (int k = 0; k < N; k++) {
        ga_mv a = rand_mv(&r, 0x3f), b = rand_mv(&r, 0x3f);
        ga_mv c = ga_mv_commutator(a, b);
        ga_mv d = ga_mv_scale(ga_mv_sub(ga_mv_gp(a, b), ga_mv_gp(b, a)), 0.5);
        ga_mv s = abs_gp(a, b);
        for (int i = 0; i < 32; i++) tk_add_tol(&ref, fabs(c.c[i] - d.c[i]), 64 * DBL_EPSILON * s.c[i]);
        tk_add_bool(&anti, same(c, ga_mv_scale(ga_mv_commutator(b, a), -1.0)));
        tk_add_bool(&self, same(ga_mv_commutator(a, a), ga_mv_zero()));
    }
    tk_end(&ref);
    tk_end(&anti);
    tk_end(&self);
}

static void section_sparse(void)
{
    tk_rng r = tk_rng_after(2903, 0);
    tk_check ev = tk_begin("gp_even_vector = gp of the parts, bit for bit", 0.0);
    tk_check vv = tk_begin("gp_vector_vector = gp of the parts, bit for bit", 0.0);
    tk_check ee = tk_begin("gp_even_even = gp of the parts, bit for bit", 0.0);
    tk_check es = tk_begin(
        "gp_even_vector_sparse = gp_even_vector on the odd blades, bit for bit (also in place)", 0.0);
    for (int k = 0; k < N; k++) {
        /* every grade present: the kernels must not read the others */
        ga_mv a = rand_mv(&r, 0x3f), b = rand_mv(&r, 0x3f);
        tk_add_bool(&ev, same(ga_mv_gp_even_vector(a, b), ga_mv_gp(grades_of(a, 0x15), grades_of(b, 0x2))));
        tk_add_bool(&vv, same(ga_mv_gp_vector_vector(a, b), ga_mv_gp(grades_of(a, 0x2), grades_of(b, 0x2))));
        tk_add_bool(&ee, same(ga_mv_gp_even_even(a, b), ga_mv_gp(grades_of(a, 0x15), grades_of(b, 0x15))));
        /* the even blades are 0, 6..15, 26..30, the odd 1..5, 16..25, 31 */
        double even[16], vec[5], odd[16];
        int ne = 0, no = 0;
        for (int i = 0; i < 32; i++)
            if (ga_blade_grade(i) % 2 == 0)
                even[ne++] = a.c[i];
        memcpy(vec, b.c + 1, sizeof vec);
        TK_OK(ga_mv_gp_even_vector_sparse(even, vec, odd));
        ga_mv want = ga_mv_gp_even_vector(a, b), got = ga_mv_zero();
        for (int i = 0; i < 32; i++)
            if (ga_blade_grade(i) % 2 == 1)
                got.c[i] = odd[no++];
        TK_OK(ga_mv_gp_even_vector_sparse(even, vec, even)); /* the result over an input */
        tk_add_bool(&es, ne == 16 && no == 16 && same(got, grades_of(want, 0x2a)) &&
                             memcmp(even, odd, sizeof odd) == 0);
    }
    tk_end(&ev);
    tk_end(&es);
    tk_end(&vv);
    tk_end(&ee);
}

static ga_rotor rand_rotor(tk_rng *r)
{
    ga_vec3 t = tk_scale(tk_unit(r), tk_loguni(r, 1e-3, 1e3));
    return ga_rotor_mul(ga_rotor_translation(t), ga_rotor_rotation(tk_unit(r), tk_range(r, -3.1, 3.1)));
}

/* an even versor (a rigid motion, a dilation, a transversion) or an odd one
   (a reflection or an inversion after a motion) */
static ga_mv rand_versor(tk_rng *r, int odd)
{
    ga_mv V = ga_rotor_to_mv(rand_rotor(r));
    ga_mv D;
    switch (tk_next(r) % 3) {
    case 0: TK_OK(ga_versor_dilation(tk_unit(r), tk_loguni(r, 0.1, 10), &D)); break;
    case 1: D = ga_versor_transversion(tk_scale(tk_unit(r), tk_range(r, 0, 0.5))); break;
    default: D = ga_mv_scalar(1.0); break;
    }
    V = ga_mv_gp(V, D);
    if (odd)
        V = ga_mv_gp(tk_next(r) % 2 ? ga_versor_reflection(tk_unit(r), tk_range(r, -2, 2))
                                    : ga_versor_inversion(tk_unit(r), tk_range(r, 0.5, 2)),
                     V);
    return V;
}

static void section_versor(void)
{
    tk_rng r = tk_rng_after(2904, 0);
    tk_check grade[7];
    for (int g = 0; g < 7; g++)
        grade[g] = g < 6 ? tk_beginf(0.0, "versor_apply = gp(gp(V, X^), V^-1), X of grade %d", g)
                         : tk_begin("versor_apply = gp(gp(V, X^), V^-1), X of mixed grades", 0.0);
    tk_check many = tk_begin("versor_apply_many = versor_apply, bit for bit", 0.0);
    tk_check inplace = tk_begin("versor_apply_many in place = versor_apply", 0.0);
    for (int k = 0; k < N / 4; k++) {
        int odd = k % 2;
        ga_mv V = rand_versor(&r, odd), Vi;
        TK_OK(ga_mv_inverse(V, &Vi));
        ga_mv X[8], Y[8], Z[8];
        for (int g = 0; g < 7; g++) {
            X[g] = rand_mv(&r, g < 6 ? 1u << g : 0x3fu);
            TK_OK(ga_versor_apply(V, X[g], &Y[g]));
            ga_mv Xh = odd ? ga_mv_involute(X[g]) : X[g];
            tk_add_bool(&grade[g], same(Y[g], ga_mv_gp(ga_mv_gp(V, Xh), Vi)));
        }
        X[7] = ga_point_up(tk_scale(tk_unit(&r), 3.0));
        TK_OK(ga_versor_apply(V, X[7], &Y[7]));
        TK_OK(ga_versor_apply_many(V, X, 8, Z));
        int ok = 1;
        for (int g = 0; g < 8; g++) ok &= memcmp(&Y[g], &Z[g], sizeof(ga_mv)) == 0;
        tk_add_bool(&many, ok);
        TK_OK(ga_versor_apply_many(V, X, 8, X));
        ok = 1;
        for (int g = 0; g < 8; g++) ok &= memcmp(&Y[g], &X[g], sizeof(ga_mv)) == 0;
        tk_add_bool(&inplace, ok);
    }
    for (int g = 0; g < 7; g++) tk_end(&grade[g]);
    tk_end(&many);
    tk_end(&inplace);
    /* near versors (a versor with a relative noise of 1e-17 to 1e-10, so
       that a ~a's grade 4 lies on both sides of ga_mv_inverse's tolerance,
       GA_MV_INVERSE_TOL U sbar) and any V of one parity: ga_versor_apply's
       inverse (its shortcuts, ga/mv_algebra.c) is ga_mv_inverse's, the same
       bits and statuses */
    tk_check near = tk_begin("versor_apply of near versors = gp(gp(V, X^), ga_mv_inverse(V))", 0.0);
    int above = 0, below = 0;
    for (int k = 0; k < N / 4; k++) {
        int odd = k % 2;
        ga_mv V = rand_versor(&r, odd);
        if (k % 8 < 2) {
            V = rand_mv(&r, odd ? 0x2au : 0x15u);
        } else {
            double eps = tk_loguni(&r, 1e-17, 1e-10) * ga_mv_maxabs(V);
            for (int i = 0; i < 32; i++)
                if (V.c[i] != 0.0) {
                    double d = tk_range(&r, -1, 1);
                    V.c[i] += eps * d;
                }
        }
        ga_mv X = rand_mv(&r, 0x3fu), Y, Vi;
        ga_mv aa = ga_mv_gp(V, ga_mv_reverse(V));
        double sq = 0.0, g4 = 0.0; /* the sum of squares, a ~a's largest grade-4 coefficient */
        for (int i = 0; i < 32; i++) sq += V.c[i] * V.c[i];
        for (int i = 26; i < 31; i++) g4 = fmax(g4, fabs(aa.c[i]));
        if (g4 > GA_MV_INVERSE_TOL * DBL_EPSILON * sq)
            above++;
        else
            below++;
        ga_status st = ga_versor_apply(V, X, &Y), sti = ga_mv_inverse(V, &Vi);
        ga_mv Xh = odd ? ga_mv_involute(X) : X;
        tk_add_bool(&near, st == sti && (st != GA_OK || same(Y, ga_mv_gp(ga_mv_gp(V, Xh), Vi))));
    }
    tk_end(&near);
    printf("near versors: a ~a's grade 4 above the tolerance in %d, within it in %d\n", above, below);
    /* nothing written on an error */
    ga_mv X[2] = {ga_mv_scalar(1.0), ga_mv_scalar(NAN)}, Z[2] = {ga_mv_scalar(7.0), ga_mv_scalar(7.0)};
    tk_expect_status("versor_apply_many with a NaN input", ga_versor_apply_many(ga_mv_scalar(2.0), X, 2, Z),
                     GA_ERR_NOTFINITE);
    tk_expect(Z[0].c[0] == 7.0 && Z[1].c[0] == 7.0, "versor_apply_many writes nothing on an error");
    X[1] = ga_mv_scalar(1.0);
    tk_expect_status("versor_apply_many of a mixed-parity V",
                     ga_versor_apply_many(ga_mv_add(ga_mv_scalar(1.0), ga_mv_blade(GA_BLADE_E1)), X, 2, Z),
                     GA_ERR_ARG);
    tk_expect_status("versor_apply_many of n = 0", ga_versor_apply_many(ga_mv_scalar(2.0), X, 0, Z), GA_OK);
}

static void section_apply_many(void)
{
    tk_rng r = tk_rng_after(2905, 0);
    enum { NP = 257 };
    static ga_vec3 in[NP], out[NP], ref[NP];
    tk_check mat = tk_begin("rotor_apply_many = mat4_apply_many(to_mat4), bit for bit", 0.0);
    tk_check rot = tk_begin("rotor_apply_many vs rotor_apply: 32 u (|x|_1 + |t|_inf)", 0.0);
    tk_check inplace = tk_begin("rotor_apply_many in place, bit for bit", 0.0);
    tk_check form = tk_begin("mat4_apply_many = ((m0 x + m1 y) + m2 z) + m3, bit for bit", 0.0);
    for (int k = 0; k < N / 40; k++) {
        ga_rotor R = rand_rotor(&r);
        ga_vec3 t = ga_rotor_to_translation(R);
        double tn = fmax(fabs(t.x), fmax(fabs(t.y), fabs(t.z)));
        for (int i = 0; i < NP; i++) in[i] = tk_scale(tk_unit(&r), tk_loguni(&r, 1e-6, 1e6));
        TK_OK(ga_rotor_apply_many(R, in, NP, out));
        ga_mat4 M = ga_rotor_to_mat4(R);
        TK_OK(ga_mat4_apply_many(M, in, NP, ref));
        tk_add_bool(&mat, memcmp(out, ref, sizeof out) == 0);
        int ok = 1;
        for (int i = 0; i < NP; i++) {
            ga_vec3 y = ga_rotor_apply(R, in[i]), x = in[i];
            double tol = 32 * DBL_EPSILON * (fabs(x.x) + fabs(x.y) + fabs(x.z) + tn);
            tk_add_tol(&rot, fabs(out[i].x - y.x), tol);
            tk_add_tol(&rot, fabs(out[i].y - y.y), tol);
            tk_add_tol(&rot, fabs(out[i].z - y.z), tol);
            const double *m = M.m;
            ok &= ref[i].x == ((m[0] * x.x + m[1] * x.y) + m[2] * x.z) + m[3] &&
                  ref[i].y == ((m[4] * x.x + m[5] * x.y) + m[6] * x.z) + m[7] &&
                  ref[i].z == ((m[8] * x.x + m[9] * x.y) + m[10] * x.z) + m[11];
        }
        tk_add_bool(&form, ok);
        TK_OK(ga_rotor_apply_many(R, in, NP, in));
        tk_add_bool(&inplace, memcmp(in, out, sizeof out) == 0);
    }
    tk_end(&mat);
    tk_end(&rot);
    tk_end(&inplace);
    tk_end(&form);
    tk_expect_status("rotor_apply_many of n = 0", ga_rotor_apply_many(ga_rotor_identity(), in, 0, out),
                     GA_OK);
}

static const tk_section sections[] = {
    {"dense", section_dense, 0},   {"commutator", section_commutator, 0}, {"sparse", section_sparse, 0},
    {"versor", section_versor, 0}, {"apply_many", section_apply_many, 0},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_products", sections, TK_COUNT(sections)); }
