/* ga/bivector_frames.c: the frames in which the parts of a bivector or rotor
 * of G(4,1) come out exact, for exp, log and split (ga/mv_exp.c, ga/mv_log.c,
 * ga/mv_split.c): the rigid frame of a null part, where the rotor is a screw
 * (ga_rotor_exp and ga_rotor_log_literal there), and an orthonormal basis of
 * an ideal of Spin(4) for two rotations. docs/numerics.md, "A null part".
 */
#include "internal/bivector_frames.h"

#include "internal/bivector_fns.h"
#include <math.h>

/* ---- a null part: the frame in which it is rigid ------------------------------- */

/* A rotation E by a small angle t beside a null part N (R = +-exp(tE) exp(N),
   or B = tE + N) is a rigid screw seen in another frame: both fix the null
   vector n of N's plane (n.n = 0, n.E = n.N = 0), and a rotor V that takes n
   to the point at infinity (V n ~V ~ e4 + e5) turns them into a rigid rotor
   or generator, whose log and split are exact for every angle
   (ga_rotor_log_literal; the screw's axis). The m and l forms find E from
   t^2 = -<B^2>_0, which is known only to u |N|^2, and lose u (|N|/t)^3 or
   more. Here n is taken from M, the 5x5 matrix of the vector map
   x -> R x ~R - x (or x -> x _| B): n spans its kernel and, since R keeps
   the metric, n.M y = 0 for every y, so n is the metric normal of M's
   columns, found by Gaussian elimination with complete pivoting on M^T
   (backward stable: an error in n lies in E's plane, u |M| / t of it, which
   R moves by only t times that; docs/versors.md). For t below u^(1/3) of
   |M| those columns are too near a rank of 2; then the columns of M^2,
   ~ (x.n) n with t^2 of E's plane beside it, give n. For a rotor, M is
   also that of x -> x _| <R>_2 (R = (c + sE)(1 + N) has <R>_2 = sE + cN,
   with the same null vector and entries of size |R|, not |R|^2), except
   where c ~ 0. */

/* The largest column of M^2 (0 where M^2 = 0) */
static int largest_square_column(double M[5][5], double n[5])
{
    double best = 0.0;
    for (int j = 0; j < 5; j++) {
        double col[5], nn = 0.0;
        for (int i = 0; i < 5; i++) {
            col[i] = 0.0;
            for (int k = 0; k < 5; k++) col[i] += M[i][k] * M[k][j];
            nn += col[i] * col[i];
        }
        if (nn > best) {
            best = nn;
            for (int i = 0; i < 5; i++) n[i] = col[i];
        }
    }
    return best > 0.0;
}

/* x with x.c = 0 for the columns c of M (Gaussian elimination with complete
   pivoting on M^T, x5 = 1 before the permutation), taken through the metric */
static int metric_normal(double M[5][5], double n[5])
{
    double A[5][5];
    int perm[5] = {0, 1, 2, 3, 4};
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++) A[i][j] = M[j][i];
    for (int k = 0; k < 4; k++) {
        int pi = k, pj = k;
        for (int i = k; i < 5; i++)
            for (int j = k; j < 5; j++)
                if (fabs(A[i][j]) > fabs(A[pi][pj]))
                    pi = i, pj = j;
        if (!(fabs(A[pi][pj]) > 0.0))
            return 0;
        for (int j = 0; j < 5; j++) {
            double t = A[k][j];
            A[k][j] = A[pi][j], A[pi][j] = t;
        }
        for (int i = 0; i < 5; i++) {
            double t = A[i][k];
            A[i][k] = A[i][pj], A[i][pj] = t;
        }
        int t = perm[k];
        perm[k] = perm[pj], perm[pj] = t;
        for (int i = k + 1; i < 5; i++) {
            double f = A[i][k] / A[k][k];
            for (int j = k; j < 5; j++) A[i][j] -= f * A[k][j];
        }
    }
    double y[5];
    y[4] = 1.0;
    for (int k = 3; k >= 0; k--) {
        double acc = 0.0;
        for (int j = k + 1; j < 5; j++) acc += A[k][j] * y[j];
        y[k] = -acc / A[k][k];
    }
    for (int k = 0; k < 5; k++) n[perm[k]] = y[k];
    n[4] = -n[4]; /* the metric: n = diag(1, 1, 1, 1, -1) x */
    return 1;
}

/* The metric normal n (n.c = 0, n5 >= 0) of the columns c of M, or 0 where
   M has rank below 4 (candidate 0), or the largest column of M^2
   (candidate 1). */
static int null_normal(double M[5][5], int cand, double n[5])
{
    if (!(cand == 1 ? largest_square_column(M, n) : metric_normal(M, n)))
        return 0;
    if (n[4] < 0.0)
        for (int i = 0; i < 5; i++) n[i] = -n[i];
    for (int i = 0; i < 5; i++)
        if (!isfinite(n[i]))
            return 0;
    return 1;
}

/* A rotor V of the Euclidean 4-space e1..e4 (so its action on the 32
   coefficients is orthogonal: it magnifies no error) with V n ~V along
   e4 + e5, for n = n5 e5 + w, n5 > 0, n null (|w| = n5): V turns w/|w| into
   e4, through a half turn in a plane e_j e4 first where w points away from e4. */
static int to_infinity(const double n[5], ga_mv *V)
{
    double w[4], nw = 0.0;
    for (int i = 0; i < 4; i++) nw = fmax(nw, fabs(n[i]));
    if (!(nw > 0.0))
        return 0;
    double len = 0.0;
    for (int i = 0; i < 4; i++) w[i] = n[i] / nw, len += w[i] * w[i];
    len = sqrt(len);
    for (int i = 0; i < 4; i++) w[i] /= len;
    ga_mv V1 = ga_mv_scalar(1.0);
    if (w[3] < 0.0) {
        int j = 0;
        for (int i = 1; i < 3; i++)
            if (fabs(w[i]) < fabs(w[j]))
                j = i;
        V1 = ga_mv_gp(ga_mv_blade(GA_BLADE_E1 + j), ga_mv_blade(GA_BLADE_E4));
        w[j] = -w[j], w[3] = -w[3];
    }
    /* (1 + e4 w)/sqrt(2 (1 + w4)) takes w to e4 */
    ga_mv wv = ga_mv_zero();
    for (int i = 0; i < 4; i++) wv.c[GA_BLADE_E1 + i] = w[i];
    ga_mv V2 = ga_mv_gp(ga_mv_blade(GA_BLADE_E4), wv);
    V2.c[0] += 1.0;
    *V = ga_mv_gp(ga_mv_scale(V2, 1.0 / sqrt(2.0 * (1.0 + w[3]))), V1);
    return 1;
}

int gabf_rigid_frame(double M[5][5], int cand, ga_mv *V)
{
    double n[5];
    return null_normal(M, cand, n) && to_infinity(n, V);
}

ga_mv gabf_sandwich(ga_mv V, ga_mv X) { return ga_mv_gp(ga_mv_gp(V, X), ga_mv_reverse(V)); }

/* The 5x5 matrix of x -> x _| b, whose kernel is b's null vector */
void gabf_contraction_matrix(ga_mv b, double M[5][5])
{
    for (int j = 0; j < 5; j++) {
        ga_mv v = ga_mv_lc(ga_mv_blade(GA_BLADE_E1 + j), b);
        for (int i = 0; i < 5; i++) M[i][j] = v.c[GA_BLADE_E1 + i];
    }
}

/* ---- two rotations: the ideals of Spin(4) -------------------------------------- */

/* An orthonormal basis U[0..2] of the bivectors of the ideal of P in the
   4-space of J (<Ui Uj>_0 = -1/2 for i = j, else 0): Gram-Schmidt on the
   parts <(e_ij _| J) P>_2 of the basis 2-blades, largest first. The
   coordinates of a bivector in it put it in the ideal to rounding of its
   own size, which a projection does not do for a bivector that is itself
   rounding noise (a factor at -P). */
void gabf_ideal_basis(ga_mv J, ga_mv P, ga_mv U[3])
{
    ga_mv cand[10];
    for (int i = 0; i < 10; i++)
        cand[i] = ga_mv_grade(ga_mv_gp(ga_mv_lc(ga_mv_blade(GA_BLADE_E12 + i), J), P), 2);
    for (int k = 0; k < 3; k++) {
        double bn = 0.0;
        int bi = 0;
        for (int i = 0; i < 10; i++) {
            ga_mv c = cand[i];
            for (int l = 0; l < k; l++) c = gab_lin(1.0, c, 2.0 * ga_mv_sp(c, U[l]), U[l]);
            cand[i] = c;
            double n = -2.0 * ga_mv_sp(c, c);
            if (n > bn)
                bn = n, bi = i;
        }
        U[k] = bn > 0.0 ? ga_mv_scale(cand[bi], 1.0 / sqrt(bn)) : ga_mv_zero();
    }
}
