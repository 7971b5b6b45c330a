/* tools/demo.c: `garotor` with no arguments, a short tour of what garotor does:
 * the conformal model in three lines, three key poses, the screw between
 * consecutive keys, samples of the screw and quadratic paths through them, and
 * the largest disagreement between the same paths computed with CGA rotors
 * and with 4x4 matrices. `--svg FILE` draws both paths, renamed onto FILE
 * once the report is written. */
#include "cli.h"
#include "html.h"
#include "svg.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define DEMO_KEYS 3
#define DEMO_SAMPLES 201 /* for the picture and the comparison */
#define DEMO_ROWS 9      /* samples printed */

static const double pi = 3.141592653589793;

/* The keys: position, then a rotation (axis, angle in degrees). */
static const struct {
    double t;
    ga_vec3 pos, axis;
    double degrees;
} demo_key[DEMO_KEYS] = {
    {0.0, {0, 0, 0}, {0, 0, 1}, 0},
    {1.0, {2, 1, 0.5}, {0, 0, 1}, 90},
    {2.0, {3, 3, 1.5}, {1, 1, 1}, 120},
};

/* v, or 0 when it prints as zero with `decimals` decimals (no "-0.00"). */
static double shown(double v, int decimals) { return fabs(v) < 0.5 * pow(10.0, -decimals) ? 0.0 : v; }

static double max_diff(const ga_mat4 *a, const ga_mat4 *b, size_t n)
{
    double d = 0.0;
    for (size_t k = 0; k < n; k++)
        for (int i = 0; i < 16; i++) d = fmax(d, fabs(a[k].m[i] - b[k].m[i]));
    return d;
}

/* The rotation angle (degrees) and unit axis of a rigid motion's 3x3 block. */
static double rotation_of(ga_mat4 m, ga_vec3 *axis)
{
    ga_rotor r;
    ga_screw s;
    if (ga_rotor_from_mat4(m, &r) != GA_OK)
        return NAN;
    ga_rotor q = {r.s, r.e12, r.e13, r.e23, 0, 0, 0, 0}; /* the rotation alone */
    if (ga_rotor_to_screw(q, &s) != GA_OK)
        return NAN;
    *axis = s.axis;
    return s.angle * 180.0 / pi;
}

/* Sample a path of `scheme` through the keys on group g, as matrices. */
static int sample(const ga_group *g, ga_scheme scheme, const double *t, const ga_mat4 *key, ga_mat4 *out)
{
    static double work[4096];
    static double elem[DEMO_SAMPLES * GA_GROUP_MAX_ELEM]; /* elem_size bytes each */
    ga_path p;
    if (ga_path_workspace_size(g, scheme, DEMO_KEYS) > sizeof work)
        return GA_ERR_ARG;
    int st = ga_path_init_mat4(g, scheme, DEMO_KEYS, t, key, NULL, work, sizeof work, &p);
    if (st == GA_OK)
        st = ga_path_sample_uniform(&p, GA_EVAL_DIRECT, 1.0, DEMO_SAMPLES, t[0], t[DEMO_KEYS - 1], elem);
    for (size_t k = 0; st == GA_OK && k < DEMO_SAMPLES; k++)
        out[k] = g->to_mat4((const char *)elem + k * g->elem_size);
    return st;
}

int cmd_demo(const cli_opts *o)
{
    svg_view view;
    if (svg_options("demo", o->svg, o->view, &view) || html_options("demo", o->html))
        return 2;

    /* compute everything first, then draw, then print: an error prints nothing */
    double t[DEMO_KEYS];
    ga_rotor R[DEMO_KEYS];
    ga_mat4 M[DEMO_KEYS];
    for (int i = 0; i < DEMO_KEYS; i++) {
        t[i] = demo_key[i].t;
        R[i] = ga_rotor_mul(ga_rotor_translation(demo_key[i].pos),
                            ga_rotor_rotation(demo_key[i].axis, demo_key[i].degrees * pi / 180.0));
        M[i] = ga_rotor_to_mat4(R[i]);
    }
    ga_screw screw[DEMO_KEYS - 1];
    for (int i = 0; i + 1 < DEMO_KEYS; i++) {
        int st = ga_rotor_to_screw(ga_rotor_mul(R[i + 1], ga_rotor_reverse(R[i])), &screw[i]);
        if (st != GA_OK) {
            fprintf(stderr, "garotor demo: screw: %s\n", ga_status_string(st));
            return 2;
        }
    }
    static ga_mat4 path[2][2][DEMO_SAMPLES]; /* [scheme][cga, matrix][sample] */
    const ga_scheme scheme[2] = {GA_SCHEME_SCREW, GA_SCHEME_QUADRATIC};
    const ga_group *group[2] = {&ga_group_cga, &ga_group_se3};
    for (int s = 0; s < 2; s++)
        for (int gi = 0; gi < 2; gi++) {
            int st = sample(group[gi], scheme[s], t, M, path[s][gi]);
            if (st != GA_OK) {
                fprintf(stderr, "garotor demo: %s path on %s: %s\n", ga_scheme_name(scheme[s]),
                        group[gi]->name, ga_status_string(st));
                return 2;
            }
        }
    /* the picture and the page are renamed onto their names once the report
       is written (svg.h): not kept when it cannot be */
    tio_out svg = TIO_OUT_NONE, html = TIO_OUT_NONE;
    if (o->svg || o->html) {
        svg_path sp[2] = {
            {"screw", "#ff7f0e", path[0][0], DEMO_SAMPLES, 8},
            {"quadratic", "#6a3d9a", path[1][0], DEMO_SAMPLES, 8},
        };
        svg_picture pic = {"garotor demo: the screw and quadratic paths through three keys",
                           view,
                           M,
                           t,
                           DEMO_KEYS,
                           sp,
                           2,
                           0,
                           {0, 0, 0},
                           {0, 0, 0}};
        if (o->svg && svg_write(&svg, o->svg, &pic))
            return 2;
        if (o->html && html_write(&html, o->html, &pic)) {
            tio_out_discard(&svg);
            return 2;
        }
    }

    printf("garotor %s: rigid motions in conformal geometric algebra G(4,1)\n\n", GAROTOR_VERSION_STRING);

    /* 1. the conformal model: points are null vectors, inner products distances */
    ga_vec3 x = {1, 2, 3}, y = {4, 6, 3};
    ga_mv X = ga_point_up(x), Y = ga_point_up(y);
    printf("Points are null vectors F(x) = x + (x^2/2) n - nbar/2 (Wareham-Lasenby §1):\n"
           "  x = (1, 2, 3), y = (4, 6, 3):  F(x).F(x) = %.3g,  -2 F(x).F(y) = %.6g = |x - y|^2\n\n",
           ga_mv_sp(X, X), -2.0 * ga_mv_sp(X, Y));

    /* 2. the keys */
    printf("Three key poses: the rotor R_i = T_p q moves the frame to position p, turned by q:\n");
    for (int i = 0; i < DEMO_KEYS; i++) {
        ga_vec3 p = demo_key[i].pos, a = demo_key[i].axis;
        printf("  t = %g:  p = (%g, %g, %g), %g deg about (%g, %g, %g)\n", t[i], p.x, p.y, p.z,
               demo_key[i].degrees, a.x, a.y, a.z);
    }

    /* 3. every rigid motion is a screw (Chasles): the one from key to key */
    printf("\nFrom key to key, R_{i+1} ~R_i is a screw motion (Chasles; ga_rotor_to_screw):\n");
    for (int i = 0; i + 1 < DEMO_KEYS; i++) {
        const ga_screw *s = &screw[i];
        printf("  t = %g to %g:  %.4g deg about (%.4f, %.4f, %.4f) through (%.4f, %.4f, %.4f),\n"
               "                shift %.4f along the axis, pitch %.4f per rad\n",
               t[i], t[i + 1], s->angle * 180.0 / pi, shown(s->axis.x, 4), shown(s->axis.y, 4),
               shown(s->axis.z, 4), shown(s->point.x, 4), shown(s->point.y, 4), shown(s->point.z, 4),
               shown(s->shift, 4), shown(s->pitch, 4));
    }

    /* 4. the two paths */
    printf("\nTwo paths through the keys: screw (piecewise screw motion) and quadratic\n"
           "(a quadratic in the generators l(R_i)); position and rotation of the frame:\n"
           "     t   screw                                     quadratic\n");
    for (int r = 0; r < DEMO_ROWS; r++) {
        size_t k = (size_t)r * (DEMO_SAMPLES - 1) / (DEMO_ROWS - 1);
        printf("  %4.2f", t[0] + (t[DEMO_KEYS - 1] - t[0]) * (double)k / (DEMO_SAMPLES - 1));
        for (int s = 0; s < 2; s++) {
            const ga_mat4 *m = &path[s][0][k];
            ga_vec3 a = {0, 0, 1};
            double deg = rotation_of(*m, &a);
            printf("   (%5.2f, %5.2f, %5.2f) %5.1f deg", shown(m->m[3], 2), shown(m->m[7], 2),
                   shown(m->m[11], 2), shown(deg, 1));
        }
        putchar('\n');
    }

    /* 5. the cross-check */
    printf("\nThe same paths computed with 4x4 matrices (Eberly's SE(3) exp and log)\n"
           "instead of rotors: the largest difference of a matrix entry, %d samples:\n"
           "  screw %.2g, quadratic %.2g\n",
           DEMO_SAMPLES, max_diff(path[0][0], path[0][1], DEMO_SAMPLES),
           max_diff(path[1][0], path[1][1], DEMO_SAMPLES));
    if (o->svg)
        printf("\nThe picture: %s\n", o->svg);
    if (o->html)
        printf("\nThe page (drag to turn): %s\n", o->html);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "garotor: <stdout>: write error\n");
        tio_out_discard(&svg);
        tio_out_discard(&html);
        return 2;
    }
    if (tio_out_commit(&svg) != 0) {
        tio_out_discard(&html);
        return 2;
    }
    if (tio_out_commit(&html) != 0) {
        if (o->svg)
            tio_out_unwrite(o->svg);
        return 2;
    }
    return 0;
}
