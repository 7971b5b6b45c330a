/* bench/cases_meet.c: the object layer's meets in garotor-bench: ga_mv_meet
 * of the common pairs (two planes, a line and a plane, two spheres, a plane
 * and a sphere), ga_mv_meet_rel of the same pairs, and ga_object_from_mv of
 * the meets, against the floor meet_floor (floors.h: the dual-wedge formula
 * undual(op(dual A, dual B)) with the library's generated outer product) on
 * the same pairs (docs/benchmarks.md, "The meets of the object layer"). The
 * pairs are drawn by inputs.c.
 */
#include "floors.h"

const int meet_pair_kind[N_MEET_PAIRS] = {GA_OBJECT_LINE, GA_OBJECT_FLATPOINT, GA_OBJECT_CIRCLE,
                                          GA_OBJECT_CIRCLE};
const int meet_pair_ix[N_MEET_PAIRS] = {MP_PLANE_PLANE, MP_LINE_PLANE, MP_SPHERE_SPHERE, MP_PLANE_SPHERE};

ga_mv meet_a[N_MEET_PAIRS][RING], meet_b[N_MEET_PAIRS][RING], meet_w[N_MEET_PAIRS][RING];
static ga_mv meet_out[RING];
static ga_object meet_obj[RING];
static size_t meet_cursor; /* where the next batch continues in the rings */

int meet_check_dual(void)
{
    for (int i = 0; i < 32; i++) {
        ga_mv d = ga_mv_dual(ga_mv_blade(i)), u = ga_mv_undual(ga_mv_blade(i));
        for (int k = 0; k < 32; k++)
            if (d.c[k] != (k == 31 - i ? dual_sign[i] : 0.0) || u.c[k] != (k == 31 - i ? -dual_sign[i] : 0.0))
                return GA_ERR_ARG;
    }
    return GA_OK;
}

/* One loop shape for all: call i takes slot j of pair p's rings (ctx: the
   pair), BODY writes slot j of the output, the last output goes to the sink. */
#define MEET_LOOP(name, BODY, LAST)                                                                          \
    size_t name(const void *ctx, size_t n)                                                                   \
    {                                                                                                        \
        const int p = *(const int *)ctx;                                                                     \
        const ga_mv *A = meet_a[p], *B = meet_b[p], *W = meet_w[p];                                          \
        (void)A, (void)B, (void)W;                                                                           \
        size_t k = meet_cursor;                                                                              \
        int st = 0;                                                                                          \
        for (size_t i = 0; i < n; i++, k++) {                                                                \
            size_t j = k & MASK;                                                                             \
            BODY;                                                                                            \
        }                                                                                                    \
        meet_cursor = k;                                                                                     \
        status_or |= st;                                                                                     \
        size_t last = (k - 1) & MASK;                                                                        \
        sink = (LAST);                                                                                       \
        return n;                                                                                            \
    }

/* ga_mv_meet: the meet, exact to its rounding, and its decision "special
   position" */
MEET_LOOP(run_meet, meet_out[j] = ga_mv_meet(A[j], B[j]), meet_out[last].c[31] + meet_out[last].c[16])
/* the floor: undual(op(dual A, dual B)), inline, the generated outer product */
MEET_LOOP(run_meet_floor, meet_floor(&A[j], &B[j], &meet_out[j]), meet_out[last].c[31] + meet_out[last].c[16])
/* the same formula as the library's one generated kernel (ga_mv_regressive) */
MEET_LOOP(run_meet_regressive, meet_out[j] = ga_mv_regressive(A[j], B[j]),
          meet_out[last].c[31] + meet_out[last].c[16])
/* the same formula through the library's symbols, as first written: each
   ga_mv_dual and ga_mv_undual a geometric product by I */
MEET_LOOP(run_meet_by_symbols, meet_out[j] = ga_mv_undual(ga_mv_op(ga_mv_dual(A[j]), ga_mv_dual(B[j]))),
          meet_out[last].c[31] + meet_out[last].c[16])
/* ga_mv_meet_rel: the join decides the whole space, then ga_mv_meet */
MEET_LOOP(run_meet_rel, st |= ga_mv_meet_rel(A[j], B[j], &meet_out[j]),
          meet_out[last].c[31] + meet_out[last].c[16])
/* ga_object_from_mv of the meet (computed by inputs.c) */
MEET_LOOP(run_meet_read, st |= ga_object_from_mv(W[j], &meet_obj[j]),
          meet_obj[last].centre.x + meet_obj[last].r2)
