/* bench/checks.c: do the figures of garotor-bench compute what they claim?
 * Each cross-check is the largest entry difference over the ring between two
 * routes to the same result; the paths' Euler and exact samples against the
 * closed form.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "floors.h"

double maxdiff(const double *a, const double *b, int n)
{
    double w = 0.0;
    for (int i = 0; i < n; i++) w = fmax(w, fabs(a[i] - b[i]));
    return w;
}

/* The largest entry difference between the 4x4 matrices of two sample arrays. */
static double samples_maxdiff(const ga_group *g, const double *a, const double *b, size_t n)
{
    double worst = 0.0;
    for (size_t k = 0; k < n; k++) {
        ga_mat4 ma = g->to_mat4((const unsigned char *)a + k * g->elem_size);
        ga_mat4 mb = g->to_mat4((const unsigned char *)b + k * g->elem_size);
        for (int i = 0; i < 16; i++) worst = fmax(worst, fabs(ma.m[i] - mb.m[i]));
    }
    return worst;
}

/* The largest error of Euler and exact samples against the closed form, over
 * all N_PATHS paths of a kind. */
void path_errors(int kind, double *euler_max, double *exact_max)
{
    const ga_group *g = path_kind[kind].group;
    size_t doubles = (size_t)N_SAMPLES * GA_GROUP_MAX_ELEM;
    double *direct = malloc(doubles * sizeof(double));
    double *other = malloc(doubles * sizeof(double));
    *euler_max = *exact_max = NAN;
    if (!direct || !other) {
        free(direct);
        free(other);
        return;
    }
    double eu = 0.0, ex = 0.0;
    int st = 0;
    for (int p = 0; p < N_PATHS; p++) {
        const ga_path *path = &paths[kind][p];
        st |= ga_path_sample_uniform(path, GA_EVAL_DIRECT, EULER_STEP, N_SAMPLES, 0.0, N_KEYS - 1.0, direct);
        st |= ga_path_sample_uniform(path, GA_EVAL_EULER, EULER_STEP, N_SAMPLES, 0.0, N_KEYS - 1.0, other);
        eu = fmax(eu, samples_maxdiff(g, direct, other, N_SAMPLES));
        st |= ga_path_sample_uniform(path, GA_EVAL_EXACT, EULER_STEP, N_SAMPLES, 0.0, N_KEYS - 1.0, other);
        ex = fmax(ex, samples_maxdiff(g, direct, other, N_SAMPLES));
    }
    if (st == GA_OK) {
        *euler_max = eu;
        *exact_max = ex;
    }
    free(direct);
    free(other);
}

checks run_checks(void)
{
    checks c;
    memset(&c, 0, sizeof c);
    c.eigen_expm_vs_se3 = c.eigen_logm_vs_se3 = NAN;
    c.eigen_expm_general = c.eigen_logm_general = NAN;
#ifdef GAROTOR_BENCH_EIGEN
    c.eigen_expm_vs_se3 = c.eigen_logm_vs_se3 = 0.0;
    c.eigen_expm_general = c.eigen_logm_general = 0.0;
#endif
    int bad = 0; /* a status other than GA_OK in the cross-checks */
    for (int j = 0; j < RING; j++) {
        ga_dualquat d1 = ga_rotor_to_dualquat(ga_rotor_mul(rot_a[j], rot_b[j]));
        ga_dualquat d2 = dualquat_mul(dq_a[j], dq_b[j]);
        c.dualquat_vs_motor = fmax(c.dualquat_vs_motor, maxdiff(&d1.real.w, &d2.real.w, 4));
        c.dualquat_vs_motor = fmax(c.dualquat_vs_motor, maxdiff(&d1.dual.w, &d2.dual.w, 4));
        ga_mv g1 = ga_mv_gp(mv_a[j], mv_b[j]), g2;
        gp_table(&mv_a[j], &mv_b[j], &g2);
        c.gp_vs_table = fmax(c.gp_vs_table, maxdiff(g1.c, g2.c, 32));

        ga_vec3 y1 = ga_rotor_apply(rot_a[j], pts[j]), y2 = mat4_apply(&rigid_a[j], pts[j]);
        ga_vec3 y3;
        bad |= ga_point_down(ga_rotor_apply_mv(rot_a[j], ga_point_up(pts[j])), &y3);
        c.apply_vs_matrix = fmax(c.apply_vs_matrix, maxdiff(&y1.x, &y2.x, 3));
        c.apply_vs_sandwich = fmax(c.apply_vs_sandwich, maxdiff(&y1.x, &y3.x, 3));

        ga_mat4 e1 = ga_rotor_to_mat4(ga_rotor_exp(gens[j])), e2 = ga_se3_exp(twists[j]), e3;
        c.exp_vs_se3 = fmax(c.exp_vs_se3, maxdiff(e1.m, e2.m, 16));
        ga_generator g;
        ga_twist t1, t2;
        bad |= ga_rotor_log(rot_a[j], &g);
        t1 = ga_generator_to_twist(g);
        bad |= ga_se3_log(rigid_a[j], &t2);
        c.log_vs_se3 = fmax(c.log_vs_se3, maxdiff(&t1.w.x, &t2.w.x, 6));
        bad |= ga_mat4_expm(hats[j], &e3);
        c.expm_vs_se3 = fmax(c.expm_vs_se3, maxdiff(e3.m, e2.m, 16));
        ga_mat4 lh = ga_twist_hat(t2), l3;
        bad |= ga_mat4_logm(rigid_a[j], &l3);
        c.logm_vs_se3 = fmax(c.logm_vs_se3, maxdiff(l3.m, lh.m, 16));
#ifdef GAROTOR_BENCH_EIGEN
        ga_mat4 m;
        garotor_eigen_expm(hats[j].m, m.m);
        c.eigen_expm_vs_se3 = fmax(c.eigen_expm_vs_se3, maxdiff(m.m, e2.m, 16));
        garotor_eigen_logm(rigid_a[j].m, m.m);
        c.eigen_logm_vs_se3 = fmax(c.eigen_logm_vs_se3, maxdiff(m.m, lh.m, 16));
        garotor_eigen_expm(gen_x[j].m, m.m);
        c.eigen_expm_general = fmax(c.eigen_expm_general, maxdiff(m.m, gen_m[j].m, 16));
        garotor_eigen_logm(gen_m[j].m, m.m);
        c.eigen_logm_general = fmax(c.eigen_logm_general, maxdiff(m.m, gen_x[j].m, 16));
#endif
    }
    /* the meets: ga_mv_meet against the floor (the same formula, the exact
       product against one rounding per term: within the floor's rounding),
       ga_mv_meet_rel against ga_mv_meet (bit for bit in general position,
       object.h), and the read-back of every meet of the pair's kind */
    for (int p = 0; p < N_MEET_PAIRS; p++)
        for (int j = 0; j < RING; j++) {
            ga_mv w = ga_mv_meet(meet_a[p][j], meet_b[p][j]), f, r;
            meet_floor(&meet_a[p][j], &meet_b[p][j], &f);
            double s = ga_mv_maxabs(w);
            c.meet_vs_floor = fmax(c.meet_vs_floor, maxdiff(w.c, f.c, 32) / s);
            if (ga_mv_meet_rel(meet_a[p][j], meet_b[p][j], &r) != GA_OK)
                c.meet_bad++;
            else
                c.meet_rel_vs_meet = fmax(c.meet_rel_vs_meet, maxdiff(w.c, r.c, 32) / s);
            ga_object o;
            if (!(s > 0.0) || ga_object_from_mv(w, &o) != GA_OK || o.kind != meet_pair_kind[p])
                c.meet_bad++;
        }
    if (bad) /* the inputs are valid rigid motions: a failure is a bug */
        fprintf(stderr, "garotor-bench: a cross-check call returned an error status\n");
    return c;
}
