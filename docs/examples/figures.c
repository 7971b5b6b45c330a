/* figures.c: the pictures of docs/conformal.md and docs/versors.md, drawn from
 * what garotor computes (docs/make-figures.sh runs it; tests/figures_test.sh
 * checks that it reproduces the committed files byte for byte).
 *
 *   figures OUTDIR
 *
 * Each object is built with garotor (from points, or as the meet of two
 * objects, or as the image of one under a versor), read back with
 * ga_object_from_mv, and drawn from what is read back: a circle from its
 * centre, radius and normal, a sphere from its centre and radius. Every point
 * drawn on an object is checked to lie on the blade garotor built
 * (F(x) ^ X = 0, to 1e-9 of the sizes of F(x) and X): if one does not, the
 * program says so and exits 1 without finishing the picture. Plain SVG, no
 * dependencies; coordinates with two decimals, so the bytes are stable. The
 * 3D scenes are an orthographic view from azimuth 35 degrees, elevation 22
 * degrees; the plane pictures (inversion, dilation) look down the z axis.
 * The null cone is drawn in three coefficients of G(4,1), (e1, e4, e5), from
 * azimuth -62 degrees, elevation 14, each point drawn on it checked null
 * (F . F = 0); an imaginary circle has no real point to check, so it is drawn
 * from its read-back, which is checked against r^2 = 1 - d^2/4 instead. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <garotor/garotor.h>

#define PI 3.14159265358979323846

/* ---- checks ----------------------------------------------------------------- */

static const char *figure = ""; /* the file being drawn, for messages */

static void die(const char *what)
{
    fprintf(stderr, "figures: %s: %s\n", figure, what);
    exit(1);
}

/* x lies on the direct blade X: F(x) ^ X = 0, relative to the sizes of both */
static void check_on(ga_vec3 x, ga_mv X)
{
    ga_mv P = ga_point_up(x);
    double e = ga_mv_maxabs(ga_mv_op(P, X)), s = ga_mv_maxabs(P) * ga_mv_maxabs(X);
    if (!(e <= 1e-9 * s)) {
        char msg[160];
        snprintf(msg, sizeof msg, "(%g, %g, %g) is not on the object: |F(x) ^ X| = %g of %g", x.x, x.y, x.z,
                 e, s);
        die(msg);
    }
}

static ga_object read_back(ga_mv X, int kind)
{
    ga_object o;
    int st = ga_object_from_mv(X, &o);
    if (st != GA_OK)
        die(ga_status_string(st));
    if (o.kind != kind)
        die("not the kind of object expected");
    return o;
}

/* ---- vectors ------------------------------------------------------------------ */

static ga_vec3 v3(double x, double y, double z) { return (ga_vec3){x, y, z}; }
static ga_vec3 add(ga_vec3 a, ga_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static ga_vec3 scale(ga_vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static ga_vec3 cross(ga_vec3 a, ga_vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double dot(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ga_vec3 unit(ga_vec3 a) { return scale(a, 1 / sqrt(dot(a, a))); }
/* two unit vectors spanning the plane orthogonal to the unit m */
static void basis(ga_vec3 m, ga_vec3 *u, ga_vec3 *w)
{
    *u = unit(cross(m, fabs(m.x) < 0.9 ? v3(1, 0, 0) : v3(0, 1, 0)));
    *w = cross(m, *u);
}

/* ---- the picture ------------------------------------------------------------ */

typedef struct {
    FILE *f;
    double ox, oy, px;         /* screen position of the origin, pixels per unit */
    int plan;                  /* 1: looking down z (x right, y up); 0: the oblique view */
    ga_vec3 right, up, toward; /* the oblique view's screen axes and the viewer */
} view;

static void num(FILE *f, double v)
{
    v = round(v * 100) / 100;
    fprintf(f, "%.2f", v == 0 ? 0.0 : v); /* no "-0.00" */
}

static void screen(const view *V, ga_vec3 p, double *sx, double *sy)
{
    double a = V->plan ? p.x : dot(p, V->right), b = V->plan ? p.y : dot(p, V->up);
    *sx = V->ox + V->px * a;
    *sy = V->oy - V->px * b;
}

static void pt(const view *V, ga_vec3 p)
{
    double x, y;
    screen(V, p, &x, &y);
    num(V->f, x);
    fputc(',', V->f);
    num(V->f, y);
}

static void begin(view *V, const char *dir, const char *name, const char *title, int w, int h)
{
    static char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    figure = name;
    V->f = fopen(path, "w");
    if (!V->f)
        die("cannot write the file");
    fprintf(V->f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(V->f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" "
            "font-family=\"sans-serif\" font-size=\"13\">\n",
            w, h, w, h);
    fprintf(V->f, "<title>%s</title>\n<rect width=\"%d\" height=\"%d\" fill=\"#ffffff\"/>\n", title, w, h);
    fprintf(V->f, "<text x=\"12\" y=\"22\" font-size=\"15\">%s</text>\n", title);
    double az = 35 * PI / 180, el = 22 * PI / 180;
    V->right = v3(-sin(az), cos(az), 0);
    V->up = v3(-sin(el) * cos(az), -sin(el) * sin(az), cos(el));
    V->toward = v3(cos(el) * cos(az), cos(el) * sin(az), sin(el));
    V->plan = 0;
}

static void end(view *V)
{
    fprintf(V->f, "</svg>\n");
    if (fclose(V->f) != 0)
        die("cannot write the file");
}

static void text(const view *V, ga_vec3 p, double dx, double dy, const char *style, const char *s)
{
    double x, y;
    screen(V, p, &x, &y);
    fputs("<text x=\"", V->f);
    num(V->f, x + dx);
    fputs("\" y=\"", V->f);
    num(V->f, y + dy);
    fprintf(V->f, "\"%s%s>%s</text>\n", *style ? " " : "", style, s);
}

static void segment(const view *V, ga_vec3 a, ga_vec3 b, const char *style)
{
    fputs("<polyline fill=\"none\" ", V->f);
    fprintf(V->f, "%s points=\"", style);
    pt(V, a);
    fputc(' ', V->f);
    pt(V, b);
    fputs("\"/>\n", V->f);
}

static void arrow(const view *V, ga_vec3 a, ga_vec3 b, const char *colour)
{
    double ax, ay, bx, by;
    screen(V, a, &ax, &ay);
    screen(V, b, &bx, &by);
    double dx = bx - ax, dy = by - ay, l = sqrt(dx * dx + dy * dy);
    dx /= l, dy /= l;
    fprintf(V->f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", colour);
    pt(V, a);
    fputc(' ', V->f);
    pt(V, b);
    fprintf(V->f, "\"/>\n<polygon fill=\"%s\" points=\"", colour);
    num(V->f, bx), fputc(',', V->f), num(V->f, by), fputc(' ', V->f);
    num(V->f, bx - 9 * dx - 4 * dy), fputc(',', V->f), num(V->f, by - 9 * dy + 4 * dx), fputc(' ', V->f);
    num(V->f, bx - 9 * dx + 4 * dy), fputc(',', V->f), num(V->f, by - 9 * dy - 4 * dx);
    fputs("\"/>\n", V->f);
}

static void point(const view *V, ga_vec3 p, const char *colour, const char *label, double dx, double dy)
{
    double x, y;
    screen(V, p, &x, &y);
    fputs("<circle cx=\"", V->f);
    num(V->f, x);
    fputs("\" cy=\"", V->f);
    num(V->f, y);
    fprintf(V->f, "\" r=\"4\" fill=\"%s\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n", colour);
    if (label)
        text(V, p, dx, dy, "", label);
}

static void axes(const view *V, double len)
{
    const char *grey = "#888888";
    ga_vec3 o = v3(0, 0, 0);
    arrow(V, o, v3(len, 0, 0), grey);
    arrow(V, o, v3(0, len, 0), grey);
    text(V, v3(len, 0, 0), -14, 14, "fill=\"#666666\"", "x");
    text(V, v3(0, len, 0), 4, 14, "fill=\"#666666\"", "y");
    if (!V->plan) {
        arrow(V, o, v3(0, 0, len), grey);
        text(V, v3(0, 0, len), 6, 4, "fill=\"#666666\"", "z");
    }
}

/* The circle of centre c, radius r in the plane of unit normal m, as a
 * polyline of 145 points, each checked to lie on the blade X. With a sphere
 * (hide_c, hide_r), the part behind it is drawn dashed. */
static void circle(const view *V, ga_vec3 c, double r, ga_vec3 m, ga_mv X, const char *style,
                   const ga_vec3 *hide_c)
{
    ga_vec3 u, w;
    basis(m, &u, &w);
    int n = 144, open = 0, back_prev = -1;
    for (int i = 0; i <= n; i++) {
        double t = 2 * PI * i / n;
        ga_vec3 p = add(c, add(scale(u, r * cos(t)), scale(w, r * sin(t))));
        check_on(p, X);
        int back = hide_c && dot(add(p, scale(*hide_c, -1)), V->toward) < -1e-9;
        if (back != back_prev) {
            if (open) {
                fputc(' ', V->f);
                pt(V, p);
                fputs("\"/>\n", V->f);
            }
            fprintf(V->f, "<polyline fill=\"none\" %s%s points=\"", style,
                    back ? " stroke-dasharray=\"4,4\" stroke-opacity=\"0.5\"" : "");
            open = 1, back_prev = back;
        } else
            fputc(' ', V->f);
        pt(V, p);
    }
    fputs("\"/>\n", V->f);
}

/* a sphere: its outline (a circle on the screen), its equator and one
 * meridian, the back halves dashed */
static void sphere(const view *V, ga_vec3 c, double r, ga_mv S, const char *colour)
{
    char style[128];
    double x, y;
    screen(V, c, &x, &y);
    fprintf(V->f, "<circle cx=\"");
    num(V->f, x);
    fputs("\" cy=\"", V->f);
    num(V->f, y);
    fputs("\" r=\"", V->f);
    num(V->f, r * V->px);
    fprintf(V->f, "\" fill=\"%s\" fill-opacity=\"0.12\" stroke=\"%s\" stroke-width=\"1.5\"/>\n", colour,
            colour);
    snprintf(style, sizeof style, "stroke=\"%s\" stroke-width=\"1\"", colour);
    circle(V, c, r, v3(0, 0, 1), S, style, &c);
    circle(V, c, r, v3(0, 1, 0), S, style, &c);
}

/* ---- the five objects --------------------------------------------------------- */

static void pointpair(const char *dir)
{
    view V = {.ox = 170, .oy = 200, .px = 70};
    begin(&V, dir, "cga-pointpair.svg", "A point pair: F(a) &#8743; F(b)", 340, 300);
    axes(&V, 1.2);
    ga_vec3 a = v3(0.5, -1, 0.3), b = v3(-0.3, 1.2, 1.1);
    ga_mv PP = ga_pointpair_from_points(a, b);
    ga_object o = read_back(PP, GA_OBJECT_POINTPAIR);
    /* the pair is its centre and half-distance along its direction */
    double h = sqrt(o.r2);
    ga_vec3 p = add(o.centre, scale(o.direction, -h)), q = add(o.centre, scale(o.direction, h));
    check_on(p, PP), check_on(q, PP);
    segment(&V, p, q, "stroke=\"#1f77b4\" stroke-width=\"1\" stroke-dasharray=\"5,4\"");
    point(&V, o.centre, "#ffffff", "centre", 8, 4);
    point(&V, p, "#1f77b4", "a", 8, 4);
    point(&V, q, "#1f77b4", "b", 8, 4);
    text(&V, v3(0, 0, 0), -155, 85, "", "read back: centre, r&#178; = |b &#8722; a|&#178;/4, direction");
    end(&V);
}

static void circle_figure(const char *dir)
{
    view V = {.ox = 170, .oy = 190, .px = 70};
    begin(&V, dir, "cga-circle.svg", "A circle: F(a) &#8743; F(b) &#8743; F(c)", 340, 300);
    axes(&V, 1.2);
    ga_vec3 a = v3(1, 0, 0.3), b = v3(0, 1, 1.1), c = v3(-0.7, -0.7, 0.9);
    ga_mv C = ga_circle_from_points(a, b, c);
    ga_object o = read_back(C, GA_OBJECT_CIRCLE);
    circle(&V, o.centre, sqrt(o.r2), o.direction, C, "stroke=\"#d62728\" stroke-width=\"2\"", NULL);
    arrow(&V, o.centre, add(o.centre, scale(o.direction, 0.45)), "#d62728");
    text(&V, add(o.centre, scale(o.direction, 0.45)), -50, 16, "", "normal");
    point(&V, o.centre, "#ffffff", "centre", 6, 14);
    point(&V, a, "#d62728", "a", 8, 4);
    point(&V, b, "#d62728", "b", 8, 4);
    point(&V, c, "#d62728", "c", -10, -8);
    end(&V);
}

static void sphere_figure(const char *dir)
{
    view V = {.ox = 170, .oy = 185, .px = 70};
    begin(&V, dir, "cga-sphere.svg", "A sphere: F(a) &#8743; F(b) &#8743; F(c) &#8743; F(d)", 340, 300);
    ga_vec3 a = v3(1.2, 0, 0.2), b = v3(0, 1.2, 0.2), c = v3(0, 0, 1.4), d = v3(-0.72, 0, -0.76);
    ga_mv S = ga_sphere_from_points(a, b, c, d);
    ga_object o = read_back(S, GA_OBJECT_SPHERE);
    double r = sqrt(o.r2);
    sphere(&V, o.centre, r, S, "#2ca02c");
    axes(&V, 1.9);
    point(&V, o.centre, "#ffffff", "centre", 6, 14);
    const ga_vec3 *p[] = {&a, &b, &c, &d};
    const char *name[] = {"a", "b", "c", "d"};
    for (int i = 0; i < 4; i++) {
        check_on(*p[i], S);
        point(&V, *p[i], "#2ca02c", name[i], 8, -4);
    }
    end(&V);
}

static void plane_figure(const char *dir)
{
    view V = {.ox = 170, .oy = 200, .px = 70};
    begin(&V, dir, "cga-plane.svg", "A plane: F(a) &#8743; F(b) &#8743; F(c) &#8743; n", 340, 300);
    axes(&V, 1.2);
    ga_vec3 a = v3(1, 0, 0.5), b = v3(0, 1, 0.2), c = v3(-0.5, 0.5, 0.9);
    ga_mv P = ga_plane_from_points(a, b, c);
    ga_object o = read_back(P, GA_OBJECT_PLANE);
    ga_vec3 u, w, q[4];
    basis(o.direction, &u, &w);
    for (int i = 0; i < 4; i++) {
        double s = (i == 0 || i == 3) ? -1.3 : 1.3, t = i < 2 ? -1.3 : 1.3;
        q[i] = add(o.centre, add(scale(u, s), scale(w, t)));
        check_on(q[i], P);
    }
    fputs("<polygon fill=\"#9467bd\" fill-opacity=\"0.15\" stroke=\"#9467bd\" stroke-width=\"1.5\" points=\"",
          V.f);
    for (int i = 0; i < 4; i++) {
        pt(&V, q[i]);
        fputc(i < 3 ? ' ' : '"', V.f);
    }
    fputs("/>\n", V.f);
    arrow(&V, v3(0, 0, 0), o.centre, "#444444");
    arrow(&V, o.centre, add(o.centre, scale(o.direction, 0.8)), "#9467bd");
    text(&V, add(o.centre, scale(o.direction, 0.8)), 6, 0, "", "normal m");
    text(&V, o.centre, 8, 16, "", "d m");
    point(&V, a, "#9467bd", "a", 8, 4);
    point(&V, b, "#9467bd", "b", 8, 4);
    point(&V, c, "#9467bd", "c", -16, 4);
    end(&V);
}

static void line_figure(const char *dir)
{
    view V = {.ox = 170, .oy = 190, .px = 70};
    begin(&V, dir, "cga-line.svg", "A line: F(a) &#8743; F(b) &#8743; n", 340, 300);
    axes(&V, 1.2);
    ga_vec3 a = v3(1, -0.5, 0.2), b = v3(0, 1, 1);
    ga_mv L = ga_line_from_points(a, b);
    ga_object o = read_back(L, GA_OBJECT_LINE);
    ga_vec3 p = add(o.centre, scale(o.direction, -2)), q = add(o.centre, scale(o.direction, 2));
    check_on(p, L), check_on(q, L);
    segment(&V, p, q, "stroke=\"#ff7f0e\" stroke-width=\"2\"");
    segment(&V, v3(0, 0, 0), o.centre, "stroke=\"#444444\" stroke-width=\"1\" stroke-dasharray=\"3,3\"");
    point(&V, o.centre, "#ffffff", "closest to 0", 8, 14);
    point(&V, a, "#ff7f0e", "a", 8, 4);
    point(&V, b, "#ff7f0e", "b", 8, 4);
    end(&V);
}

/* ---- meets ---------------------------------------------------------------------- */

static void meet_spheres(const char *dir)
{
    view V = {.ox = 190, .oy = 190, .px = 70};
    begin(&V, dir, "cga-meet-spheres.svg", "Two spheres meet in a circle", 380, 300);
    ga_vec3 c1 = v3(0, -0.5, 0), c2 = v3(0, 0.8, 0.2);
    ga_mv S1 = ga_sphere_dual(c1, 1.1), S2 = ga_sphere_dual(c2, 0.9);
    ga_mv D1 = ga_mv_undual(S1), D2 = ga_mv_undual(S2); /* the direct forms, for the checks */
    sphere(&V, c1, 1.1, D1, "#1f77b4");
    sphere(&V, c2, 0.9, D2, "#2ca02c");
    ga_mv M = ga_mv_meet(S1, S2);
    ga_object o = read_back(M, GA_OBJECT_CIRCLE);
    if (o.reality != GA_REALITY_REAL)
        die("the circle is not real");
    circle(&V, o.centre, sqrt(o.r2), o.direction, M, "stroke=\"#d62728\" stroke-width=\"2.5\"", NULL);
    point(&V, c1, "#1f77b4", "S1", -24, 4);
    point(&V, c2, "#2ca02c", "S2", 8, 4);
    text(&V, o.centre, 0, -74, "fill=\"#d62728\"", "meet(S1, S2)");
    end(&V);
}

static void meet_line(const char *dir)
{
    view V = {.ox = 190, .oy = 170, .px = 80};
    begin(&V, dir, "cga-meet-line.svg", "A line meets a sphere in a point pair", 380, 300);
    ga_vec3 c = v3(0, 0, 0);
    ga_mv S = ga_sphere_dual(c, 1);
    sphere(&V, c, 1, ga_mv_undual(S), "#2ca02c");
    ga_vec3 a = v3(0.6, -1.8, -0.3), b = v3(-0.3, 1.8, 0.6);
    ga_mv L = ga_line_from_points(a, b);
    ga_object l = read_back(L, GA_OBJECT_LINE);
    ga_mv M = ga_mv_meet(L, S);
    ga_object o = read_back(M, GA_OBJECT_POINTPAIR);
    if (o.reality != GA_REALITY_REAL)
        die("the point pair is not real");
    double h = sqrt(o.r2);
    ga_vec3 p = add(o.centre, scale(o.direction, -h)), q = add(o.centre, scale(o.direction, h));
    check_on(p, M), check_on(q, M), check_on(p, L), check_on(q, L);
    ga_vec3 e0 = add(l.centre, scale(l.direction, -2)), e1 = add(l.centre, scale(l.direction, 2));
    check_on(e0, L), check_on(e1, L);
    segment(&V, e0, e1, "stroke=\"#ff7f0e\" stroke-width=\"2\"");
    point(&V, p, "#d62728", NULL, 0, 0);
    point(&V, q, "#d62728", NULL, 0, 0);
    text(&V, q, -30, 22, "fill=\"#d62728\"", "meet(L, S)");
    text(&V, e1, 6, 12, "fill=\"#ff7f0e\"", "L");
    text(&V, c, 60, 70, "fill=\"#2ca02c\"", "S");
    end(&V);
}

/* ---- inversion and dilation: views down the z axis -------------------------- */

static void panel_frame(const view *V, double half, const char *label)
{
    double x0, y0, x1, y1;
    screen(V, v3(-half, half, 0), &x0, &y0);
    screen(V, v3(half, -half, 0), &x1, &y1);
    fputs("<rect x=\"", V->f);
    num(V->f, x0);
    fputs("\" y=\"", V->f);
    num(V->f, y0);
    fputs("\" width=\"", V->f);
    num(V->f, x1 - x0);
    fputs("\" height=\"", V->f);
    num(V->f, y1 - y0);
    fputs("\" fill=\"none\" stroke=\"#cccccc\"/>\n", V->f);
    fprintf(V->f, "<text x=\"");
    num(V->f, x0);
    fputs("\" y=\"", V->f);
    num(V->f, y0 - 8);
    fprintf(V->f, "\">%s</text>\n", label);
}

/* the image under the versor W of the line (or circle) X, drawn from its read-back */
static void image(const view *V, ga_mv W, ga_mv X, const char *style)
{
    ga_mv Y;
    if (ga_versor_apply(W, X, &Y) != GA_OK)
        die("the versor does not apply");
    ga_object o;
    int st = ga_object_from_mv(Y, &o);
    if (st != GA_OK)
        die(ga_status_string(st));
    if (o.kind == GA_OBJECT_LINE) {
        ga_vec3 p = add(o.centre, scale(o.direction, -9)), q = add(o.centre, scale(o.direction, 9));
        check_on(p, Y), check_on(q, Y);
        segment(V, p, q, style);
    } else if (o.kind == GA_OBJECT_CIRCLE && o.reality == GA_REALITY_REAL)
        circle(V, o.centre, sqrt(o.r2), o.direction, Y, style, NULL);
    else
        die("the image is neither a line nor a real circle");
}

static void inversion_figure(const char *dir)
{
    view V = {.plan = 1, .oy = 190, .px = 45};
    begin(&V, dir, "cga-inversion.svg", "Inversion in a sphere: lines become circles through its centre", 640,
          380);
    V.plan = 1;
    fputs("<defs><clipPath id=\"right\"><rect x=\"340\" y=\"55\" width=\"270\" height=\"270\"/></clipPath>"
          "</defs>\n",
          V.f);
    double half = 3;
    ga_vec3 c = v3(0, 0, 0);
    double r = 1.5;
    ga_mv W = ga_versor_inversion(c, r);
    ga_mv Sc = ga_mv_undual(ga_sphere_dual(c, r)); /* the sphere, for the check of its trace */
    const char *blue = "stroke=\"#1f77b4\" stroke-width=\"1.5\"",
               *orange = "stroke=\"#ff7f0e\" stroke-width=\"1.5\"";
    const char *green = "stroke=\"#2ca02c\" stroke-width=\"2\"";
    ga_mv small = ga_circle_from_points(v3(2.6, 1.7, 0), v3(1.8, 2.5, 0), v3(1.0, 1.7, 0));
    for (int panel = 0; panel < 2; panel++) {
        V.ox = panel ? 475 : 175;
        panel_frame(&V, half, panel ? "after: their images" : "before: lines x = k, y = k and a circle");
        if (panel)
            fputs("<g clip-path=\"url(#right)\">\n", V.f);
        for (int k = -3; k <= 3; k++) {
            ga_mv X = ga_line_from_points(v3(k, -1, 0), v3(k, 1, 0));
            ga_mv Y = ga_line_from_points(v3(-1, k, 0), v3(1, k, 0));
            if (panel)
                image(&V, W, X, blue), image(&V, W, Y, orange);
            else {
                segment(&V, v3(k, -half, 0), v3(k, half, 0), blue);
                segment(&V, v3(-half, k, 0), v3(half, k, 0), orange);
            }
        }
        if (panel) {
            image(&V, W, small, green);
            fputs("</g>\n", V.f);
        } else {
            ga_object o = read_back(small, GA_OBJECT_CIRCLE);
            circle(&V, o.centre, sqrt(o.r2), o.direction, small, green, NULL);
        }
        /* the sphere of inversion, where it cuts the plane z = 0 */
        circle(&V, c, r, v3(0, 0, 1), Sc, "stroke=\"#000000\" stroke-width=\"2\" stroke-dasharray=\"6,4\"",
               NULL);
        point(&V, c, "#000000", NULL, 0, 0);
    }
    fprintf(V.f, "<text x=\"12\" y=\"350\">dashed: the sphere of inversion, centre 0, radius 1.5: its points "
                 "stay put, inside and outside swap.</text>\n"
                 "<text x=\"12\" y=\"368\">x = 0 and y = 0 pass through the centre and map to "
                 "themselves.</text>\n");
    end(&V);
}

static void dilation_figure(const char *dir)
{
    view V = {.plan = 1, .ox = 120, .oy = 290, .px = 55};
    begin(&V, dir, "cga-dilation.svg", "Dilation about c by s = 2: lines stay parallel, circles stay circles",
          600, 340);
    V.plan = 1;
    ga_vec3 c = v3(-1, -0.5, 0);
    ga_mv W;
    if (ga_versor_dilation(c, 2, &W) != GA_OK)
        die("ga_versor_dilation");
    ga_vec3 tri[3] = {v3(0, 0, 0), v3(1.2, 0, 0), v3(0.3, 1.1, 0)};
    ga_mv circ = ga_circle_from_points(v3(2.3, 0.2, 0), v3(2.6, -0.1, 0), v3(2.3, -0.4, 0));
    const char *ray = "stroke=\"#aaaaaa\" stroke-width=\"1\" stroke-dasharray=\"3,3\"";
    ga_vec3 img[3];
    for (int i = 0; i < 3; i++) {
        ga_mv Y;
        if (ga_versor_apply(W, ga_point_up(tri[i]), &Y) != GA_OK || ga_point_down(Y, &img[i]) != GA_OK)
            die("a point does not map");
        segment(&V, c, img[i], ray);
    }
    const char *blue = "stroke=\"#1f77b4\" stroke-width=\"2\"",
               *light = "stroke=\"#1f77b4\" stroke-width=\"1\"";
    for (int k = 0; k < 2; k++) {
        const ga_vec3 *t = k ? img : tri;
        fprintf(V.f, "<polygon fill=\"#1f77b4\" fill-opacity=\"%s\" %s points=\"", k ? "0.15" : "0.05",
                k ? blue : light);
        for (int i = 0; i < 3; i++) {
            pt(&V, t[i]);
            fputc(i < 2 ? ' ' : '"', V.f);
        }
        fputs("/>\n", V.f);
    }
    /* the lines of the triangle's sides, mapped as lines: each image is parallel */
    for (int i = 0; i < 3; i++) {
        ga_mv L = ga_line_from_points(tri[i], tri[(i + 1) % 3]), M;
        if (ga_versor_apply(W, L, &M) != GA_OK)
            die("a line does not map");
        ga_object a = read_back(L, GA_OBJECT_LINE), b = read_back(M, GA_OBJECT_LINE);
        if (fabs(fabs(dot(a.direction, b.direction)) - 1) > 1e-12)
            die("a side's image is not parallel to it");
        check_on(img[i], M), check_on(img[(i + 1) % 3], M);
    }
    ga_object o = read_back(circ, GA_OBJECT_CIRCLE);
    circle(&V, o.centre, sqrt(o.r2), o.direction, circ, "stroke=\"#d62728\" stroke-width=\"1\"", NULL);
    ga_mv circ2;
    if (ga_versor_apply(W, circ, &circ2) != GA_OK)
        die("the circle does not map");
    ga_object o2 = read_back(circ2, GA_OBJECT_CIRCLE);
    segment(&V, c, o2.centre, ray);
    circle(&V, o2.centre, sqrt(o2.r2), o2.direction, circ2, "stroke=\"#d62728\" stroke-width=\"2\"", NULL);
    point(&V, c, "#000000", "c", -14, 4);
    text(&V, tri[2], -14, -8, "", "before");
    text(&V, img[2], -20, -8, "", "after");
    char s[160];
    snprintf(s, sizeof s, "circle: radius %.3g becomes %.3g", sqrt(o.r2), sqrt(o2.r2));
    text(&V, o2.centre, -40, 14 + sqrt(o2.r2) * V.px, "fill=\"#d62728\"", s);
    end(&V);
}

/* ---- the null cone and an imaginary circle -------------------------------------- */

/* the vector c1 e1 + c4 e4 + c5 e5 of G(4,1), drawn at (c1, c4, c5) */
static ga_mv e145(double c1, double c4, double c5)
{
    ga_mv v = ga_mv_scalar(0);
    v.c[0] = 0, v.c[1] = c1, v.c[4] = c4, v.c[5] = c5;
    return v;
}

/* v is null: v.v = 0 to 1e-12 of |v|^2 */
static void check_null(ga_mv v)
{
    double s = ga_mv_sp(v, v), m = ga_mv_maxabs(v);
    if (!(fabs(s) <= 1e-12 * (m * m + 1)))
        die("a point drawn on the cone is not a null vector");
}

static void null_cone(const char *dir)
{
    view V = {.ox = 230, .oy = 300, .px = 58};
    begin(&V, dir, "cga-null-cone.svg", "Points are null vectors: F(x) lies on the cone F &#183; F = 0", 460,
          390);
    /* the coordinates (c1, c4, c5) of e1, e4, e5, drawn as x, y, z, seen from the side of e1 */
    double az = -62 * PI / 180, el = 14 * PI / 180;
    V.right = v3(-sin(az), cos(az), 0);
    V.up = v3(-sin(el) * cos(az), -sin(el) * sin(az), cos(el));
    V.toward = v3(cos(el) * cos(az), cos(el) * sin(az), sin(el));
    const double top = 3.4;
    const char *cone = "stroke=\"#1f77b4\" stroke-width=\"1\" stroke-opacity=\"0.6\"";
    /* the cone c1^2 + c4^2 = c5^2, 0 <= c5 <= top: its rim and 12 of its lines, each point checked null */
    fprintf(V.f, "<polyline fill=\"#1f77b4\" fill-opacity=\"0.08\" %s points=\"", cone);
    for (int i = 0; i <= 120; i++) {
        double a = 2 * PI * i / 120;
        check_null(e145(top * cos(a), top * sin(a), top));
        if (i)
            fputc(' ', V.f);
        pt(&V, v3(top * cos(a), top * sin(a), top));
    }
    fputs("\"/>\n", V.f);
    for (int k = 0; k < 12; k++) {
        double a = 2 * PI * k / 12;
        check_null(e145(top * cos(a), top * sin(a), top));
        segment(&V, v3(0, 0, 0), v3(top * cos(a), top * sin(a), top), cone);
    }
    /* the hyperplane F . n = -1, c5 - c4 = 1, where the points of space lie */
    fputs("<polygon fill=\"#ff7f0e\" fill-opacity=\"0.10\" stroke=\"#ff7f0e\" stroke-width=\"1\" points=\"",
          V.f);
    pt(&V, v3(-2.6, -0.7, 0.3)), fputc(' ', V.f), pt(&V, v3(2.6, -0.7, 0.3)), fputc(' ', V.f);
    pt(&V, v3(2.6, 2.4, 3.4)), fputc(' ', V.f), pt(&V, v3(-2.6, 2.4, 3.4));
    fputs("\"/>\n", V.f);
    /* the axes e1, e4, e5 */
    const char *grey = "#888888";
    arrow(&V, v3(0, 0, 0), v3(1.6, 0, 0), grey);
    arrow(&V, v3(0, 0, 0), v3(0, 1.3, 0), grey);
    arrow(&V, v3(0, 0, 0), v3(0, 0, 1.3), grey);
    text(&V, v3(1.6, 0, 0), 4, 14, "fill=\"#666666\"", "e1");
    text(&V, v3(0, 1.3, 0), 6, 4, "fill=\"#666666\"", "e4");
    text(&V, v3(0, 0, 1.3), -22, 0, "fill=\"#666666\"", "e5");
    /* the points of the e1 axis, F(t e1), from the library: a parabola on the cone */
    fputs("<polyline fill=\"none\" stroke=\"#d62728\" stroke-width=\"2.5\" points=\"", V.f);
    for (int i = 0; i <= 100; i++) {
        double t = -2.3 + 4.6 * i / 100;
        ga_mv F = ga_point_up(v3(t, 0, 0));
        check_null(F);
        if (fabs(ga_mv_sp(F, ga_mv_add(e145(0, 1, 0), e145(0, 0, 1))) + 1) > 1e-12)
            die("F(x) . n is not -1");
        if (i)
            fputc(' ', V.f);
        pt(&V, v3(F.c[1], F.c[4], F.c[5]));
    }
    fputs("\"/>\n", V.f);
    const double ts[] = {0, 1, -1, 2};
    const char *names[] = {"F(0) = &#8722;n&#772;/2", "F(e1)", "F(&#8722;e1)", "F(2 e1)"};
    const double dx[] = {-96, 10, -58, 10}, dy[] = {22, 14, 14, 14};
    for (int i = 0; i < 4; i++) {
        ga_mv F = ga_point_up(v3(ts[i], 0, 0));
        point(&V, v3(F.c[1], F.c[4], F.c[5]), "#d62728", names[i], dx[i], dy[i]);
    }
    /* n = e4 + e5 lies on the cone: the point at infinity, where F(x) goes as |x| grows */
    check_null(e145(0, 1, 1));
    arrow(&V, v3(0, 0, 0), v3(0, 2.2, 2.2), "#2ca02c");
    text(&V, v3(0, 2.2, 2.2), -150, -4, "fill=\"#2ca02c\"", "n = e4 + e5 (infinity)");
    fprintf(
        V.f,
        "<text x=\"12\" y=\"44\">the coefficients (c1, c4, c5) of F(t e1) = t e1 + (t&#178; &#8722; 1)/2 e4 "
        "+ (t&#178; + 1)/2 e5</text>\n"
        "<text x=\"12\" y=\"352\">blue: the null cone c1&#178; + c4&#178; = c5&#178;; orange: the "
        "hyperplane F &#183; n = &#8722;1.</text>\n"
        "<text x=\"12\" y=\"370\">red: the points of the e1 axis, a parabola where the two "
        "meet.</text>\n");
    end(&V);
}

/* two unit spheres whose centres are d apart meet in a circle of r^2 = 1 - d^2/4: real,
 * tangent (one point) or imaginary (no real point, drawn dashed with radius sqrt(-r^2)) */
static void imaginary_circle(const char *dir)
{
    view V = {.oy = 135, .px = 50};
    begin(&V, dir, "cga-imaginary-circle.svg",
          "Two unit spheres d apart meet in a real, tangent or imaginary circle", 760, 280);
    const double ds[] = {1.5, 2, 3};
    const int want[] = {GA_REALITY_REAL, GA_REALITY_TANGENT, GA_REALITY_IMAGINARY};
    for (int k = 0; k < 3; k++) {
        V.ox = 70 + 250 * k;
        ga_vec3 c1 = v3(0, 0, 0), c2 = v3(0, ds[k], 0);
        ga_mv S1 = ga_sphere_dual(c1, 1), S2 = ga_sphere_dual(c2, 1);
        sphere(&V, c1, 1, ga_mv_undual(S1), "#1f77b4");
        sphere(&V, c2, 1, ga_mv_undual(S2), "#2ca02c");
        ga_mv M = ga_mv_meet(S1, S2);
        ga_object o = read_back(M, GA_OBJECT_CIRCLE);
        if (o.reality != want[k] || fabs(o.r2 - (1 - ds[k] * ds[k] / 4)) > 1e-12 ||
            fabs(o.centre.y - ds[k] / 2) > 1e-12 || fabs(fabs(o.direction.y) - 1) > 1e-12)
            die("the meet is not the circle of r^2 = 1 - d^2/4 halfway between the centres");
        char s[160];
        if (o.reality == GA_REALITY_REAL)
            circle(&V, o.centre, sqrt(o.r2), o.direction, M, "stroke=\"#d62728\" stroke-width=\"2.5\"", NULL);
        else if (o.reality == GA_REALITY_TANGENT)
            point(&V, o.centre, "#d62728", NULL, 0, 0);
        else { /* no real point to check: drawn from the read-back, radius sqrt(-r^2), dashed */
            ga_vec3 u, w;
            basis(o.direction, &u, &w);
            double r = sqrt(-o.r2);
            fputs("<polyline fill=\"none\" stroke=\"#d62728\" stroke-width=\"2.5\" stroke-dasharray=\"7,5\" "
                  "points=\"",
                  V.f);
            for (int i = 0; i <= 144; i++) {
                double t = 2 * PI * i / 144;
                if (i)
                    fputc(' ', V.f);
                pt(&V, add(o.centre, add(scale(u, r * cos(t)), scale(w, r * sin(t)))));
            }
            fputs("\"/>\n", V.f);
            point(&V, o.centre, "#d62728", NULL, 0, 0);
        }
        snprintf(s, sizeof s, "d = %g: %s, r&#178; = %g", ds[k],
                 k == 0   ? "real"
                 : k == 1 ? "tangent"
                          : "imaginary",
                 o.r2 == 0 ? 0.0 : o.r2);
        text(&V, c1, -50, 95, "", s);
    }
    fprintf(V.f,
            "<text x=\"12\" y=\"252\">The meet is a circle halfway between the centres, r&#178; = 1 &#8722; "
            "d&#178;/4. Beyond d = 2 it has no real point:</text>\n"
            "<text x=\"12\" y=\"270\">r&#178; &lt; 0, an imaginary circle, drawn dashed with radius "
            "&#8730;&#8722;r&#178; about its centre, where the real one would be.</text>\n");
    end(&V);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: figures OUTDIR\n");
        return 2;
    }
    pointpair(argv[1]);
    circle_figure(argv[1]);
    sphere_figure(argv[1]);
    plane_figure(argv[1]);
    line_figure(argv[1]);
    meet_spheres(argv[1]);
    meet_line(argv[1]);
    inversion_figure(argv[1]);
    dilation_figure(argv[1]);
    null_cone(argv[1]);
    imaginary_circle(argv[1]);
    return 0;
}
