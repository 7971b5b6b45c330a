/* wasm/shim.c: the library's public API with pointers for JavaScript.
 *
 * Compiled with the library by emscripten (wasm/meson.build) into
 * garotor.wasm. The public functions take and return their value types
 * (ga_vec3, ga_mv, ga_object, ga_mat4) by value, which JavaScript cannot
 * pass; each function here reads them from and writes them to arrays of
 * doubles in the module's memory and calls one public function (the path
 * keeps its state in static storage: one path per page).
 * No arithmetic of its own: every number the page shows comes out of the
 * library. JavaScript reads the arrays at gw_scratch(), 4096 doubles, and
 * the text at gw_text(). Layouts:
 *   a point: x, y, z; a multivector: 32 coefficients (canonical order);
 *   an object (gw_object): kind, reality, centre (3), direction (3), r2,
 *   err, r2_err, angle_err; a pose: a 4x4 matrix, row-major (16);
 *   a velocity: a body twist wx, wy, wz, vx, vy, vz.
 */
#include <garotor/garotor.h>

#include <emscripten.h>
#include <stddef.h>

static double scratch[4096];
static char text[GA_MV_TEXT_MAX];

static ga_vec3 v3(const double *p)
{
    ga_vec3 v = {p[0], p[1], p[2]};
    return v;
}

static ga_mv mv(const double *p)
{
    ga_mv m;
    for (int i = 0; i < 32; i++) m.c[i] = p[i];
    return m;
}

static void put(ga_mv m, double *out)
{
    for (int i = 0; i < 32; i++) out[i] = m.c[i];
}

EMSCRIPTEN_KEEPALIVE double *gw_scratch(void) { return scratch; }
EMSCRIPTEN_KEEPALIVE char *gw_text(void) { return text; }

/* ---- objects from points (conformal.h) ---- */
EMSCRIPTEN_KEEPALIVE void gw_point_up(const double *x, double *out) { put(ga_point_up(v3(x)), out); }
EMSCRIPTEN_KEEPALIVE void gw_pointpair(const double *a, const double *b, double *out)
{
    put(ga_pointpair_from_points(v3(a), v3(b)), out);
}
EMSCRIPTEN_KEEPALIVE void gw_line(const double *a, const double *b, double *out)
{
    put(ga_line_from_points(v3(a), v3(b)), out);
}
EMSCRIPTEN_KEEPALIVE void gw_circle(const double *a, const double *b, const double *c, double *out)
{
    put(ga_circle_from_points(v3(a), v3(b), v3(c)), out);
}
EMSCRIPTEN_KEEPALIVE void gw_plane(const double *a, const double *b, const double *c, double *out)
{
    put(ga_plane_from_points(v3(a), v3(b), v3(c)), out);
}
EMSCRIPTEN_KEEPALIVE void gw_sphere(const double *a, const double *b, const double *c, const double *d,
                                    double *out)
{
    put(ga_sphere_from_points(v3(a), v3(b), v3(c), v3(d)), out);
}
EMSCRIPTEN_KEEPALIVE void gw_sphere_dual(const double *c, double r, double *out)
{
    put(ga_sphere_dual(v3(c), r), out);
}
EMSCRIPTEN_KEEPALIVE void gw_plane_dual(const double *n, double d, double *out)
{
    put(ga_plane_dual(v3(n), d), out);
}

/* ---- products, meets, read-back (mv.h, object.h) ---- */
EMSCRIPTEN_KEEPALIVE void gw_gp(const double *a, const double *b, double *out)
{
    put(ga_mv_gp(mv(a), mv(b)), out);
}
EMSCRIPTEN_KEEPALIVE void gw_op(const double *a, const double *b, double *out)
{
    put(ga_mv_op(mv(a), mv(b)), out);
}
EMSCRIPTEN_KEEPALIVE void gw_dual(const double *a, double *out) { put(ga_mv_dual(mv(a)), out); }
EMSCRIPTEN_KEEPALIVE void gw_meet(const double *a, const double *b, double *out)
{
    put(ga_mv_meet(mv(a), mv(b)), out);
}
EMSCRIPTEN_KEEPALIVE int gw_object(const double *x, double *out)
{
    ga_object o;
    ga_status s = ga_object_from_mv(mv(x), &o);
    if (s != GA_OK)
        return s;
    const double v[12] = {o.kind,        o.reality,     o.centre.x, o.centre.y, o.centre.z, o.direction.x,
                          o.direction.y, o.direction.z, o.r2,       o.err,      o.r2_err,   o.angle_err};
    for (int i = 0; i < 12; i++) out[i] = v[i];
    return GA_OK;
}
/* the text of ga_mv_format at gw_text(): its length, or a status (< 0) */
EMSCRIPTEN_KEEPALIVE int gw_format(const double *x)
{
    size_t len = 0;
    ga_status s = ga_mv_format(mv(x), text, sizeof text, &len);
    return s != GA_OK ? s : (int)len;
}

/* ---- versors (versor.h) ---- */
EMSCRIPTEN_KEEPALIVE void gw_reflection(const double *n, double d, double *out)
{
    put(ga_versor_reflection(v3(n), d), out);
}
EMSCRIPTEN_KEEPALIVE void gw_inversion(const double *c, double r, double *out)
{
    put(ga_versor_inversion(v3(c), r), out);
}
EMSCRIPTEN_KEEPALIVE int gw_dilation(const double *c, double s, double *out)
{
    ga_mv m;
    ga_status st = ga_versor_dilation(v3(c), s, &m);
    if (st == GA_OK)
        put(m, out);
    return st;
}
EMSCRIPTEN_KEEPALIVE void gw_rotation(const double *axis, double angle, double *out)
{
    put(ga_versor_rotation(v3(axis), angle), out);
}
EMSCRIPTEN_KEEPALIVE void gw_translation(const double *a, double *out)
{
    put(ga_versor_translation(v3(a)), out);
}
EMSCRIPTEN_KEEPALIVE int gw_versor_apply(const double *v, const double *x, double *out)
{
    ga_mv m;
    ga_status s = ga_versor_apply(mv(v), mv(x), &m);
    if (s == GA_OK)
        put(m, out);
    return s;
}

/* ---- a path through key poses on the cga group (path.h) ---- */
#define GW_MAX_KEYS 8
static ga_path path;
static int have_path;
static unsigned char work[1 << 16];

/* keys: n 4x4 matrices (row-major); GA_ERR_ARG beyond GW_MAX_KEYS keys */
EMSCRIPTEN_KEEPALIVE int gw_path_build(int scheme, int n, const double *times, const double *keys)
{
    ga_mat4 k[GW_MAX_KEYS];
    have_path = 0;
    if (n < 1 || n > GW_MAX_KEYS || scheme < 0 || scheme >= GA_SCHEME_COUNT)
        return GA_ERR_ARG;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < 16; j++) k[i].m[j] = keys[16 * i + j];
    size_t need = ga_path_workspace_size(&ga_group_cga, (ga_scheme)scheme, (size_t)n);
    if (need == 0 || need > sizeof work)
        return GA_ERR_ARG;
    ga_status s = ga_path_init_mat4(&ga_group_cga, (ga_scheme)scheme, (size_t)n, times, k, NULL, work,
                                    sizeof work, &path);
    have_path = s == GA_OK;
    return s;
}
EMSCRIPTEN_KEEPALIVE int gw_path_range(double *out)
{
    return have_path ? ga_path_range(&path, out, out + 1) : GA_ERR_ARG;
}
EMSCRIPTEN_KEEPALIVE int gw_path_eval(double t, double *out)
{
    if (!have_path)
        return GA_ERR_ARG;
    ga_rotor r;
    ga_status s = ga_path_eval(&path, t, &r);
    if (s != GA_OK)
        return s;
    ga_mat4 m = ga_rotor_to_mat4(r);
    for (int j = 0; j < 16; j++) out[j] = m.m[j];
    return GA_OK;
}
EMSCRIPTEN_KEEPALIVE int gw_path_velocity(double t, double *out)
{
    return have_path ? ga_path_velocity(&path, t, out) : GA_ERR_ARG;
}
