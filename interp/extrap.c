/* interp/extrap.c: a path at times outside its range (path.h, ga_extrap):
 * held at the range's end, its end segment's formula continued, or the end
 * pose moved on by its body velocity there; `garotor interp --extrapolate`
 * and garotor.Path's extrapolate= both call these, so they give the same
 * samples and derivatives bit for bit.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <garotor/path.h>

static const char *const extrap_names[] = {"error", "hold", "extend", "constant-velocity"};

const char *ga_extrap_name(ga_extrap x)
{
    return (unsigned)x <= GA_EXTRAP_CONSTANT_VELOCITY ? extrap_names[x] : "unknown";
}

ga_status ga_extrap_by_name(const char *name, ga_extrap *out)
{
    if (!name || !out)
        return GA_ERR_ARG;
    for (int i = 0; i <= GA_EXTRAP_CONSTANT_VELOCITY; i++)
        if (strcmp(name, extrap_names[i]) == 0) {
            *out = (ga_extrap)i;
            return GA_OK;
        }
    return GA_ERR_ARG;
}

ga_status ga_path_extrap_init(const ga_path *p, ga_extrap mode, ga_path_extrap *out)
{
    if (!p || !out || (unsigned)mode > GA_EXTRAP_CONSTANT_VELOCITY)
        return GA_ERR_ARG;
    ga_path_extrap x;
    memset(&x, 0, sizeof x);
    x.path = p;
    x.mode = mode;
    ga_status st = ga_path_range(p, &x.r0, &x.r1);
    if (mode == GA_EXTRAP_CONSTANT_VELOCITY) {
        const double r[2] = {x.r0, x.r1};
        for (int i = 0; i < 2 && st == GA_OK; i++) {
            st = ga_path_eval(p, r[i], x.pose[i]);
            if (st == GA_OK)
                st = ga_path_differentiate(p, r[i], GA_FRAME_BODY, x.vel[i], NULL);
        }
    }
    if (st != GA_OK)
        return st;
    *out = x;
    return GA_OK;
}

/* Where t goes: 0 inside the range (or ERROR: the path's own functions say
 * what is wrong); else 1 with *end (0 before the start, 1 after the end) and
 * for EXTEND *seg and *u, for CONSTANT_VELOCITY *u the time past the end
 * (negative before the start). HOLD, and EXTEND on one key, hold the end. */
static int outside(const ga_path_extrap *x, double t, int *end, size_t *seg, double *u)
{
    const ga_path *p = x->path;
    if (x->mode == GA_EXTRAP_ERROR || isnan(t) || (t >= x->r0 && t <= x->r1))
        return 0;
    *end = t > x->r1;
    *seg = SIZE_MAX;
    *u = 0.0;
    size_t m = ga_path_segments(p);
    double s0, s1;
    if (x->mode == GA_EXTRAP_CONSTANT_VELOCITY)
        *u = *end ? t - x->r1 : t - x->r0;
    else if (x->mode == GA_EXTRAP_EXTEND && m > 0 &&
             ga_path_segment_range(p, *end ? m - 1 : 0, &s0, &s1) == GA_OK) {
        *seg = *end ? m - 1 : 0;
        *u = (t - s0) / (s1 - s0);
    }
    return 1;
}

/* CONSTANT_VELOCITY: E exp(d V), E and V the end's pose and body velocity. */
static ga_status moved_on(const ga_path_extrap *x, int end, double d, void *out)
{
    const ga_group *g = x->path->group;
    double v[GA_GROUP_MAX_DIM], e[GA_GROUP_MAX_ELEM];
    for (size_t i = 0; i < g->dim; i++) v[i] = d * x->vel[end][i];
    ga_status st = g->exp(v, e);
    if (st == GA_OK)
        g->compose(x->pose[end], e, out);
    return st;
}

ga_status ga_path_extrap_eval(const ga_path_extrap *x, double t, void *out)
{
    if (!x || !x->path || !out)
        return GA_ERR_ARG;
    int end;
    size_t seg;
    double u;
    if (!outside(x, t, &end, &seg, &u))
        return ga_path_eval(x->path, t, out);
    if (x->mode == GA_EXTRAP_CONSTANT_VELOCITY)
        return moved_on(x, end, u, out);
    if (seg == SIZE_MAX) /* held: the range's end (the end key, or bspline's end pose) */
        return ga_path_eval(x->path, end ? x->r1 : x->r0, out);
    return ga_path_eval_segment(x->path, seg, u, out);
}

/* CONSTANT_VELOCITY's derivatives at the pose e: in the body frame V, in the
 * spatial frame Ad(e) V, and neither changes; in the world frame (rotation R
 * of e, V = (w, v)) the rate R w, which stays, and the position's derivatives
 * R v, R (w x v), R (w x (w x v)). */
static void constant_velocity_derivs(const ga_group *g, const double *vb, ga_frame f, const void *e,
                                     double *v, double *a, double *j)
{
    double *x[3] = {v, a, j};
    for (int k = 0; k < 3; k++)
        if (x[k])
            memset(x[k], 0, g->dim * sizeof *x[k]);
    if (f == GA_FRAME_WORLD) {
        ga_mat4 M = g->to_mat4(e);
        double d[3][3]; /* v, w x v, w x (w x v) */
        memcpy(d[0], vb + 3, sizeof d[0]);
        for (int k = 1; k < 3; k++) {
            d[k][0] = vb[1] * d[k - 1][2] - vb[2] * d[k - 1][1];
            d[k][1] = vb[2] * d[k - 1][0] - vb[0] * d[k - 1][2];
            d[k][2] = vb[0] * d[k - 1][1] - vb[1] * d[k - 1][0];
        }
        for (int r = 0; r < 3; r++) {
            const double *R = M.m + 4 * r;
            if (v)
                v[r] = R[0] * vb[0] + R[1] * vb[1] + R[2] * vb[2];
            for (int k = 0; k < 3; k++)
                if (x[k])
                    x[k][3 + r] = R[0] * d[k][0] + R[1] * d[k][1] + R[2] * d[k][2];
        }
    } else if (v && f == GA_FRAME_SPATIAL)
        g->adjoint(e, vb, v);
    else if (v)
        memcpy(v, vb, g->dim * sizeof *v);
}

ga_status ga_path_extrap_derivatives(const ga_path_extrap *x, double t, ga_frame f, double *v, double *a,
                                     double *j)
{
    if (!x || !x->path)
        return GA_ERR_ARG;
    const ga_path *p = x->path;
    const ga_group *g = p->group;
    int end;
    size_t seg;
    double u;
    if ((unsigned)f > GA_FRAME_WORLD || (f == GA_FRAME_WORLD && !g->rigid))
        return GA_ERR_ARG;
    if (!outside(x, t, &end, &seg, &u))
        return ga_path_derivatives(p, t, f, v, a, j);
    if (x->mode == GA_EXTRAP_CONSTANT_VELOCITY) {
        double e[GA_GROUP_MAX_ELEM];
        ga_status st = f == GA_FRAME_BODY ? GA_OK : moved_on(x, end, u, e);
        if (st == GA_OK)
            constant_velocity_derivs(g, x->vel[end], f, e, v, a, j);
        return st;
    }
    if (seg == SIZE_MAX) { /* held: nothing moves */
        double *d[3] = {v, a, j};
        for (int k = 0; k < 3; k++)
            if (d[k])
                memset(d[k], 0, g->dim * sizeof *d[k]);
        return GA_OK;
    }
    return ga_path_derivatives_segment(p, seg, u, f, v, a, j);
}
