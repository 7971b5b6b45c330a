/* interp/group_cga.c: ga_group_cga, CGA rotors (ga_rotor) with
 * Wareham-Lasenby's closed forms (rotor.h); an algebra element is a twist,
 * carried to the generator B(xi) = -(w I3 + v n)/2 and back
 * (docs/conventions.md). Also its fast screw sampler
 * (internal/group_fast.h).
 */
#include <math.h>
#include <string.h>

#include <garotor/group.h>
#include <garotor/rotor.h>
#include <garotor/rotor_inline.h>

/* the series of ga_rotor_exp, for the screw sampler */
#include "ga/internal/series.h"
#include "ga/internal/vec3.h"
#include "internal/groups.h"

static void cga_identity(void *out) { *(ga_rotor *)out = ga_rotor_identity(); }
static void cga_compose(const void *a, const void *b, void *out)
{
    *(ga_rotor *)out = ga_rotor_mul(*(const ga_rotor *)a, *(const ga_rotor *)b);
}
static int cga_inverse(const void *a, void *out)
{
    *(ga_rotor *)out = ga_rotor_reverse(*(const ga_rotor *)a);
    return GA_OK;
}
static int cga_exp(const double *x, void *out)
{
    /* B(xi) = -(w I3 + v n)/2 (ga_twist_to_generator), read from x in place */
    ga_generator b = {-0.5 * x[2], 0.5 * x[1], -0.5 * x[0], -0.5 * x[3], -0.5 * x[4], -0.5 * x[5]};
    ga_rotor r = ga_rotor_exp(b);
    int st = gig_finite_status(x, 6, &r.s, 8);
    if (st == GA_OK)
        *(ga_rotor *)out = r;
    return st;
}
static int cga_log(const void *g, double *x)
{
    ga_generator b;
    int st = ga_rotor_log(*(const ga_rotor *)g, &b);
    if (st != GA_OK)
        return st;
    ga_twist t = ga_generator_to_twist(b);
    st = gig_finite_status(NULL, 0, &t.w.x, 6);
    if (st == GA_OK)
        gig_twist_put(t, x);
    return st;
}
/* Ad_R B = R B ~R, computed in the compact 8-component form, which is closed
 * under the product for any q, P (rotor.h); B sits in its bivector slots. */
static void cga_adjoint(const void *g, const double *x, double *out)
{
    ga_rotor r = *(const ga_rotor *)g;
    ga_generator b = ga_twist_to_generator(gig_twist_of(x));
    ga_rotor bb = {0.0, b.e12, b.e13, b.e23, b.e1n, b.e2n, b.e3n, 0.0};
    ga_rotor s = ga_rotor_mul(ga_rotor_mul(r, bb), ga_rotor_reverse(r));
    ga_generator o = {s.e12, s.e13, s.e23, s.e1n, s.e2n, s.e3n};
    gig_twist_put(ga_generator_to_twist(o), out);
}
/* (quaternion, translation) of a rotor: r = T_t q (rotor.h) */
static void cga_to_qt(const void *g, double q[4], double p[3])
{
    ga_rotor r = *(const ga_rotor *)g;
    ga_quat a = ga_rotor_to_quat(r);
    ga_vec3 t = ga_rotor_to_translation(r);
    q[0] = a.w;
    q[1] = a.x;
    q[2] = a.y;
    q[3] = a.z;
    p[0] = t.x;
    p[1] = t.y;
    p[2] = t.z;
}
/* ga_rotor_from_quat_inline's terms, written to out in place (no ga_rotor
   built on the stack and copied: the decoupled samplers call it per pose) */
static void cga_from_qt(const double q[4], const double p[3], void *res)
{
    double *out = res, bx = -q[1], by = -q[2], bz = -q[3];
    out[0] = q[0];
    out[1] = bz;
    out[2] = -by;
    out[3] = bx;
    out[4] = 0.5 * ((p[1] * bz - p[2] * by) - q[0] * p[0]);
    out[5] = 0.5 * ((p[2] * bx - p[0] * bz) - q[0] * p[1]);
    out[6] = 0.5 * ((p[0] * by - p[1] * bx) - q[0] * p[2]);
    out[7] = -0.5 * (p[0] * bx + p[1] * by + p[2] * bz);
}
static int cga_from_mat4(ga_mat4 m, void *out) { return ga_rotor_from_mat4(m, (ga_rotor *)out); }
static ga_mat4 cga_to_mat4(const void *g) { return ga_rotor_to_mat4(*(const ga_rotor *)g); }

const ga_group ga_group_cga = {
    .name = "cga",
    .elem_size = sizeof(ga_rotor),
    .dim = 6,
    .rigid = 1,
    .identity = cga_identity,
    .compose = cga_compose,
    .inverse = cga_inverse,
    .exp = cga_exp,
    .log = cga_log,
    .adjoint = cga_adjoint,
    .dexp = gig_se3_dexp,
    .from_mat4 = cga_from_mat4,
    .to_mat4 = cga_to_mat4,
    .hat = gig_twist_hat,
    .vee = gig_twist_vee,
    .half_turn = gig_twist_half_turn,
    .branch = gig_twist_branch,
    .to_qt = cga_to_qt,
    .from_qt = cga_from_qt,
};

/* ---- the screw sampler (internal/group_fast.h): four fixed rotors ------------------
 * On the cga group a screw segment is A_i exp(u B), B = -(w I3 + v n)/2 the
 * generator of its twist X = (w, v) (cga_exp above). With beta = -w/2,
 * c = -v/2 (as vectors, rotor.h), phi = |beta| and a = u phi, ga_rotor_exp's
 * closed form of exp(u B) is
 *   cos a + u sinc a (beta + c n) + u^2 sinc a (beta.c) I n + u^3 k(a) (beta.c) beta n,
 * sinc a = sin(a)/a, k(a) = (cos a - sinc a)/a^2, the bivector beta and the
 * vector c written into a rotor as rotor.c's rotor_make does: linear in four
 * rotors E_0 = 1, E_1, E_2, E_3 that are fixed on the segment, with
 * coefficients that depend on u alone. So A_i exp(u B) = sum_j f_j(u) (A_i E_j):
 * the three products A_i E_j once per segment (screw_prep), then per sample
 * the three functions of a, by ga_rotor_exp's series and branches, and 32
 * multiply-adds (screw_at), not an exp and a 48-multiplication product
 * through the group's function pointers. It is the same closed form as
 * ga_rotor_mul(A_i, ga_rotor_exp(u B)), rounded in another order. */

/* k01 = A_i E_0 | A_i E_1, k23 = A_i E_2 | A_i E_3 (8 doubles each), *phi2 = |beta|^2. */
static void screw_prep(const void *key, const double *x, double *k01, double *k23, double *phi2)
{
    double bx = -0.5 * x[0], by = -0.5 * x[1], bz = -0.5 * x[2];
    double cx = -0.5 * x[3], cy = -0.5 * x[4], cz = -0.5 * x[5];
    double bc = bx * cx + by * cy + bz * cz;
    ga_rotor a, e1 = {0, bz, -by, bx, cx, cy, cz, 0}, e2 = {0, 0, 0, 0, 0, 0, 0, bc},
                e3 = {0, 0, 0, 0, bc * bx, bc * by, bc * bz, 0};
    memcpy(&a, key, sizeof a);
    ga_rotor r1 = ga_rotor_mul_inline(a, e1), r2 = ga_rotor_mul_inline(a, e2),
             r3 = ga_rotor_mul_inline(a, e3);
    memcpy(k01, &a, sizeof a);
    memcpy(k01 + 8, &r1, sizeof r1);
    memcpy(k23, &r2, sizeof r2);
    memcpy(k23 + 8, &r3, sizeof r3);
    *phi2 = bx * bx + by * by + bz * bz;
}

/* A_i exp(u B) from screw_prep's rotors and |beta|^2; GA_ERR_DOMAIN where it is not finite
 * (an extrapolation far outside [0, 1]). */
static int screw_at(const double *k01, const double *k23, const double *phi2p, double u, void *res)
{
    double phi2 = *phi2p, *out = res;
    double a2 = (u * u) * phi2, cs, sinc, f3;
    if (a2 <= (GA_PI / 4) * (GA_PI / 4)) {
        double y2 = a2 * a2, y4 = y2 * y2, y8 = y4 * y4;
        cs = ga__series_estrin9(GA__SERIES_F0, a2, y2, y4, y8);
        sinc = ga__series_estrin9(GA__SERIES_F1, a2, y2, y4, y8);
        f3 = u * (u * (u * ga__series_estrin9(GA__SERIES_K, a2, y2, y4, y8)));
    } else {
        double a = sqrt(a2);
        if (a <= 3 * GA_PI / 4) { /* as ga_rotor_exp: r = pi/2 - a, sin a = cos r, cos a = r sinc r */
            double r = (GA_PIO2_HI - a) + GA_PIO2_LO, y = r * r, y2 = y * y, y4 = y2 * y2, y8 = y4 * y4;
            cs = r * ga__series_estrin9(GA__SERIES_F1, y, y2, y4, y8);
            sinc = ga__series_estrin9(GA__SERIES_F0, y, y2, y4, y8) / a;
        } else {
            cs = cos(a);
            sinc = sin(a) / a;
        }
        f3 = u * ((cs - sinc) / phi2); /* u^3 k(a); phi2 > 0 here */
    }
    double f1 = u * sinc, f2 = u * f1, z = 0.0;
    for (int i = 0; i < 8; ++i) {
        out[i] = (cs * k01[i] + f1 * k01[8 + i]) + (f2 * k23[i] + f3 * k23[8 + i]);
        z += out[i] - out[i]; /* 0 for finite, NaN for Inf and NaN */
    }
    return z == 0.0 ? GA_OK : GA_ERR_DOMAIN;
}

/* a = a e by the inline product (ga_rotor_mul's bits, without passing the
 * rotors by value through a call), and out = a. The running rotor a is the
 * chain from one sample to the next: it is read and written here one double
 * at a time, and the finiteness test reads the registers. Built with
 * -march=native, gcc otherwise packed the eight results into one 512-bit
 * store (struct copies, the SLP and loop vectorizers) that the next step's
 * scalar loads of a, and the test's wide load of scalar stores, could not
 * take from the store buffer: sample_exact 1.35 times slower than the
 * baseline build. The same operations in the same order: the same bits. */
#if defined(__GNUC__) && !defined(__clang__)
#define GIG_SCALAR_CHAIN __attribute__((optimize("no-tree-slp-vectorize", "no-tree-loop-vectorize")))
#else
#define GIG_SCALAR_CHAIN
#endif
GIG_SCALAR_CHAIN static int screw_step(void *a, const void *e, void *res)
{
    double *ap = a, *out = res;
    const double *ep = e;
    ga_rotor x = {ap[0], ap[1], ap[2], ap[3], ap[4], ap[5], ap[6], ap[7]};
    ga_rotor y = {ep[0], ep[1], ep[2], ep[3], ep[4], ep[5], ep[6], ep[7]};
    x = ga_rotor_mul_inline(x, y);
    const double v[8] = {x.s, x.e12, x.e13, x.e23, x.e1n, x.e2n, x.e3n, x.e123n};
    double z = 0.0;
    for (int i = 0; i < 8; ++i) {
        ap[i] = v[i];
        out[i] = v[i];
        z += v[i] - v[i]; /* 0 for finite, NaN for Inf and NaN */
    }
    return z == 0.0 ? GA_OK : GA_ERR_DOMAIN;
}

const gai_group_fast gig_cga_fast = {
    .screw_prep = screw_prep,
    .screw_at = screw_at,
    .screw_step = screw_step,
};
