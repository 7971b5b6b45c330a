/* tests/page_ref.c: what docs/interactive/conformal.html computes
 * (wasm/conformal.js, compute() and poseAt()), computed again here with the
 * native library and the public API only, for tests/page_test.py to compare
 * with the page bit for bit.
 *
 * stdin (numbers as Python's repr writes them, read back exactly by strtod):
 *   p X Y Z          five times: P0 .. P3 and Q
 *   rho R
 *   versor NAME V    none, reflection, inversion, dilation or screw; its parameter
 *   scheme K N       the scheme's number and its number of keys
 *   times T...       N times
 *   key M...         N times, a pose as 16 numbers (row-major)
 *   s S              the slider, in [0, 1]
 * stdout: one JSON object, every number as the 16 hex digits of its double's
 * bits (the page's state as tests/page_test.py writes it), so that -0 and
 * the last bit count:
 *   {"objects": [{"name", "mv", "obj": {status, kind, reality, centre,
 *    direction, r2}, "text"}...], "range": [t0, t1],
 *    "pose": {"t", "status", "pose", "velocity"}} */
#include <garotor/garotor.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void hex(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    printf("\"%016llx\"", (unsigned long long)u);
}

static void hexes(const double *x, int n)
{
    putchar('[');
    for (int i = 0; i < n; i++) {
        if (i)
            putchar(',');
        hex(x[i]);
    }
    putchar(']');
}

/* a JSON string: the names and texts here are ASCII or UTF-8 without quotes */
static void str(const char *s) { printf("\"%s\"", s); }

static int first = 1;

static void entry(const char *name, const ga_mv *X)
{
    printf("%s\n{\"name\":", first ? "" : ",");
    first = 0;
    str(name);
    printf(",\"mv\":");
    if (!X) {
        printf("null,\"obj\":{\"status\":");
        hex(GA_ERR_ARG);
        printf("},\"text\":\"not applied\"}");
        return;
    }
    hexes(X->c, 32);
    ga_object o;
    ga_status s = ga_object_from_mv(*X, &o);
    printf(",\"obj\":{\"status\":");
    hex(s);
    if (s == GA_OK) {
        double c[3] = {o.centre.x, o.centre.y, o.centre.z},
               d[3] = {o.direction.x, o.direction.y, o.direction.z};
        printf(",\"kind\":");
        hex(o.kind);
        printf(",\"reality\":");
        hex(o.reality);
        printf(",\"centre\":");
        hexes(c, 3);
        printf(",\"direction\":");
        hexes(d, 3);
        printf(",\"r2\":");
        hex(o.r2);
    }
    char buf[GA_MV_TEXT_MAX];
    size_t len;
    s = ga_mv_format(*X, buf, sizeof buf, &len);
    printf("},\"text\":");
    str(s == GA_OK ? buf : ga_status_string(s));
    putchar('}');
}

static int word(const char *w)
{
    char got[32];
    if (scanf("%31s", got) != 1 || strcmp(got, w) != 0) {
        fprintf(stderr, "page_ref: expected '%s'\n", w);
        exit(2);
    }
    return 1;
}

static double num(void)
{
    char tok[64];
    if (scanf("%63s", tok) != 1) {
        fprintf(stderr, "page_ref: a number is missing\n");
        exit(2);
    }
    return strtod(tok, NULL);
}

int main(void)
{
    ga_vec3 P[5];
    for (int i = 0; i < 5; i++) {
        word("p");
        P[i].x = num();
        P[i].y = num();
        P[i].z = num();
    }
    word("rho");
    double rho = num();
    char vname[32];
    word("versor");
    if (scanf("%31s", vname) != 1)
        return 2;
    double vp = num();
    word("scheme");
    int scheme = (int)num(), n = (int)num();
    if (n < 1 || n > 8 || scheme < 0 || scheme >= GA_SCHEME_COUNT)
        return 2;
    double times[8];
    ga_mat4 keys[8];
    word("times");
    for (int i = 0; i < n; i++) times[i] = num();
    for (int i = 0; i < n; i++) {
        word("key");
        for (int j = 0; j < 16; j++) keys[i].m[j] = num();
    }
    word("s");
    double sl = num();

    /* compute() */
    ga_mv pair = ga_pointpair_from_points(P[0], P[1]), line = ga_line_from_points(P[0], P[1]);
    ga_mv circle = ga_circle_from_points(P[0], P[1], P[2]), plane = ga_plane_from_points(P[0], P[1], P[2]);
    ga_mv sphere = ga_sphere_from_points(P[0], P[1], P[2], P[3]), S = ga_sphere_dual(P[4], rho);
    ga_mv m1 = ga_mv_meet(sphere, S), m2 = ga_mv_meet(line, S), m3 = ga_mv_meet(circle, S);
    ga_mv V;
    int have_v = 1;
    if (strcmp(vname, "reflection") == 0) {
        ga_vec3 e1 = {1, 0, 0};
        V = ga_versor_reflection(e1, vp);
    } else if (strcmp(vname, "inversion") == 0) {
        V = ga_versor_inversion(P[4], rho);
    } else if (strcmp(vname, "dilation") == 0) {
        have_v = ga_versor_dilation(P[4], vp, &V) == GA_OK;
    } else if (strcmp(vname, "screw") == 0) {
        ga_vec3 z = {0, 0, 1}, mq = {-P[4].x, -P[4].y, -P[4].z}, up = {0, 0, 0.3 * vp};
        ga_mv T = ga_versor_translation(P[4]), Rz = ga_versor_rotation(z, vp);
        V = ga_mv_gp(ga_mv_gp(ga_mv_gp(T, Rz), ga_versor_translation(mq)), ga_versor_translation(up));
    } else {
        have_v = 0;
    }
    printf("{\"objects\":[");
    entry("pair", &pair);
    entry("line", &line);
    entry("circle", &circle);
    entry("plane", &plane);
    entry("sphere", &sphere);
    entry("S", &S);
    entry("sphere \xe2\x88\xa7 S", &m1); /* U+2227 LOGICAL AND, as the page names them */
    entry("line \xe2\x88\xa7 S", &m2);
    entry("circle \xe2\x88\xa7 S", &m3);
    if (have_v) {
        const char *names[3] = {"line", "circle", "sphere"};
        ga_mv X[3] = {line, circle, sphere};
        for (int k = 0; k < 3; k++) {
            char name[64];
            ga_mv Y;
            snprintf(name, sizeof name, "%s of %s", vname, names[k]);
            entry(name, ga_versor_apply(V, X[k], &Y) == GA_OK ? &Y : NULL);
        }
    }
    printf("],\n");

    /* buildPath() and poseAt() */
    static unsigned char work[1 << 16];
    ga_path path;
    ga_status s = ga_path_init_mat4(&ga_group_cga, (ga_scheme)scheme, (size_t)n, times, keys, NULL, work,
                                    sizeof work, &path);
    double range[2] = {0, 1};
    if (s == GA_OK)
        s = ga_path_range(&path, &range[0], &range[1]);
    printf("\"range\":");
    hexes(range, 2);
    double t = range[0] + (range[1] - range[0]) * sl;
    printf(",\n\"pose\":{\"t\":");
    hex(t);
    if (s == GA_OK) {
        ga_rotor r;
        double v[6];
        s = ga_path_eval(&path, t, &r);
        ga_status s2 = ga_path_velocity(&path, t, v);
        ga_mat4 m = ga_rotor_to_mat4(r);
        printf(",\"status\":");
        hex(s ? s : s2);
        if (s == GA_OK && s2 == GA_OK) {
            printf(",\"pose\":");
            hexes(m.m, 16);
            printf(",\"velocity\":");
            hexes(v, 6);
        }
    } else {
        printf(",\"status\":");
        hex(s);
    }
    printf("}}\n");
    return 0;
}
