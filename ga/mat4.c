/* ga/mat4.c: 4x4 matrices: identity, product, points moved (in arrays), 1-norm, the LU factorisation
 * (ga/internal/mat4.h) and the inverse; the se(3) hat and vee between twists
 * and 4x4 generators. See mat4.h for what each function computes. */
#include <garotor/mat4.h>

#include <float.h>
#include <math.h>

#include "internal/dispatch.h"
#include "internal/mat4.h"
#include "internal/vec3.h"

#define M GA__M

ga_mat4 ga_mat4_identity(void) { return ga__mat4_add_id(ga__mat4_zero(), 1.0); }

ga_mat4 ga_mat4_mul(ga_mat4 a, ga_mat4 b)
{
    ga_mat4 c;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            M(c, i, j) = M(a, i, 0) * M(b, 0, j) + M(a, i, 1) * M(b, 1, j) + M(a, i, 2) * M(b, 2, j) +
                         M(a, i, 3) * M(b, 3, j);
    return c;
}

/* One point after the other, each read whole before it is written (so in ==
   out works); 9 multiplications and 9 additions a point: the loop of
   ga/internal/dispatch.h, in the form picked for this CPU (the same bits). */
ga_status ga_mat4_apply_many(ga_mat4 m, const ga_vec3 *in, size_t n, ga_vec3 *out)
{
    if (!in || !out)
        return GA_ERR_ARG;
    gad_mat4_apply(m.m, in, n, out);
    return GA_OK;
}

double ga_mat4_norm1(ga_mat4 a)
{
    double best = 0.0;
    for (int j = 0; j < 4; j++) {
        double s = fabs(M(a, 0, j)) + fabs(M(a, 1, j)) + fabs(M(a, 2, j)) + fabs(M(a, 3, j));
        if (s > best || isnan(s))
            best = s; /* NaN in, NaN out */
    }
    return best;
}

/* ---- LU with partial pivoting (the factors: ga/internal/mat4.h) -------- */

/* Elimination with the pivot test |u_kk| > 4 eps max|A^_ij| (otherwise A^ is
 * within a few ulps, relative, of a singular matrix). With equilibrate, rows
 * then columns of A are first scaled so that each has its largest entry in
 * [1, 2). */
static int lu4_try(ga_mat4 a, ga__mat4_lu *f, int equilibrate)
{
    for (int i = 0; i < 4; i++) f->re[i] = f->ce[i] = 0;
    for (int pass = 0; equilibrate && pass < 2; pass++) /* rows, then columns */
        for (int i = 0; i < 4; i++) {
            double mx = 0.0;
            for (int j = 0; j < 4; j++) mx = fmax(mx, fabs(pass ? M(a, j, i) : M(a, i, j)));
            if (!(mx > 0.0))
                return GA_ERR_SINGULAR;
            int e = ilogb(mx);
            for (int j = 0; j < 4; j++) {
                double *x = pass ? &M(a, j, i) : &M(a, i, j);
                *x = ldexp(*x, -e);
            }
            (pass ? f->ce : f->re)[i] = e;
        }
    double big = 0.0; /* max |a_ij| (a is finite here: no NaN to skip) */
    for (int i = 0; i < 16; i++) big = fabs(a.m[i]) > big ? fabs(a.m[i]) : big;
    for (int k = 0; k < 4; k++) {
        int p = k;
        for (int i = k + 1; i < 4; i++)
            if (fabs(M(a, i, k)) > fabs(M(a, p, k)))
                p = i;
        f->piv[k] = p;
        for (int j = 0; j < 4; j++) {
            double t = M(a, k, j);
            M(a, k, j) = M(a, p, j);
            M(a, p, j) = t;
        }
        if (!(fabs(M(a, k, k)) > 4.0 * DBL_EPSILON * big))
            return GA_ERR_SINGULAR;
        for (int i = k + 1; i < 4; i++) {
            double l = M(a, i, k) /= M(a, k, k);
            for (int j = k + 1; j < 4; j++) M(a, i, j) -= l * M(a, k, j);
        }
    }
    f->lu = a;
    return GA_OK;
}

/* A as given first: partial pivoting is not invariant under row scaling, and
 * equilibrating a well-scaled matrix can hurt (an affine [R, t; 0 1] whose
 * t_i differ by 2^10 would scale R's rows apart and lose 10 bits in R^{-1}).
 * Only when A looks singular is the equilibrated A^ tried: [R, t; 0 1] with
 * |t| = 1e16 has normwise condition |t|^2 but A^ is well conditioned; a
 * rank-deficient A fails both. */
int ga__mat4_lu_factor(ga_mat4 a, ga__mat4_lu *f)
{
    return lu4_try(a, f, 0) == GA_OK ? GA_OK : lu4_try(a, f, 1);
}

/* A^{-1} b = Dc A^^{-1} Dr b from the factors of A. */
ga_mat4 ga__mat4_lu_solve(const ga__mat4_lu *f, ga_mat4 b)
{
    /* the scalings are powers of 2, and 2^0 (A not equilibrated, the common
     * case) is skipped: ldexp is a call per entry */
    for (int i = 0; i < 4; i++)
        if (f->re[i])
            for (int j = 0; j < 4; j++) M(b, i, j) = ldexp(M(b, i, j), -f->re[i]);
    for (int k = 0; k < 4; k++)
        for (int j = 0; j < 4; j++) {
            double t = M(b, k, j);
            M(b, k, j) = M(b, f->piv[k], j);
            M(b, f->piv[k], j) = t;
        }
    for (int c = 0; c < 4; c++) {
        for (int i = 1; i < 4; i++)
            for (int j = 0; j < i; j++) M(b, i, c) -= M(f->lu, i, j) * M(b, j, c);
        for (int i = 3; i >= 0; i--) {
            for (int j = i + 1; j < 4; j++) M(b, i, c) -= M(f->lu, i, j) * M(b, j, c);
            M(b, i, c) /= M(f->lu, i, i);
        }
    }
    for (int i = 0; i < 4; i++)
        if (f->ce[i])
            for (int j = 0; j < 4; j++) M(b, i, j) = ldexp(M(b, i, j), -f->ce[i]);
    return b;
}

ga_status ga_mat4_inverse(ga_mat4 a, ga_mat4 *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga__mat4_lu f;
    if (!ga__mat4_isfinite(&a))
        return GA_ERR_NOTFINITE;
    if (ga__mat4_lu_factor(a, &f) != GA_OK)
        return GA_ERR_SINGULAR;
    ga_mat4 r = ga__mat4_lu_solve(&f, ga_mat4_identity());
    if (!ga__mat4_isfinite(&r))
        return GA_ERR_SINGULAR; /* the inverse overflows */
    *out = r;
    return GA_OK;
}

/* ---- se(3): hat and vee ------------------------------------------------ */

ga_mat4 ga_twist_hat(ga_twist xi)
{
    ga_mat4 a = ga__mat4_zero();
    /* clang-format off */
    M(a, 0, 1) = -xi.w.z; M(a, 0, 2) =  xi.w.y; M(a, 0, 3) = xi.v.x;
    M(a, 1, 0) =  xi.w.z; M(a, 1, 2) = -xi.w.x; M(a, 1, 3) = xi.v.y;
    M(a, 2, 0) = -xi.w.y; M(a, 2, 1) =  xi.w.x; M(a, 2, 3) = xi.v.z;
    /* clang-format on */
    return a;
}

ga_twist ga_twist_vee(ga_mat4 a)
{
    ga_twist xi;
    /* halves first: the same result as (a21 - a12)/2 (scaling by 2 commutes
       with rounding), but no overflow for entries beyond DBL_MAX/2 */
    xi.w = ga__v3(0.5 * M(a, 2, 1) - 0.5 * M(a, 1, 2), 0.5 * M(a, 0, 2) - 0.5 * M(a, 2, 0),
                  0.5 * M(a, 1, 0) - 0.5 * M(a, 0, 1));
    xi.v = ga__v3(M(a, 0, 3), M(a, 1, 3), M(a, 2, 3));
    return xi;
}
