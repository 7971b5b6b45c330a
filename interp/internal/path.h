/* interp/internal/path.h (internal, not installed): what the files of interp/
 * share about a path (include/garotor/path.h): where a segment's knots and
 * coefficients are, the factor polynomials of the product forms, small
 * vector helpers, and the entry points of each scheme and evaluator file.
 * Prefix gip_ (garotor interp path); nothing here is exported.
 */
#ifndef GA_INTERP_INTERNAL_PATH_H
#define GA_INTERP_INTERNAL_PATH_H

#include <math.h>
#include <string.h>

#include <garotor/mat4.h>
#include <garotor/path.h>

#include "group_fast.h"

#define GIP_MAXD GA_GROUP_MAX_DIM
#define GIP_MAXE GA_GROUP_MAX_ELEM

/* The exponent polynomials p_j(u) = c0 + c1 u + c2 u^2 + c3 u^3 of the
 * factors exp(p_j(u) X_j). Li-Hao: u (eq. 9), u^2 (eq. 14), u^3 - u^2
 * (eq. 21); factor j has degree j + 1. BSPLINE: the cumulative cubic basis
 * (path.h), each of degree 3. */
static inline const double *gip_fac_poly(ga_scheme s, size_t j)
{
    static const double lihao_poly[3][4] = {{0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, -1, 1}};
    static const double bspline_poly[3][4] = {
        {5.0 / 6, 0.5, -0.5, 1.0 / 6}, {1.0 / 6, 0.5, 0.5, -1.0 / 3}, {0, 0, 0, 1.0 / 6}};
    return s == GA_SCHEME_BSPLINE ? bspline_poly[j] : lihao_poly[j];
}
static inline size_t gip_fac_deg(ga_scheme s, size_t j) { return s == GA_SCHEME_BSPLINE ? 3 : j + 1; }

static inline size_t gip_nfac(ga_scheme s)
{
    return s == GA_SCHEME_SCREW                            ? 1
         : s == GA_SCHEME_LIHAO2                           ? 2
         : s == GA_SCHEME_LIHAO3 || s == GA_SCHEME_BSPLINE ? 3
                                                           : 0;
}

/* The order-m forward difference of p with step d at u (m = 0: p(u) itself),
 * expanded so that no difference of nearby values is formed. */
static inline double gip_poly_diff(const double *c, size_t m, double u, double d)
{
    switch (m) {
    case 0: return c[0] + u * (c[1] + u * (c[2] + u * c[3]));
    case 1: return c[1] * d + c[2] * d * (2 * u + d) + c[3] * d * (3 * u * u + 3 * u * d + d * d);
    case 2: return c[2] * 2 * d * d + c[3] * 6 * d * d * (u + d);
    default: return c[3] * 6 * d * d * d;
    }
}

static inline double gip_poly_deriv(const double *c, double u)
{
    return c[1] + u * (2 * c[2] + 3 * u * c[3]);
}
static inline double gip_poly_deriv2(const double *c, double u) { return 2 * c[2] + 6 * c[3] * u; }

static inline double *gip_key_of(const ga_path *p, size_t i) { return p->key + i * p->key_stride; }
/* Segment i runs from knot i to knot i + 1: the key times, except BSPLINE,
 * whose segment i is [t_{i+1}, t_{i+2}] (path.h). */
static inline size_t gip_knot_off(const ga_path *p) { return p->scheme == GA_SCHEME_BSPLINE && p->n > 1; }
static inline double gip_knot(const ga_path *p, size_t i) { return p->t[i + gip_knot_off(p)]; }
static inline size_t gip_nseg(const ga_path *p) { return p->n > 1 ? p->n - 1 - 2 * gip_knot_off(p) : 0; }
static inline double gip_seg_len(const ga_path *p, size_t i) { return gip_knot(p, i + 1) - gip_knot(p, i); }
/* X_1 of segment seg; X_2, X_3 follow at strides of dim. Li-Hao: B, C, D per
 * segment; BSPLINE: the n - 1 relative logs d_i, shared by the segments. */
static inline const double *gip_seg_coef(const ga_path *p, size_t seg)
{
    return p->coef + seg * (p->scheme == GA_SCHEME_BSPLINE ? 1 : gip_nfac(p->scheme)) * p->group->dim;
}

/* Element sizes of 8 and 16 doubles (a rotor, a 4x4 matrix) get a memcpy of
 * constant size, which the compiler turns into a few moves, not a call. */
static inline void gip_copy_elem(const ga_group *g, void *dst, const void *src)
{
    if (g->elem_size == 8 * sizeof(double))
        memcpy(dst, src, 8 * sizeof(double));
    else if (g->elem_size == 16 * sizeof(double))
        memcpy(dst, src, 16 * sizeof(double));
    else
        memcpy(dst, src, g->elem_size);
}

static inline void gip_lin(size_t d, double *out, double s, const double *a, double r, const double *b)
{
    for (size_t k = 0; k < d; ++k) out[k] = s * a[k] + r * b[k];
}

static inline int gip_allfinite(const double *x, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

/* Results are checked before they are handed out: finite input can still
 * overflow on the way (a velocity divided by a subnormal segment length, a
 * lihao2 velocity scaled by a ratio h_{i+1}/h_i near DBL_MAX, products of
 * keys near DBL_MAX), and a result that is not finite is GA_ERR_DOMAIN, never
 * GA_OK with Inf or NaN (docs/errors.md). */
static inline int gip_finite_elem(const ga_group *g, const void *x)
{
    return gip_allfinite(x, g->elem_size / sizeof(double)) ? GA_OK : GA_ERR_DOMAIN;
}

/* ---- path.c: the core ----------------------------------------------------------- */

/* The principal log, made deterministic at half turns (group.h half_turn). */
int gip_plog(const ga_group *g, const void *a, double *x);
/* rel = a^-1 b; exactly the identity where a and b are the same bits */
int gip_rel(const ga_group *g, const void *a, const void *b, void *rel);
/* x = plog(a^-1 b) (exactly 0 where a and b are the same bits); rel receives a^-1 b */
int gip_rel_log(const ga_group *g, const void *a, const void *b, double *x, double *rel);
/* Doubles of the scheme's block in the workspace for N keys of algebra dimension D. */
size_t gip_scheme_doubles(ga_scheme s, size_t N, size_t D);
static inline int gip_is_decoupled(ga_scheme s)
{
    return s == GA_SCHEME_DECOUPLED || s == GA_SCHEME_DECOUPLED_C2;
}

/* ---- the schemes: building (GA_OK or a status) and their curves --------------------- */

/* scheme_screw.c: SCREW and BSPLINE, the relative logs of neighbouring keys */
int gip_build_screw(ga_path *p);
/* scheme_lihao.c: LIHAO2 and LIHAO3 */
int gip_build_lihao(ga_path *p, const double *vel);
int gip_lihao_segment(ga_path *p, size_t i);
/* scheme_generator.c: BIVECTOR, QUADRATIC, SMOOTH */
int gip_build_generators(ga_path *p);
void gip_build_smooth(ga_path *p);
void gip_gen_curve(const ga_path *p, size_t j, double u, double *x, double *xd);
void gip_gen_curve2(const ga_path *p, size_t j, double u, double *xdd);
/* scheme_decoupled.c: DECOUPLED and DECOUPLED_C2 */
size_t gip_dec_doubles(size_t N);
int gip_build_decoupled(ga_path *p);
int gip_dec_append(ga_path *q, size_t i, const void *key);
int gip_dec_eval(const ga_path *p, size_t seg, double u, void *out, double *v, double *a, double *j,
                 double *pw);
/* DECOUPLED's pose at (seg, u) from its segment's GIP_DEC_CONST constants,
   made by gip_dec_prep; GA_OK or GA_ERR_DOMAIN where it is not finite */
#define GIP_DEC_CONST 16
void gip_dec_prep(const ga_path *p, size_t seg, double *c);
int gip_dec_at(const ga_path *p, const double *c, double u, void *out);
/* scheme_c2.c: C2 */
int gip_build_c2(ga_path *p);
void gip_c2_curve(const ga_path *p, size_t seg, double u, double *x, double *xd, double *xdd, double *xddd);

/* ---- c2_solve.c: the C2 system of key velocities ------------------------------------ */

typedef struct {
    ga_path *p;
    size_t d;
    const double *(*theta)(const ga_path *p, size_t seg); /* theta_i */
    double *(*rate)(const ga_path *p, size_t key);        /* w_i */
    double *(*scratch)(const ga_path *p, size_t key);     /* d*d + d doubles */
    /* m = the d x d matrix of J_r(th) (inv = 0) or of J_r(th)^-1 (inv = 1) */
    int (*jr)(const ga_path *p, const double *th, int inv, double *m);
    /* o = N(th, y) */
    int (*nonlin)(const ga_path *p, const double *th, const double *y, double *o);
    /* the interior rates set to where the sweeps start */
    void (*start)(ga_path *p);
    /* NULL, or d*d doubles per segment: J_r(theta_i), filled once by
       gip_c2_solve and read by every sweep, which inverts it by jinv */
    double *(*jcache)(const ga_path *p, size_t seg);
    int (*jinv)(size_t d, const double *J, double *o);
} gip_c2_sys;

int gip_c2_solve(const gip_c2_sys *s);
/* d x d matrices (d <= GIP_MAXD, row-major): o = a b, o = a x, o = a^-1
 * (GA_ERR_DOMAIN where a is singular to working precision or not finite) */
void gip_md_mul(size_t d, const double *a, const double *b, double *o);
void gip_md_vec(size_t d, const double *a, const double *x, double *o);
int gip_md_inv(size_t d, const double *a, double *o);

/* ---- jet.c: Lie brackets and derivatives of exp through 4x4 jets -------------------- */

int gip_bracket(const ga_group *g, const double *x, const double *y, double *out);
int gip_exp_curve_deriv(const ga_group *g, const double *x, const double *xd, const double *xdd, double *v,
                        double *a);
/* The body velocity (group.h dexp; may be NULL), acceleration (m >= 2) and
 * jerk (m = 3) of exp(X(t)), x[k] the k-th derivative of X (k <= 3, each
 * given): the rigid groups in closed form (twist_deriv.c), the others by the
 * 4x4 jet; a and j may be NULL. */
int gip_exp_curve_jet(const ga_group *g, const double *const *x, int m, double *v, double *a, double *j);

/* ---- twist_deriv.c: the same on the rigid groups, in closed form -------------------- */

/* x[0..m] the derivatives of a twist curve X(t) (1 <= m <= 3); v, a (m >= 2),
 * j (m = 3): the body velocity, acceleration and jerk of exp(X(t)); each
 * may be NULL. */
void gip_twist_exp_derivs(const double *const *x, int m, double *v, double *a, double *j);

/* ---- scheme_lihao.c: the product forms A_i exp(p_1(u) X_1) exp(p_2(u) X_2) ... ------
 * (SCREW, LIHAO2, LIHAO3, BSPLINE) at u: pose, body velocity per unit u, and
 * with it the body acceleration and jerk per unit u^2, u^3 (m = 2, 3) */
int gip_prod_eval(const ga_path *p, size_t seg, double u, void *out);
int gip_prod_velocity(const ga_path *p, size_t seg, double u, double *v);
int gip_prod_derivs(const ga_path *p, size_t seg, double u, int m, double *v, double *a, double *j);

/* ---- eval.c ------------------------------------------------------------------------- */

/* DIRECT at (seg, u): at a key time the key itself */
int gip_eval_direct(const ga_path *p, size_t seg, double u, void *out);
/* body velocity per unit u on segment seg */
int gip_velocity_u(const ga_path *p, size_t seg, double u, double *v);

/* ---- the group's fast screw sampler (internal/group_fast.h) ------------------------- */

/* The group's fast operations when p is a SCREW path of at least two keys
 * on a group that has a screw sampler, else NULL. Inline: the samplers ask
 * for every sample. */
static inline const gai_group_fast *gip_screw_fast(const ga_path *p)
{
    if (p->scheme != GA_SCHEME_SCREW || p->n < 2)
        return NULL;
    const gai_group_fast *f = gai_group_fast_of(p->group);
    return f && f->screw_prep && f->screw_at && f->screw_step ? f : NULL;
}
/* scheme_screw.c: A_i exp(u B) on segment seg by the group's screw sampler */
int gip_screw_eval(const ga_path *p, const gai_group_fast *f, size_t seg, double u, void *out);

#endif
