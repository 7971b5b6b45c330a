/* bench/floors.h: the floors of garotor-bench, what a user would otherwise
 * write: a dual-quaternion product, a 4x4 matrix on a point, a table-driven
 * dense product (its tables: bench.h, filled by inputs.c), the meet of two
 * objects as the dual-wedge formula (its tables: cases_meet.c).
 *
 * Each floor is plain C written here, static inline, compiled at full strength
 * into its timed loop exactly as a user's own code would be: no call, no
 * by-value struct crossing a library boundary.
 */
#ifndef GAROTOR_BENCH_FLOORS_H
#define GAROTOR_BENCH_FLOORS_H

#include <string.h>

#include "bench.h"

/* the library's outer product by pointer (gak_op_p: ga_mv_op's generated
   straight-line kernel, not exported; the bench links the library's objects) */
#include "../ga/internal/mv_kernels.h"

/* Hamilton's product of quaternions, as in any textbook. */
static inline ga_quat quat_mul(ga_quat a, ga_quat b)
{
    ga_quat r;
    r.w = a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z;
    r.x = a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y;
    r.y = a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x;
    r.z = a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w;
    return r;
}

static inline ga_quat quat_add(ga_quat a, ga_quat b)
{
    ga_quat r = {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    return r;
}

/* (ra + eps da)(rb + eps db) = ra rb + eps (ra db + da rb): 48 multiplications. */
static inline ga_dualquat dualquat_mul(ga_dualquat a, ga_dualquat b)
{
    ga_dualquat r;
    r.real = quat_mul(a.real, b.real);
    r.dual = quat_add(quat_mul(a.real, b.dual), quat_mul(a.dual, b.real));
    return r;
}

/* A rigid-motion matrix applied to a point: 9 multiplications, 9 additions. */
static inline ga_vec3 mat4_apply(const ga_mat4 *m, ga_vec3 x)
{
    const double *a = m->m;
    ga_vec3 r = {a[0] * x.x + a[1] * x.y + a[2] * x.z + a[3], a[4] * x.x + a[5] * x.y + a[6] * x.z + a[7],
                 a[8] * x.x + a[9] * x.y + a[10] * x.z + a[11]};
    return r;
}

/* The table-driven dense product a user writes from a GA textbook: for every
 * pair of blades (i, j), the sign of e_i e_j and the index of its blade, from
 * two 32x32 tables filled once (by ga_blade_mask and the swap-counting rule),
 * then two nested loops. */
static inline void gp_table(const ga_mv *a, const ga_mv *b, ga_mv *r)
{
    double acc[32] = {0};
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++) acc[gp_index[i][j]] += gp_sign[i][j] * (a->c[i] * b->c[j]);
    memcpy(r->c, acc, sizeof acc);
}

/* The meet of two objects as a user writes it from the textbook formula,
 * meet = (A* ^ B*)*, i.e. undual(op(dual A, dual B)) (DFM §5.5, clifford's
 * meet, ganja's dual wedge): the dual A I^-1 and the undual A I as the
 * signed permutations of the coefficients they are (blade i goes to blade
 * 31 - i; the signs written out, checked against ga_mv_dual and
 * ga_mv_undual by meet_check_dual), the outer product by the library's
 * generated dense kernel. No decision, one rounding per term: in general
 * position the meet ga_mv_meet returns, to the rounding of the sums. */
static const double dual_sign[32] = {-1, -1, 1,  -1, 1, 1,  1,  -1, 1, 1,  1,  -1, -1, 1,  1, -1,
                                     1,  -1, -1, 1,  1, -1, -1, -1, 1, -1, -1, -1, 1,  -1, 1, 1};
static inline void meet_floor(const ga_mv *a, const ga_mv *b, ga_mv *r)
{
    ga_mv da, db, w;
    for (int i = 0; i < 32; i++) {
        da.c[31 - i] = dual_sign[i] * a->c[i];
        db.c[31 - i] = dual_sign[i] * b->c[i];
    }
    gak_op_p(&da, &db, &w);
    for (int i = 0; i < 32; i++) r->c[31 - i] = -dual_sign[i] * w.c[i]; /* undual = -dual */
}

#endif
