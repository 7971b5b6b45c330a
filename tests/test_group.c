/* tests/test_group.c: the Lie-group properties, checked on every group of the
 * library.
 *
 * The groups are enumerated with ga_group_nth, so a group added to the
 * library is checked here with no edit. Each group's random elements are
 * exp(x) for algebra elements x of every family of tests/testkit.h its
 * algebra holds (the families are drawn as 4x4 matrices and read with the
 * group's own vee; a family whose matrices vee rejects is not in the
 * algebra: the rigid groups take the twist families, the affine group also
 * the scalings, shears and general 3x4 matrices).
 *
 * Per group:
 *   exp(log g) = g; log(exp x) = x where x is the principal log (at exact half
 *     turns and beyond them the motions are compared, not the twists);
 *   g g^-1 = e = g^-1 g; (a b) c = a (b c); e g = g = g e;
 *   the adjoint against conjugation, in the algebra (Ad_g x = g x g^-1 as
 *     4x4) and in the group (exp(Ad_g x) = g exp(x) g^-1);
 *   dexp against a central difference of exp (no log in it);
 *   from_mat4(to_mat4(g)) = g; vee(hat(x)) = x exactly; vee, from_mat4
 *     reject what is outside the algebra or the group, outputs untouched;
 *   half_turn and branch (where not NULL): the same group element, half_turn
 *     idempotent, branch(x, x) = x.
 *
 * How errors are measured. A 4x4 difference is taken entry by entry against
 * a bound matrix (the check fails if any entry is above its bound) and
 * printed relative to a scale matrix (the entry nearest its bound: its error
 * and its bound, both divided by its scale); an algebra difference coordinate
 * by coordinate against a bound per coordinate. The bounds come from one
 * rounding model, stated once here and used by every tolerance below:
 *
 *   (R) A computed group element G (as its 4x4) has each entry wrong by at
 *       most c u kappa N(G)_ij, u = 2^-53, where N(G)_ij is the largest
 *       magnitude in column j of G (the linear part's columns are O(1) for a
 *       rigid motion, the translation column is O(|t|)): the rounding of a
 *       closed form or of a product is relative to the size of what it sums.
 *       kappa = kappa_2 of the 3x3 linear part A of G (||A|| ||A^-1||, the
 *       amplification of rounding by the squarings of scaling and squaring
 *       and by the inverse; exactly 1, up to rounding, for a rigid motion).
 *       Below DBL_MIN a rounding errs absolutely, by at most ETA = 2^-1074,
 *       so every bound has c ETA added (Higham's underflow term).
 *   (R') A computed algebra element X (as its hat) has each entry wrong by at
 *       most c u of N'(X): the largest magnitude in its 3x3 block for the
 *       block's entries (a twist's w is a vector: a rotor computes it from
 *       all its components at once), the largest in its translation column
 *       for that column.
 *   (J) A perturbation dx of an algebra element x moves exp(x) by
 *       exp(x) hat(J_r(x) dx) to first order (the definition of dexp), so
 *       |d exp| <= |exp(x)| |hat|(|J_r(x)| |dx|), |hat|(z) = sum_k z_k
 *       |hat(e_k)|. J_r(x) is taken column by column from the group's dexp
 *       (checked against finite differences below), and its inverse gives
 *       the log's sensitivity: d log = J_r(x)^-1 vee(g^-1 dg).
 *
 * Constants count roundings: c = C_OP = 32 for one exp, log, inverse or
 * product of the representations here (a rotor product coefficient sums 8
 * products and to_mat4 of a rotor adds a quadratic form of its 8
 * coefficients, ~16 roundings; Rodrigues' formula, Eberly's V v and a 4x4
 * product take fewer; doubled for the cancellation of sums of terms of
 * either sign). A check that chains k such operations uses k c. Every check
 * prints its worst measured error, so the figures can be quoted against
 * these bounds.
 *
 *   test_group [SEED]   (default: the fixed seed; a few tenths of a second)
 */
#include "testkit.h"

#include <stdlib.h>

#define U (DBL_EPSILON / 2) /* unit roundoff 2^-53 */
#define ETA 0x1p-1074       /* the smallest subnormal: a rounding's absolute error below DBL_MIN */
#define C_OP 32.0           /* roundings of one operation, in units of u (see (R)) */
#define N_PER_FAMILY 128
#define MAXS (TK_FAMILIES * N_PER_FAMILY)
#define DMAX GA_GROUP_MAX_DIM

/* ---- 4x4 helpers ---------------------------------------------------------------- */
static ga_mat4 mmul(ga_mat4 a, ga_mat4 b) { return ga_mat4_mul(a, b); }
static ga_mat4 mabs(ga_mat4 a)
{
    for (int i = 0; i < 16; i++) a.m[i] = fabs(a.m[i]);
    return a;
}
static ga_mat4 madd(ga_mat4 a, ga_mat4 b)
{
    for (int i = 0; i < 16; i++) a.m[i] += b.m[i];
    return a;
}
static ga_mat4 mscale(ga_mat4 a, double k)
{
    for (int i = 0; i < 16; i++) a.m[i] *= k;
    return a;
}
static double mmax(ga_mat4 a)
{
    double e = 0;
    for (int i = 0; i < 16; i++) e = tk_max(e, fabs(a.m[i]));
    return e;
}
/* N(G) of (R): each entry replaced by the largest magnitude in its column. */
static ga_mat4 colmax(ga_mat4 g)
{
    ga_mat4 n;
    for (int j = 0; j < 4; j++) {
        double c = 0;
        for (int i = 0; i < 4; i++) c = fmax(c, fabs(g.m[4 * i + j]));
        for (int i = 0; i < 4; i++) n.m[4 * i + j] = c;
    }
    return n;
}
/* N'(X) for an algebra element (R'): the columns of the 3x3 block take the
 * block's largest magnitude, the translation column its own. */
static ga_mat4 blockmax(ga_mat4 x)
{
    double a = 0, t = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if (j < 3)
                a = fmax(a, fabs(x.m[4 * i + j]));
            else
                t = fmax(t, fabs(x.m[4 * i + j]));
    ga_mat4 n;
    for (int i = 0; i < 16; i++) n.m[i] = i % 4 < 3 ? a : t;
    return n;
}
/* max_ij |a_ij - b_ij| / s_ij (0/0 = 0; NaN or x/0 for x != 0: infinite) */
static double rel_err(ga_mat4 a, ga_mat4 b, ga_mat4 s)
{
    double e = 0;
    for (int i = 0; i < 16; i++) {
        double d = fabs(a.m[i] - b.m[i]);
        if (d == 0)
            continue;
        double r = d / s.m[i];
        e = r > e || isnan(r) ? (isnan(r) ? INFINITY : r) : e;
    }
    return e;
}

/* The entrywise check |a_ij - b_ij| <= t_ij + C_OP ETA (the underflow of
 * each rounding, (R)), reported in the units of a scale n (the entry nearest
 * its bound: its |a - b| / n and its bound / n). */
static void add_entrywise(tk_check *c, ga_mat4 a, ga_mat4 b, ga_mat4 t, ga_mat4 n)
{
    for (int i = 0; i < 16; i++) t.m[i] += C_OP * ETA;
    int w = -1;
    double wr = -1, tmin = INFINITY;
    for (int i = 0; i < 16; i++) {
        double d = fabs(a.m[i] - b.m[i]);
        double r = d == 0 ? 0 : isnan(d) ? INFINITY : d / t.m[i];
        if (n.m[i] > 0 && t.m[i] / n.m[i] < tmin)
            tmin = t.m[i] / n.m[i];
        if (r > wr && d > 0)
            wr = r, w = i;
    }
    if (w < 0) { /* equal: the tightest bound met */
        tk_add_tol(c, 0, tmin);
        return;
    }
    double d = fabs(a.m[w] - b.m[w]);
    tk_add_tol(c, isnan(d) ? INFINITY : d / n.m[w], t.m[w] / n.m[w]);
}

/* kappa_2 of the 3x3 linear part: sqrt of the eigenvalue ratio of A^T A, by
 * cyclic Jacobi rotations (a symmetric 3x3 converges in a few sweeps). */
static double cond_lin(ga_mat4 g)
{
    double b[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0;
            for (int k = 0; k < 3; k++) s += g.m[4 * k + i] * g.m[4 * k + j];
            b[i][j] = s;
        }
    for (int sweep = 0; sweep < 30; sweep++) {
        double off = fabs(b[0][1]) + fabs(b[0][2]) + fabs(b[1][2]);
        if (off <= 1e-300)
            break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (b[p][q] == 0)
                    continue;
                double th = 0.5 * atan2(2 * b[p][q], b[q][q] - b[p][p]);
                double c = cos(th), s = sin(th);
                for (int k = 0; k < 3; k++) { /* B <- B J, then J^T B */
                    double bkp = b[k][p], bkq = b[k][q];
                    b[k][p] = c * bkp - s * bkq;
                    b[k][q] = s * bkp + c * bkq;
                }
                for (int k = 0; k < 3; k++) {
                    double bpk = b[p][k], bqk = b[q][k];
                    b[p][k] = c * bpk - s * bqk;
                    b[q][k] = s * bpk + c * bqk;
                }
            }
    }
    double lo = fmin(b[0][0], fmin(b[1][1], b[2][2])), hi = fmax(b[0][0], fmax(b[1][1], b[2][2]));
    return lo > 0 ? fmax(1.0, sqrt(hi / lo)) : INFINITY;
}

/* ---- algebra helpers -------------------------------------------------------------- */
static const ga_group *G;     /* the group under test */
static tk_rng rng;            /* its stream: the samples, then check_dexp */
static int D;                 /* its dim */
static ga_mat4 hat_abs[DMAX]; /* |hat(e_k)| */

static void setup_group(const ga_group *g)
{
    G = g;
    D = (int)g->dim;
    for (int k = 0; k < D; k++) {
        double e[DMAX] = {0};
        e[k] = 1;
        hat_abs[k] = mabs(g->hat(e));
    }
}
/* |hat|(z) = sum_k z_k |hat(e_k)| for z >= 0 */
static ga_mat4 hat_of_abs(const double *z)
{
    ga_mat4 h;
    memset(&h, 0, sizeof h);
    for (int k = 0; k < D; k++) h = madd(h, mscale(hat_abs[k], z[k]));
    return h;
}
/* Per algebra coordinate, the largest entry of s where hat(e_k) has one. */
static void coord_size(ga_mat4 s, double *b)
{
    for (int k = 0; k < D; k++) {
        b[k] = 0;
        for (int i = 0; i < 16; i++)
            if (hat_abs[k].m[i] != 0)
                b[k] = fmax(b[k], s.m[i]);
    }
}
/* J_r(x) as a D x D matrix, J[i D + j], column j = dexp(x, e_j). */
static void jacobian(const double *x, double *J)
{
    for (int j = 0; j < D; j++) {
        double e[DMAX] = {0}, c[DMAX];
        e[j] = 1;
        G->dexp(x, e, c);
        for (int i = 0; i < D; i++) J[i * D + j] = c[i];
    }
}
/* Gauss-Jordan with partial pivoting; 0 if singular. */
static int invert(const double *A, double *Ai)
{
    double a[DMAX][2 * DMAX];
    for (int i = 0; i < D; i++)
        for (int j = 0; j < 2 * D; j++) a[i][j] = j < D ? A[i * D + j] : (j - D == i);
    for (int c = 0; c < D; c++) {
        int p = c;
        for (int i = c + 1; i < D; i++)
            if (fabs(a[i][c]) > fabs(a[p][c]))
                p = i;
        if (a[p][c] == 0)
            return 0;
        for (int j = 0; j < 2 * D; j++) {
            double t = a[c][j];
            a[c][j] = a[p][j];
            a[p][j] = t;
        }
        for (int i = 0; i < D; i++) {
            if (i == c)
                continue;
            double f = a[i][c] / a[c][c];
            for (int j = 0; j < 2 * D; j++) a[i][j] -= f * a[c][j];
        }
    }
    for (int i = 0; i < D; i++)
        for (int j = 0; j < D; j++) Ai[i * D + j] = a[i][D + j] / a[i][i];
    return 1;
}
/* z = |M| b */
static void absmatvec(const double *M, const double *b, double *z)
{
    for (int i = 0; i < D; i++) {
        z[i] = 0;
        for (int j = 0; j < D; j++) z[i] += fabs(M[i * D + j]) * b[j];
    }
}
/* (J): the entrywise bound |E| |hat|(|J| b) on how far exp(x) moves when x
 * moves by at most b_k in each coordinate (E = exp(x) as 4x4, J = J_r(x)). */
static ga_mat4 exp_moves(ga_mat4 E, const double *J, const double *b)
{
    double z[DMAX];
    absmatvec(J, b, z);
    return mmul(mabs(E), hat_of_abs(z));
}

/* ---- the samples ---------------------------------------------------------------- */
enum { PRINCIPAL, HALF_TURN, BEYOND };
typedef struct {
    int fam, where;               /* family; PRINCIPAL, HALF_TURN or BEYOND */
    double margin;                /* pi - the principal rotation angle (a lower bound) */
    double x[DMAX];               /* the algebra element */
    double e[GA_GROUP_MAX_ELEM];  /* exp(x) */
    double ei[GA_GROUP_MAX_ELEM]; /* its inverse */
    ga_mat4 m, mi;                /* both as 4x4 */
    double J[DMAX * DMAX];        /* J_r(x) */
    double kappa;                 /* kappa_2 of the linear part of m */
} sample;

static sample S[MAXS];
static int NS;
static long families_out; /* family draws the group's vee rejected */

/* Draw every family; keep those in the group's algebra. */
static void draw_samples(tk_rng *r, tk_check *c_status)
{
    NS = 0;
    families_out = 0;
    for (int f = 0; f < TK_FAMILIES; f++)
        for (int k = 0; k < N_PER_FAMILY; k++) {
            ga_mat4 X = tk_algebra(r, f);
            sample *s = &S[NS];
            memset(s, 0, sizeof *s);
            if (G->vee(X, s->x) != GA_OK) {
                families_out++;
                continue;
            }
            s->fam = f;
            /* the rotation angle: |w| of the skew part of X's 3x3 block, which
               bounds the imaginary parts of its eigenvalues (Bendixson) */
            double th = tk_norm(ga_twist_vee(X).w);
            s->where = f == TK_ROT_PI ? HALF_TURN : f == TK_BEYOND_PI ? BEYOND : PRINCIPAL;
            s->margin = s->where == HALF_TURN ? 0
                      : s->where == BEYOND    ? TK_PI - fabs(th - 2 * TK_PI)
                                              : TK_PI - th;
            int st = G->exp(s->x, s->e);
            tk_add_status(c_status, st, GA_OK);
            if (st != GA_OK)
                continue;
            st = G->inverse(s->e, s->ei);
            tk_add_status(c_status, st, GA_OK);
            if (st != GA_OK)
                continue;
            s->m = G->to_mat4(s->e);
            s->mi = G->to_mat4(s->ei);
            s->kappa = cond_lin(s->m);
            jacobian(s->x, s->J);
            NS++;
        }
}

/* The partner of sample i for checks that take two or three elements:
 * 7 i + 13 k + 5 (mod the count), so that partners come from other families. */
static int partner(int i, int k) { return (int)(((long)i * 7 + 13 * k + 5) % NS); }

/* ---- the checks ------------------------------------------------------------------- */

/* exp(log g) = g, and log(exp x) = x on the principal domain.
 *   log(exp x): exp(x) is g + dg with |dg| <= C_OP u kappa N(g) by (R); the
 *   log adds a backward error of the same size; by (J) the log then moves by
 *   J_r(x)^-1 vee(g^-1 dg), and |g^-1 dg| <= 2 C_OP u kappa |g^-1| N(g):
 *   per coordinate, bound_k = 2 C_OP u kappa (|J_r(x)^-1| b)_k with b the
 *   coordinate sizes of |g^-1| N(g). J_r(x)^-1 carries the log's
 *   conditioning: O(1) in the twist algebra up to a half turn, th / sin th
 *   in the general linear algebra near one.
 *   exp(log g): the log l is wrong by at most that bound (at l), which (J)
 *   carries back through exp as |g| |hat|(|J_r(l)| |J_r(l)^-1| b) 2 C_OP u
 *   kappa, plus exp's own rounding C_OP u kappa N(g) and the log's backward
 *   error: entrywise <= 2 C_OP u kappa (N(g) + |g| |hat|(|J_r(l)| |J_r(l)^-1|
 *   b)). Where the log is well conditioned this is a few C_OP u N(g); near a
 *   half turn of the general linear group it is as loose as the problem.
 *   Status: a rigid group's log always exists (angle in [0, pi]); a
 *   non-rigid group may answer GA_ERR_DOMAIN only where there is no real
 *   principal log, taken as: within 1e-10 rad of a half turn (mat4.h's band
 *   for ga_mat4_logm). */
static void check_exp_log(void)
{
    tk_check el = tk_begin("exp(log g) = g, |D| / N(g)", 0);
    tk_check le = tk_begin("log(exp x) = x (principal x), per coordinate", 0);
    tk_check st_c = tk_begin("log status (GA_ERR_DOMAIN only within 1e-10 of a half turn)", 0);
    long domain = 0;
    double domain_margin = 0;
    for (int i = 0; i < NS; i++) {
        sample *s = &S[i];
        double l[DMAX], e2[GA_GROUP_MAX_ELEM];
        int st = G->log(s->e, l);
        if (st == GA_ERR_DOMAIN && !G->rigid && s->margin <= 1e-10) {
            domain++;
            domain_margin = fmax(domain_margin, s->margin);
            tk_add_status(&st_c, GA_OK, GA_OK);
            continue;
        }
        tk_add_status(&st_c, st, GA_OK);
        if (st != GA_OK)
            continue;
        st = G->exp(l, e2);
        tk_add_status(&st_c, st, GA_OK);
        if (st != GA_OK)
            continue;
        double J[DMAX * DMAX], Ji[DMAX * DMAX], b[DMAX], z[DMAX], w[DMAX];
        double k2 = 2 * C_OP * U * s->kappa;
        coord_size(mmul(mabs(s->mi), colmax(s->m)), b);
        jacobian(l, J);
        if (!invert(J, Ji)) {
            tk_add_tol(&el, INFINITY, 0);
            continue;
        }
        absmatvec(Ji, b, z);
        absmatvec(J, z, w);
        ga_mat4 bound = mscale(madd(colmax(s->m), mmul(mabs(s->m), hat_of_abs(w))), k2);
        add_entrywise(&el, G->to_mat4(e2), s->m, bound, colmax(s->m));
        if (s->where != PRINCIPAL)
            continue;
        if (!invert(s->J, Ji)) {
            tk_add_tol(&le, INFINITY, 0);
            continue;
        }
        absmatvec(Ji, b, z);
        double worst = 0, wtol = 0, wratio = -1;
        for (int k = 0; k < D; k++) {
            double err = fabs(l[k] - s->x[k]), tol = k2 * z[k] + 2 * C_OP * ETA;
            double ratio = err == 0 ? 0 : err / tol;
            if (!(ratio <= wratio))
                worst = err, wtol = tol, wratio = isnan(ratio) ? INFINITY : ratio;
        }
        tk_add_tol(&le, worst, wtol);
    }
    tk_end(&el);
    tk_end(&le);
    tk_end(&st_c);
    if (domain)
        tk_note("     (GA_ERR_DOMAIN for %ld elements, all within %.2e rad of a half turn)\n", domain,
                domain_margin);
}

/* g g^-1 = e = g^-1 g. The computed inverse is wrong by C_OP u kappa
 * N(g^-1) by (R), and the product rounds by C_OP u of the sizes it sums,
 * |g| N(g^-1): so |g g^-1 - I| <= 2 C_OP u kappa |g| N(g^-1) entrywise, and
 * |g^-1 g - I| <= 2 C_OP u kappa |g^-1| N(g). */
static void check_inverse(void)
{
    tk_check a = tk_begin("g g^-1 = e, |D| / (|g| N(g^-1))", 0),
             b = tk_begin("g^-1 g = e, |D| / (|g^-1| N(g))", 0);
    ga_mat4 id = ga_mat4_identity();
    for (int i = 0; i < NS; i++) {
        sample *s = &S[i];
        double p[GA_GROUP_MAX_ELEM], q[GA_GROUP_MAX_ELEM];
        G->compose(s->e, s->ei, p);
        G->compose(s->ei, s->e, q);
        ga_mat4 na = mmul(mabs(s->m), colmax(s->mi)), nb = mmul(mabs(s->mi), colmax(s->m));
        add_entrywise(&a, G->to_mat4(p), id, mscale(na, 2 * C_OP * U * s->kappa), na);
        add_entrywise(&b, G->to_mat4(q), id, mscale(nb, 2 * C_OP * U * s->kappa), nb);
    }
    tk_end(&a);
    tk_end(&b);
}

/* (a b) c = a (b c): each side is two products, each rounding by C_OP u of
 * the sizes it sums, column by column (R): the sides differ by at most
 * 4 C_OP u N(|a| |b| |c|) entrywise. e g = g = g e exactly: every product
 * term is a product by 0 or 1, and a sum of one value with zeros is that
 * value. */
static void check_assoc_identity(void)
{
    tk_check as = tk_begin("(a b) c = a (b c), |D| / N(|a||b||c|)", 0);
    tk_check id = tk_begin("e g = g = g e (exact)", 0);
    double e[GA_GROUP_MAX_ELEM];
    G->identity(e);
    for (int i = 0; i < NS; i++) {
        sample *a = &S[i], *b = &S[partner(i, 1)], *c = &S[partner(i, 2)];
        double ab[GA_GROUP_MAX_ELEM], bc[GA_GROUP_MAX_ELEM], l[GA_GROUP_MAX_ELEM], r[GA_GROUP_MAX_ELEM];
        G->compose(a->e, b->e, ab);
        G->compose(ab, c->e, l);
        G->compose(b->e, c->e, bc);
        G->compose(a->e, bc, r);
        ga_mat4 n = colmax(mmul(mmul(mabs(a->m), mabs(b->m)), mabs(c->m)));
        add_entrywise(&as, G->to_mat4(l), G->to_mat4(r), mscale(n, 4 * C_OP * U), n);
        G->compose(e, a->e, l);
        G->compose(a->e, e, r);
        ga_mat4 lm = G->to_mat4(l), rm = G->to_mat4(r);
        double z = 0;
        for (int k = 0; k < 16; k++)
            z = tk_max(z, tk_max(fabs(lm.m[k] - a->m.m[k]), fabs(rm.m[k] - a->m.m[k])));
        tk_add(&id, isnan(mmax(lm)) || isnan(mmax(rm)) ? NAN : z);
    }
    tk_end(&as);
    tk_end(&id);
}

/* The adjoint against conjugation, y = Ad_g x with x another sample's
 * element.
 *   In the algebra: hat(y) = g hat(x) g^-1. Both sides sum the products
 *   |g| |hat x| |g^-1| (a rotor sandwich sums the same terms in another
 *   order), and the right side uses the computed inverse: by (R)
 *   2 C_OP u kappa N(|g| |hat x| |g^-1|) entrywise.
 *   In the group: exp(y) = g exp(x) g^-1. The right side is two products of
 *   elements computed by (R): 4 C_OP u kappa' N(|g| |exp x| |g^-1|), kappa'
 *   the largest kappa of g and exp(x). The left side: y is wrong by the
 *   algebra bound, which (J) carries through exp(y), plus exp's own
 *   C_OP u kappa_y N(exp y). */
static void check_adjoint(void)
{
    tk_check alg = tk_begin("Ad_g x = g x g^-1 (algebra), |D| / N'(|g||x||g^-1|)", 0);
    tk_check grp = tk_begin("exp(Ad_g x) = g exp(x) g^-1 (group), |D| / N", 0);
    for (int i = 0; i < NS; i++) {
        sample *g = &S[i], *x = &S[partner(i, 3)];
        double y[DMAX], ey[GA_GROUP_MAX_ELEM], t[GA_GROUP_MAX_ELEM], r[GA_GROUP_MAX_ELEM];
        G->adjoint(g->e, x->x, y);
        ga_mat4 hx = G->hat(x->x), conj = mmul(mmul(g->m, hx), g->mi);
        ga_mat4 sz = blockmax(mmul(mmul(mabs(g->m), mabs(hx)), mabs(g->mi)));
        add_entrywise(&alg, G->hat(y), conj, mscale(sz, 2 * C_OP * U * g->kappa), sz);
        if (G->exp(y, ey) != GA_OK) {
            tk_add_tol(&grp, INFINITY, 0);
            continue;
        }
        G->compose(g->e, x->e, t);
        G->compose(t, g->ei, r);
        ga_mat4 em = G->to_mat4(ey), rm = G->to_mat4(r);
        double Jy[DMAX * DMAX], b[DMAX];
        jacobian(y, Jy);
        coord_size(mscale(sz, 2 * C_OP * U * g->kappa), b);
        ga_mat4 prod = colmax(mmul(mmul(mabs(g->m), mabs(x->m)), mabs(g->mi)));
        ga_mat4 bound = madd(mscale(prod, 4 * C_OP * U * fmax(g->kappa, x->kappa)),
                             madd(exp_moves(em, Jy, b), mscale(colmax(em), C_OP * U * cond_lin(em))));
        add_entrywise(&grp, em, rm, bound, colmax(rm));
    }
    tk_end(&alg);
    tk_end(&grp);
}

/* dexp against a central difference of g(s) = exp(x + s y), y uniform in
 * [-1, 1]^dim, read as the 4x4 D(s) = g(0)^-1 (g(s) - g(-s)) / (2s) and
 * compared with hat(J_r(x) y), entry by entry.
 *   Truncation: D(s) = hat(J_r y) + a s^2 + O(s^4); a s^2 is estimated from
 *   the difference at 2s, (D(2s) - D(s)) / 3, and allowed twice.
 *   Rounding: by (R) g(+-s) are each wrong by C_OP u kappa N(g(+-s)), so D(s)
 *   by C_OP u kappa |g(0)^-1| (N(g(s)) + N(g(-s))) / (2s); and x +- s y round
 *   by u |x +- s y| per coordinate, which (J) carries to g(+-s), again over
 *   2s. The estimate of a s^2 carries the rounding at s and 2s as well (1.5
 *   times that at s), so the rounding term is allowed 2.5 times.
 *   The step s = 2^-17 ~ u^(1/3) balances s^2 and u/s for y of size 1. */
static void check_dexp(void)
{
    tk_rng *r = &rng;
    tk_check c = tk_begin("dexp = central difference of exp (no log), |D| / N'(J y)", 0);
    const double h = 0x1p-17;
    for (int i = 0; i < NS; i++) {
        sample *s = &S[i];
        double y[DMAX], jy[DMAX];
        for (int k = 0; k < D; k++) y[k] = tk_range(r, -1, 1);
        G->dexp(s->x, y, jy);
        ga_mat4 dd[2], noise;
        int ok = 1;
        for (int q = 0; q < 2 && ok; q++) {
            double step = (q + 1) * h, xp[DMAX], xm[DMAX], xa[DMAX];
            double ep[GA_GROUP_MAX_ELEM], em[GA_GROUP_MAX_ELEM];
            for (int k = 0; k < D; k++) {
                xp[k] = s->x[k] + step * y[k];
                xm[k] = s->x[k] - step * y[k];
                xa[k] = U * fmax(fabs(xp[k]), fabs(xm[k]));
            }
            if (G->exp(xp, ep) != GA_OK || G->exp(xm, em) != GA_OK) {
                ok = 0;
                break;
            }
            ga_mat4 mp = G->to_mat4(ep), mm = G->to_mat4(em), diff;
            for (int k = 0; k < 16; k++) diff.m[k] = (mp.m[k] - mm.m[k]) / (2 * step);
            dd[q] = mmul(s->mi, diff);
            if (q == 0) {
                double kap = fmax(s->kappa, fmax(cond_lin(mp), cond_lin(mm)));
                ga_mat4 rnd = mscale(madd(colmax(mp), colmax(mm)), C_OP * U * kap);
                rnd = madd(rnd, madd(exp_moves(mp, s->J, xa), exp_moves(mm, s->J, xa)));
                noise = mscale(mmul(mabs(s->mi), rnd), 1 / (2 * step));
            }
        }
        if (!ok) {
            tk_add_tol(&c, INFINITY, 0);
            continue;
        }
        ga_mat4 hj = G->hat(jy), bound, n = blockmax(hj);
        for (int k = 0; k < 16; k++) {
            bound.m[k] = 2 * fabs(dd[1].m[k] - dd[0].m[k]) / 3 + 2.5 * noise.m[k];
            if (n.m[k] == 0)
                n.m[k] = mmax(hj);
        }
        add_entrywise(&c, hj, dd[0], bound, n);
    }
    tk_end(&c);
}

static void check_mat4(void)
{
    tk_check rt = tk_begin("to_mat4(from_mat4(to_mat4 g)) = to_mat4 g, |D| / N(g)", 2 * C_OP * U);
    tk_check st = tk_begin("from_mat4 status", 0);
    tk_check rej = tk_begin("from_mat4 rejects last row 0 0 0.5 1, output untouched", 0);
    for (int i = 0; i < NS; i++) {
        sample *s = &S[i];
        double e[GA_GROUP_MAX_ELEM];
        int k = G->from_mat4(s->m, e);
        tk_add_status(&st, k, GA_OK);
        if (k == GA_OK)
            tk_add(&rt, rel_err(G->to_mat4(e), s->m, colmax(s->m)));
        ga_mat4 bad = s->m;
        bad.m[14] = 0.5;
        for (int j = 0; j < GA_GROUP_MAX_ELEM; j++) e[j] = 12345.0;
        k = G->from_mat4(bad, e);
        int untouched = 1;
        for (size_t j = 0; j < G->elem_size / sizeof(double); j++) untouched &= e[j] == 12345.0;
        tk_add_bool(&rej, k != GA_OK && untouched);
    }
    tk_end(&rt);
    tk_end(&st);
    tk_end(&rej);
}

/* vee(hat(x)) = x exactly (hat places each coordinate, and for a twist vee
 * reads (a - (-a))/2 = a); vee rejects a nonzero last row, and for a rigid
 * group a symmetric part of the 3x3 block, with GA_ERR_ARG, output untouched. */
static void check_hat_vee(void)
{
    tk_check rt = tk_begin("vee(hat(x)) = x (exact)", 0);
    tk_check rows = tk_begin("vee rejects a nonzero last row: GA_ERR_ARG, untouched", 0);
    tk_check sym = tk_begin("vee rejects a symmetric 3x3 part: GA_ERR_ARG, untouched", 0);
    for (int i = 0; i < NS; i++) {
        sample *s = &S[i];
        double x[DMAX];
        ga_mat4 h = G->hat(s->x);
        int st = G->vee(h, x);
        double e = st == GA_OK ? 0 : INFINITY;
        for (int k = 0; st == GA_OK && k < D; k++) e = tk_max(e, fabs(x[k] - s->x[k]));
        tk_add(&rt, e);
        for (int k = 12; k < 16; k++) {
            ga_mat4 b = h;
            b.m[k] = k % 2 ? 1e-300 : 1.0;
            for (int j = 0; j < D; j++) x[j] = 777.0;
            st = G->vee(b, x);
            int untouched = 1;
            for (int j = 0; j < D; j++) untouched &= x[j] == 777.0;
            tk_add_status(&rows, untouched ? st : 99, GA_ERR_ARG);
        }
        if (G->rigid) {
            ga_mat4 b = h;
            double d = 1e-6 * fmax(1.0, mmax(h));
            b.m[1] += d; /* a symmetric pair, off the diagonal */
            b.m[4] += d;
            for (int j = 0; j < D; j++) x[j] = 777.0;
            st = G->vee(b, x);
            int untouched = 1;
            for (int j = 0; j < D; j++) untouched &= x[j] == 777.0;
            tk_add_status(&sym, untouched ? st : 99, GA_ERR_ARG);
            b = h;
            b.m[10] += d; /* on the diagonal */
            st = G->vee(b, x);
            tk_add_status(&sym, st, GA_ERR_ARG);
        }
    }
    tk_end(&rt);
    tk_end(&rows);
    if (G->rigid)
        tk_end(&sym);
    else
        tk_note("     (a non-rigid algebra holds symmetric 3x3 parts: not rejected)\n");
}

/* The same group element from two algebra elements x and x2, x2 computed
 * from x by a rule (half_turn, branch): exp(x) and exp(x2) each by (R),
 * C_OP u kappa N, and x2 carries the rounding of its rule, which (J) carries
 * to exp(x2). For a twist the rules scale w by k = |w2| / |w| and v across w
 * by k, a few roundings each of k and of w.v / |w|^2: x2's coordinates are
 * wrong by at most 16 u max(|w|, |w2|) (w) and 16 u max(|v|, |v2|, |k| |v|)
 * (v); for another layout, 16 u max |x| max(1, |x2| / |x|). */
/* |(a0, a1, a2)|, scaled so that no square underflows */
static double norm3(const double *a)
{
    double m = fmax(fabs(a[0]), fmax(fabs(a[1]), fabs(a[2])));
    if (!(m > 0) || isinf(m))
        return m;
    double p = a[0] / m, q = a[1] / m, r = a[2] / m;
    return m * sqrt(p * p + q * q + r * r);
}

static void same_element(const double *x, const double *x2, tk_check *c)
{
    double e1[GA_GROUP_MAX_ELEM], e2[GA_GROUP_MAX_ELEM];
    if (G->exp(x, e1) != GA_OK || G->exp(x2, e2) != GA_OK) {
        tk_add_tol(c, INFINITY, 0);
        return;
    }
    ga_mat4 m1 = G->to_mat4(e1), m2 = G->to_mat4(e2);
    double b[DMAX], J2[DMAX * DMAX];
    if (G->rigid) {
        double w = norm3(x), w2 = norm3(x2), v = 0, v2 = 0;
        for (int k = 0; k < 3; k++) v = fmax(v, fabs(x[3 + k])), v2 = fmax(v2, fabs(x2[3 + k]));
        double k = w > 0 ? w2 / w : 1;
        for (int j = 0; j < 3; j++) b[j] = 16 * U * fmax(w, w2), b[3 + j] = 16 * U * fmax(fmax(v, v2), k * v);
    } else {
        double sx = 0, sx2 = 0;
        for (int k = 0; k < D; k++) sx = fmax(sx, fabs(x[k])), sx2 = fmax(sx2, fabs(x2[k]));
        for (int k = 0; k < D; k++) b[k] = 16 * U * fmax(sx, sx2);
    }
    jacobian(x2, J2);
    ga_mat4 bound = madd(mscale(madd(colmax(m1), colmax(m2)), C_OP * U * fmax(cond_lin(m1), cond_lin(m2))),
                         exp_moves(m2, J2, b));
    add_entrywise(c, m2, m1, bound, colmax(m1));
}

static void check_half_turn_branch(void)
{
    if (!G->half_turn)
        tk_note("     (no half_turn rule: the principal log is unique)\n");
    else {
        tk_check same = tk_begin("half_turn(x): the same element, |D| / bound", 0);
        tk_check idem = tk_begin("half_turn(half_turn(x)) = half_turn(x) (exact)", 0);
        long changed = 0;
        for (int i = 0; i < NS; i++) {
            double x[DMAX], x2[DMAX];
            memcpy(x, S[i].x, sizeof x);
            G->half_turn(x);
            changed += memcmp(x, S[i].x, D * sizeof(double)) != 0;
            same_element(S[i].x, x, &same);
            memcpy(x2, x, sizeof x);
            G->half_turn(x2);
            double e = 0;
            for (int k = 0; k < D; k++) e = tk_max(e, fabs(x2[k] - x[k]));
            tk_add(&idem, e);
        }
        tk_end(&same);
        tk_end(&idem);
        tk_note("     (half_turn changed %ld of %d elements)\n", changed, NS);
    }
    if (!G->branch)
        tk_note("     (no branch rule: one log to offer)\n");
    else {
        tk_check same = tk_begin("branch(prev, x): the same element, |D| / bound", 0);
        tk_check self = tk_begin("branch(x, x) = x (exact)", 0);
        long changed = 0, tries = 0;
        /* prev: another sample, and a sample beyond a half turn (whose
           rotation is the long way round, so that x's other branch is taken
           wherever the group has one) */
        int beyond[MAXS], nb = 0;
        for (int i = 0; i < NS; i++)
            if (S[i].where == BEYOND)
                beyond[nb++] = i;
        for (int i = 0; i < NS; i++) {
            double x[DMAX];
            for (int q = 0; q < (nb ? 2 : 1); q++) {
                memcpy(x, S[i].x, sizeof x);
                G->branch(S[q ? beyond[i % nb] : partner(i, 4)].x, x);
                changed += memcmp(x, S[i].x, D * sizeof(double)) != 0;
                tries++;
                same_element(S[i].x, x, &same);
            }
            memcpy(x, S[i].x, sizeof x);
            G->branch(S[i].x, x);
            double e = 0;
            for (int k = 0; k < D; k++) e = tk_max(e, fabs(x[k] - S[i].x[k]));
            tk_add(&self, e);
        }
        tk_end(&same);
        tk_end(&self);
        tk_note("     (branch changed %ld of %ld elements)\n", changed, tries);
    }
}

/* The group's header, its samples and their status. */
static void samples(void)
{
    tk_note("== group %s (dim %zu, %s)\n", G->name, G->dim, G->rigid ? "rigid" : "not rigid");
    tk_check st = tk_begin("exp and inverse of every sample: status", 0);
    draw_samples(&rng, &st);
    tk_end(&st);
    tk_note("     (%d elements from the families of its algebra; %ld draws outside it)\n", NS, families_out);
}

/* run for each group in turn */
static const tk_section sections[] = {
    {"samples", samples, TK_SETUP},
    {"exp_log", check_exp_log, 0},
    {"inverse", check_inverse, 0},
    {"assoc_identity", check_assoc_identity, 0},
    {"adjoint", check_adjoint, 0},
    {"dexp", check_dexp, 0},
    {"mat4", check_mat4, 0},
    {"hat_vee", check_hat_vee, 0},
    {"half_turn_branch", check_half_turn_branch, 0},
};

int main(int argc, char **argv)
{
    const ga_group *g;
    const char *arg;
    int st = tk_options(argc, argv, "test_group", sections, TK_COUNT(sections), &arg);
    if (st >= 0)
        return st;
    uint64_t seed = arg ? strtoull(arg, NULL, 0) : 0x67726f7570ull; /* "group" */
    for (size_t i = 0; (g = ga_group_nth(i)); i++) {
        rng = (tk_rng){seed + i};
        setup_group(g);
        tk_run(sections, TK_COUNT(sections));
    }
    return tk_done("test_group", sections, TK_COUNT(sections));
}
