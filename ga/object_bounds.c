/* garotor/object_bounds.c: the numerics under the object layer (ga/internal/
 * object.h): the translation sandwich, the constructors from points and the
 * geometric and outer products carried exactly, and the bounds of object.h's
 * accuracy model, coefficient by coefficient. */
#include <math.h>

#include "internal/blade.h"
#include "internal/eft.h"
#include "internal/object.h"

double gao_off_grade(ga_mv X, int k) { return ga_mv_maxabs(ga_mv_sub(X, ga_mv_grade(X, k))); }

ga_mv gao_unit_scaled(ga_mv X)
{
    int e;
    frexp(ga_mv_maxabs(X), &e);
    for (int i = 0; i < 32; i++) X.c[i] = ldexp(X.c[i], -e);
    return X;
}

/* T_a = 1 + n a / 2 = 1 - sum a_i (e_i4 + e_i5) / 2, exactly (a_i / 2 is
   exact unless it underflows, which changes nothing above the rounding) */
static ga_mv translator(ga_vec3 a)
{
    ga_mv T = ga_mv_scalar(1.0);
    T.c[GA_BLADE_E14] = T.c[GA_BLADE_E15] = -0.5 * a.x;
    T.c[GA_BLADE_E24] = T.c[GA_BLADE_E25] = -0.5 * a.y;
    T.c[GA_BLADE_E34] = T.c[GA_BLADE_E35] = -0.5 * a.z;
    return T;
}

/* the indices of the nonzero coefficients of x (n of them) */
static int nonzero(const double *x, int *idx)
{
    int n = 0;
    for (int i = 0; i < 32; i++)
        if (x[i] != 0.0)
            idx[n++] = i;
    return n;
}

/* T_a X ~T_a for X in double-double (x the values, each hi + lo) */
static ga_mv translate_dd(const ga__eft_dd *x, ga_vec3 a)
{
    ga_mv T = translator(a), X;
    for (int i = 0; i < 32; i++) X.c[i] = x[i].hi;
    ga__eft_dd p[32] = {{0, 0}}, y[32] = {{0, 0}};
    int it[32], ix[32], ip[32], nt = nonzero(T.c, it), nx = nonzero(X.c, ix);
    /* p = T X, each product exact (two-product; X's low parts added to
       it), the sums double-double */
    for (int u = 0; u < nt; u++) {
        int i = it[u];
        unsigned mi = gabl_mask[i];
        for (int v = 0; v < nx; v++) {
            int j = ix[v];
            unsigned mj = gabl_mask[j];
            ga__eft_dd q = ga__eft_dd_prod(T.c[i], X.c[j]);
            if (x[j].lo != 0.0)
                q = ga__eft_dd_norm(q.hi, q.lo + T.c[i] * x[j].lo);
            int k = gabl_index_of[mi ^ mj];
            p[k] = ga__eft_dd_add(p[k], gabl_sign(mi, mj) < 0.0 ? ga__eft_dd_neg(q) : q);
        }
    }
    /* y = p ~T, ~T = 1 - (T - 1): the same blades, the bivectors negated */
    int np = 0;
    for (int i = 0; i < 32; i++)
        if (p[i].hi != 0.0)
            ip[np++] = i;
    for (int u = 0; u < np; u++) {
        int i = ip[u];
        unsigned mi = gabl_mask[i];
        for (int v = 0; v < nt; v++) {
            int j = it[v];
            unsigned mj = gabl_mask[j];
            double tj = j == 0 ? T.c[j] : -T.c[j];
            ga__eft_dd q = ga__eft_dd_prod(p[i].hi, tj);
            q = ga__eft_dd_norm(q.hi, q.lo + p[i].lo * tj);
            int k = gabl_index_of[mi ^ mj];
            y[k] = ga__eft_dd_add(y[k], gabl_sign(mi, mj) < 0.0 ? ga__eft_dd_neg(q) : q);
        }
    }
    /* a translation keeps each grade: the grades X has none of stay 0 (the
       double-double sums leave ~u^2 of their terms there) */
    int has[6] = {0};
    for (int v = 0; v < nx; v++) has[gabl_popcount5(gabl_mask[ix[v]])] = 1;
    ga_mv r;
    for (int i = 0; i < 32; i++) r.c[i] = has[gabl_popcount5(gabl_mask[i])] ? y[i].hi + y[i].lo : 0.0;
    return r;
}

ga_mv gao_translate(ga_mv X, ga_vec3 a)
{
    ga__eft_dd x[32];
    for (int i = 0; i < 32; i++) x[i] = (ga__eft_dd){X.c[i], 0.0};
    return translate_dd(x, a);
}

/* a ^ b in double-double, into r (each product to ~u^2 of itself) */
static void op_dd(const ga__eft_dd *a, const ga__eft_dd *b, ga__eft_dd *r)
{
    for (int k = 0; k < 32; k++) r[k] = (ga__eft_dd){0.0, 0.0};
    for (int i = 0; i < 32; i++) {
        if (a[i].hi == 0.0)
            continue;
        unsigned mi = gabl_mask[i];
        for (int j = 0; j < 32; j++) {
            unsigned mj = gabl_mask[j];
            if (b[j].hi == 0.0 || (mi & mj))
                continue;
            ga__eft_dd q = ga__eft_dd_mul(a[i], b[j]);
            int k = gabl_index_of[mi | mj];
            r[k] = ga__eft_dd_add(r[k], gabl_sign(mi, mj) < 0.0 ? ga__eft_dd_neg(q) : q);
        }
    }
}

/* F(y) in double-double for y = p - a (the differences exact) */
static void up_dd(ga_vec3 p, ga_vec3 a, ga__eft_dd *f)
{
    for (int k = 0; k < 32; k++) f[k] = (ga__eft_dd){0.0, 0.0};
    ga__eft_dd y[3] = {ga__eft_dd_sum(p.x, -a.x), ga__eft_dd_sum(p.y, -a.y), ga__eft_dd_sum(p.z, -a.z)};
    ga__eft_dd y2 = {0.0, 0.0};
    for (int i = 0; i < 3; i++) y2 = ga__eft_dd_add(y2, ga__eft_dd_mul(y[i], y[i]));
    f[GA_BLADE_E1] = y[0];
    f[GA_BLADE_E2] = y[1];
    f[GA_BLADE_E3] = y[2];
    f[GA_BLADE_E4] = ga__eft_dd_ldexp(ga__eft_dd_add(y2, ga__eft_dd_sum(-1.0, 0.0)), -1);
    f[GA_BLADE_E5] = ga__eft_dd_ldexp(ga__eft_dd_add(y2, ga__eft_dd_sum(1.0, 0.0)), -1);
}

ga_mv gao_build_about(const ga_vec3 *p, int np, int with_n)
{
    ga__eft_dd x[32] = {{0, 0}}, f[32], r[32];
    x[GA_BLADE_E4] = (ga__eft_dd){-0.5, 0.0}; /* F(0) = (e5 - e4) / 2 */
    x[GA_BLADE_E5] = (ga__eft_dd){0.5, 0.0};
    for (int i = 1; i <= np; i++) {
        if (i < np)
            up_dd(p[i], p[0], f);
        else if (with_n) {
            for (int k = 0; k < 32; k++) f[k] = (ga__eft_dd){0.0, 0.0};
            f[GA_BLADE_E4] = f[GA_BLADE_E5] = (ga__eft_dd){1.0, 0.0}; /* n */
        } else
            break;
        op_dd(x, f, r);
        for (int k = 0; k < 32; k++) x[k] = r[k];
    }
    return translate_dd(x, p[0]);
}

/* a b (outer = 0) or a ^ b (outer = 1): each product exact, the sums
   double-double, rounded once */
static ga_mv product_exact(ga_mv a, ga_mv b, int outer)
{
    ga__eft_dd r[32] = {{0, 0}};
    for (int i = 0; i < 32; i++) {
        if (a.c[i] == 0.0)
            continue;
        unsigned mi = gabl_mask[i];
        for (int j = 0; j < 32; j++) {
            unsigned mj = gabl_mask[j];
            if (b.c[j] == 0.0 || (outer && (mi & mj)))
                continue;
            ga__eft_dd q = ga__eft_dd_prod(a.c[i], b.c[j]);
            if (gabl_sign(mi, mj) < 0.0)
                q = ga__eft_dd_neg(q);
            int k = gabl_index_of[mi ^ mj];
            r[k] = ga__eft_dd_add(r[k], q);
        }
    }
    ga_mv w;
    for (int i = 0; i < 32; i++) w.c[i] = r[i].hi + r[i].lo;
    return w;
}

ga_mv gao_gp_exact(ga_mv a, ga_mv b) { return product_exact(a, b, 0); }
ga_mv gao_op_exact(ga_mv a, ga_mv b) { return product_exact(a, b, 1); }

ga_mv gao_abs(ga_mv X)
{
    for (int i = 0; i < 32; i++) X.c[i] = fabs(X.c[i]);
    return X;
}

ga_mv gao_abs_gp(ga_mv a, ga_mv b)
{
    ga_mv r = ga_mv_zero();
    for (int i = 0; i < 32; i++) {
        if (a.c[i] == 0.0)
            continue;
        unsigned mi = gabl_mask[i];
        for (int j = 0; j < 32; j++)
            if (b.c[j] != 0.0)
                r.c[gabl_index_of[mi ^ gabl_mask[j]]] += fabs(a.c[i]) * fabs(b.c[j]);
    }
    return r;
}

ga_mv gao_abs_translate(ga_mv X, ga_vec3 a)
{
    ga_mv T = gao_abs(translator(a));
    return gao_abs_gp(gao_abs_gp(T, gao_abs(X)), T);
}

/* The pairs of blades A e4, A e5 (A without e4, e5): e4 at i, e5 at i + 1
   in the canonical order; in null coordinates A ^ n and A ^ nbar, with
   coefficients (p + q) / 2 and (p - q) / 2 (n = e4 + e5, nbar = e4 - e5). */
static int pair_e5(int i) { return i > 0 && gabl_pair_e4(i - 1); }

ga_mv gao_scale_n_nbar(ga_mv X, double kn, double kb)
{
    for (int i = 0; i < 32; i++) {
        if (!gabl_pair_e4(i))
            continue;
        int j = i + 1;
        double hn = 0.5 * (X.c[i] + X.c[j]) * kn, hb = kb == 0.0 ? 0.0 : 0.5 * (X.c[i] - X.c[j]) * kb;
        X.c[i] = hn + hb;
        X.c[j] = hn - hb;
    }
    return X;
}

ga_mv gao_unc_to_null(ga_mv e)
{
    for (int i = 0; i < 32; i++)
        if (gabl_pair_e4(i)) {
            double h = 0.5 * (e.c[i] + e.c[i + 1]);
            e.c[i] = e.c[i + 1] = h;
        }
    return e;
}

ga_mv gao_unc_from_null(ga_mv e, double kn, double kb)
{
    for (int i = 0; i < 32; i++)
        if (gabl_pair_e4(i)) {
            double h = e.c[i] * kn + e.c[i + 1] * kb;
            e.c[i] = e.c[i + 1] = h;
        }
    return e;
}

ga_mv gao_abs_translate_null(ga_mv e, ga_vec3 a)
{
    ga_mv r = ga_mv_zero();
    for (int j = 0; j < 32; j++) {
        if (e.c[j] == 0.0)
            continue;
        /* the null blade of slot j in e4/e5 coefficients, moved exactly */
        ga_mv B = ga_mv_zero();
        B.c[j] = 1.0;
        if (gabl_pair_e4(j))
            B.c[j + 1] = 1.0; /* A ^ n */
        else if (pair_e5(j))
            B.c[j - 1] = 1.0, B.c[j] = -1.0; /* A ^ nbar */
        ga_mv Y = gao_translate(B, a);
        for (int i = 0; i < 32; i++) {
            double y = gabl_pair_e4(i) ? 0.5 * (Y.c[i] + Y.c[i + 1])
                     : pair_e5(i)      ? 0.5 * (Y.c[i - 1] - Y.c[i])
                                       : Y.c[i];
            r.c[i] += e.c[j] * fabs(y);
        }
    }
    return r;
}

/* the class of blade i: its grade + 6 (number of its factors e4, e5), 0..17 */
static int blade_class(int i)
{
    unsigned m = gabl_mask[i];
    return gabl_popcount5(m) + 6 * gabl_popcount5(m & 0x18u);
}

ga_mv gao_uncertainty(ga_mv X, double kappa)
{
    double top[18] = {0};
    for (int i = 0; i < 32; i++) top[blade_class(i)] = fmax(top[blade_class(i)], fabs(X.c[i]));
    ga_mv r;
    for (int i = 0; i < 32; i++) r.c[i] = kappa * GAO_U * top[blade_class(i)];
    return r;
}
